#pragma once

#include "FrequencyResponse.h"
#include "FrequencySweepPlan.h"
#include "LoopGains.h"

#include <QtCore/QDateTime>
#include <QtCore/QString>

#include <optional>

namespace lk::tuning {

/// One frequency sweep kept: what was asked, on which drive, with which gains, and the
/// response measured. FrequencyRunFile saves and loads it.
struct FrequencyRun {
    int number = 0;  ///< "Run 3"
    QString label;   ///< the user's name for it; may be empty
    QDateTime ranAt; ///< when the sweep started, UTC
    int driveId = 0; ///< 1..32
    QString series;  ///< "MS", "MF", "MG" or "MH"; empty if unknown
    QString model;   ///< read_model's motor name; empty if unknown
    FrequencySweepSpec spec;
    std::optional<LoopGains> gains; ///< as the sweep read them
    FrequencyResponse response;

    /// Whether two runs may share a Bode chart's axes: the same loop, so the same unit.
    bool comparableWith(const FrequencyRun &o) const { return spec.loop == o.spec.loop; }
};

} // namespace lk::tuning
