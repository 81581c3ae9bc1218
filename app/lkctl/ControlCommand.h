#pragma once

#include "LiveCommand.h"

#include "LiveBus.h"
#include "MotionLimitOptions.h"
#include "RequestText.h"
#include <protocol/FieldJson.h>

#include <safety/DriveLimits.h>
#include <safety/MotionPlanner.h>
#include <safety/SoftLimits.h>

#include <QtCore/QByteArray>

#include <optional>

namespace lk::lkctl {

class ControlWatch;

/// `lkctl control ID MODE VALUE`: one motion command, made safe by safety::MotionPlanner
/// (speed bound on every move, targets from the drive's read angle) and checked by the series
/// limits and the user's soft limits before anything is sent.
class ControlCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("control"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// The command line, checked before the bus is touched.
    struct Plan {
        protocol::Request request; ///< built for a V2.3 drive until the drive is identified
        QString command;           ///< its name and fields, to build it for the drive found
        FieldValues values;
        MotionLimitOptions limits;
        bool json = false;
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    std::optional<FieldBuildResult> build(const QStringList &pos, const ArgParser &parser,
                                          Console &console, int *status, Plan &plan) const;
    /// V2.35: reads the motor state (0x9A) and the brake (0x8C) before motion. False, after
    /// printing why (`status`), when the drive is off: a control command would not turn it on
    /// (docs/V2.35.md section 11). An engaged brake is a warning: the shaft is held.
    bool checkDriveState(LiveBus &bus, int id, int *status) const;
    /// V2.35: the limits the drive holds itself (Max Speed, max torque current or Max Power,
    /// Max Angle), read with 0x40; a parameter that does not answer bounds nothing.
    safety::DriveLimits readDriveLimits(LiveBus &bus, int id,
                                        const protocol::DecodeContext &drive) const;
    /// Reads the multi-turn angle (0x92) when the move needs it; false after printing why.
    bool readPosition(LiveBus &bus, const Plan &plan, const LiveBus::Identity &who,
                      const safety::SoftLimits &limits, safety::DrivePosition &position) const;
    /// Builds, plans, checks and sends the command for the drive identified.
    /// `watch`: what happens after a torque or open-loop command (ControlWatch).
    int runFor(LiveBus &bus, Plan plan, const LiveBus::Identity &who, ControlWatch &watch) const;
    int send(LiveBus &bus, const Plan &plan, const safety::MotionPlan &motion,
             const safety::DrivePosition &position, const protocol::DecodeContext &drive) const;
};

} // namespace lk::lkctl
