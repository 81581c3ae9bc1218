// The speed watch of drives under torque or open-loop commands (SpeedWatch): which commands
// put a drive under watch and which end it, the threshold (limit + 5 %, at least 30 dps), one
// Motor Stop per trip, and what the trip reports. Then the same watch inside a BusWorker on a
// clock the test advances: the watched drive is read as often as the bus allows (with no poll
// plan at all, and besides a dashboard's plan), and the Motor Stop goes out the moment a reply
// shows the speed past the limit.

#include "BusTestUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/PollPlan.h>
#include <bus/SpeedWatch.h>
#include <protocol/Reply.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

namespace {

protocol::Request torque(int id, qint16 raw)
{
    protocol::Request r = plainRequest(Command::Torque, id);
    r.payload = protocol::TorqueCommand{raw};
    return r;
}

protocol::Request openLoop(int id, qint16 power)
{
    protocol::Request r = plainRequest(Command::OpenLoop, id);
    r.payload = protocol::OpenLoopCommand{power};
    return r;
}

protocol::Request speed(int id, double dps)
{
    protocol::Request r = plainRequest(Command::Speed, id);
    r.payload = protocol::SpeedCommand{qint32(std::lround(dps * 100))};
    return r;
}

TelemetrySample speedSample(int id, double dps, double time = 1.0)
{
    TelemetrySample s;
    s.id = id;
    s.time = time;
    s.fields = TelemetryField::Speed;
    s.speedDps = dps;
    return s;
}

/// A SpeedWatch with a stop sender that records the stops and ends them when told.
struct WatchRig {
    QVector<int> stops;
    QVector<std::function<void(const RequestResult &)>> pending;
    double clockS = 2.0;
    SpeedWatch watch{[this](int id, std::function<void(const RequestResult &)> done) {
                         stops.append(id);
                         pending.append(std::move(done));
                     },
                     [](int) { return std::optional<Series>(Series::MF); },
                     [this] { return clockS; }};

    /// The stop sent last ends with `status`, as BusWorker would: the request's end first.
    void endStop(RequestStatus status)
    {
        RequestResult r;
        r.request = plainRequest(Command::MotorStop, stops.last());
        r.status = status;
        r.attempts = 1;
        r.reason = status == RequestStatus::Ok ? QString() : QStringLiteral("timeout");
        watch.noteRequestEnded(r.request, status, 1);
        pending.takeLast()(r);
    }
};

/// A drive that speeds up under torque at `accelDps2` (rotor dps/s) on the rig's clock, and
/// coasts at the speed it had once stopped; it answers every command as FakeDrives does, with
/// its speed in each state-2 reply.
struct AcceleratingDrive {
    double accelDps2 = 20000;
    std::shared_ptr<testsupport::ManualClock> clock;
    double startMs = -1; ///< when the torque command arrived; -1: still
    double frozenDps = 0;
    bool stopped = false;

    double speedDps() const
    {
        if (stopped || startMs < 0)
            return frozenDps;
        return accelDps2 * (clock->nowMs() - startMs) * 1e-3;
    }
    QByteArray answer(FakeTransport &t, const protocol::Frame &req)
    {
        const auto command = static_cast<Command>(req.command);
        if (command == Command::Torque && startMs < 0)
            startMs = clock->nowMs();
        if (command == Command::MotorStop || command == Command::MotorOff) {
            frozenDps = speedDps();
            stopped = true;
        }
        const QByteArray bytes = t.defaultReply(req);
        if (command != Command::ReadState2 && command != Command::Torque)
            return bytes;
        protocol::Reply r;
        r.command = command;
        r.id = req.id;
        r.payload = protocol::State2{
            30, 0, false, qint16(std::lround(speedDps())), 0, protocol::kIqReplyAmpsPerLsb};
        return r.encode();
    }
};

} // namespace

class tst_SpeedWatch : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void threshold_data();
    void threshold();
    void commandsArmAndEnd_data();
    void commandsArmAndEnd();
    void stopsOncePerTrip();
    void unacknowledgedStopWatchesOn();
    void heldDriveResumesOnRun();
    void limitSource();
    void workerPollsAndStopsWithoutPlan();
    void workerReadsWatchedDriveBesidePlan();
    void workerStopsTheSetpointStream();
};

