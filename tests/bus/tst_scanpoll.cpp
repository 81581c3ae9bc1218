#include "BusTestUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/BusWorker.h>
#include <bus/MotorRegistry.h>
#include <bus/Scanner.h>

#include <QtCore/QSet>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

namespace {
/// Scans cost a timeout per silent ID: keep the margin modest; tests that must find every
/// drive also allow one retry, so a loaded machine cannot make a drive look absent.
BusConfig scanConfig()
{
    BusConfig c = relaxedConfig();
    c.minMarginMs = c.initialMarginMs = 30;
    return c;
}

void addDrives(FakeTransport &t)
{
    t.drives().add(3, Series::MF);
    t.drives().add(17, Series::MS);
    t.drives().add(32, Series::MG);
}

int samplesIn(const QSignalSpy &spy, int id, TelemetryField field)
{
    int n = 0;
    for (const auto &args : spy) {
        for (const TelemetrySample &s : args.at(0).value<TelemetryBatch>())
            n += (s.id == id && s.has(field)) ? 1 : 0;
    }
    return n;
}
} // namespace

/// Scanner and polling on a BusWorker over a scripted FakeTransport, on a clock the test
/// advances (RigTime::Manual): probe timeouts, late replies and poll pacing do not depend on
/// the machine's load.
class tst_ScanPoll : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void seriesInference_data();
    void seriesInference();
    void scanFindsExactlyTheAnsweringIds();
    void scanProbeFeedsNoTelemetryBeforeTheModel();
    void scanHonoursCancel();
    void scanBaudSweepStaysWhereDrivesAnswer();
    void scanRejectsBadRange();
    void scanReprobesACorruptReply();
    void scanFastLinkProbesEachIdOnce();
    void scanSlowLinkIsCompleteWithSecondPass();
    void estimateIsWhatTheScanTakes_data();
    void estimateIsWhatTheScanTakes();
    void sweepCountsEachDriveOnce();
    void driveCount_data();
    void driveCount();
    void pollingSkipsUnsupportedAndBatches();
    void pollingContinuesPastSilentCommands();
    void pollingHonoursRateAndStops();
};

void tst_ScanPoll::seriesInference_data()
{
    QTest::addColumn<QString>("driver");
    QTest::addColumn<QString>("motor");
    QTest::addColumn<QString>("series");
    QTest::newRow("motor name") << ""
                                << "MG6010E-i10"
                                << "MG";
    QTest::newRow("driver name when motor is blank") << "MS4015"
                                                     << ""
                                                     << "MS";
    QTest::newRow("motor wins") << "MF4015"
                                << "MH7015"
                                << "MH";
    QTest::newRow("lower case") << ""
                                << "mf4010v2"
                                << "MF";
    QTest::newRow("unknown") << "DRV-1"
                             << "X"
                             << "";
}

void tst_ScanPoll::seriesInference()
{
    QFETCH(QString, driver);
    QFETCH(QString, motor);
    QFETCH(QString, series);
    protocol::ModelInfo m;
    m.driverName = driver;
    m.motorName = motor;
    const auto s = MotorRegistry::seriesOf(m); // what the scan records for a found drive
    QCOMPARE(s ? protocol::seriesName(*s) : QString(), series);
}

void tst_ScanPoll::scanProbeFeedsNoTelemetryBeforeTheModel()
{
    // A scan probes with read_state1 before read_model has told the drive's generation: a
    // V2.35 drive's 24 V decoded with the V2.3 layout read 0.90 V on the dashboard until the
    // first poll. The scan's own result re-reads the probe once the model is known
    // (FoundMotor::state1); the probe feeds no telemetry.
    WorkerRig rig(addDrives, scanConfig(), 115200, RigTime::Manual);
    QSignalSpy batches(rig.worker.get(), &BusWorker::telemetryReceived);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    rig.worker->scan(ScanOptions{});
    QVERIFY(rig.runUntil([&] { return finished.size() == 1; }, 60000));
    const double endMs = rig.nowMs();
    rig.runUntil([&] { return rig.nowMs() > endMs + 100; }, 200); // any batch still held
    QCOMPARE(finished.at(0).at(0).value<ScanSummary>().motors.size(), 3);
    for (int id : {3, 17, 32})
        QCOMPARE(samplesIn(batches, id, TelemetryField::Voltage), 0);
}

