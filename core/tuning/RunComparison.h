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
/// time, oscillation count), among the runs it can be compared with. Pure; the run table
/// marks its cells from it.
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
    /// What a run's `column` is measured in, as a key: runs compare only when their keys are
    /// equal. Every metric: the loop (a speed step's rise is not a position step's, and the
    /// steady-state error is in dps or degrees). Peak effort and time at the limit also: the
    /// effort's unit, A or power; power is relative to the drive's own maximum, so power
    /// compares only on the same series and model (the same drive ID when the model is
    /// unknown).
    static QString comparableKey(const StepRun &run, MetricColumn column);
    /// The runs `runs[index]`'s `column` compares with (comparableKey() equal), itself
    /// included, ascending.
    static QVector<int> comparableWith(const QVector<StepRun> &runs, int index,
                                       MetricColumn column);
    /// best() over the runs' steps under test (StepRun::stepMetrics()), within each group of
    /// comparable runs (comparableKey()) of two or more: a run alone in its group is best of
    /// nothing. `metrics` are the runs' stepMetrics() when the caller has them already.
    static QVector<int> best(const QVector<StepRun> &runs, MetricColumn column,
                             const QVector<EdgeMetrics> &metrics = {});
};

} // namespace lk::tuning
