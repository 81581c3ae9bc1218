#include "TuningCommand.h"

namespace lk::lkctl {

std::optional<safety::SoftLimits> TuningCommand::openDrive(LiveBus &bus,
                                                           const BusOptions &busOptions, int id,
                                                           const MotionLimitOptions &options,
                                                           Console &console, int *status) const
{
    *status = kExitFailure;
    if (!bus.open(busOptions))
        return std::nullopt;
    const std::optional<LiveBus::Identity> who = bus.identify(id);
    if (!who)
        return std::nullopt;
    QString error;
    std::optional<safety::SoftLimits> limits = options.limitsFor(who->series, &error);
    if (!limits)
        *status = usageError(console, error);
    return limits;
}

} // namespace lk::lkctl