void tst_ScanPoll::scanFindsExactlyTheAnsweringIds()
{
    WorkerRig rig(addDrives, scanConfig(), 115200, RigTime::Manual);
    rig.worker->setSeries(5, Series::MF); // known before, silent now: forgotten by the scan
    QSignalSpy found(rig.worker.get(), &BusWorker::motorFound);
    QSignalSpy progress(rig.worker.get(), &BusWorker::scanProgress);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    ScanOptions o;
    o.retries = 1; // a loaded machine may delay a reply past the margin once
    rig.worker->scan(o);
    rig.runUntil([&] { return finished.size() == 1; }, 60000);
    QCOMPARE(finished.size(), 1);
    const auto summary = finished.at(0).at(0).value<ScanSummary>();
    QVERIFY(!summary.cancelled);
    QVERIFY(summary.error.isEmpty());
    QCOMPARE(summary.motors.size(), 3);
    QMap<int, Series> expected{{3, Series::MF}, {17, Series::MS}, {32, Series::MG}};
    for (const FoundMotor &m : summary.motors) {
        QVERIFY(expected.contains(m.id));
        QCOMPARE(m.series, std::optional<Series>(expected.value(m.id)));
        QVERIFY(m.state1);
        QCOMPARE(m.state1->voltageRaw, quint16(240));
        QCOMPARE(m.baud, 115200);
    }
    QCOMPARE(found.size(), 3);
    QCOMPARE(progress.last().at(0).value<ScanProgress>().done, 32);
    QCOMPARE(progress.last().at(0).value<ScanProgress>().total, 32);
    QCOMPARE(rig.worker->knownMotors().keys(), (QList<int>{3, 17, 32}));
    QCOMPARE(rig.worker->seriesOf(17), std::optional<Series>(Series::MS));
    // Every ID was probed with read_state1; only the answering ones were asked their model.
    QSet<int> asked;
    QSet<int> models;
    for (const auto &w : rig.writtenRequests()) {
        if (w.first == Command::ReadState1)
            asked.insert(w.second);
        if (w.first == Command::ReadModel)
            models.insert(w.second);
    }
    QCOMPARE(asked.size(), 32);
    QCOMPARE(models, (QSet<int>{3, 17, 32}));
}

void tst_ScanPoll::scanHonoursCancel()
{
    WorkerRig rig(addDrives, scanConfig(), 115200, RigTime::Manual);
    QSignalSpy progress(rig.worker.get(), &BusWorker::scanProgress);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    ScanOptions o;
    o.retries = 1; // a loaded machine may delay a reply past the margin once
    rig.worker->scan(o);
    QVERIFY(rig.runUntil([&] { return progress.size() >= 2; }, 20000));
    rig.worker->cancelScan();
    rig.runUntil([&] { return finished.size() == 1; }, 20000);
    QCOMPARE(finished.size(), 1);
    const auto summary = finished.at(0).at(0).value<ScanSummary>();
    QVERIFY(summary.cancelled);
    QVERIFY(progress.last().at(0).value<ScanProgress>().done < 32);
    const int writes = rig.log->writtenCopy().size();
    rig.timers->advance(300);
    QCOMPARE(rig.log->writtenCopy().size(), writes); // nothing more goes out
    QVERIFY(!rig.worker->isScanning());
}

void tst_ScanPoll::scanBaudSweepStaysWhereDrivesAnswer()
{
    // The drive is set to 38400 baud: at any other baud it hears only noise and stays silent.
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(2, Series::MF);
            FakeTransport *tp = &t;
            t.setResponder([tp](const protocol::Frame &req, int) {
                return tp->baud() == 38400 ? tp->defaultReply(req) : QByteArray();
            });
        },
        scanConfig(), 115200, RigTime::Manual);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    ScanOptions o;
    o.firstId = 1;
    o.lastId = 4;
    o.sweepBauds = true;
    o.bauds = {9600, 38400, 115200};
    o.retries = 1;
    rig.worker->scan(o);
    rig.runUntil([&] { return finished.size() == 1; }, 60000);
    QCOMPARE(finished.size(), 1);
    const auto summary = finished.at(0).at(0).value<ScanSummary>();
    QVERIFY2(summary.error.isEmpty(), qPrintable(summary.error));
    QCOMPARE(summary.motors.size(), 1);
    QCOMPARE(summary.motors.at(0).id, 2);
    QCOMPARE(summary.motors.at(0).baud, 38400);
    QCOMPARE(summary.finalBaud, 38400);
    QCOMPARE(rig.worker->baud(), 38400);
    QVERIFY(rig.worker->isOpen());
    QMutexLocker lock(&rig.log->mutex);
    QVERIFY(rig.log->bauds.contains(9600));
    QVERIFY(rig.log->bauds.contains(115200));
    QCOMPARE(rig.log->bauds.last(), 38400);
}

