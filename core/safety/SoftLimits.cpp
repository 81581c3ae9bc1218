#include "SoftLimits.h"

#include <QtCore/QCoreApplication>

#include <motor/SeriesLimits.h>

#include <QtCore/QJsonValue>

#include <functional>

namespace lk::safety {

namespace {
constexpr double kDefaultCurrentShare = 0.25;

void putOptional(QJsonObject &o, const char *key, const std::optional<double> &v)
{
    if (v)
        o.insert(QLatin1String(key), *v);
}

// Reads an optional non-negative (or any-sign) number; false when present but unusable.
bool readNumber(const QJsonObject &o, const char *key, bool allowNegative, double &out,
                bool &present)
{
    present = o.contains(QLatin1String(key)) && !o.value(QLatin1String(key)).isNull();
    if (!present)
        return true;
    const QJsonValue v = o.value(QLatin1String(key));
    if (!v.isDouble())
        return false;
    out = v.toDouble();
    return allowNegative || out >= 0;
}
} // namespace

SoftLimits SoftLimits::defaults(protocol::Series series)
{
    const motor::SeriesLimits &s = motor::seriesLimits(series);
    SoftLimits l;
    l.maxTorqueA = s.maxCurrentA * kDefaultCurrentShare;
    l.maxPower = 200;
    l.maxSpeedDps = s.maxSpeedDps();
    return l;
}

QJsonObject SoftLimits::toJson() const
{
    QJsonObject o;
    o.insert(QStringLiteral("max_torque_a"), maxTorqueA);
    o.insert(QStringLiteral("max_power"), maxPower);
    o.insert(QStringLiteral("max_speed_dps"), maxSpeedDps);
    putOptional(o, "min_angle_deg", minAngleDeg);
    putOptional(o, "max_angle_deg", maxAngleDeg);
    putOptional(o, "max_increment_deg", maxIncrementDeg);
    return o;
}

std::optional<SoftLimits> SoftLimits::fromJson(const QJsonObject &json, const SoftLimits &fallback,
                                               QString *error)
{
    SoftLimits l = fallback;
    struct Field {
        const char *key;
        bool allowNegative;
        std::function<void(double)> set;
    };
    const Field fields[] = {
        {"max_torque_a", false, [&](double v) { l.maxTorqueA = v; }},
        {"max_power", false, [&](double v) { l.maxPower = static_cast<int>(v); }},
        {"max_speed_dps", false, [&](double v) { l.maxSpeedDps = v; }},
        {"min_angle_deg", true, [&](double v) { l.minAngleDeg = v; }},
        {"max_angle_deg", true, [&](double v) { l.maxAngleDeg = v; }},
        {"max_increment_deg", false, [&](double v) { l.maxIncrementDeg = v; }},
    };
    for (const Field &f : fields) {
        double value = 0;
        bool present = false;
        if (!readNumber(json, f.key, f.allowNegative, value, present)) {
            if (error)
                *error = (f.allowNegative
                              ? QCoreApplication::translate("lk::safety::SoftLimits",
                                                            "%1 must be a number")
                              : QCoreApplication::translate("lk::safety::SoftLimits",
                                                            "%1 must be a non-negative number"))
                             .arg(QLatin1String(f.key));
            return std::nullopt;
        }
        if (present)
            f.set(value);
    }
    if (l.minAngleDeg && l.maxAngleDeg && *l.minAngleDeg > *l.maxAngleDeg) {
        if (error)
            *error = QCoreApplication::translate("lk::safety::SoftLimits",
                                                 "min_angle_deg must not exceed max_angle_deg");
        return std::nullopt;
    }
    return l;
}

bool SoftLimits::operator==(const SoftLimits &o) const
{
    return maxTorqueA == o.maxTorqueA && maxPower == o.maxPower && maxSpeedDps == o.maxSpeedDps &&
           minAngleDeg == o.minAngleDeg && maxAngleDeg == o.maxAngleDeg &&
           maxIncrementDeg == o.maxIncrementDeg;
}

} // namespace lk::safety
