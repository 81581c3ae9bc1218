#pragma once

#include "LiveBus.h"
#include "MotionLimitOptions.h"
#include "TuningCommand.h"

#include <tuning/GainSearchRunner.h>

#include <optional>

namespace lk::lkctl {

/// `lkctl tune ID speed`: suggested speed-loop gains (tuning::GainSearchRunner): candidates
/// scored by short speed steps within the limits, the best beside the gains read. Nothing is
/// written unless `--write ram` asks for the best in RAM; ROM is never written here.
class TuneCommand : public TuningCommand {
public:
    QString name() const override { return QStringLiteral("tune"); }
    QString summary() const override;
    QString example() const override;
    QString usage() const override;
    int run(const QStringList &args, Console &console) override;

private:
    struct Plan {
        tuning::GainSearchSpec spec;
        MotionLimitOptions limits;
        bool writeRam = false;
        bool json = false;
    };
    std::optional<Plan> parse(const ArgParser &parser, Console &console, int *status) const;
    tuning::GainSearchResult runSearch(LiveBus &bus, const Plan &plan,
                                       const safety::SoftLimits &limits) const;
    /// Writes the best candidate's gains to RAM; false after printing why.
    bool writeBest(LiveBus &bus, const tuning::GainSearchResult &r) const;
    void printJson(Console &console, const tuning::GainSearchResult &r, bool written) const;
    void printText(Console &console, const tuning::GainSearchResult &r, bool written) const;
};

} // namespace lk::lkctl
