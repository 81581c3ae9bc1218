#pragma once

#include "StepTestRunner.h"

#include <safety/SoftLimits.h>

#include <QtCore/QString>

#include <functional>

class QObject;

namespace lk::bus {
class BusSession;
}

namespace lk::tuning {

class GainKeeper;

/// Why a gain search ended.
enum class SearchEnd {
    Finished,        ///< ran to its end (with a best or none)
    Unstable,        ///< ran to its end at the first unstable candidate
    AbortedByUser,   ///< abort(): Esc, the Stop button, Ctrl-C
    EmergencyStop,   ///< an emergency stop from anywhere else
    Refused,         ///< a soft limit refused a step or the Bode's sweep
    BadSpec,         ///< it cannot run as set: nothing was sent
    FailedToRead,    ///< the gains could not be read: nothing was sent
    DriveSilent,     ///< a step, a write or the return went unanswered: it stopped
    LinkLost,        ///< the bus went away: it stopped
    FailedToRestore, ///< the gains read could not be written back at the end: it stopped
};

/// What the drive was left doing when a run ended.
enum class DriveLeft {
    Untouched,   ///< nothing was sent
    NoStepSent,  ///< gains were written (and put back), nothing that moves
    Off,         ///< Motor Off, acknowledged
    MayBeMoving, ///< Motor Off went out and was not acknowledged
    HoldsZero,   ///< at 0 dps, the speed read at the start, motor on
    BackAtSpeed, ///< back at the speed read at the start (TuningOutcome::speedDps), turning
    HoldsAngle,  ///< holds the angle read at the start (TuningOutcome::angleDeg), motor on
};

/// How a gain search ended, as facts (the views word them; the English message is for logs).
struct TuningOutcome {
    SearchEnd end = SearchEnd::BadSpec;
    DriveLeft drive = DriveLeft::Untouched;
    double speedDps = 0;       ///< BackAtSpeed: the speed
    double angleDeg = 0;       ///< HoldsAngle: the multi-turn rotor angle, deg
    bool gainsRestored = true; ///< false: RAM may hold a candidate's gains (read them back)
};

/// What TuningEnd::halt() did: the facts a user needs after a stop.
struct HaltOutcome {
    int id = 0;
    bool offAcknowledged = false; ///< false: the drive may still be moving
    bool gainsRestored = false;   ///< false: RAM holds what the run last wrote, or nothing known
    QString restoreError;         ///< why they were not written back (English)
    /// English: "drive 3 is off; the gains and acceleration read before are back in RAM".
    QString words() const;
};

/// How a frequency sweep or a gain search begins and the two ways it ends on the drive,
/// shared so that both run alike: the gains read first, the safe stop (abort, failure) and the
/// return to the speed read at the start.
class TuningEnd {
public:
    /// The first step of a run: a `specError` ends it (BadSpec, "...; nothing was sent", from
    /// the event loop: never inside start()); otherwise `keeper` reads drive `id`'s gains and
    /// acceleration, without which nothing runs (they are what an abort puts back). `done`
    /// gets None once they were read, Silent with the words when they were not.
    static void readFirst(GainKeeper &keeper, int id, const QString &specError, QObject *context,
                          std::function<void(StepTestFailure, const QString &)> done);
    /// Stops the setpoint stream, sends motor off (an emergency stop: `id` first, then every
    /// ID), then writes the settings `keeper` read back to RAM; `done` gets the outcome in
    /// words ("drive 3 is off; the gains and acceleration read before are back in RAM").
    static void haltAndRestore(bus::BusSession &session, GainKeeper &keeper, int id,
                               QObject *context, std::function<void(const QString &)> done);
    /// haltAndRestore() with the outcome as facts.
    static void halt(bus::BusSession &session, GainKeeper &keeper, int id, QObject *context,
                     std::function<void(const HaltOutcome &)> done);
    /// Speed `dps` to drive `id` through the motion gate; `done(ok, words)`: what the drive
    /// does now, or why it was not sent or not answered.
    static void returnToSpeed(bus::BusSession &session, int id, double dps,
                              const safety::SoftLimits &limits, QObject *context,
                              std::function<void(bool, const QString &)> done);
};

} // namespace lk::tuning
