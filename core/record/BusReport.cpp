#include "BusReport.h"

#include "ParameterSet.h"

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
    QT_TRANSLATE_NOOP("lk::record::BusReport",
                      "PID (angle Kp/Ki \u00b7 speed Kp/Ki \u00b7 iq Kp/Ki)"),
    QT_TRANSLATE_NOOP("lk::record::BusReport", "Acceleration (dps/s)"),
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

QJsonObject state1Json(const protocol::State1 &s)
{
    QJsonObject o;
    o.insert(QStringLiteral("temperature_c"), s.temperatureC);
    o.insert(QStringLiteral("voltage_v"), s.voltageV());
    o.insert(QStringLiteral("error_state"), s.errorState);
    o.insert(QStringLiteral("low_voltage"), s.lowVoltage());
    o.insert(QStringLiteral("over_temperature"), s.overTemperature());
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
    if (d.pid)
        o.insert(QStringLiteral("pid"), pidJson(*d.pid));
    if (d.accelDps2)
        o.insert(QStringLiteral("accel_dps2"), qint64(*d.accelDps2));
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

QString pidText(const std::optional<protocol::PidGains> &p)
{
    if (!p)
        return dash();
    return QStringLiteral("%1 / %2 \u00b7 %3 / %4 \u00b7 %5 / %6")
        .arg(p->angleKp)
        .arg(p->angleKi)
        .arg(p->speedKp)
        .arg(p->speedKi)
        .arg(p->iqKp)
        .arg(p->iqKi);
}

QString stateText(const std::optional<protocol::State1> &s)
{
    if (!s)
        return dash();
    QString t =
        QStringLiteral("%1 \u00b0C, %2 V").arg(s->temperatureC).arg(s->voltageV(), 0, 'f', 1);
    if (s->lowVoltage())
        t += QStringLiteral(", ") +
             QCoreApplication::translate("lk::record::BusReport", "LOW VOLTAGE");
    if (s->overTemperature())
        t += QStringLiteral(", ") +
             QCoreApplication::translate("lk::record::BusReport", "OVER TEMPERATURE");
    return t;
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
    row += cell(pidText(d.pid));
    row += cell(d.accelDps2 ? QString::number(*d.accelDps2) : dash());
    row += cell(stateText(d.state1));
    row += cell(d.problems.isEmpty() ? QCoreApplication::translate("lk::record::BusReport", "none")
                                     : d.problems.join(QStringLiteral("; ")));
    return row + QStringLiteral("</tr>\n");
}

} // namespace

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
