// `lkctl control ... torque|open-loop` and --watch SECONDS on the in-process simulated bus
// (--sim): without --watch the output says the drive stays under the command, unwatched;
// with it, the bus thread's speed watch stops a drive past the speed limit (exit 6), and the
// end of the watch, Ctrl+C and SIGTERM stop it too (Motor Stop, acknowledged).

#include "E2eUtil.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QProcess>
#include <QtTest/QtTest>

#include <csignal>
#include <sys/types.h>

namespace {

using lk::e2e::lkctl;
using Result = lk::e2e::CtlResult;

QStringList words(const char *text)
{
    return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

QString describe(const Result &r)
{
    return lk::e2e::describeRun(r);
}

} // namespace

class tst_LkctlWatch : public QObject {
    Q_OBJECT
private slots:
    void withoutWatchSaysItIsUnwatched_data();
    void withoutWatchSaysItIsUnwatched();
    void watchStopsPastTheLimit_data();
    void watchStopsPastTheLimit();
    void watchEndsWithAStop();
    void watchJsonLine();
    void signalStopsTheDrive_data();
    void signalStopsTheDrive();
    void watchArgumentErrors_data();
    void watchArgumentErrors();
};

void tst_LkctlWatch::withoutWatchSaysItIsUnwatched_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<bool>("json");
    QTest::newRow("torque") << words("control 3 torque 0.2 --sim 3:MF") << false;
    QTest::newRow("open loop") << words("control 17 open-loop 100 --sim 17:MS") << false;
    QTest::newRow("json: the note on stderr")
        << words("control 3 torque 0.2 --sim 3:MF --json") << true;
}

void tst_LkctlWatch::withoutWatchSaysItIsUnwatched()
{
    QFETCH(QStringList, args);
    QFETCH(bool, json);
    const Result r = lkctl(args);
    QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
    const QByteArray where = json ? r.err : r.out;
    QVERIFY2(where.contains("stays under") && where.contains("nothing watches its speed") &&
                 where.contains("--watch SECONDS"),
             qPrintable(describe(r)));
    if (json) // stdout stays one JSON line
        QCOMPARE(r.out.trimmed().count('\n'), 0);
}

void tst_LkctlWatch::watchStopsPastTheLimit_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("MF torque 0.3 A, 720 dps")
        << words("control 3 torque 0.3 --max-speed-dps 720 --watch 20 --sim 3:MF");
    QTest::newRow("MS open loop 300, 360 dps")
        << words("control 17 open-loop 300 --max-power 300 --max-speed-dps 360 --watch 20 "
                 "--sim 17:MS");
}

void tst_LkctlWatch::watchStopsPastTheLimit()
{
    QFETCH(QStringList, args);
    const Result r = lkctl(args);
    QVERIFY2(r.exitCode == 6, qPrintable(describe(r)));
    QVERIFY2(r.out.contains("Watching drive"), qPrintable(describe(r)));
    QVERIFY2(r.out.contains("the speed watch sent Motor Stop (0x81)") &&
                 r.out.contains("acknowledged"),
             qPrintable(describe(r)));
    QVERIFY2(!r.out.contains("stays under"), qPrintable(describe(r)));
}

void tst_LkctlWatch::watchEndsWithAStop()
{
    // Below the limit for the whole watch: at its end the drive gets Motor Stop all the same.
    const Result r =
        lkctl(words("control 3 torque 0.05 --max-speed-dps 18000 --watch 0.5 --sim 3:MF"));
    QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
    QVERIFY2(r.out.contains("Watch over after") &&
                 r.out.contains("drive 3 acknowledged Motor Stop (0x81)"),
             qPrintable(describe(r)));
}

void tst_LkctlWatch::watchJsonLine()
{
    const Result r =
        lkctl(words("control 3 torque 0.3 --max-speed-dps 720 --watch 20 --sim 3:MF --json"));
    QVERIFY2(r.exitCode == 6, qPrintable(describe(r)));
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 2);
    const QJsonObject watch =
        QJsonDocument::fromJson(lines.at(1)).object().value("watch").toObject();
    QCOMPARE(watch.value("id").toInt(), 3);
    QCOMPARE(watch.value("ended").toString(), QStringLiteral("speed_limit"));
    QCOMPARE(watch.value("limit_dps").toDouble(), 720.0);
    QCOMPARE(watch.value("threshold_dps").toDouble(), 756.0);
    QVERIFY(watch.value("peak_dps").toDouble() > 756);
    QCOMPARE(watch.value("stop_acknowledged").toBool(), true);
}

void tst_LkctlWatch::signalStopsTheDrive_data()
{
    QTest::addColumn<int>("signalNumber");
    QTest::newRow("Ctrl+C") << int(SIGINT);
    QTest::newRow("SIGTERM") << int(SIGTERM);
}

void tst_LkctlWatch::signalStopsTheDrive()
{
    QFETCH(int, signalNumber);
    QProcess p;
    p.start(QStringLiteral(LKCTL_PATH),
            words("control 3 torque 0.05 --max-speed-dps 18000 --watch 60 --sim 3:MF"));
    QVERIFY(p.waitForStarted(60000));
    QByteArray out;
    QElapsedTimer clock;
    clock.start();
    while (!out.contains("Watching drive") && clock.elapsed() < 60000 &&
           p.state() == QProcess::Running) {
        p.waitForReadyRead(100);
        out += p.readAllStandardOutput();
    }
    QVERIFY2(out.contains("Watching drive"), out.constData());
    ::kill(pid_t(p.processId()), signalNumber);
    QVERIFY(p.waitForFinished(30000)); // long before the 60 s of the watch
    out += p.readAllStandardOutput();
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QVERIFY2(p.exitCode() == 0, out.constData());
    QVERIFY2(out.contains("Interrupted after") &&
                 out.contains("drive 3 acknowledged Motor Stop (0x81)"),
             out.constData());
}

void tst_LkctlWatch::watchArgumentErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("message");
    QTest::newRow("speed mode") << words("control 3 speed 90 --watch 5 --sim 3:MF")
                                << QByteArray(
                                       "--watch goes with torque, open-loop and multi-torque only");
    QTest::newRow("no number") << words("control 3 torque 0.1 --watch soon --sim 3:MF")
                               << QByteArray("--watch");
    QTest::newRow("too short") << words("control 3 torque 0.1 --watch 0 --sim 3:MF")
                               << QByteArray("--watch");
    QTest::newRow("too long") << words("control 3 torque 0.1 --watch 90000 --sim 3:MF")
                              << QByteArray("0.1..86400");
}

void tst_LkctlWatch::watchArgumentErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, message);
    const Result r = lkctl(args);
    QVERIFY2(r.exitCode == 2, qPrintable(describe(r)));
    QVERIFY2(r.err.contains(message), qPrintable(describe(r)));
    QVERIFY(r.out.isEmpty()); // refused before the bus was opened: nothing sent
}

QTEST_GUILESS_MAIN(tst_LkctlWatch)
#include "tst_lkctlwatch.moc"
