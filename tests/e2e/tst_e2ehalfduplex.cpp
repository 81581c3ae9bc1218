#include "CpuHog.h"
#include "E2eUtil.h"

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <transport/SerialTransport.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QHash>
#include <QtCore/QTemporaryDir>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <algorithm>
#include <thread>

using namespace lk;
using namespace lk::bus;
using namespace lk::e2e;
using protocol::Command;
using protocol::Series;

namespace {

constexpr int kWaitMs = 30000;
constexpr int kWorkloadMs = 6000;    ///< polling + commands this long
constexpr double kHogMaxS = 60;      ///< the hog stops by itself after this, whatever happens
constexpr int kCommandsInFlight = 4; ///< operator requests kept queued beside the polling

/// The operator's share of the workload: reads and RAM writes that every drive answers.
protocol::Request operatorRequest(int n)
{
    using namespace protocol::build;
    const int ids[] = {3, 17, 32};
    const int id = ids[n % 3];
    switch (n % 4) {
    case 0:
        return *plain(Command::ReadPid, id).request;
    case 1:
        return *writeAcceleration(id, 1000 + n % 500).request;
    case 2:
        return *plain(Command::ReadMultiTurn, id).request;
    default:
        return *plain(Command::ReadState1, id).request;
    }
}

} // namespace

/// Half duplex on a loaded host: lksim on a pty with wire-time emulation, polling and
/// operator commands through BusSession with the product's default timing while bursts of
/// busy loops take every core. The host must never talk while a drive may still be answering (lksim
/// counts 0 collisions) and every reply must be taken once: by its own request, or counted
/// late and dropped.
class tst_E2eHalfDuplex : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void init();
    void cleanup();
    void pollingAndCommandsBesideACpuHog();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
};

void tst_E2eHalfDuplex::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    QVERIFY2(m_sim->start(simArgs(m_dir->filePath(QStringLiteral("lkbus")))),
             qPrintable(m_sim->errorString()));
}

void tst_E2eHalfDuplex::cleanup()
{
    if (m_sim)
        verifyNoCollisions(*m_sim);
    m_sim.reset();
    m_dir.reset();
}

void tst_E2eHalfDuplex::pollingAndCommandsBesideACpuHog()
{
    BusSession session;
    QSignalSpy stats(&session, &BusSession::statisticsUpdated);
    QHash<quint64, int> completions;
    int sent = 0;
    int mismatched = 0;
    QObject::connect(&session, &BusSession::requestCompleted,
                     [&completions, &mismatched](const RequestResult &r) {
                         ++completions[r.ticket];
                         if (r.reply &&
                             (r.reply->id != r.request.id || r.reply->command != r.request.command))
                             ++mismatched;
                     });
    transport::SerialSettings s;
    s.portName = m_sim->devicePath();
    BusConfig config; // the product's defaults: the timing adapts to the loaded host
    config.statisticsHz = 10;
    session.open(transport::SerialTransport::factory(s), 115200, config);
    QTRY_VERIFY_WITH_TIMEOUT(session.connection().isOpen(), kWaitMs);
    QStringList timeouts; // what timed out, when: the figures to look at when this fails
    QObject::connect(&session, &BusSession::trafficCaptured,
                     [&timeouts](const TrafficBatch &batch) {
                         for (const TrafficEvent &e : batch) {
                             if (e.kind == TrafficEvent::Kind::Timeout)
                                 timeouts << QStringLiteral("%1 ID %2 at %3 s")
                                                 .arg(protocol::CommandTable::codeText(e.command))
                                                 .arg(e.id)
                                                 .arg(e.time, 0, 'f', 3);
                         }
                     });
    session.setTrafficCapture(true);
    session.setSeries(3, Series::MF);
    session.setSeries(17, Series::MS);
    session.setSeries(32, Series::MG);

    // Two busy threads per core in bursts: the latency the bus sees jumps between calm and
    // tens of milliseconds, as on a laptop that is compiling or rendering a page. (A steady
    // hog is easier: the margins learn it once.)
    CpuHog::Options load;
    load.maxSeconds = kHogMaxS;
    load.threads = 2 * int(std::max(1u, std::thread::hardware_concurrency()));
    load.burstMs = 30;
    load.pauseMs = 70;
    CpuHog hog(load);
    session.startPolling(PollPlan::standard({3, 17, 32}));
    QElapsedTimer workload;
    workload.start();
    const auto inFlight = [&completions] {
        return int(std::count(completions.cbegin(), completions.cend(), 0));
    };
    while (workload.elapsed() < kWorkloadMs) {
        while (inFlight() < kCommandsInFlight)
            completions.insert(session.send(operatorRequest(sent++)), 0);
        QTest::qWait(5);
    }
    session.stopPolling();
    QTRY_VERIFY_WITH_TIMEOUT(
        std::all_of(completions.cbegin(), completions.cend(), [](int n) { return n > 0; }),
        kWaitMs);
    hog.stop();
    QVERIFY(hog.turns() > 0);
    QTest::qWait(500); // the last snapshot covers everything
    QVERIFY(!stats.isEmpty());
    const BusStatistics st = stats.last().at(0).value<BusStatistics>();
    session.close();
    m_sim->stop();
    const std::optional<LksimCounters> sim = m_sim->counters();
    QVERIFY(sim);
    qInfo("with %d busy threads: %llu requests, %llu replies, %llu timeouts, %llu retries, %llu "
          "late replies; lksim: %lld requests, %lld replies, %lld collisions; margin %.1f ms; "
          "timed out: %s",
          hog.threadCount(), st.bus.requests, st.bus.replies, st.bus.timeouts, st.bus.retries,
          st.bus.lateReplies, sim->requests, sim->replies, sim->collisions, st.timeoutMarginMs,
          qPrintable(timeouts.join(QStringLiteral(", "))));

    QVERIFY(sent > 20);
    for (auto it = completions.cbegin(); it != completions.cend(); ++it)
        QCOMPARE(it.value(), 1); // every request ended exactly once
    QCOMPARE(mismatched, 0);     // ... with the reply to what it asked
    // Each reply lksim sent was taken once: by the request that asked for it, or counted as
    // late (the answer to an attempt that had timed out, which a spike of load beyond the
    // margins can cause) and dropped. None answered a later request, none went unaccounted.
    QCOMPARE(st.bus.unexpectedFrames, quint64(0));
    QVERIFY(st.bus.lateReplies <= st.bus.timeouts);
    QCOMPARE(qint64(st.bus.requests), sim->requests);
    QCOMPARE(qint64(st.bus.replies + st.bus.lateReplies), sim->replies);
    // The collision count itself is checked in cleanup(), as in every end-to-end test.
}

QTEST_GUILESS_MAIN(tst_E2eHalfDuplex)
#include "tst_e2ehalfduplex.moc"
