#pragma once

#include "LiveCommand.h"

#include <protocol/FieldJson.h>
#include <safety/SoftLimits.h>

#include <QtCore/QJsonObject>

#include <optional>

namespace lk::lkctl {

/// `lkctl control ID MODE VALUE`: one motion command, checked by the series limits and the
/// user's soft limits (safety::MotionGuard) before anything is sent.
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
        std::optional<QJsonObject> limitsJson; ///< --limits FILE
        std::optional<double> maxTorqueA, maxSpeedDps;
        std::optional<int> maxPower;
        bool json = false;
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    std::optional<protocol::FieldBuildResult> build(const QStringList &pos, const ArgParser &parser,
                                                    Console &console, int *status) const;
    bool readLimitFlags(const ArgParser &parser, Plan &plan, Console &console, int *status) const;
    safety::SoftLimits limitsFor(const Plan &plan, std::optional<protocol::Series> series) const;
};

} // namespace lk::lkctl
