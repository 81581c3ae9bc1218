#pragma once

#include "FieldError.h"
#include "Reply.h"
#include "Request.h"
#include "Series.h"

#include <QtCore/QByteArray>

namespace lk::protocol {

/// What goes to a transport for one typed value: RS485 frame bytes, or one CanRecord.
struct WireEncodeResult {
    QByteArray bytes; ///< empty when refused
    FieldError error; ///< why the value cannot be sent on this link and generation
    bool ok() const { return !bytes.isEmpty(); }
};

/// The bytes a host writes for `request` on `context.link`: the codec, not the transport,
/// decides what bytes mean. RS485: Request::encode(). CAN: one CanRecord of the CAN layout,
/// or the refusal of a value the generation cannot carry (can::encodeRequest).
WireEncodeResult encodeRequest(const Request &request, const DecodeContext &context);
/// The bytes a drive answers `reply` with on `context.link` (the simulator's side).
WireEncodeResult encodeReply(const Reply &reply, const DecodeContext &context);

} // namespace lk::protocol
