#include "BusReport.h"

#include "ParameterFields.h"
#include "ParameterSet.h"

#include <protocol/ErrorFlags.h>
#include <protocol/FieldJson.h>
#include <protocol/Reply.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>

namespace lk::record {

namespace {

const char kFormat[] = "lkstudio-bus-report";

// Column headings of the HTML table (translatable).
const char *const kHeaders[] = {
    QT_TRANSLATE_NOOP("lk::record::BusReport", "ID"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Series"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Driver"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Motor"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Hardware"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Firmware"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Protocol"),
    QT_TRANSLATE_NOOP("lk::record::BusReport",
                      "Gains (angle \u00b7 speed \u00b7 iq: Kp/Ki, V2.35 Kp/Ki/Kd)"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Acceleration or limits"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "State"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Problems"),
};

QString translated(const char *text)
{
    return QCoreApplication::translate("lk::record::BusReport", text);
}

QJsonObject modelJson(const protocol::ModelInfo &m)
{
    QJsonObject o;
    o.insert(QStringLiteral("driver_name"), m.driverName);
    o.insert(QStringLiteral("motor_name"), m.motorName);
    o.insert(QStringLiteral("hardware_version"), m.hardwareVersion());
    o.insert(QStringLiteral("firmware_version"), m.firmwareVersion());
    o.insert(QStringLiteral("generation"), m.generation == protocol::Generation::V2_3
                                               ? QStringLiteral("V2.3")
                                               : QStringLiteral("V2.35"));
    return o;
}

QJsonObject pidJson(const protocol::PidGains &p)
{
    QJsonObject o;
    o.insert(QStringLiteral("angle_kp"), p.angleKp);
    o.insert(QStringLiteral("angle_ki"), p.angleKi);
    o.insert(QStringLiteral("speed_kp"), p.speedKp);
    o.insert(QStringLiteral("speed_ki"), p.speedKi);
    o.insert(QStringLiteral("iq_kp"), p.iqKp);
    o.insert(QStringLiteral("iq_ki"), p.iqKi);
    return o;
}

/// The fields lkctl prints for read_state1 (by the reply's generation), and the set flags by
/// name as `lkctl scan` lists them.
QJsonObject state1Json(const protocol::State1 &s)
{
    protocol::Reply r;
    r.command = protocol::Command::ReadState1;
    r.payload = s;
    QJsonObject o = protocol::FieldJson::replyFields(r);
    QStringList errors;
    for (const protocol::ErrorFlag &f : protocol::ErrorFlags::set(s.errorState, s.generation))
        errors << QLatin1String(f.key);
    if (protocol::ErrorFlags::unnamedBits(s.errorState, s.generation))
        errors << QStringLiteral("unknown_bits");
    o.insert(QStringLiteral("errors"), QJsonArray::fromStringList(errors));
    return o;
}

QJsonObject driveJson(const BusReportDrive &d)
{
    QJsonObject o;
    o.insert(QStringLiteral("id"), d.id);
    o.insert(QStringLiteral("answered"), d.answered());
    if (d.series)
        o.insert(QStringLiteral("series"), protocol::seriesName(*d.series));
    if (d.model)
        o.insert(QStringLiteral("model"), modelJson(*d.model));
    if (d.generation)
        o.insert(QStringLiteral("generation"), protocol::generationName(*d.generation));
    if (d.pid)
        o.insert(QStringLiteral("pid"), pidJson(*d.pid));
    if (d.accelDps2)
        o.insert(QStringLiteral("accel_dps2"), qint64(*d.accelDps2));
    if (!d.params.isEmpty()) {
        // V2.35: the gains with Kd under the V2.3 names, and `params` as `lkctl info` has them.
        QJsonObject pid, params;
        ParameterFields::split(d.params, pid, params);
        if (!pid.isEmpty())
            o.insert(QStringLiteral("pid"), pid);
        if (!params.isEmpty())
            o.insert(QStringLiteral("params"), params);
    }
    if (d.state1)
        o.insert(QStringLiteral("state1"), state1Json(*d.state1));
    o.insert(QStringLiteral("problems"), QJsonArray::fromStringList(d.problems));
    return o;
}

QString cell(const QString &text)
{
    return QStringLiteral("<td>%1</td>").arg(text.toHtmlEscaped());
}

QString dash()
{
    return QStringLiteral("\u2013");
}

QString driveRow(const BusReportDrive &d)
{
    const auto &m = d.model;
    QString row = QStringLiteral("<tr>");
    row += cell(QString::number(d.id));
    row += cell(d.series ? protocol::seriesName(*d.series) : dash());
    row += cell(m ? m->driverName : dash());
    row += cell(m ? m->motorName : dash());
    row += cell(m ? QString::number(m->hardwareVersion(), 'f', m->divisor() > 10 ? 2 : 1) : dash());
    row += cell(m ? QString::number(m->firmwareVersion(), 'f', m->divisor() > 10 ? 2 : 1) : dash());
    row += cell(d.generation ? protocol::generationName(*d.generation).toUpper() : dash());
    row += cell(d.gainsText());
    row += cell(d.limitsText());
    row += cell(d.stateText());
    row += cell(d.problems.isEmpty() ? QCoreApplication::translate("lk::record::BusReport", "none")
                                     : d.problems.join(QStringLiteral("; ")));
    return row + QStringLiteral("</tr>\n");
}

} // namespace

QString BusReportDrive::stateText() const
{
    if (!state1)
        return dash();
    const protocol::State1 &s = *state1;
    const int decimals = s.generation == protocol::Generation::V2_3 ? 1 : 2;
    QString t =
        QStringLiteral("%1 \u00b0C, %2 V").arg(s.temperatureC).arg(s.voltageV(), 0, 'f', decimals);
    QStringList flags;
    for (const protocol::ErrorFlag &f : protocol::ErrorFlags::set(s.errorState, s.generation))
        flags << QCoreApplication::translate("lk::protocol::ErrorFlags", f.text);
    if (const quint8 rest = protocol::ErrorFlags::unnamedBits(s.errorState, s.generation))
        flags << QCoreApplication::translate("lk::record::BusReport", "unknown bits 0x%1")
                     .arg(rest, 2, 16, QLatin1Char('0'));
    if (!flags.isEmpty())
        t += QStringLiteral("; ") + flags.join(QStringLiteral(", "));
    return t;
}

QString BusReportDrive::gainsText() const
{
    if (pid)
        return QStringLiteral("%1/%2 \u00b7 %3/%4 \u00b7 %5/%6")
            .arg(pid->angleKp)
            .arg(pid->angleKi)
            .arg(pid->speedKp)
            .arg(pid->speedKi)
            .arg(pid->iqKp)
            .arg(pid->iqKi);
    QStringList loops;
    for (protocol::ParamId id : {protocol::ParamId::AnglePid, protocol::ParamId::SpeedPid,
                                 protocol::ParamId::CurrentPid}) {
        QString loop = dash();
        for (const protocol::ParameterValue &v : params) {
            if (v.id() == id)
                loop = QStringLiteral("%1/%2/%3").arg(v.pidKp()).arg(v.pidKi()).arg(v.pidKd());
        }
        loops << loop;
    }
    return loops == QStringList(3, dash()) ? dash() : loops.join(QStringLiteral(" \u00b7 "));
}

QString BusReportDrive::limitsText() const
{
    const auto say = [](const char *text) {
        return QCoreApplication::translate("lk::record::BusReport", text);
    };
    if (accelDps2)
        return say(QT_TRANSLATE_NOOP("lk::record::BusReport", "%1 dps/s")).arg(*accelDps2);
    QJsonObject gains, values;
    ParameterFields::split(params, gains, values);
    if (values.isEmpty())
        return dash();
    // 0x99 bounds the power on MS, the torque current elsewhere.
    const char *torque = series == protocol::Series::MS
                             ? QT_TRANSLATE_NOOP("lk::record::BusReport", "max power %1")
                             : QT_TRANSLATE_NOOP("lk::record::BusReport", "max torque %1");
    const std::pair<const char *, const char *> shown[] = {
        {"max_torque", torque},
        {"max_speed_dps", QT_TRANSLATE_NOOP("lk::record::BusReport", "max speed %1 dps")},
        {"max_angle_deg", QT_TRANSLATE_NOOP("lk::record::BusReport", "max angle %1\u00b0")},
        {"current_ramp", QT_TRANSLATE_NOOP("lk::record::BusReport", "current ramp %1")},
        {"speed_ramp_dps2", QT_TRANSLATE_NOOP("lk::record::BusReport", "speed ramp %1 dps/s")},
    };
    QStringList parts;
    for (const auto &[key, text] : shown) {
        if (values.contains(QLatin1String(key)))
            parts << say(text).arg(
                QString::number(values.value(QLatin1String(key)).toDouble(), 'g', 12));
    }
    return parts.join(QStringLiteral(" \u00b7 "));
}

QJsonObject BusReport::toJson() const
{
    QJsonArray list;
    for (const BusReportDrive &d : drives)
        list.append(driveJson(d));
    QJsonObject o;
    o.insert(QStringLiteral("format"), QLatin1String(kFormat));
    o.insert(QStringLiteral("version"), kFormatVersion);
    o.insert(QStringLiteral("created_at"), createdAt.toUTC().toString(Qt::ISODateWithMs));
    o.insert(QStringLiteral("connection"), connection);
    o.insert(QStringLiteral("baud"), baud);
    o.insert(QStringLiteral("tool_version"), toolVersion);
    o.insert(QStringLiteral("drive_count"), int(drives.size()));
    o.insert(QStringLiteral("drives"), list);
    return o;
}

QByteArray BusReport::toJsonBytes() const
{
    return QJsonDocument(toJson()).toJson(QJsonDocument::Indented);
}

QString BusReport::toHtml() const
{
    const QString title = QCoreApplication::translate("lk::record::BusReport", "LK bus report");
    QString h = QStringLiteral("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">"
                               "<title>%1</title>\n<style>body{font-family:sans-serif}"
                               "table{border-collapse:collapse}td,th{border:1px solid #999;"
                               "padding:3px 8px;text-align:left}th{background:#eee}</style>"
                               "</head><body>\n")
                    .arg(title.toHtmlEscaped());
    h += QStringLiteral("<h1>%1</h1>\n<p>").arg(title.toHtmlEscaped());
    h += QCoreApplication::translate("lk::record::BusReport", "Created: %1 (UTC)")
             .arg(createdAt.toUTC().toString(Qt::ISODate))
             .toHtmlEscaped();
    h += QStringLiteral("<br>") +
         QCoreApplication::translate("lk::record::BusReport", "Connection: %1")
             .arg(connection)
             .toHtmlEscaped();
    h += QStringLiteral("<br>") + QCoreApplication::translate("lk::record::BusReport", "Drives: %1")
                                      .arg(drives.size())
                                      .toHtmlEscaped();
    if (!toolVersion.isEmpty())
        h += QStringLiteral("<br>") +
             QCoreApplication::translate("lk::record::BusReport", "Written by: %1")
                 .arg(toolVersion)
                 .toHtmlEscaped();
    h += QStringLiteral("</p>\n<table>\n<tr>");

    for (const char *header : kHeaders)
        h += QStringLiteral("<th>%1</th>").arg(translated(header).toHtmlEscaped());
    h += QStringLiteral("</tr>\n");
    for (const BusReportDrive &d : drives)
        h += driveRow(d);
    h += QStringLiteral("</table>\n</body></html>\n");
    return h;
}

QString BusReport::save(const QString &jsonPath, const QString &htmlPath) const
{
    const QString jsonError = writeFileAtomically(jsonPath, toJsonBytes());
    if (!jsonError.isEmpty())
        return jsonError;
    return writeFileAtomically(htmlPath, toHtml().toUtf8());
}

} // namespace lk::record
