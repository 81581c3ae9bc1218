#include "StepRun.h"

#include <QtCore/QStringList>

#include <motor/SeriesLimits.h>

namespace lk::tuning {

std::optional<double> seriesEffortLimit(std::optional<protocol::Series> series)
{
    if (!series)
        return std::nullopt;
    const motor::SeriesLimits &limits = motor::seriesLimits(*series);
    return limits.repliesCarryPower ? 1000.0 : limits.maxCurrentA;
}

StepMetricOptions StepRun::metricOptions() const
{
    StepMetricOptions options;
    options.effortLimit = effortLimit;
    return options;
}

QVector<EdgeMetrics> StepRun::metrics() const
{
    return StepMetrics::forAllEdges(trace, metricOptions());
}

EdgeMetrics StepRun::stepMetrics() const
{
    return StepMetrics::forEdge(trace, 0, metricOptions());
}

QStringList stepRunGainKeys()
{
    return {QStringLiteral("angle_kp"), QStringLiteral("angle_ki"), QStringLiteral("angle_kd"),
            QStringLiteral("speed_kp"), QStringLiteral("speed_ki"), QStringLiteral("speed_kd"),
            QStringLiteral("iq_kp"),    QStringLiteral("iq_ki"),    QStringLiteral("iq_kd")};
}

QStringList stepRunRampKeys()
{
    return {QStringLiteral("accel_dps2"), QStringLiteral("current_ramp"),
            QStringLiteral("speed_ramp_dps2")};
}

QString stepLoopWord(StepLoop loop)
{
    return loop == StepLoop::Position ? QStringLiteral("position") : QStringLiteral("speed");
}

std::optional<StepLoop> stepLoopFromWord(const QString &word)
{
    if (word == QLatin1String("speed"))
        return StepLoop::Speed;
    if (word == QLatin1String("position"))
        return StepLoop::Position;
    return std::nullopt;
}

} // namespace lk::tuning