void tst_ScanPoll::scanRejectsBadRange()
{
    WorkerRig rig(addDrives, scanConfig(), 115200, RigTime::Manual);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    ScanOptions o;
    o.firstId = 0;
    rig.worker->scan(o);
    QCOMPARE(finished.size(), 1);
    QVERIFY(!finished.at(0).at(0).value<ScanSummary>().error.isEmpty());
    QVERIFY(rig.log->writtenCopy().isEmpty());
}

void tst_ScanPoll::scanReprobesACorruptReply()
{
    // A noisy line spoils the first read_model reply: the drive is there and must be found.
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(2, Series::MH);
            FakeTransport *tp = &t;
            auto spoiled = std::make_shared<bool>(false);
            t.setResponder([tp, spoiled](const protocol::Frame &req, int) {
                QByteArray reply = tp->defaultReply(req);
                if (!reply.isEmpty() && !*spoiled) {
                    *spoiled = true;
                    reply[reply.size() - 1] = char(reply.at(reply.size() - 1) ^ 0x01);
                }
                return reply;
            });
        },
        scanConfig(), 115200, RigTime::Manual);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    ScanOptions o;
    o.lastId = 3;
    o.retries = 0;
    rig.worker->scan(o);
    rig.runUntil([&] { return finished.size() == 1; }, 20000);
    QCOMPARE(finished.size(), 1);
    const auto summary = finished.at(0).at(0).value<ScanSummary>();
    QCOMPARE(summary.motors.size(), 1);
    QCOMPARE(summary.motors.at(0).id, 2);
    QCOMPARE(summary.motors.at(0).series, std::optional<Series>(Series::MH));
    QCOMPARE(rig.worker->statisticsSnapshot().bus.checksumErrors, quint64(1));
}

void tst_ScanPoll::scanFastLinkProbesEachIdOnce()
{
    WorkerRig rig(addDrives, scanConfig(), 115200, RigTime::Manual);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    rig.worker->scan(ScanOptions{});
    rig.runUntil([&] { return finished.size() == 1; }, 60000);
    QCOMPARE(finished.size(), 1);
    int probes = 0;
    for (const auto &w : rig.writtenRequests())
        probes += w.first == Command::ReadState1 ? 1 : 0;
    QList<int> ids;
    for (const FoundMotor &m : finished.at(0).at(0).value<ScanSummary>().motors)
        ids << m.id;
    QCOMPARE(ids, (QList<int>{3, 17, 32}));
    // No late reply, no second pass: one probe per ID. (A reply delayed past the timeout by
    // a loaded machine is a late reply, and then the second pass is right to run.)
    if (rig.worker->lateReplyCount() > 0)
        QSKIP("a reply came late (loaded machine): the second pass ran, as it should");
    QCOMPARE(probes, 32);
}

void tst_ScanPoll::scanSlowLinkIsCompleteWithSecondPass()
{
    // An adapter that delivers every reply 40 ms late: the first pass's short timeouts miss
    // them all, the late replies teach the margin, the second pass finds every drive.
    BusConfig c = relaxedConfig();
    c.minMarginMs = 5;
    c.initialMarginMs = 20;
    WorkerRig rig(
        [](FakeTransport &t) {
            addDrives(t);
            t.setReplyDelayMs(40);
        },
        c, 115200, RigTime::Manual);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    rig.worker->scan(ScanOptions{});
    rig.runUntil([&] { return finished.size() == 1; }, 120000);
    QCOMPARE(finished.size(), 1);
    const auto summary = finished.at(0).at(0).value<ScanSummary>();
    QVERIFY2(summary.error.isEmpty(), qPrintable(summary.error));
    QSet<int> found;
    for (const FoundMotor &m : summary.motors)
        found.insert(m.id);
    QCOMPARE(found, (QSet<int>{3, 17, 32}));
    QVERIFY(rig.worker->lateReplyCount() > 0);
    QVERIFY(rig.worker->currentMarginMs() > 30);
    QCOMPARE(rig.worker->knownMotors().keys(), (QList<int>{3, 17, 32}));
}

