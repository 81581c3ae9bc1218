#include "E2eUtil.h"

#include <bus/TelemetryFieldInfo.h>

#include <QtCore/QFile>
#include <QtCore/QHash>
#include <QtCore/QJsonArray>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>

// lkctl listen on the tap of lksim --controller, against the controller's own log (its ground
// truth): every request with a commanded value and every reply the log has in the window
// lkctl listened to comes out as its row, in bus order, of the right drive, with the log's
// values; the pairing's counts agree with the log's outcomes, and no echo frame is guessed.

using namespace lk;
using namespace lk::e2e;

namespace {

constexpr int kBaud = 115200;

/// One row lkctl listen printed, or one the log says it should print.
struct Row {
    int id = 0;
    QJsonObject values; ///< column -> value, time_s and id left out
    int logLine = -1;   ///< expected rows: the transaction of the log it comes from
};

/// Per drive, the log lines of its answered read_model requests: from them on, a listener
/// knows its series and generation.
using ModelLines = QHash<int, QList<int>>;

/// Whether a listener that began at log line `start` may not know the drive of `row` yet
/// (no read_model reply of it since): its replies may read with another layout.
bool learning(const Row &row, int start, const ModelLines &models)
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
QString commandedColumn(const QString &code, const QString &field)
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
QString replyColumn(const QString &code, const QString &field)
{
    if (field == QLatin1String("angle_deg"))
        return code == QLatin1String("0x92") ? QStringLiteral("multi_turn_deg")
                                             : QStringLiteral("single_turn_deg");
    return bus::TelemetryFieldInfo::indexOf(field) ? field : QString();
}

QJsonValue columnValue(const QJsonValue &v)
{
    if (v.isBool())
        return v.toBool() ? 1 : 0;
    if (v.isString()) // a direction
        return v.toString() == QLatin1String("ccw") ? 1 : 0;
    return v;
}

/// The rows lkctl listen must print for the log's transactions, in bus order.
QList<Row> expectedRows(const QList<QJsonObject> &log, ModelLines &models)
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
        if (code == QLatin1String("0x12"))
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

QList<Row> listenedRows(const QByteArray &out)
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

QList<QJsonObject> readLog(const QString &path)
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
QString difference(const Row &got, const Row &want)
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
QString differenceFrom(int start, const Row &got, const Row &want, const ModelLines &models,
                       int *learnt = nullptr)
{
    if (!learning(want, start, models))
        return difference(got, want);
    if (learnt)
        ++*learnt;
    return got.id == want.id ? QString()
                             : QStringLiteral("drive %1, expected %2").arg(got.id).arg(want.id);
}

/// Where the listened rows begin among the expected ones: the first place the first rows
/// (up to 8) all match; -1 when there is none.
qsizetype alignment(const QList<Row> &got, const QList<Row> &want, const ModelLines &models)
{
    const qsizetype probe = std::min<qsizetype>(8, got.size());
    for (qsizetype k = 0; k + probe <= want.size(); ++k) {
        bool all = true;
        for (qsizetype j = 0; j < probe && all; ++j)
            all = differenceFrom(want[k].logLine, got[j], want[k + j], models).isEmpty();
        if (all)
            return k;
    }
    return -1;
}

/// A count lkctl listen reported on standard error ("paired 123"), or -1.
qint64 reported(const QByteArray &err, const QString &name)
{
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("the other master:.*?(?:: |, )%1 (\\d+)").arg(name))
            .match(QString::fromUtf8(err));
    return m.hasMatch() ? m.captured(1).toLongLong() : -1;
}

} // namespace

class tst_E2eListen : public QObject {
    Q_OBJECT
private slots:
    void listenMatchesTheControllersLog_data();
    void listenMatchesTheControllersLog();
};

void tst_E2eListen::listenMatchesTheControllersLog_data()
{
    QTest::addColumn<QString>("faults");
    QTest::newRow("clean bus") << QString();
    QTest::newRow("2% drops and garbage") << QStringLiteral("drop=0.02,garbage=0.02,seed=11");
}

