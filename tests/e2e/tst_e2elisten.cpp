#include "E2eUtil.h"
#include "ListenTruth.h"

#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

// lkctl listen on the tap of lksim --controller, against the controller's own log (its ground
// truth): every request with a commanded value and every reply the log has in the window
// lkctl listened to comes out as its row, in bus order, of the right drive, with the log's
// values; the pairing's counts agree with the log's outcomes, and no echo frame is guessed.

using namespace lk;
using namespace lk::e2e;
using namespace lk::e2e::listen;

namespace {

constexpr int kBaud = 115200;

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
    // lkctl may stop listening before the last row's request is answered or given up: a last
    // row that is a request is left out of what lkctl must have counted.
    const bool endsOnARequest = want[at + got.size() - 1].values.keys().constFirst().startsWith(
        QLatin1String("commanded_"));
    qint64 answered = 0, unanswered = 0, commanded = 0;
    for (int line = first; line <= last - (endsOnARequest ? 1 : 0); ++line) {
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
    // The controller's speed sine is one command in about twenty: the window holds dozens (50
    // on CI's loaded host, 56 on a quiet one). Fewer than 20 would mean setpoints went missing.
    QVERIFY2(commanded >= 20, qPrintable(QString::number(commanded)));
}

QTEST_GUILESS_MAIN(tst_E2eListen)
#include "tst_e2elisten.moc"
