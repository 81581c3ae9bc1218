#include "MotionLimitOptions.h"

#include "ArgParser.h"

#include <motor/SeriesLimits.h>
#include <system/BoundedFile.h>

namespace lk::lkctl {

void MotionLimitOptions::declare(ArgParser &parser)
{
    for (const char *o : {"limits", "max-torque-a", "max-speed-dps", "max-power"})
        parser.addOption(QLatin1String(o), true);
}

QString MotionLimitOptions::helpText()
{
    return QStringLiteral(
        "Limits (defaults per series: a quarter of its rated current, open-loop power "
        "200,\n"
        "speed limit = its top speed; positions unbounded but one output turn per move):\n"
        "  --limits FILE.json     soft limits, e.g. {\"max_torque_a\":1.5,\"max_power\":"
        "300,\n"
        "                         \"max_speed_dps\":720,\"min_angle_deg\":-360,"
        "\"max_angle_deg\":360,\n"
        "                         \"max_increment_deg\":90} (missing keys keep the "
        "defaults;\n"
        "                         unknown or repeated keys, wrong types and values out "
        "of\n"
        "                         range are refused naming the key and its range, exit "
        "2):\n"
        "                         max_torque_a 0..32, max_power 0..1000 (whole),\n"
        "                         max_speed_dps 0.01..18000, min/max_angle_deg\n"
        "                         -1e9..1e9, max_increment_deg 0..21474836.47\n"
        "  --max-torque-a A, --max-speed-dps DPS, --max-power P\n"
        "                         override the defaults and the file: 0..32 A,\n"
        "                         0.01..18000 dps, 0..1000; and no more than the drive's\n"
        "                         series can do (its current limit and top speed, exit 2)\n");
}

std::optional<MotionLimitOptions> MotionLimitOptions::read(const ArgParser &parser, QString *error)
{
    MotionLimitOptions o;
    // Each flag within the range its key has in a limits file; the series' own range is
    // checked once the series is known (limitsFor).
    const auto number = [&](const char *name, double min, double max) -> std::optional<double> {
        const QString option = QLatin1String(name);
        const std::optional<double> v = parser.numberValue(option, 0, error);
        if (v && (*v < min || *v > max)) {
            *error = QStringLiteral("--%1 must be in %2..%3 (got %4)")
                         .arg(option)
                         .arg(min)
                         .arg(max)
                         .arg(parser.value(option));
            return std::nullopt;
        }
        return v;
    };
    if (parser.isSet(QStringLiteral("max-torque-a"))) {
        o.m_maxTorqueA = number("max-torque-a", 0, kMaxTorqueA);
        if (!o.m_maxTorqueA)
            return std::nullopt;
    }
    if (parser.isSet(QStringLiteral("max-speed-dps"))) {
        // Above 0: a speed limit always exists, and 0 would mean none.
        o.m_maxSpeedDps = number("max-speed-dps", kMinSpeedDps, kMaxSpeedDps);
        if (!o.m_maxSpeedDps)
            return std::nullopt;
    }
    if (parser.isSet(QStringLiteral("max-power"))) {
        const auto p = parser.intValue(QStringLiteral("max-power"), 0, 1000, error);
        if (!p)
            return std::nullopt;
        o.m_maxPower = int(*p);
    }
    if (!parser.isSet(QStringLiteral("limits")))
        return o;
    const QString path = parser.value(QStringLiteral("limits"));
    // Bounded: a limits file is a few hundred bytes, and /dev/zero or a FIFO must not hang
    // or exhaust lkctl.
    const system::BoundedRead file = system::BoundedFile::read(path, kMaxFileBytes);
    if (!file.ok()) {
        *error = QStringLiteral("cannot read --limits %1: %2; nothing was sent")
                     .arg(path, file.error->reason());
        return std::nullopt;
    }
    // Check the whole file now (keys, types, ranges, repeats), so that a bad file never gets
    // as far as the bus; it is read again over the series' defaults once the series is known.
    const QByteArray text = file.bytes;
    QString why;
    if (!safety::SoftLimits::fromJsonText(text, safety::SoftLimits{}, &why)) {
        *error = QStringLiteral("--limits %1: %2; nothing was sent").arg(path, why);
        return std::nullopt;
    }
    o.m_limitsText = text;
    o.m_limitsPath = path;
    return o;
}

std::optional<safety::SoftLimits>
MotionLimitOptions::limitsFor(std::optional<protocol::Series> series, QString *error) const
{
    std::optional<safety::SoftLimits> limits = safety::SoftLimits::defaults(series);
    if (m_limitsText) {
        limits = safety::SoftLimits::fromJsonText(*m_limitsText, *limits, error);
        if (!limits) {
            *error = QStringLiteral("--limits %1: %2; nothing was sent").arg(m_limitsPath, *error);
            return std::nullopt;
        }
    }
    if (m_maxTorqueA)
        limits->maxTorqueA = *m_maxTorqueA;
    if (m_maxSpeedDps)
        limits->maxSpeedDps = *m_maxSpeedDps;
    if (m_maxPower)
        limits->maxPower = *m_maxPower;
    if (series) {
        const QString why = beyondSeries(*limits, *series);
        if (!why.isEmpty()) {
            *error = why;
            return std::nullopt;
        }
    }
    return limits;
}

QString MotionLimitOptions::sourceOf(const char *option, const char *key) const
{
    const bool flag = (qstrcmp(option, "max-torque-a") == 0 && m_maxTorqueA) ||
                      (qstrcmp(option, "max-speed-dps") == 0 && m_maxSpeedDps);
    if (flag)
        return QStringLiteral("--%1").arg(QLatin1String(option));
    return m_limitsText ? QStringLiteral("--limits %1: %2").arg(m_limitsPath, QLatin1String(key))
                        : QStringLiteral("the default %1").arg(QLatin1String(key));
}

QString MotionLimitOptions::beyondSeries(const safety::SoftLimits &limits,
                                         protocol::Series series) const
{
    // A limit above what the series can do would not bound anything there: refused, naming
    // where it came from, rather than left to look like a limit.
    const motor::SeriesLimits &s = motor::seriesLimits(series);
    const QString name = protocol::seriesName(series);
    if (s.hasTorqueLoop && limits.maxTorqueA > s.maxCurrentA)
        return QStringLiteral("%1 %2 A is above %3 A, the current limit of the %4 series; "
                              "nothing was sent")
            .arg(sourceOf("max-torque-a", "max_torque_a"))
            .arg(limits.maxTorqueA)
            .arg(s.maxCurrentA)
            .arg(name);
    if (limits.maxSpeedDps > s.maxSpeedDps())
        return QStringLiteral("%1 %2 dps is above %3 dps, the top speed of the %4 series; "
                              "nothing was sent")
            .arg(sourceOf("max-speed-dps", "max_speed_dps"))
            .arg(limits.maxSpeedDps)
            .arg(s.maxSpeedDps())
            .arg(name);
    return {};
}

QByteArray MotionLimitOptions::boundJson(safety::SpeedBound bound, double dps)
{
    const char *source = "command";
    switch (bound) {
    case safety::SpeedBound::SoftLimit:
        source = "soft_limit";
        break;
    case safety::SpeedBound::SeriesTop:
        source = "series_top";
        break;
    case safety::SpeedBound::UserMaxSpeed:
        source = "max_speed";
        break;
    default:
        break;
    }
    return QByteArray("{\"source\":\"") + source +
           "\",\"dps\":" + QByteArray::number(dps, 'g', 10) + '}';
}

} // namespace lk::lkctl
