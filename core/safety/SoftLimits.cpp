#include "SoftLimits.h"

#include "JsonKeyCheck.h"

#include <motor/SeriesLimits.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonValue>
#include <QtCore/QStringList>

#include <algorithm>
#include <cmath>
#include <functional>

namespace lk::safety {

namespace {
constexpr double kDefaultCurrentShare = 0.25;
constexpr double kMaxTorqueA = 32;               // the torque command's wire range
constexpr double kMaxAngleDeg = 1e9;             // what the editor's fields hold
constexpr double kMaxIncrementDeg = 21474836.47; // int32 of 0.01 deg
constexpr double kMinSpeedDps = 0.01;            // one wire unit: a speed limit is never 0

// Strings are marked with QT_TRANSLATE_NOOP so that lupdate files them under this context.
QString translated(const char *text)
{
    return QCoreApplication::translate("lk::safety::SoftLimits", text);
}

double fastestSeriesSpeedDps()
{
    double top = 0;
    for (protocol::Series s :
         {protocol::Series::MS, protocol::Series::MF, protocol::Series::MG, protocol::Series::MH})
        top = std::max(top, motor::seriesLimits(s).maxSpeedDps());
    return top;
}

void putOptional(QJsonObject &o, const char *key, const std::optional<double> &v)
{
    if (v)
        o.insert(QLatin1String(key), *v);
}

// What a refused value was, in JSON spelling.
QString shown(const QJsonValue &v)
{
    if (v.isDouble())
        return QString::number(v.toDouble(), 'g', 12);
    if (v.isString())
        return QLatin1Char('"') + v.toString() + QLatin1Char('"');
    if (v.isBool())
        return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (v.isNull())
        return QStringLiteral("null");
    return v.isArray() ? QStringLiteral("an array") : QStringLiteral("an object");
}

struct Field {
    const char *key;
    double lo, hi;
    const char *unit;
    bool whole;    ///< a whole number (max_power)
    bool nullable; ///< null means "not set" (the optional angle limits)
    std::function<void(std::optional<double>)> set;
};

QString rangeError(const Field &f, const QJsonValue &v)
{
    const QString range = QStringLiteral("%1..%2%3")
                              .arg(f.lo, 0, 'g', 12)
                              .arg(f.hi, 0, 'g', 12)
                              .arg(*f.unit ? QLatin1Char(' ') + QLatin1String(f.unit) : QString());
    return (f.whole ? translated(QT_TRANSLATE_NOOP("lk::safety::SoftLimits",
                                                   "%1 must be a whole number in %2 (got %3)"))
                    : translated(QT_TRANSLATE_NOOP("lk::safety::SoftLimits",
                                                   "%1 must be a number in %2 (got %3)")))
        .arg(QLatin1String(f.key), range, shown(v));
}

// True when `v` is usable for `f`; NaN and infinity never are (JSON can carry 1e999).
bool accepts(const Field &f, const QJsonValue &v)
{
    if (!v.isDouble())
        return false;
    const double d = v.toDouble();
    if (!std::isfinite(d) || d < f.lo || d > f.hi)
        return false;
    return !f.whole || d == std::floor(d);
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

SoftLimits SoftLimits::defaults(std::optional<protocol::Series> series)
{
    return series ? defaults(*series) : SoftLimits{};
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

QString SoftLimits::keyList()
{
    return QStringLiteral("max_torque_a, max_power, max_speed_dps, min_angle_deg, "
                          "max_angle_deg, max_increment_deg");
}

std::optional<SoftLimits> SoftLimits::fromJson(const QJsonObject &json, const SoftLimits &fallback,
                                               QString *error)
{
    SoftLimits l = fallback;
    const Field fields[] = {
        {"max_torque_a", 0, kMaxTorqueA, "A", false, false,
         [&](std::optional<double> v) { l.maxTorqueA = *v; }},
        {"max_power", 0, 1000, "", true, false,
         [&](std::optional<double> v) { l.maxPower = static_cast<int>(*v); }},
        {"max_speed_dps", kMinSpeedDps, fastestSeriesSpeedDps(), "dps", false, false,
         [&](std::optional<double> v) { l.maxSpeedDps = *v; }},
        {"min_angle_deg", -kMaxAngleDeg, kMaxAngleDeg, "deg", false, true,
         [&](std::optional<double> v) { l.minAngleDeg = v; }},
        {"max_angle_deg", -kMaxAngleDeg, kMaxAngleDeg, "deg", false, true,
         [&](std::optional<double> v) { l.maxAngleDeg = v; }},
        {"max_increment_deg", 0, kMaxIncrementDeg, "deg", false, true,
         [&](std::optional<double> v) { l.maxIncrementDeg = v; }},
    };
    const auto fail = [&](const QString &message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    for (auto it = json.begin(); it != json.end(); ++it) {
        const Field *field =
            std::find_if(std::begin(fields), std::end(fields),
                         [&](const Field &f) { return it.key() == QLatin1String(f.key); });
        if (field == std::end(fields))
            return fail(translated(QT_TRANSLATE_NOOP("lk::safety::SoftLimits",
                                                     "unknown key \"%1\" (the keys are %2)"))
                            .arg(it.key(), keyList()));
        const QJsonValue v = it.value();
        if (field->nullable && v.isNull())
            field->set(std::nullopt);
        else if (accepts(*field, v))
            field->set(v.toDouble());
        else
            return fail(rangeError(*field, v));
    }
    if (l.minAngleDeg && l.maxAngleDeg && *l.minAngleDeg > *l.maxAngleDeg)
        return fail(
            translated(QT_TRANSLATE_NOOP("lk::safety::SoftLimits",
                                         "min_angle_deg (%1) must not exceed max_angle_deg (%2)"))
                .arg(*l.minAngleDeg)
                .arg(*l.maxAngleDeg));
    return l;
}

std::optional<SoftLimits> SoftLimits::fromJsonText(const QByteArray &text,
                                                   const SoftLimits &fallback, QString *error)
{
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(text, &pe);
    if (!doc.isObject()) {
        if (error)
            *error =
                pe.error == QJsonParseError::NoError
                    ? translated(QT_TRANSLATE_NOOP("lk::safety::SoftLimits", "not a JSON object"))
                    : translated(QT_TRANSLATE_NOOP("lk::safety::SoftLimits",
                                                   "not a JSON object (%1 at byte %2)"))
                          .arg(pe.errorString())
                          .arg(pe.offset);
        return std::nullopt;
    }
    if (const std::optional<QString> twice = JsonKeyCheck::duplicateKey(text)) {
        if (error)
            *error =
                translated(QT_TRANSLATE_NOOP("lk::safety::SoftLimits", "key \"%1\" is given twice"))
                    .arg(*twice);
        return std::nullopt;
    }
    return fromJson(doc.object(), fallback, error);
}

bool SoftLimits::operator==(const SoftLimits &o) const
{
    return maxTorqueA == o.maxTorqueA && maxPower == o.maxPower && maxSpeedDps == o.maxSpeedDps &&
           minAngleDeg == o.minAngleDeg && maxAngleDeg == o.maxAngleDeg &&
           maxIncrementDeg == o.maxIncrementDeg;
}

} // namespace lk::safety
