#pragma once

#include "Frame.h"
#include "Reply.h"
#include "Request.h"
#include "Series.h"

#include <QtCore/QString>

namespace lk::protocol {

/// Compact one-line human summaries of requests and replies for the GUI's traffic view,
/// e.g. "speed 100.00 dps" or "T 31 C, iq 1.23 A, 360 dps, enc 12345". Not localised and not
/// a contract: scripts read `lkctl decode` JSON instead. Commands without data (reads,
/// off/stop/run, plain echoes) give an empty summary; the command name says it all.
class FieldText {
public:
    /// The context gives the torque command's scale (V2.35 MF drives differ).
    static QString request(const Request &request, const DecodeContext &context = {});
    static QString reply(const Reply &reply);
    /// A valid frame as seen on the bus (an echo reads as its request); empty when the frame
    /// does not decode in that direction.
    static QString frame(const Frame &frame, FrameDirection direction,
                         const DecodeContext &context);
};

} // namespace lk::protocol