void tst_SpeedWatch::threshold_data()
{
    QTest::addColumn<double>("limit");
    QTest::addColumn<double>("threshold");
    QTest::newRow("720 dps: +5 %") << 720.0 << 756.0;
    QTest::newRow("6000 dps: +5 %") << 6000.0 << 6300.0;
    QTest::newRow("600 dps: 5 % is exactly 30") << 600.0 << 630.0;
    QTest::newRow("100 dps: at least 30 dps") << 100.0 << 130.0;
    QTest::newRow("0.01 dps") << 0.01 << 30.01;
}

void tst_SpeedWatch::threshold()
{
    QFETCH(double, limit);
    QFETCH(double, threshold);
    QCOMPARE(SpeedWatch::thresholdDps(limit), threshold);
}

void tst_SpeedWatch::commandsArmAndEnd_data()
{
    QTest::addColumn<QVector<protocol::Request>>("requests");
    QTest::addColumn<QVector<int>>("statuses"); // RequestStatus, per request
    QTest::addColumn<QVector<int>>("attempts");
    QTest::addColumn<bool>("watched");
    using S = RequestStatus;
    using Requests = QVector<protocol::Request>;
    using Ints = QVector<int>;
    const auto ok = int(S::Ok);
    const auto timeout = int(S::Timeout);
    const protocol::Request off = plainRequest(Command::MotorOff, 1);
    QTest::newRow("torque acknowledged") << Requests{torque(1, 300)} << Ints{ok} << Ints{1} << true;
    QTest::newRow("torque unanswered: may have acted")
        << Requests{torque(1, 300)} << Ints{timeout} << Ints{2} << true;
    QTest::newRow("torque never sent")
        << Requests{torque(1, 300)} << Ints{int(S::Cancelled)} << Ints{0} << false;
    QTest::newRow("open loop") << Requests{openLoop(1, 150)} << Ints{ok} << Ints{1} << true;
    QTest::newRow("torque 0 ends it")
        << Requests{torque(1, 300), torque(1, 0)} << Ints{ok, ok} << Ints{1, 1} << false;
    QTest::newRow("power 0 ends it")
        << Requests{openLoop(1, 150), openLoop(1, 0)} << Ints{ok, ok} << Ints{1, 1} << false;
    QTest::newRow("torque 0 unanswered: still watched")
        << Requests{torque(1, 300), torque(1, 0)} << Ints{ok, timeout} << Ints{1, 1} << true;
    QTest::newRow("speed command: a closed loop")
        << Requests{torque(1, 300), speed(1, 90)} << Ints{ok, ok} << Ints{1, 1} << false;
    QTest::newRow("speed command unanswered: still watched")
        << Requests{torque(1, 300), speed(1, 90)} << Ints{ok, timeout} << Ints{1, 1} << true;
    QTest::newRow("motor off") << Requests{torque(1, 300), off} << Ints{ok, ok} << Ints{1, 1}
                               << false;
    QTest::newRow("motor off unanswered")
        << Requests{torque(1, 300), off} << Ints{ok, timeout} << Ints{1, 1} << true;
    QTest::newRow("motor stop holds")
        << Requests{torque(1, 300), plainRequest(Command::MotorStop, 1)} << Ints{ok, ok}
        << Ints{1, 1} << false;
    QTest::newRow("another drive's off")
        << Requests{torque(1, 300), plainRequest(Command::MotorOff, 2)} << Ints{ok, ok}
        << Ints{1, 1} << true;
    QTest::newRow("a read changes nothing")
        << Requests{torque(1, 300), plainRequest(Command::ReadState2, 1)} << Ints{ok, ok}
        << Ints{1, 1} << true;
}

