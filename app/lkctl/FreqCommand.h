#pragma once

#include "LiveBus.h"
#include "MotionLimitOptions.h"
#include "TuningCommand.h"

#include <tuning/FrequencySweepRunner.h>

#include <optional>

namespace lk::lkctl {

/// `lkctl freq ID speed|position`: the speed or position loop's frequency response
/// (tuning::FrequencySweepRunner): a stepped sine of the speed setpoint around an operating
/// point, or of the angle around where the drive is, fitted per frequency on the replies' real
/// times, with the -3 dB bandwidth, the peak and the phase at the bandwidth (--save: the run as
/// a FrequencyRunFile).
/// Writes nothing lasting: the acceleration limit lifted for the sweep goes back to RAM.
class FreqCommand : public TuningCommand {
public:
    QString name() const override { return QStringLiteral("freq"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    struct Plan {
        tuning::FrequencySweepSpec spec;
        MotionLimitOptions limits;
        bool json = false;
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    tuning::FrequencySweepResult runSweep(LiveBus &bus, const Plan &plan,
                                          const safety::SoftLimits &limits) const;
    /// Saves the run as FrequencyRunFile; false (and said on stderr) when it could not be.
    bool saveRun(const QString &path, std::optional<protocol::Series> series,
                 const tuning::FrequencySweepResult &r, Console &console) const;
    void printJson(Console &console, const Plan &plan, const tuning::FrequencySweepResult &r) const;
    void printText(Console &console, const Plan &plan, const tuning::FrequencySweepResult &r) const;
};

} // namespace lk::lkctl