// The estimate models pass 1 as the scanner runs it: on a bus where every ID is silent (the
// estimate's case) the scan takes what it said, on the clock the test advances. (The old
// formula added a quiet period of BusConfig::initialMarginMs per ID that a probe does not
// wait: 9.0 s for a 3.4 s baud sweep.)
void tst_ScanPoll::estimateIsWhatTheScanTakes_data()
{
    QTest::addColumn<int>("baud");
    QTest::addColumn<int>("firstId");
    QTest::addColumn<int>("lastId");
    QTest::addColumn<QVector<int>>("sweep"); // empty: no sweep
    QTest::newRow("1..32 at 9600") << 9600 << 1 << 32 << QVector<int>{};
    QTest::newRow("1..32 at 115200") << 115200 << 1 << 32 << QVector<int>{};
    QTest::newRow("1..32 at 1000000") << 1000000 << 1 << 32 << QVector<int>{};
    QTest::newRow("5..12 at 57600") << 57600 << 5 << 12 << QVector<int>{};
    QTest::newRow("1..32 at 4000000") << 4000000 << 1 << 32 << QVector<int>{};
    QTest::newRow("sweep 1..8, three bauds")
        << 115200 << 1 << 8 << QVector<int>{9600, 115200, 1000000};
    QTest::newRow("sweep 1..32, every baud") << 115200 << 1 << 32 << QVector<int>{0};
}

void tst_ScanPoll::estimateIsWhatTheScanTakes()
{
    QFETCH(int, baud);
    QFETCH(int, firstId);
    QFETCH(int, lastId);
    QFETCH(QVector<int>, sweep);
    const BusConfig config; // the defaults lkstudio runs with
    WorkerRig rig({}, config, baud, RigTime::Manual);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    ScanOptions o;
    o.firstId = firstId;
    o.lastId = lastId;
    o.sweepBauds = !sweep.isEmpty();
    if (sweep != QVector<int>{0})
        o.bauds = sweep;
    rig.worker->scan(o);
    QVERIFY(rig.runUntil([&] { return finished.size() == 1; }, 120000));
    const auto summary = finished.at(0).at(0).value<ScanSummary>();
    QVERIFY2(summary.error.isEmpty(), qPrintable(summary.error));
    const double estimate = Scanner::estimatedSeconds(o, baud, config);
    QVERIFY2(
        std::abs(estimate - summary.elapsedS) <= 0.02 * summary.elapsedS,
        qPrintable(QStringLiteral("estimate %1 s, scan %2 s").arg(estimate).arg(summary.elapsedS)));
}

// A drive that answers at every baud of a sweep (as lkstudio's built-in bus does) is one
// drive, in the progress and in the count the summary gives.
void tst_ScanPoll::sweepCountsEachDriveOnce()
{
    WorkerRig rig(addDrives, scanConfig(), 115200, RigTime::Manual);
    QSignalSpy progress(rig.worker.get(), &BusWorker::scanProgress);
    QSignalSpy finished(rig.worker.get(), &BusWorker::scanFinished);
    ScanOptions o;
    o.sweepBauds = true;
    o.bauds = {9600, 115200, 1000000};
    o.retries = 1;
    rig.worker->scan(o);
    QVERIFY(rig.runUntil([&] { return finished.size() == 1; }, 120000));
    const auto summary = finished.at(0).at(0).value<ScanSummary>();
    QCOMPARE(summary.motors.size(), 9); // three drives heard at three bauds
    QCOMPARE(Scanner::driveCount(summary.motors), 3);
    QCOMPARE(progress.last().at(0).value<ScanProgress>().found, 3);
    int most = 0;
    for (const auto &args : progress)
        most = std::max(most, args.at(0).value<ScanProgress>().found);
    QCOMPARE(most, 3);
}

void tst_ScanPoll::driveCount_data()
{
    QTest::addColumn<QVector<FoundMotor>>("motors");
    QTest::addColumn<int>("drives");
    auto hit = [](int id, int baud, const char *motor) {
        FoundMotor m;
        m.id = id;
        m.baud = baud;
        m.modelKnown = motor != nullptr;
        if (motor)
            m.model.motorName = QString::fromLatin1(motor);
        return m;
    };
    QTest::newRow("none") << QVector<FoundMotor>{} << 0;
    QTest::newRow("one baud") << QVector<FoundMotor>{hit(1, 9600, "MF4015"), hit(2, 9600, "MG6010")}
                              << 2;
    QTest::newRow("same drive, two bauds")
        << QVector<FoundMotor>{hit(1, 9600, "MF4015"), hit(1, 115200, "MF4015")} << 1;
    QTest::newRow("model unread at one baud")
        << QVector<FoundMotor>{hit(1, 9600, nullptr), hit(1, 115200, "MF4015")} << 1;
    QTest::newRow("two drives sharing an ID at two bauds")
        << QVector<FoundMotor>{hit(1, 9600, "MF4015"), hit(1, 115200, "MH7015")} << 2;
}

