#pragma once

// What lkctl listen must print for lksim --controller's log (its ground truth), and how what
// it printed is compared with it: shared by the RS485 tap (tst_e2elisten) and the CAN bus
// (tst_e2ecanlistencontroller).

#include "E2eUtil.h"

#include <bus/TelemetryFieldInfo.h>

#include <QtCore/QFile>
#include <QtCore/QHash>
#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QRegularExpression>

#include <algorithm>
#include <cmath>

namespace lk::e2e::listen {

/// One row lkctl listen printed, or one the log says it should print.
struct Row {
    int id = 0;
    QJsonObject values; ///< column -> value, time_s and id left out
    int logLine = -1;   ///< expected rows: the transaction of the log it comes from
};

/// Per drive, the log lines of the answered requests a listener learns the drive from (RS485:
/// read_model; CAN: any reply, whose ID or layout names the generation): from them on, it
/// knows its series and generation.
using ModelLines = QHash<int, QList<int>>;

/// Whether a listener that began at log line `start` may not know the drive of `row` yet
/// (no read_model reply of it since): its replies may read with another layout.
inline bool learning(const Row &row, int start, const ModelLines &models)
{
    if (row.values.keys().constFirst().startsWith(QLatin1String("commanded_")))
        return false;
    for (const int line : models.value(row.id)) {
        if (line >= start && line < row.logLine)
            return false;
    }
    return true;
}

/// The column of a logged request field, by command: what the master commanded.
inline QString commandedColumn(const QString &code, const QString &field)
{
    if (field == QLatin1String("speed_dps") && code == QLatin1String("0xA2"))
        return QStringLiteral("commanded_speed_dps");
    if (field == QLatin1String("max_speed_dps"))
        return QStringLiteral("commanded_max_speed_dps");
    if (field != QLatin1String("angle_deg") && field != QLatin1String("direction"))
        return {};
    if (code == QLatin1String("0xA3") || code == QLatin1String("0xA4"))
        return QStringLiteral("commanded_angle_deg");
    if (code == QLatin1String("0xA5") || code == QLatin1String("0xA6"))
        return field == QLatin1String("direction") ? QStringLiteral("commanded_direction")
                                                   : QStringLiteral("commanded_single_turn_deg");
    if (code == QLatin1String("0xA7") || code == QLatin1String("0xA8"))
        return QStringLiteral("commanded_increment_deg");
    return {};
}

/// The column of a logged reply field: the log names a reply's fields as lkctl decode does.
inline QString replyColumn(const QString &code, const QString &field)
{
    if (field == QLatin1String("angle_deg"))
        return code == QLatin1String("0x92") ? QStringLiteral("multi_turn_deg")
                                             : QStringLiteral("single_turn_deg");
    return bus::TelemetryFieldInfo::indexOf(field) ? field : QString();
}

inline QJsonValue columnValue(const QJsonValue &v)
{
    if (v.isBool())
        return v.toBool() ? 1 : 0;
    if (v.isString()) // a direction
        return v.toString() == QLatin1String("ccw") ? 1 : 0;
    return v;
}

/// The rows lkctl listen must print for the log's transactions, in bus order. `learnCode`:
/// the code of the answered requests a listener learns a drive from ("0x12"; empty: any).
inline QList<Row> expectedRows(const QList<QJsonObject> &log, ModelLines &models,
                               const QString &learnCode = QStringLiteral("0x12"))
{
    QList<Row> out;
    for (int line = 0; line < log.size(); ++line) {
        const QJsonObject &t = log.at(line);
        const int id = t.value(QStringLiteral("id")).toInt();
        const QString code = t.value(QStringLiteral("code")).toString();
        Row commanded{id, {}, line};
        const QJsonObject request = t.value(QStringLiteral("request")).toObject();
        for (auto it = request.begin(); it != request.end(); ++it) {
            const QString column = commandedColumn(code, it.key());
            if (!column.isEmpty())
                commanded.values.insert(column, columnValue(it.value()));
        }
        if (!commanded.values.isEmpty())
            out.append(commanded);
        if (t.value(QStringLiteral("outcome")).toString() != QLatin1String("answered"))
            continue;
        if (learnCode.isEmpty() || code == learnCode)
            models[id].append(line);
        Row reply{id, {}, line};
        const QJsonObject fields = t.value(QStringLiteral("reply")).toObject();
        for (auto it = fields.begin(); it != fields.end(); ++it) {
            const QString column = replyColumn(code, it.key());
            if (!column.isEmpty() && !it.value().isNull())
                reply.values.insert(column, columnValue(it.value()));
        }
        if (!reply.values.isEmpty())
            out.append(reply);
    }
    return out;
}

inline QList<Row> listenedRows(const QByteArray &out)
{
    QList<Row> rows;
    for (const QByteArray &line : out.split('\n')) {
        QJsonObject o = jsonOf(line);
        if (o.isEmpty())
            continue;
        Row r;
        r.id = o.take(QStringLiteral("id")).toInt();
        o.remove(QStringLiteral("time_s"));
        r.values = o;
        rows.append(r);
    }
    return rows;
}

inline QList<QJsonObject> readLog(const QString &path)
{
    QFile f(path);
    QList<QJsonObject> out;
    if (f.open(QIODevice::ReadOnly)) {
        for (const QByteArray &line : f.readAll().split('\n'))
            if (!line.isEmpty())
                out.append(jsonOf(line));
    }
    return out;
}

/// Empty when the row lkctl printed is the one expected (values at the column's resolution),
/// else why not.
inline QString difference(const Row &got, const Row &want)
{
    if (got.id != want.id)
        return QStringLiteral("drive %1, expected %2").arg(got.id).arg(want.id);
    if (got.values.keys() != want.values.keys())
        return QStringLiteral("columns %1, expected %2")
            .arg(got.values.keys().join(QLatin1Char(' ')),
                 want.values.keys().join(QLatin1Char(' ')));
    for (auto it = want.values.begin(); it != want.values.end(); ++it) {
        const int decimals =
            bus::TelemetryFieldInfo::all().at(*bus::TelemetryFieldInfo::indexOf(it.key())).decimals;
        const double half = 0.5 * std::pow(10.0, -decimals) + 1e-9;
        const double g = got.values.value(it.key()).toDouble();
        if (std::abs(g - it.value().toDouble()) > half)
            return QStringLiteral("%1 = %2, expected %3")
                .arg(it.key())
                .arg(g)
                .arg(it.value().toDouble());
    }
    return {};
}

/// Empty when the row lkctl printed is the one expected, for a listener that began at log
/// line `start`, else why not. A row of a drive the listener cannot know yet is compared by
/// drive alone; `learnt` counts those.
inline QString differenceFrom(int start, const Row &got, const Row &want, const ModelLines &models,
                              int *learnt = nullptr)
{
    if (!learning(want, start, models))
        return difference(got, want);
    if (learnt)
        ++*learnt;
    return got.id == want.id ? QString()
                             : QStringLiteral("drive %1, expected %2").arg(got.id).arg(want.id);
}

/// Where the listened rows begin among the expected ones: the first place where the first
/// rows all match, up to the eighth compared by value (or all rows, when fewer); -1 when there
/// is none. A row of a drive not learnt yet matches by drive alone and the drives take turns,
/// so a probe of such rows alone could match a round early or late (the likely cause of a
/// failure under ASan, where the ninth row, the first compared by value, met another line).
inline qsizetype alignment(const QList<Row> &got, const QList<Row> &want, const ModelLines &models)
{
    constexpr int kByValue = 8;
    for (qsizetype k = 0; k < want.size(); ++k) {
        const int start = want[k].logLine;
        int byValue = 0;
        qsizetype j = 0;
        bool all = true;
        for (; j < got.size() && k + j < want.size() && byValue < kByValue && all; ++j) {
            all = differenceFrom(start, got[j], want[k + j], models).isEmpty();
            byValue += learning(want[k + j], start, models) ? 0 : 1;
        }
        if (all && (byValue == kByValue || j == got.size()))
            return k;
    }
    return -1;
}

/// A count lkctl listen reported on standard error ("paired 123"), or -1.
inline qint64 reported(const QByteArray &err, const QString &name)
{
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("the other master:.*?(?:: |, )%1 (\\d+)").arg(name))
            .match(QString::fromUtf8(err));
    return m.hasMatch() ? m.captured(1).toLongLong() : -1;
}

} // namespace lk::e2e::listen
