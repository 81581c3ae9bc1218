#include "ReplyText.h"

#include <protocol/ErrorFlags.h>

#include <QtCore/QList>

#include <algorithm>

namespace lk::lkctl {

namespace {

struct FieldLabel {
    const char *key;
    const char *label;
    const char *unit;
    int decimals; ///< places for reals; -1 for text, integers and flags
    bool trim;    ///< drop trailing zeros (speeds, currents); keep them for voltage, angles
};

// CLI.md field order.
const QList<FieldLabel> &labels()
{
    static const QList<FieldLabel> kLabels{
        {"driver_name", "driver", "", -1, true},
        {"motor_name", "motor", "", -1, true},
        {"hardware_version", "hardware version", "", 1, true},
        {"firmware_version", "firmware version", "", 2, true},
        {"motor_id", "motor ID", "", -1, true}, // V2.35: the 12-byte unique ID, hex
        {"temperature_c", "temperature", "C", -1, true},
        {"voltage_v", "voltage", "V", 1, false}, // 2 places for V2.35's 0.01 V (valueText)
        {"bus_current_a", "bus current", "A", 2, false},
        {"motor_on", "motor on", "", -1, true},
        {"error_state", "errors", "", -1, true},
        {"iq_a", "torque current", "A", 3, true},
        {"power", "power", "(of 1000)", -1, true},
        {"speed_dps", "speed", "dps", 2, true},
        {"ia_a", "phase A current", "A", 3, true},
        {"ib_a", "phase B current", "A", 3, true},
        {"ic_a", "phase C current", "A", 3, true},
        {"encoder", "encoder", "counts", -1, true},
        {"encoder_raw", "encoder raw", "counts", -1, true},
        {"encoder_offset", "encoder offset", "counts", -1, true},
        {"direction", "direction", "", -1, true},
        {"angle_deg", "angle", "deg", 2, false},
        {"max_speed_dps", "max speed", "dps", 2, false},
        {"angle_kp", "angle Kp", "", -1, true},
        {"angle_ki", "angle Ki", "", -1, true},
        {"speed_kp", "speed Kp", "", -1, true},
        {"speed_ki", "speed Ki", "", -1, true},
        {"angle_kd", "angle Kd", "", -1, true},
        {"speed_kd", "speed Kd", "", -1, true},
        {"iq_kp", "iq Kp", "", -1, true},
        {"iq_ki", "iq Ki", "", -1, true},
        {"iq_kd", "iq Kd", "", -1, true},
        {"accel_dps2", "acceleration", "dps/s", -1, true},
        {"max_torque", "max torque current", "(of 2048)", -1, true},
        {"max_angle_deg", "max angle", "deg", 2, false},
        {"current_ramp", "current ramp", "", -1, true},
        {"speed_ramp_dps2", "speed ramp", "dps/s", -1, true},
    };
    return kLabels;
}

QString valueText(const FieldLabel &l, const QJsonValue &v, const QJsonObject &fields)
{
    if (QLatin1String(l.key) == QLatin1String("error_state"))
        return ReplyText::errorText(v.toInt(), fields);
    if (QLatin1String(l.key) == QLatin1String("voltage_v") &&
        fields.contains(QStringLiteral("bus_current_a")))
        return QString::number(v.toDouble(), 'f', 2) + QStringLiteral(" V");
    if (v.isString())
        return v.toString();
    if (v.isBool())
        return v.toBool() ? QStringLiteral("yes") : QStringLiteral("no");
    QString n = QString::number(v.toInteger());
    if (l.decimals >= 0)
        n = l.trim ? ReplyText::number(v.toDouble(), l.decimals)
                   : QString::number(v.toDouble(), 'f', l.decimals);
    if (QByteArray(l.key).endsWith("_version") && !n.contains(QLatin1Char('.')))
        n += QStringLiteral(".0"); // "1.0", as the vendor's tools show versions
    return *l.unit ? n + QLatin1Char(' ') + QLatin1String(l.unit) : n;
}

} // namespace

QString ReplyText::number(double value, int decimals)
{
    QString t = QString::number(value, 'f', decimals);
    if (t.contains(QLatin1Char('.'))) {
        while (t.endsWith(QLatin1Char('0')))
            t.chop(1);
        if (t.endsWith(QLatin1Char('.')))
            t.chop(1);
    }
    return t == QLatin1String("-0") ? QStringLiteral("0") : t;
}

QString ReplyText::errorText(int errorState, protocol::Generation generation)
{
    const QStringList flags = protocol::ErrorFlags::words(quint8(errorState), generation);
    if (flags.isEmpty())
        return QStringLiteral("none");
    return QStringLiteral("%1 (0x%2)")
        .arg(flags.join(QStringLiteral(", ")))
        .arg(errorState, 2, 16, QLatin1Char('0'));
}

QString ReplyText::errorText(int errorState, const QJsonObject &fields)
{
    // read_state1's fields name every flag of the drive's generation (FieldJson): eight
    // keys from a V2.35 drive, two from a V2.3 one. Their presence tells the generation.
    const bool v235 = fields.contains(QStringLiteral("bus_current_a"));
    return errorText(errorState, v235 ? protocol::Generation::V2_35 : protocol::Generation::V2_3);
}

QStringList ReplyText::lines(const QJsonObject &fields, const QString &indent)
{
    qsizetype width = 0;
    for (const FieldLabel &l : labels()) {
        if (fields.contains(QLatin1String(l.key)))
            width = std::max(width, qsizetype(qstrlen(l.label)));
    }
    QStringList out;
    for (const FieldLabel &l : labels()) {
        const QJsonValue v = fields.value(QLatin1String(l.key));
        if (v.isUndefined())
            continue;
        out << indent + QString::fromLatin1(l.label).leftJustified(width + 2) +
                   valueText(l, v, fields);
    }
    return out;
}

QString ReplyText::oneLine(const QJsonObject &fields)
{
    QStringList parts;
    for (const QString &line : lines(fields))
        parts << line.simplified();
    return parts.join(QStringLiteral(", "));
}

} // namespace lk::lkctl
