#include "TuningCommand.h"

namespace lk::lkctl {

std::optional<safety::SoftLimits> TuningCommand::openDrive(LiveBus &bus,
                                                           const BusOptions &busOptions, int id,
                                                           const MotionLimitOptions &options,
                                                           Console &console, int *status,
                                                           LiveBus::Identity *who) const
{
    *status = kExitFailure;
    if (!bus.open(busOptions))
        return std::nullopt;
    const std::optional<LiveBus::Identity> identity = bus.identify(id);
    if (!identity)
        return std::nullopt;
    if (who)
        *who = *identity;
    QString error;
    std::optional<safety::SoftLimits> limits = options.limitsFor(identity->series, &error);
    if (!limits) {
        *status = usageError(console, error);
        return limits;
    }
    // The engine's own bounds for this drive: the speed watch, and the torque limit a CAN
    // V2.36 speed command carries (the sweep's, the step's and the return to the start speed).
    bus.session().setSoftLimits(id, *limits);
    return limits;
}

std::optional<int> TuningCommand::failureStatus(LiveBus &bus, Console &console,
                                                tuning::StepTestFailure failure,
                                                const QString &message,
                                                const std::function<void()> &refusal) const
{
    using tuning::StepTestFailure;
    switch (failure) {
    case StepTestFailure::None:
        return std::nullopt;
    case StepTestFailure::Refused:
        refusal();
        return kExitRefused;
    case StepTestFailure::BadSpec:
        return usageError(console, message);
    default:
        bus.error(message);
        return kExitFailure;
    }
}

} // namespace lk::lkctl
