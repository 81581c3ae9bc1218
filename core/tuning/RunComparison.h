#pragma once

#include "StepMetrics.h"
#include "StepRun.h"

#include <QtCore/QVector>

namespace lk::tuning {

/// A metric column of the run table, in display order.
enum class MetricColumn {
    RiseTime,
    Overshoot,
    Settling2,
    Settling5,
    SteadyStateError,
    PeakEffort,
    Saturation,
    Oscillations,
};

/// Which run holds the best value of each metric: for every metric the one closest to zero
/// (lowest rise and settling time, overshoot, |steady-state error|, peak effort, saturated
/// time, oscillation count). Pure; the run table marks its cells from it.
class RunComparison {
public:
    /// Every column, in display order.
    static QVector<MetricColumn> columns();
    /// The metric of `column` in `metrics`.
    static const Metric &metric(const EdgeMetrics &metrics, MetricColumn column);
    /// The indices of the values closest to zero (|value|), ascending; several when they tie
    /// (equal to within 1e-9 relative). A value without a number is never best; no index when
    /// no value has one.
    static QVector<int> closestToZero(const QVector<Metric> &values);
    /// closestToZero() of `column` over one EdgeMetrics per run.
    static QVector<int> best(const QVector<EdgeMetrics> &metrics, MetricColumn column);
    /// best() over the runs' steps under test (StepRun::stepMetrics()). Peak effort of runs
    /// that mix current (A) and power has no best: the numbers are not comparable.
    static QVector<int> best(const QVector<StepRun> &runs, MetricColumn column);
};

} // namespace lk::tuning
