#pragma once

#include "LiveBus.h"
#include "LiveCommand.h"
#include "MotionLimitOptions.h"

#include <system/SignalWatcher.h>
#include <tuning/StepTestRunner.h>

#include <functional>
#include <optional>

namespace lk::lkctl {

/// What lkctl step, freq and tune share: the bus opened, the drive identified (series and
/// generation) and the soft limits for its series before anything is read or moved; a runner
/// run to its end under Ctrl-C; and the exit status of how it ended.
class TuningCommand : public LiveCommand {
protected:
    /// Opens `bus`, identifies drive `id` and lays `options` over its series' limits; nullopt
    /// after printing why, with `status` set (failure, or a usage error for the limits).
    /// `who`, when given, receives the drive's identity.
    std::optional<safety::SoftLimits> openDrive(LiveBus &bus, const BusOptions &busOptions, int id,
                                                const MotionLimitOptions &options, Console &console,
                                                int *status,
                                                LiveBus::Identity *who = nullptr) const;

    /// Runs `runner` (a StepTestRunner, FrequencySweepRunner or GainSearchRunner) to its end:
    /// `start` starts it; Ctrl-C calls its abort() (what that stops is the runner's: the
    /// setpoints, or also the motor and the settings read); past `waitMs` it is aborted too,
    /// the safety net: never returns without a result.
    template <typename Runner, typename Result>
    static Result runToEnd(LiveBus &bus, Runner &runner, const std::function<void()> &start,
                           int waitMs)
    {
        std::optional<Result> result;
        QObject::connect(&runner, &Runner::finished, [&](const Result &r) { result = r; });
        QObject::connect(&runner, &Runner::failed, [&](const Result &r) { result = r; });
        system::SignalWatcher watcher;
        QObject::connect(&watcher, &system::SignalWatcher::signalled, &runner, &Runner::abort);
        start();
        if (!bus.waitUntil([&] { return result.has_value(); }, waitMs)) {
            runner.abort();
            (void)bus.waitUntil([&] { return result.has_value(); });
        }
        return result.value_or(Result{});
    }

    /// The exit status of a run that ended with `failure`, after printing it: nullopt when it
    /// did not fail (the caller prints the result). A refusal is worded by `refusal` (exit 4),
    /// a bad spec is a usage error, anything else prints `message` (exit 1).
    std::optional<int> failureStatus(LiveBus &bus, Console &console,
                                     tuning::StepTestFailure failure, const QString &message,
                                     const std::function<void()> &refusal) const;
};

} // namespace lk::lkctl