void tst_SpeedWatch::commandsArmAndEnd()
{
    QFETCH(QVector<protocol::Request>, requests);
    QFETCH(QVector<int>, statuses);
    QFETCH(QVector<int>, attempts);
    QFETCH(bool, watched);
    WatchRig rig;
    QSignalSpy changed(&rig.watch, &SpeedWatch::watchedChanged);
    for (int i = 0; i < requests.size(); ++i)
        rig.watch.noteRequestEnded(requests[i], RequestStatus(statuses[i]), attempts[i]);
    QCOMPARE(rig.watch.isWatched(1), watched);
    QCOMPARE(rig.watch.watchedIds(), watched ? QVector<int>{1} : QVector<int>{});
    if (watched)
        QCOMPARE(changed.last().at(0).value<QVector<int>>(), QVector<int>{1});
    QVERIFY(rig.stops.isEmpty());
}

void tst_SpeedWatch::stopsOncePerTrip()
{
    WatchRig rig;
    rig.watch.setSoftLimits(1, [] {
        safety::SoftLimits l;
        l.maxSpeedDps = 720;
        return l;
    }());
    QSignalSpy tripped(&rig.watch, &SpeedWatch::tripped);
    rig.watch.noteSample(speedSample(1, 5000)); // not watched yet: nothing
    rig.watch.noteRequestEnded(torque(1, 300), RequestStatus::Ok, 1);
    rig.watch.noteSample(speedSample(1, 756)); // at the threshold: not past it
    rig.watch.noteSample(speedSample(1, -700));
    QVERIFY(rig.stops.isEmpty());
    rig.watch.noteSample(speedSample(1, -757.5, 1.25)); // either direction
    QCOMPARE(rig.stops, QVector<int>{1});
    rig.watch.noteSample(speedSample(1, -900, 1.5)); // the stop is on its way: not again
    QCOMPARE(rig.stops, QVector<int>{1});
    QVERIFY(rig.watch.isWatched(1)); // still read until the stop has landed
    QCOMPARE(tripped.size(), 0);

    rig.clockS = 1.262;
    rig.endStop(RequestStatus::Ok);
    QCOMPARE(tripped.size(), 1);
    const auto t = tripped.at(0).at(0).value<SpeedWatchTrip>();
    QCOMPARE(t.id, 1);
    QCOMPARE(t.mode, Command::Torque);
    QCOMPARE(t.limitDps, 720.0);
    QCOMPARE(t.thresholdDps, 756.0);
    QCOMPARE(t.source, SpeedWatchSource::SoftLimit);
    QCOMPARE(t.speedDps, -757.5);
    QVERIFY(t.stopAcknowledged());
    QCOMPARE(qRound(t.reactionMs()), 12);
    QVERIFY(!rig.watch.isWatched(1));               // held: nothing turns it
    rig.watch.noteSample(speedSample(1, 900, 1.3)); // coasting down: no second stop
    QCOMPARE(rig.stops.size(), 1);
}

void tst_SpeedWatch::unacknowledgedStopWatchesOn()
{
    WatchRig rig;
    QSignalSpy tripped(&rig.watch, &SpeedWatch::tripped);
    rig.watch.noteRequestEnded(openLoop(1, 400), RequestStatus::Ok, 1);
    rig.watch.noteSample(speedSample(1, 20000)); // MF default: 18000 dps top speed
    QCOMPARE(rig.stops.size(), 1);
    rig.endStop(RequestStatus::Timeout);
    QCOMPARE(tripped.size(), 1);
    const auto t = tripped.at(0).at(0).value<SpeedWatchTrip>();
    QVERIFY(!t.stopAcknowledged());
    QCOMPARE(t.stopReason, QStringLiteral("timeout"));
    QCOMPARE(t.mode, Command::OpenLoop);
    QVERIFY(rig.watch.isWatched(1));
    rig.watch.noteSample(speedSample(1, 20000)); // still fast: stopped again
    QCOMPARE(rig.stops.size(), 2);
}

void tst_SpeedWatch::heldDriveResumesOnRun()
{
    WatchRig rig;
    rig.watch.noteRequestEnded(torque(3, 300), RequestStatus::Ok, 1);
    rig.watch.noteRequestEnded(plainRequest(Command::MotorStop, 3), RequestStatus::Ok, 1);
    QVERIFY(!rig.watch.isWatched(3));
    rig.watch.noteRequestEnded(plainRequest(Command::MotorRun, 3), RequestStatus::Ok, 1);
    QVERIFY(rig.watch.isWatched(3)); // V2.3 resumes the torque command the stop kept
    QCOMPARE(rig.watch.modeOf(3), std::optional<Command>(Command::Torque));
    rig.watch.noteRequestEnded(plainRequest(Command::MotorOff, 3), RequestStatus::Ok, 1);
    rig.watch.noteRequestEnded(plainRequest(Command::MotorRun, 3), RequestStatus::Ok, 1);
    QVERIFY(!rig.watch.isWatched(3)); // off cleared the command: Run has nothing to resume
}

