#include "RunComparison.h"

#include <QtCore/QStringList>

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

QString RunComparison::comparableKey(const StepRun &run, MetricColumn column)
{
    QString key = stepLoopWord(run.spec.loop);
    if (column != MetricColumn::PeakEffort && column != MetricColumn::Saturation)
        return key;
    if (!run.trace.effortIsPower)
        return key + QStringLiteral("/A");
    const QString drive = run.model.isEmpty() ? QStringLiteral("id%1").arg(run.driveId) : run.model;
    return key + QStringLiteral("/power/%1/%2").arg(run.series, drive);
}

QVector<int> RunComparison::comparableWith(const QVector<StepRun> &runs, int index,
                                           MetricColumn column)
{
    QVector<int> out;
    if (index < 0 || index >= runs.size())
        return out;
    const QString key = comparableKey(runs.at(index), column);
    for (int i = 0; i < runs.size(); ++i)
        if (comparableKey(runs.at(i), column) == key)
            out.append(i);
    return out;
}

QVector<int> RunComparison::best(const QVector<StepRun> &runs, MetricColumn column,
                                 const QVector<EdgeMetrics> &metrics)
{
    QVector<int> out;
    QStringList done;
    for (int i = 0; i < runs.size(); ++i) {
        const QString key = comparableKey(runs.at(i), column);
        if (done.contains(key))
            continue;
        done.append(key);
        const QVector<int> group = comparableWith(runs, i, column);
        if (group.size() < 2)
            continue;
        QVector<Metric> values;
        for (int g : group)
            values.append(metric(
                metrics.size() == runs.size() ? metrics.at(g) : runs.at(g).stepMetrics(), column));
        for (int b : closestToZero(values))
            out.append(group.at(b));
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace lk::tuning
