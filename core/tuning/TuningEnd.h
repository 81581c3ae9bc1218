#pragma once

#include <safety/SoftLimits.h>

#include <QtCore/QString>

#include <functional>

class QObject;

namespace lk::bus {
class BusSession;
}

namespace lk::tuning {

class GainKeeper;

/// The two ways a frequency sweep or a gain search ends on the drive, shared so that both
/// end alike: the safe stop (abort, failure) and the return to the speed read at the start.
class TuningEnd {
public:
    /// Stops the setpoint stream, sends motor off (an emergency stop: `id` first, then every
    /// ID), then writes the settings `keeper` read back to RAM; `done` gets the outcome in
    /// words ("drive 3 is off; the gains and acceleration read before are back in RAM").
    static void haltAndRestore(bus::BusSession &session, GainKeeper &keeper, int id,
                               QObject *context, std::function<void(const QString &)> done);
    /// Speed `dps` to drive `id` through the motion gate; `done(ok, words)`: what the drive
    /// does now, or why it was not sent or not answered.
    static void returnToSpeed(bus::BusSession &session, int id, double dps,
                              const safety::SoftLimits &limits, QObject *context,
                              std::function<void(bool, const QString &)> done);
};

} // namespace lk::tuning
