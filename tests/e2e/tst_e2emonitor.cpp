#include "E2eUtil.h"

#include <system/FileHolders.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <csignal>

using namespace lk::e2e;

/// lkctl monitor against lksim on a pseudo-terminal: it never waits forever - drives that go
/// quiet mid-run (lksim frozen with SIGSTOP, the pty still open, as a drive powered off
/// behind a live adapter) end it with status 1 naming them.
class tst_E2eMonitor : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void quietDrivesEndMonitoring();
    void rateIsAShareOfTheWire_data();
    void rateIsAShareOfTheWire();

private:
    /// lksim's process: the holder of its own pty that is called lksim.
    qint64 lksimPid() const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

void tst_E2eMonitor::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    m_link = m_dir->filePath(QStringLiteral("bus"));
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    QVERIFY2(m_sim->start(simArgs(m_link)), qPrintable(m_sim->errorString()));
}

void tst_E2eMonitor::cleanup()
{
    m_sim.reset();
}

qint64 tst_E2eMonitor::lksimPid() const
{
    for (const lk::system::FileHolder &h : lk::system::FileHolders::of(m_sim->devicePath())) {
        if (h.command == QLatin1String("lksim"))
            return h.pid;
    }
    return 0;
}

void tst_E2eMonitor::quietDrivesEndMonitoring()
{
    QProcess monitor;
    monitor.start(QStringLiteral(LKCTL_PATH),
                  {QStringLiteral("monitor"), QStringLiteral("3"), QStringLiteral("17"),
                   QStringLiteral("--rate"), QStringLiteral("20"), QStringLiteral("--port"),
                   m_link});
    QVERIFY(monitor.waitForStarted());
    QByteArray out;
    // A header and some rows: the drives answer.
    QTRY_VERIFY_WITH_TIMEOUT((out += monitor.readAllStandardOutput()).count('\n') >= 3, 30000);
    const qint64 pid = lksimPid();
    QVERIFY(pid > 0);
    QCOMPARE(::kill(pid_t(pid), SIGSTOP), 0);
    QElapsedTimer quiet;
    quiet.start();
    const bool ended = monitor.waitForFinished(60000);
    ::kill(pid_t(pid), SIGCONT);
    m_sim->kill(); // its pty holds a backlog of polls now: no half-duplex verdict on that
    if (!ended) {
        monitor.kill();
        monitor.waitForFinished();
        QFAIL("lkctl monitor went on waiting after the drives went quiet");
    }
    QVERIFY2(quiet.elapsed() >= 4000, "not before the silence bound");
    const QByteArray err = monitor.readAllStandardError();
    QCOMPARE(monitor.exitCode(), 1);
    QVERIFY2(err.contains("no reply from drive 3, 17 for 5.0 s"), err.constData());
}

void tst_E2eMonitor::rateIsAShareOfTheWire_data()
{
    QTest::addColumn<QString>("what");
    QTest::newRow("state2") << "state2";
    QTest::newRow("default mix, three drives") << "state2,state1,multi-turn";
}

// lksim answers after 0.2 ms, sooner than the 0.5 ms a drive may take: a rate measured against
// a 0.5 ms turnaround passed 100 % ("107 % of the bus limit"). The share is of what the wire
// alone carries, which no rate can pass.
void tst_E2eMonitor::rateIsAShareOfTheWire()
{
    QFETCH(QString, what);
    const CtlResult r = lkctl({"monitor", "3", "17", "32", "--what", what, "--rate", "0",
                               "--duration", "2", "--port", m_link});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QRegularExpression share(
        QStringLiteral("(\\d+) replies/s, (\\d+)% of the (\\d+)/s the wire carries for this mix "
                       "at 115200 baud \\((\\d+)/s if every drive took the 0.5 ms it may to "
                       "answer\\)"));
    const QRegularExpressionMatch m = share.match(QString::fromUtf8(r.err));
    QVERIFY2(m.hasMatch(), r.err.constData());
    const int percent = m.captured(2).toInt();
    QVERIFY2(percent > 30 && percent <= 100, r.err.constData());
    QVERIFY(m.captured(4).toInt() < m.captured(3).toInt());
    QVERIFY(m.captured(1).toInt() <= m.captured(3).toInt());
}

QTEST_GUILESS_MAIN(tst_E2eMonitor)
#include "tst_e2emonitor.moc"