void tst_E2eListen::listenMatchesTheControllersLog()
{
    QFETCH(QString, faults);
    QTemporaryDir dir;
    const QString logPath = dir.filePath(QStringLiteral("truth.jsonl"));
    // 1: MF, 2: MS (power instead of iq), 3: a V2.35 MG; ID 4 is polled and never answers.
    // read_model first in each drive's round: a listener learns series and generation from it.
    QStringList args{QStringLiteral("--motors"),
                     QStringLiteral("1:MF,2:MS,3:MG4010@2.35"),
                     QStringLiteral("--baud"),
                     QString::number(kBaud),
                     QStringLiteral("--controller"),
                     QStringLiteral("rate=400,ids=1-4,poll=12:9c:9a:92:94,"
                                    "speed=sine:300dps:2Hz,move=every:0.5s"),
                     QStringLiteral("--controller-log"),
                     logPath};
    if (!faults.isEmpty())
        args << QStringLiteral("--faults") << faults;
    LksimProcess sim(QStringLiteral(LKSIM_PATH));
    QVERIFY2(sim.start(args), qPrintable(sim.errorString()));
    const CtlResult r =
        lkctl({QStringLiteral("listen"), QStringLiteral("--port"), sim.devicePath(),
               QStringLiteral("--baud"), QString::number(kBaud), QStringLiteral("--json"),
               QStringLiteral("--duration"), QStringLiteral("4")});
    sim.stop(); // the log is complete only now
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));

    const QList<QJsonObject> log = readLog(logPath);
    ModelLines models;
    const QList<Row> want = expectedRows(log, models);
    const QList<Row> got = listenedRows(r.out);
    QVERIFY2(got.size() > 400, qPrintable(QString::number(got.size())));
    const qsizetype at = alignment(got, want, models);
    QVERIFY2(at >= 0, "the first rows lkctl listen printed are nowhere in the log");
    QVERIFY2(at + got.size() <= want.size(), "lkctl listen printed rows the log has not");
    int learnt = 0;
    for (qsizetype j = 0; j < got.size(); ++j) {
        const Row &w = want[at + j];
        const QString why = differenceFrom(want[at].logLine, got[j], w, models, &learnt);
        QVERIFY2(
            why.isEmpty(),
            qPrintable(
                QStringLiteral("row %1 (log line %2): %3").arg(j + 1).arg(w.logLine + 1).arg(why)));
    }
    // A drive's rows before its read_model reply passed: at most one round of each drive.
    QVERIFY2(learnt <= 4 * 6, qPrintable(QString::number(learnt)));

    // The window the rows cover: what the log says happened there, against what lkctl
    // listen counted over its whole run (which may hold a few more transactions at each end,
    // without a row of their own: read_model, unanswered requests).
    const int first = want[at].logLine;
    const int last = want[at + got.size() - 1].logLine;
    qint64 answered = 0, unanswered = 0, commanded = 0;
    for (int line = first; line <= last; ++line) {
        const QString outcome = log[line].value(QStringLiteral("outcome")).toString();
        answered += outcome == QLatin1String("answered");
        unanswered += outcome != QLatin1String("answered");
        commanded += log[line].value(QStringLiteral("code")).toString() == QLatin1String("0xA2");
    }
    const qint64 replies = reported(r.err, QStringLiteral("replies"));
    const qint64 paired = reported(r.err, QStringLiteral("paired"));
    // The first reply may come before lkctl saw its request (it began listening mid-way).
    const qint64 orphans = reported(r.err, QStringLiteral("replies without their request"));
    const qint64 notAnswered = reported(r.err, QStringLiteral("unanswered")) +
                               reported(r.err, QStringLiteral("pairs broken by lost bytes"));
    const qint64 ambiguous = reported(r.err, QStringLiteral("ambiguous echo frames"));
    qInfo("%lld rows matched (log lines %d..%d: %lld answered, %lld not, %lld speed commands); "
          "lkctl listen: replies %lld, paired %lld, without their request %lld, unanswered or "
          "broken %lld, ambiguous %lld",
          qint64(got.size()), first + 1, last + 1, answered, unanswered, commanded, replies, paired,
          orphans, notAnswered, ambiguous);
    // Its counts also cover what passed after its last row was printed (the final statistics
    // come after the rows stop), so they may be larger, never smaller.
    QVERIFY2(replies >= answered, r.err.constData());
    QVERIFY2(orphans <= 1 && paired + orphans == replies, r.err.constData());
    QVERIFY2(notAnswered >= unanswered, r.err.constData());
    // The controller sends no echo command (reads, speed and incremental moves): an echo frame
    // counted ambiguous here would be a guess gone wrong the other way.
    QCOMPARE(ambiguous, qint64(0));
    QVERIFY(commanded > 50);
}

QTEST_GUILESS_MAIN(tst_E2eListen)
#include "tst_e2elisten.moc"
