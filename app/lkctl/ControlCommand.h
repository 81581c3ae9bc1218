#pragma once

#include "LiveCommand.h"

#include "LiveBus.h"
#include "MotionLimitOptions.h"
#include "RequestText.h"
#include <protocol/FieldJson.h>

#include <safety/MotionPlanner.h>
#include <safety/SoftLimits.h>

#include <QtCore/QByteArray>

#include <optional>

namespace lk::lkctl {

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
        protocol::Request request;
        MotionLimitOptions limits;
        bool json = false;
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    std::optional<FieldBuildResult> build(const QStringList &pos, const ArgParser &parser,
                                          Console &console, int *status) const;
    /// Reads the multi-turn angle (0x92) when the move needs it; false after printing why.
    bool readPosition(LiveBus &bus, const Plan &plan, const LiveBus::Identity &who,
                      const safety::SoftLimits &limits, safety::DrivePosition &position) const;
    int send(LiveBus &bus, const Plan &plan, const safety::MotionPlan &motion,
             const safety::DrivePosition &position) const;
};

} // namespace lk::lkctl
