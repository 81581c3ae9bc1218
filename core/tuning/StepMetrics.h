#pragma once

#include "StepTrace.h"

#include <QtCore/QVector>

#include <optional>

namespace lk::tuning {

/// Why a metric has no value. The UI words these; core never shows a number it could not
/// compute.
enum class MetricGap {
    None,          ///< the metric has a value
    TooFewSamples, ///< fewer than StepMetricOptions::minSamples samples in the edge's window
    NoStep,        ///< the edge's amplitude is zero
    NotReached,    ///< the response never crossed the level the metric needs (e.g. 90 %)
    NeverSettled,  ///< the response was outside the band at the end of the window
    NoEffort,      ///< no sample in the window carried the current (or power)
    NoLimit,       ///< saturation needs the drive's current (power) limit, which is unknown
};

/// One metric: a value, or the reason there is none.
struct Metric {
    std::optional<double> value;
    MetricGap gap = MetricGap::None;
    bool known() const { return value.has_value(); }
    static Metric of(double v) { return {v, MetricGap::None}; }
    static Metric none(MetricGap why) { return {std::nullopt, why}; }
};

/// Thresholds of the metric definitions.
struct StepMetricOptions {
    int minSamples = 8; ///< fewer samples in an edge's window give TooFewSamples everywhere
    /// |effort| at which the drive's current (power) loop is at its limit; nullopt: unknown.
    std::optional<double> effortLimit;
    double saturationFraction = 0.98; ///< |effort| >= this x effortLimit counts as saturated
    double saturationMinS = 0.02;     ///< saturated for at least this long to count
    double steadyFraction = 0.2;      ///< the last fraction of the window gives the steady state
};

/// The metrics of one edge of a step test. Window: from the edge to the next edge (or the
/// trace's end). Amplitude A = to - from; levels are from + p x A.
///
/// Crossing times are interpolated linearly between samples (the sample just before the edge
/// anchors a crossing before the window's first sample), so times do not quantise to the
/// sample period. With A = 0 the response metrics (rise, overshoot, settling, oscillations)
/// are NoStep; the steady-state error and the effort metrics are still measured. The
/// steady-state error is NeverSettled when the response ends outside the 5 % band: the mean of
/// a response still moving is no steady state. Oscillations count half-cycles (from one
/// crossing of `to` to the next) whose peak leaves the 2 % band, so noise inside the band never
/// counts and noise at the band's edge counts once. Effort samples that are missing neither
/// break nor extend a saturated run; its ends are interpolated where |effort| crosses the
/// threshold.
struct EdgeMetrics {
    StepEdge edge;
    int samples = 0;         ///< samples in the window
    double sampleRateHz = 0; ///< (samples - 1) / window span; 0 with fewer than 2 samples
    Metric riseTimeS;        ///< first crossing of 10 % to first crossing of 90 % of A
    Metric overshootPct;     ///< largest excursion past `to`, in % of |A| (0 when none)
    Metric settling2S;       ///< edge to the last time outside +-2 % of |A| around `to`
    Metric settling5S;       ///< the same with +-5 %
    Metric steadyStateError; ///< to - mean of the window's last steadyFraction (units of value)
    Metric peakEffort;       ///< largest |effort| in the window (A, or power on MS)
    Metric saturatedS;   ///< longest run at >= saturationFraction x limit (0 if < saturationMinS)
    Metric oscillations; ///< peaks past the 2 % band after the first crossing of `to`
};

/// Step-response metrics: pure functions of a StepTrace, tested on synthetic traces.
class StepMetrics {
public:
    static EdgeMetrics forEdge(const StepTrace &trace, int edgeIndex,
                               const StepMetricOptions &options = {});
    /// forEdge() of every edge, in order.
    static QVector<EdgeMetrics> forAllEdges(const StepTrace &trace,
                                            const StepMetricOptions &options = {});
    /// Samples per second over the whole trace; 0 with fewer than 2 samples.
    static double sampleRateHz(const StepTrace &trace);
};

} // namespace lk::tuning
