#include <bus/BusSession.h>
#include <transport/SerialTransport.h>

#include <QtCore/QFileInfo>
#include <QtCore/QProcess>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using protocol::Command;
using protocol::Series;

namespace {
QString lksimPath()
{
    const QString dir = qEnvironmentVariable("LK_TEST_BINARY_DIR");
    const QString path = dir + QStringLiteral("/app/lksim/lksim");
    return !dir.isEmpty() && QFileInfo(path).isExecutable() ? path : QString();
}

int samples(const QSignalSpy &spy)
{
    int n = 0;
    for (const auto &args : spy)
        n += int(args.at(0).value<TelemetryBatch>().size());
    return n;
}
} // namespace

/// SerialTransport + BusSession over a real QSerialPort: lksim serves the bus on a pty.
class tst_BusOverPty : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void scanPollAndStop();
    void simulatorExitIsAnUnplug();

private:
    bool startSim(const QStringList &extra = {});
    QProcess m_sim;
    QString m_device;
};

bool tst_BusOverPty::startSim(const QStringList &extra)
{
    const QString exe = lksimPath();
    if (exe.isEmpty())
        return false;
    m_sim.start(exe, QStringList{QStringLiteral("--motors"), QStringLiteral("3:MF,17:MS,32:MG"),
                                 QStringLiteral("--wire-time"), QStringLiteral("--baud"),
                                 QStringLiteral("115200")} +
                         extra);
    if (!m_sim.waitForStarted(10000))
        return false;
    while (!m_sim.canReadLine() && m_sim.waitForReadyRead(10000)) {
    }
    m_device = QString::fromLocal8Bit(m_sim.readLine()).trimmed();
    return !m_device.isEmpty();
}

void tst_BusOverPty::init()
{
    if (lksimPath().isEmpty())
        QSKIP("lksim is not built (LK_TEST_BINARY_DIR/app/lksim/lksim)");
    QVERIFY2(startSim(), "lksim did not print its device path");
}

void tst_BusOverPty::cleanup()
{
    if (m_sim.state() != QProcess::NotRunning) {
        m_sim.terminate();
        if (!m_sim.waitForFinished(5000))
            m_sim.kill();
        m_sim.waitForFinished(5000);
    }
}

void tst_BusOverPty::scanPollAndStop()
{
    BusSession session;
    QSignalSpy finished(&session, &BusSession::scanFinished);
    QSignalSpy telemetry(&session, &BusSession::telemetryReceived);
    QSignalSpy stats(&session, &BusSession::statisticsUpdated);
    QSignalSpy stopped(&session, &BusSession::emergencyStopFinished);
    transport::SerialSettings s;
    s.portName = m_device;
    session.open(transport::SerialTransport::factory(s), 115200);
    QTRY_VERIFY_WITH_TIMEOUT(session.connection().isOpen(), 10000);

    session.scan();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 60000);
    const auto quick = finished.at(0).at(0).value<ScanSummary>();
    qInfo("default scan of IDs 1..32, lksim on a pty at 115200 (wire time): %.0f ms, %d of 3 "
          "found",
          quick.elapsedS * 1e3, int(quick.motors.size()));
    ScanOptions o;
    o.retries = 1;
    session.scan(o);
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 60000);
    QCOMPARE(finished.at(1).at(0).value<ScanSummary>().motors.size(), 3);
    QTRY_COMPARE(session.knownMotors().keys(), (QList<int>{3, 17, 32}));
    QCOMPARE(session.series(17), std::optional<Series>(Series::MS));

    stats.clear();
    session.startPolling(PollPlan::standard({3, 17, 32}));
    QTRY_VERIFY_WITH_TIMEOUT(stats.size() >= 4, 20000);
    const BusStatistics st = stats.last().at(0).value<BusStatistics>();
    qInfo("polling 3 drives x {9C,9A,92,9D} over the pty: %.0f txn/s (bus limit %.0f), latency "
          "min/median/max %.2f/%.2f/%.2f ms, margin %.1f ms",
          st.bus.transactionsPerSecond, st.pollLimitPerSecond, st.bus.latency.minMs,
          st.bus.latency.medianMs, st.bus.latency.maxMs, st.timeoutMarginMs);
    QVERIFY(samples(telemetry) > 20);
    QCOMPARE(st.bus.checksumErrors, quint64(0));

    session.emergencyStop();
    QTRY_COMPARE_WITH_TIMEOUT(stopped.size(), 1, 10000);
    QCOMPARE(stopped.at(0).at(1).value<QVector<int>>(), (QVector<int>{3, 17, 32}));
    session.close();
}

void tst_BusOverPty::simulatorExitIsAnUnplug()
{
    BusSession session;
    QSignalSpy errors(&session, &BusSession::errorOccurred);
    transport::SerialSettings s;
    s.portName = m_device;
    session.open(transport::SerialTransport::factory(s), 115200);
    QTRY_VERIFY_WITH_TIMEOUT(session.connection().isOpen(), 10000);
    session.startPolling(PollPlan::standard({3}));
    m_sim.terminate(); // the "adapter" disappears
    m_sim.waitForFinished(5000);
    QTRY_COMPARE_WITH_TIMEOUT(session.connection().state, transport::Transport::State::Disconnected,
                              10000);
    QVERIFY2(session.connection().reason.contains(QStringLiteral("unplugged")),
             qPrintable(session.connection().reason));
    QTest::qWait(300);
    QCOMPARE(errors.size(), 0); // an unplug is a state, not an error
}

QTEST_GUILESS_MAIN(tst_BusOverPty)
#include "tst_busoverpty.moc"
