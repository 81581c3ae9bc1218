#include "E2eUtil.h"

#include <system/FileHolders.h>

#include <QtCore/QElapsedTimer>
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

QTEST_GUILESS_MAIN(tst_E2eMonitor)
#include "tst_e2emonitor.moc"
