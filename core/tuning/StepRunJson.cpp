#include "StepRunJson.h"

#include <QtCore/QJsonValue>

#include <cmath>
#include <utility>

namespace lk::tuning {

namespace {

constexpr std::pair<MetricGap, const char *> gapWords[] = {
    {MetricGap::None, "none"},
    {MetricGap::TooFewSamples, "too_few_samples"},
    {MetricGap::NoStep, "no_step"},
    {MetricGap::NotReached, "not_reached"},
    {MetricGap::NeverSettled, "never_settled"},
    {MetricGap::NoEffort, "no_effort"},
    {MetricGap::NoLimit, "no_limit"},
};

double rounded(double v, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    return std::round(v * scale) / scale; // QJsonDocument writes -0.0 as 0
}

void put(QJsonObject &o, const QString &key, const Metric &m, int decimals)
{
    if (m.known()) {
        o.insert(key, decimals == 0 ? QJsonValue(qint64(std::llround(*m.value)))
                                    : QJsonValue(rounded(*m.value, decimals)));
        return;
    }
    o.insert(key, QJsonValue::Null);
    o.insert(key + QLatin1String("_why"), StepRunJson::gapWord(m.gap));
}

} // namespace

QJsonObject StepRunJson::metricsObject(const EdgeMetrics &m, bool effortIsPower)
{
    QJsonObject o;
    put(o, QStringLiteral("rise_time_s"), m.riseTimeS, 4);
    put(o, QStringLiteral("overshoot_pct"), m.overshootPct, 2);
    put(o, QStringLiteral("settling_time_s"), m.settling2S, 4);
    put(o, QStringLiteral("settling_time_5pct_s"), m.settling5S, 4);
    put(o, QStringLiteral("steady_state_error"), m.steadyStateError, 4);
    put(o, effortIsPower ? QStringLiteral("peak_power") : QStringLiteral("peak_iq_a"), m.peakEffort,
        3);
    put(o, QStringLiteral("saturated_s"), m.saturatedS, 4);
    put(o, QStringLiteral("oscillations"), m.oscillations, 0);
    o.insert(QStringLiteral("samples"), m.samples);
    o.insert(QStringLiteral("sample_rate_hz"), rounded(m.sampleRateHz, 1));
    return o;
}

QJsonObject StepRunJson::toJson(const StepRun &run)
{
    QJsonObject o = metricsObject(run.stepMetrics(), run.trace.effortIsPower);
    o.insert(QStringLiteral("gains"), run.gains);
    return o;
}

QString StepRunJson::gapWord(MetricGap gap)
{
    for (const auto &[g, word] : gapWords)
        if (g == gap)
            return QLatin1String(word);
    return QStringLiteral("none");
}

std::optional<MetricGap> StepRunJson::gapFromWord(const QString &word)
{
    for (const auto &[g, w] : gapWords)
        if (word == QLatin1String(w))
            return g;
    return std::nullopt;
}

} // namespace lk::tuning
