#include "TuningJson.h"

#include "OrderedJson.h"

#include <cmath>

namespace lk::lkctl::TuningJson {

namespace {
double rounded(double v, double unit)
{
    return std::round(v / unit) * unit;
}

template <typename Item, typename Write> QByteArray list(const QVector<Item> &items, Write write)
{
    QByteArray out = "[";
    for (const Item &item : items) {
        OrderedJson o;
        write(o, item);
        out += (out.size() > 1 ? "," : "") + o.toJson();
    }
    return out + ']';
}
} // namespace

QByteArray gains(const tuning::LoopGains &g)
{
    OrderedJson o;
    const bool v235 = g.generation == protocol::Generation::V2_35;
    const std::pair<const char *, const tuning::PidTriple *> loops[] = {
        {"angle", &g.angle}, {"speed", &g.speed}, {"iq", &g.current}};
    for (const auto &[name, pid] : loops) {
        const QString prefix = QLatin1String(name);
        o.integer(prefix + QLatin1String("_kp"), pid->kp)
            .integer(prefix + QLatin1String("_ki"), pid->ki);
        if (v235)
            o.integer(prefix + QLatin1String("_kd"), pid->kd);
    }
    o.integer(QStringLiteral("accel_dps2"), g.accelerationDps2);
    return o.toJson();
}

QString speedGainsText(const tuning::LoopGains &g)
{
    QString text = QStringLiteral("speed Kp %1 Ki %2").arg(g.speed.kp).arg(g.speed.ki);
    if (g.generation == protocol::Generation::V2_35)
        text += QStringLiteral(" Kd %1").arg(g.speed.kd);
    return text;
}

const char *droppedWord(tuning::DroppedReason reason)
{
    switch (reason) {
    case tuning::DroppedReason::AboveResolution:
        return "above_resolution";
    case tuning::DroppedReason::TooFewSamples:
        return "too_few_samples";
    case tuning::DroppedReason::NoInput:
        return "no_input";
    }
    return "";
}

QByteArray points(const tuning::FrequencyResponse &r)
{
    return list(r.points, [](OrderedJson &o, const tuning::FrequencyPoint &p) {
        o.real(QStringLiteral("hz"), rounded(p.hz, 0.001))
            .real(QStringLiteral("magnitude_db"), rounded(p.magnitudeDb, 0.01))
            .real(QStringLiteral("phase_deg"), rounded(p.phaseDeg, 0.1))
            .real(QStringLiteral("quality"), rounded(p.quality, 0.001))
            .integer(QStringLiteral("samples"), p.samples);
    });
}

QByteArray dropped(const tuning::FrequencyResponse &r)
{
    return list(r.dropped, [](OrderedJson &o, const tuning::DroppedFrequency &d) {
        o.real(QStringLiteral("hz"), rounded(d.hz, 0.001))
            .text(QStringLiteral("reason"), QLatin1String(droppedWord(d.reason)));
    });
}

} // namespace lk::lkctl::TuningJson
