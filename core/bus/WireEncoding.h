#pragma once

#include <protocol/LinkCodec.h>
#include <protocol/Request.h>
#include <protocol/Series.h>
#include <safety/SoftLimits.h>

namespace lk::bus {

/// The bytes `request` goes out as for a drive of `context` (an RS485 frame, or one
/// CanRecord). A speed command to a CAN V2.36 drive, which reads B2-B3 as the command's torque
/// limit, first gets `limits`' max torque (rounded down at the drive's iq scale, never 0): what
/// 0 means there is unknown (docs/CAN.md section 9). Without `limits` it keeps none, and the
/// codec refuses it. Nor is it sent while the drive's series is not known (`seriesKnown`):
/// the limit's raw value would be a guess at the iq scale.
protocol::WireEncodeResult encodeForWire(protocol::Request &request,
                                         const protocol::DecodeContext &context,
                                         const safety::SoftLimits *limits, bool seriesKnown);

} // namespace lk::bus