void tst_SpeedWatch::limitSource()
{
    WatchRig rig;
    SpeedWatchSource source;
    QCOMPARE(rig.watch.limitDps(2, &source), 18000.0); // MF's top speed, 3000 rpm
    QCOMPARE(source, SpeedWatchSource::SeriesDefault);
    safety::SoftLimits l;
    l.maxSpeedDps = 360;
    rig.watch.setSoftLimits(2, l);
    QCOMPARE(rig.watch.limitDps(2, &source), 360.0);
    QCOMPARE(source, SpeedWatchSource::SoftLimit);
}

void tst_SpeedWatch::workerPollsAndStopsWithoutPlan()
{
    auto drive = std::make_shared<AcceleratingDrive>();
    WorkerRig rig(
        [drive](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            t.setReplyDelayMs(2); // 2 ms per exchange, as 115200 baud gives a state-2 read
            FakeTransport *tp = &t;
            t.setResponder(
                [tp, drive](const protocol::Frame &req, int) { return drive->answer(*tp, req); });
        },
        relaxedConfig(), 115200, RigTime::Manual);
    drive->clock = rig.timers->clock();
    safety::SoftLimits limits;
    limits.maxSpeedDps = 720;
    rig.worker->setSoftLimits(1, limits);
    QSignalSpy tripped(rig.worker.get(), &BusWorker::speedWatchTripped);
    rig.send(torque(1, 19)); // 0.3 A
    QVERIFY(rig.runUntil([&] { return tripped.size() == 1; }, 2000));

    const auto t = tripped.at(0).at(0).value<SpeedWatchTrip>();
    QCOMPARE(t.id, 1);
    QCOMPARE(t.limitDps, 720.0);
    QVERIFY2(t.speedDps > 756 && t.speedDps < 756 + 20000 * 0.0041,
             qPrintable(QString::number(t.speedDps)));
    QVERIFY(t.stopAcknowledged());
    // Nothing but the watch's reads of drive 1 between the torque and the stop, and the stop
    // right after the reply that showed the speed.
    const auto frames = rig.writtenRequests();
    QCOMPARE(frames.first(), qMakePair(Command::Torque, 1));
    const int stopAt = int(frames.indexOf(qMakePair(Command::MotorStop, 1)));
    QVERIFY(stopAt > 1);
    for (int i = 1; i < stopAt; ++i)
        QCOMPARE(frames.at(i), qMakePair(Command::ReadState2, 1));
    // Each read takes 2 ms: the stop went out within one read of the speed passing 756 dps.
    QVERIFY(stopAt <= 1 + int(std::ceil(756.0 / 20000 / 0.002)) + 1);
    QCOMPARE(rig.worker->speedWatch().watchedIds(), QVector<int>{});
    // The stop's end reached requestCompleted too, for whoever follows the drive's motion.
    QVERIFY(std::any_of(rig.results.cbegin(), rig.results.cend(), [](const RequestResult &r) {
        return r.request.command == Command::MotorStop && r.ok() && r.ticket == 0;
    }));
    // Held: the watch's reads end with the trip.
    const int written = int(rig.writtenRequests().size());
    rig.runUntil([] { return false; }, 200);
    QCOMPARE(int(rig.writtenRequests().size()), written);
}