void tst_ScanPoll::driveCount()
{
    QFETCH(QVector<FoundMotor>, motors);
    QFETCH(int, drives);
    QCOMPARE(Scanner::driveCount(motors), drives);
}

void tst_ScanPoll::pollingSkipsUnsupportedAndBatches()
{
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            t.drives().add(2, Series::MS);
            // Every reply takes time, as on a wire: the clock only moves on timers, and
            // replies in no time would poll without end between two of them.
            t.setReplyDelayMs(2);
        },
        relaxedConfig(), 115200, RigTime::Manual);
    rig.worker->setSeries(1, Series::MF);
    rig.worker->setSeries(2, Series::MS);
    QSignalSpy batches(rig.worker.get(), &BusWorker::telemetryReceived);
    const double startMs = rig.nowMs();
    rig.worker->startPolling(PollPlan::standard({1, 2}));
    QVERIFY(rig.runUntil([&] { return samplesIn(batches, 2, TelemetryField::MultiTurn) >= 20; },
                         30000));
    rig.worker->stopPolling();
    const double elapsed = (rig.nowMs() - startMs) * 1e-3;

    QVERIFY(samplesIn(batches, 1, TelemetryField::IqA) > 0);
    QVERIFY(samplesIn(batches, 1, TelemetryField::PhaseCurrents) > 0);
    QVERIFY(samplesIn(batches, 2, TelemetryField::Power) > 0);
    QCOMPARE(samplesIn(batches, 2, TelemetryField::IqA), 0);
    QCOMPARE(samplesIn(batches, 2, TelemetryField::PhaseCurrents), 0);
    for (const auto &w : rig.writtenRequests())
        QVERIFY(!(w.first == Command::ReadState3 && w.second == 2)); // skipped on MS
    QCOMPARE(rig.worker->statisticsSnapshot().bus.timeouts, quint64(0));
    // At most ~60 batches a second, however fast the samples come.
    QVERIFY2(batches.size() <= elapsed * 60 * 1.5 + 2,
             qPrintable(QStringLiteral("%1 batches in %2 s").arg(batches.size()).arg(elapsed)));
    double last = -1;
    for (const auto &args : batches) {
        for (const TelemetrySample &s : args.at(0).value<TelemetryBatch>()) {
            QVERIFY(s.time >= last); // host timestamps, monotonic
            last = s.time;
        }
    }
}

void tst_ScanPoll::pollingContinuesPastSilentCommands()
{
    // Series not declared: read_state3 is polled, the MS drive stays silent, polling goes on.
    WorkerRig rig([](FakeTransport &t) { t.drives().add(5, Series::MS); }, relaxedConfig(), 115200,
                  RigTime::Manual);
    QSignalSpy batches(rig.worker.get(), &BusWorker::telemetryReceived);
    PollPlan p = PollPlan::standard({5});
    p.commands = {Command::ReadState3, Command::ReadState2};
    rig.worker->startPolling(p);
    QVERIFY(rig.runUntil([&] { return samplesIn(batches, 5, TelemetryField::Speed) >= 3; }, 30000));
    QVERIFY(rig.worker->statisticsSnapshot().perId.value(5).timeouts >= 2);
}

void tst_ScanPoll::pollingHonoursRateAndStops()
{
    WorkerRig rig([](FakeTransport &t) { t.drives().add(1, Series::MF); }, relaxedConfig(), 115200,
                  RigTime::Manual);
    QSignalSpy polling(rig.worker.get(), &BusWorker::pollingChanged);
    const double startMs = rig.nowMs();
    PollPlan p = PollPlan::standard({1}, 20);
    p.commands = {Command::ReadState2};
    rig.worker->startPolling(p);
    QVERIFY(rig.runUntil([&] { return rig.log->writtenCopy().size() >= 5; }, 20000));
    rig.timers->advance(200);
    const double elapsed = (rig.nowMs() - startMs) * 1e-3;
    const int polls = rig.log->writtenCopy().size();
    QVERIFY2(polls <= elapsed * 20 + 2,
             qPrintable(QStringLiteral("%1 polls in %2 s").arg(polls).arg(elapsed)));
    rig.worker->stopPolling();
    QCOMPARE(polling.last().at(0).toBool(), false);
    rig.timers->advance(100); // a poll already on the wire may still complete
    const int after = rig.log->writtenCopy().size();
    rig.timers->advance(300);
    QCOMPARE(rig.log->writtenCopy().size(), after);
}

QTEST_GUILESS_MAIN(tst_ScanPoll)
#include "tst_scanpoll.moc"
