#pragma once

#include "RequestResult.h"

#include <protocol/Command.h>

#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace lk::bus {

/// Where the speed bound of a watched drive came from.
enum class SpeedWatchSource {
    SoftLimit,     ///< the user's soft limits (BusSession::setSoftLimits)
    SeriesDefault, ///< none given: SoftLimits::defaults(series), the series' top speed
};

/// A drive under a torque (0xA1) or open-loop (0xA0) command went past its speed bound and
/// the bus thread's speed watch (SpeedWatch) sent it Motor Stop (0x81): which drive, which
/// limit, the speed seen, and how the stop ended.
struct SpeedWatchTrip {
    int id = 0;
    protocol::Command mode = protocol::Command::Torque; ///< Torque or OpenLoop
    double limitDps = 0;                                ///< the speed limit (rotor dps)
    double thresholdDps = 0; ///< limit + margin (SpeedWatch::thresholdDps): what was passed
    SpeedWatchSource source = SpeedWatchSource::SoftLimit;
    double speedDps = 0;   ///< the speed the drive reported, rotor dps, signed
    double seenS = 0;      ///< session clock (s) when that reply arrived
    double stopEndedS = 0; ///< session clock (s) when the Motor Stop ended
    RequestStatus stopStatus = RequestStatus::Ok; ///< Ok: the drive acknowledged the stop
    QString stopReason; ///< English detail when it did not (RequestResult::reason)

    bool stopAcknowledged() const { return stopStatus == RequestStatus::Ok; }
    /// From the reply that showed the speed to the stop's end, in ms.
    double reactionMs() const { return (stopEndedS - seenS) * 1e3; }
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::SpeedWatchTrip)
