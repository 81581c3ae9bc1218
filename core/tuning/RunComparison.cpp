#include "RunComparison.h"

#include <algorithm>
#include <cmath>

namespace lk::tuning {

QVector<MetricColumn> RunComparison::columns()
{
    return {MetricColumn::RiseTime,   MetricColumn::Overshoot,        MetricColumn::Settling2,
            MetricColumn::Settling5,  MetricColumn::SteadyStateError, MetricColumn::PeakEffort,
            MetricColumn::Saturation, MetricColumn::Oscillations};
}

const Metric &RunComparison::metric(const EdgeMetrics &m, MetricColumn column)
{
    switch (column) {
    case MetricColumn::RiseTime:
        return m.riseTimeS;
    case MetricColumn::Overshoot:
        return m.overshootPct;
    case MetricColumn::Settling2:
        return m.settling2S;
    case MetricColumn::Settling5:
        return m.settling5S;
    case MetricColumn::SteadyStateError:
        return m.steadyStateError;
    case MetricColumn::PeakEffort:
        return m.peakEffort;
    case MetricColumn::Saturation:
        return m.saturatedS;
    case MetricColumn::Oscillations:
        break;
    }
    return m.oscillations;
}

QVector<int> RunComparison::closestToZero(const QVector<Metric> &values)
{
    double lowest = INFINITY;
    for (const Metric &m : values)
        if (m.known())
            lowest = std::min(lowest, std::abs(*m.value));
    QVector<int> best;
    if (!std::isfinite(lowest))
        return best;
    const double tie = 1e-9 * std::max(1.0, lowest);
    for (int i = 0; i < values.size(); ++i)
        if (values[i].known() && std::abs(*values[i].value) - lowest <= tie)
            best.append(i);
    return best;
}

QVector<int> RunComparison::best(const QVector<EdgeMetrics> &metrics, MetricColumn column)
{
    QVector<Metric> values;
    values.reserve(metrics.size());
    for (const EdgeMetrics &m : metrics)
        values.append(metric(m, column));
    return closestToZero(values);
}

QVector<int> RunComparison::best(const QVector<StepRun> &runs, MetricColumn column)
{
    if (column == MetricColumn::PeakEffort && !runs.isEmpty()) {
        const bool power = runs.first().trace.effortIsPower;
        const bool mixed = std::any_of(runs.begin(), runs.end(), [&](const StepRun &r) {
            return r.trace.effortIsPower != power;
        });
        if (mixed)
            return {};
    }
    QVector<EdgeMetrics> metrics;
    metrics.reserve(runs.size());
    for (const StepRun &run : runs)
        metrics.append(run.stepMetrics());
    return best(metrics, column);
}

} // namespace lk::tuning
