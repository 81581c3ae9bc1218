#pragma once

#include "LiveCommand.h"

#include <protocol/Values.h>

#include <optional>

namespace lk::lkctl {

class LiveBus;

/// `lkctl brake ID status|engage|release [--yes] [--motor-off-ok]`: the V2.35 holding brake
/// (0x8C). Releasing needs --yes (a vertical axis drops its load); with the motor off (read
/// first with read_state1) nothing holds the load, so that also needs --motor-off-ok.
class BrakeCommand : public LiveCommand {
public:
    QString name() const override { return QStringLiteral("brake"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    /// Release only: whether the motor is on; nullopt after printing why it is refused.
    std::optional<std::optional<bool>> checkRelease(LiveBus &bus, int id, bool motorOffOk,
                                                    int *status) const;
    static int finish(LiveBus &bus, int id, protocol::BrakeAction action,
                      std::optional<bool> motorOn, bool json);
};

} // namespace lk::lkctl