void tst_SpeedWatch::workerReadsWatchedDriveBesidePlan()
{
    auto drive = std::make_shared<AcceleratingDrive>();
    drive->accelDps2 = 1000; // slow: the test watches the polling, not the trip
    WorkerRig rig(
        [drive](FakeTransport &t) {
            for (int id : {1, 2, 3, 4})
                t.drives().add(id, Series::MF);
            t.setReplyDelayMs(2);
            FakeTransport *tp = &t;
            t.setResponder([tp, drive](const protocol::Frame &req, int) {
                return req.id == 1 ? drive->answer(*tp, req) : tp->defaultReply(req);
            });
        },
        relaxedConfig(), 115200, RigTime::Manual);
    drive->clock = rig.timers->clock();
    // A dashboard's plan of four drives at 5 rounds a second: drive 1's speed alone would be
    // read every 200 ms.
    rig.worker->startPolling(PollPlan::standard({1, 2, 3, 4}, 5));
    rig.runUntil([] { return false; }, 500);
    rig.send(torque(1, 19));
    const double start = rig.nowMs();
    rig.runUntil([] { return false; }, 200);
    const auto frames = rig.writtenRequests();
    const int from = int(frames.indexOf(qMakePair(Command::Torque, 1)));
    QVERIFY(from >= 0);
    int gap = 0, longest = 0, reads = 0;
    for (int i = from + 1; i < frames.size(); ++i) {
        if (frames.at(i) == qMakePair(Command::ReadState2, 1)) {
            ++reads;
            gap = 0;
        } else {
            longest = std::max(longest, ++gap);
        }
    }
    QVERIFY2(longest <= 1, "a plan poll at most between two reads of the watched drive");
    QVERIFY2(reads >= int((rig.nowMs() - start) / 2 / 2),
             qPrintable(QStringLiteral("%1 reads in %2 ms").arg(reads).arg(rig.nowMs() - start)));
    QCOMPARE(rig.worker->speedWatch().watchedIds(), QVector<int>{1});
    // Without the watch the plan's pace returns.
    rig.send(torque(1, 0));
    rig.runUntil([&] { return rig.worker->speedWatch().watchedIds().isEmpty(); }, 100);
    const int before = int(rig.writtenRequests().size());
    rig.runUntil([] { return false; }, 1000);
    const int polls = int(rig.writtenRequests().size()) - before;
    QVERIFY2(polls <= 5 * 4 * 4 + 4, qPrintable(QString::number(polls))); // 5 rounds x 16 reads
}

void tst_SpeedWatch::workerStopsTheSetpointStream()
{
    auto drive = std::make_shared<AcceleratingDrive>();
    WorkerRig rig(
        [drive](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            t.setReplyDelayMs(2);
            FakeTransport *tp = &t;
            t.setResponder(
                [tp, drive](const protocol::Frame &req, int) { return drive->answer(*tp, req); });
        },
        relaxedConfig(), 115200, RigTime::Manual);
    drive->clock = rig.timers->clock();
    rig.worker->setSeries(1, Series::MF);
    SetpointStreamPlan plan;
    plan.stream = 7;
    plan.id = 1;
    plan.series = Series::MF;
    plan.limits.maxSpeedDps = 720;
    plan.limits.maxTorqueA = 1;
    plan.settings.target = SetpointWaveform::Target::Torque;
    plan.settings.waveform = SetpointWaveform::Waveform::Square;
    plan.settings.amplitude = 0.05;
    plan.settings.offset = 0.3; // 0.25..0.35 A: always driving
    plan.settings.rateHz = 100;
    rig.worker->setSoftLimits(1, plan.limits);
    QSignalSpy stopped(rig.worker.get(), &BusWorker::setpointStreamStopped);
    QSignalSpy tripped(rig.worker.get(), &BusWorker::speedWatchTripped);
    rig.worker->startSetpointStream(plan);
    QVERIFY(rig.runUntil([&] { return tripped.size() == 1; }, 2000));
    QCOMPARE(stopped.size(), 1);
    QCOMPARE(stopped.at(0).at(0).value<SetpointStop>().reason, SetpointStopReason::SpeedLimit);
    // No torque setpoint after the stop.
    rig.runUntil([] { return false; }, 300);
    const auto frames = rig.writtenRequests();
    const int stopAt = int(frames.indexOf(qMakePair(Command::MotorStop, 1)));
    QVERIFY(stopAt > 0);
    for (int i = stopAt + 1; i < frames.size(); ++i)
        QVERIFY(frames.at(i).first != Command::Torque);
}

QTEST_GUILESS_MAIN(tst_SpeedWatch)
#include "tst_speedwatch.moc"
