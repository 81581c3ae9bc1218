#pragma once

#include "StepMetrics.h"
#include "StepRun.h"

#include <QtCore/QJsonObject>
#include <QtCore/QString>

namespace lk::tuning {

/// The metrics of a step test as JSON under lkctl step's keys: the one mapping shared by
/// `lkctl step --json`, the run files and anything else that writes metrics.
class StepRunJson {
public:
    /// {"rise_time_s", "overshoot_pct", "settling_time_s" (2 %), "settling_time_5pct_s",
    ///  "steady_state_error", "peak_iq_a" (or "peak_power" when effortIsPower), "saturated_s",
    ///  "oscillations", "samples", "sample_rate_hz"}. A metric without a value is null, with
    /// "<key>_why" holding gapWord() of the reason; a metric with a value has no "_why" key.
    /// Values are rounded for reading: times to 0.1 ms, percentages to 0.01, the steady-state
    /// error to 1e-4 (units of value), effort to 1e-3, the sample rate to 0.1 Hz.
    static QJsonObject metricsObject(const EdgeMetrics &metrics, bool effortIsPower);
    /// metricsObject() of the run's step under test (its first edge, computed now) plus
    /// "gains" (the run's gains object, as lkctl names them).
    static QJsonObject toJson(const StepRun &run);
    /// The stable machine word of a gap: "too_few_samples", "no_step", "not_reached",
    /// "never_settled", "no_effort", "no_limit"; "none" for MetricGap::None.
    static QString gapWord(MetricGap gap);
    /// The gap gapWord() names; nullopt for any other text.
    static std::optional<MetricGap> gapFromWord(const QString &word);
};

} // namespace lk::tuning
