#pragma once

#include "BusOptions.h"

#include <bus/MultiTorque.h>
#include <protocol/Request.h>

#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::lkctl {

class ArgParser;
class Console;
class LiveBus;

/// `lkctl control multi-torque ID=IQ_A[,ID=IQ_A...]`: the old CAN generation's multi-motor
/// torque frame (0x280), up to four drives (IDs 1..4) in one frame. Every drive is checked as
/// `control ID torque` checks one (its series known, its series' current, its torque limit),
/// before the bus is opened; one refusal names the drive and the limit and sends nothing to
/// any drive. Then the same --watch and end-of-watch stop as `control ID torque`, for all of
/// them (ControlWatch::followGroup).
class MultiTorqueControl {
public:
    static constexpr const char *kMode = "multi-torque";
    /// The usage lines of the mode, for control's --help.
    static QString helpText();
    /// Runs it; `command` is "control" (for messages). Returns the exit status.
    static int run(const ArgParser &parser, const BusOptions &options, Console &console,
                   const QString &command);

private:
    struct Drive {
        int id = 0;
        double iqA = 0;
    };
    /// "1=1.6,2=-1.6": IDs 1..4, each once; nullopt with a usage `error`.
    static std::optional<QVector<Drive>> parseDrives(const QString &text, QString *error);
    static int report(LiveBus &bus, const QVector<protocol::Request> &torques,
                      const bus::MultiTorqueResult &result, bool json);
};

} // namespace lk::lkctl
