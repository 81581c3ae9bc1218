#pragma once

#include "protocol/Reply.h"
#include "protocol/Request.h"
#include "protocol/Series.h"

#include <QtCore/QByteArray>

#include <optional>

namespace lk::sim {

/// One request of lksim's foreign master and what came of it: the ground truth a listen-only
/// monitor is tested against (`--controller-log`, one JSON line each).
struct ControllerTransaction {
    enum class Outcome {
        Answered,   ///< a valid reply for this ID and command came back
        Unanswered, ///< no reply: no such drive, a command it lacks, or a silenced drive
        Dropped,    ///< the drive acted but its reply was lost (--faults drop)
        Garbled,    ///< reply bytes came that do not decode (corrupt, length, bad checksum)
        Collided,   ///< another master transmitted while this request or its reply was on the wire
    };

    double requestS = 0; ///< the request's first byte on the wire (seconds since the start)
    double requestEndS = 0;
    protocol::Request request;
    protocol::DecodeContext context; ///< the addressed drive's (MF V2.3 for an absent ID)
    Outcome outcome = Outcome::Unanswered;
    std::optional<protocol::Reply> reply; ///< Answered only
    QByteArray replyBytes;                ///< what the drive put on the wire, noise included
    double replyEndS = -1;                ///< the reply's last byte; < 0: no reply bytes
    int noiseBytes = 0;                   ///< garbage before the reply (--faults garbage)

    static const char *outcomeName(Outcome outcome); ///< "answered", "unanswered", ...
    /// {"time_s","id","command","code","request":{fields},"outcome"[,"reply_s"]
    /// [,"noise_bytes"][,"reply":{fields}]} on one line, fields as FieldJson writes them.
    QByteArray toJsonLine() const;
};

} // namespace lk::sim
