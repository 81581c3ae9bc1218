// A listen-only session transmits nothing, ever: every entry point of the bus engine that
// would send (a request, an emergency stop, a scan, a poll plan and its extras, a setpoint
// stream, the speed watch's stop) completes refused with a typed reason, and 0 bytes reach the
// transport (counted at the FakeTransport, which logs every write whatever its mode). The
// transport is opened read-only. Taking the bus over reopens it read-write, and then the same
// calls work as in a session opened active. Bus time is a clock the test advances.

#include "BusTestUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/BusSession.h>
#include <bus/PollPlan.h>
#include <bus/SetpointStreamPlan.h>
#include <bus/TransportLink.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <functional>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

namespace {

constexpr double kRunMs = 3000; ///< long enough for any poll, retry or stop to have gone out

void addDrives(FakeTransport &t)
{
    t.drives().add(1, Series::MF);
    t.drives().add(2, Series::MS);
}

std::unique_ptr<WorkerRig> listeningRig()
{
    return std::make_unique<WorkerRig>(addDrives, relaxedConfig(), 115200, RigTime::Manual,
                                       LinkMode::ListenOnly);
}

protocol::Request speedRequest(int id, double dps)
{
    protocol::Request r = plainRequest(Command::Speed, id);
    r.payload = protocol::SpeedCommand{qint32(dps * 100)};
    return r;
}

SetpointStreamPlan sineOn(int id)
{
    SetpointStreamPlan plan;
    plan.stream = 7;
    plan.id = id;
    plan.series = Series::MF;
    plan.settings.waveform = SetpointWaveform::Waveform::Sine;
    plan.settings.target = SetpointWaveform::Target::Speed;
    plan.settings.amplitude = 10;
    plan.settings.periodS = 1;
    plan.settings.rateHz = 50;
    plan.limits.maxSpeedDps = 100;
    return plan;
}

/// What an entry point does to the worker, and how the test sees that it was refused.
using Action = std::function<void(WorkerRig &)>;
using Refused = std::function<bool(WorkerRig &)>;

bool resultRefused(const WorkerRig &rig)
{
    return !rig.results.isEmpty() && rig.results.last().refused() &&
           rig.results.last().refusal == SendRefusal::ListenOnly &&
           rig.results.last().status == RequestStatus::Error && rig.results.last().attempts == 0 &&
           rig.results.last().reason == QStringLiteral("listen-only: nothing was sent");
}

} // namespace

Q_DECLARE_METATYPE(Action)
Q_DECLARE_METATYPE(Refused)

class tst_ListenOnly : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void everyEntryPointWritesNothing_data();
    void everyEntryPointWritesNothing();
    void emergencyStopSaysNothingWasSent();
    void setpointStreamRefusedTyped();
    void takeOverThenWorksAsToday();
    void linkDropsWritesWhileListening();
    void sessionListensThenTakesOver();
};

void tst_ListenOnly::everyEntryPointWritesNothing_data()
{
    QTest::addColumn<Action>("action");
    QTest::addColumn<Refused>("refused");
    const Refused byResult = [](WorkerRig &rig) { return resultRefused(rig); };
    const Refused byCount = [](WorkerRig &rig) { return rig.worker->refusedCalls() > 0; };

    QTest::newRow("read request") << Action([](WorkerRig &rig) {
        rig.send(plainRequest(Command::ReadState2, 1));
    }) << byResult;
    QTest::newRow("motion request")
        << Action([](WorkerRig &rig) { rig.send(speedRequest(1, 30)); }) << byResult;
    QTest::newRow("emergency-lane motor_off") << Action([](WorkerRig &rig) {
        rig.send(plainRequest(Command::MotorOff, 1), Priority::Emergency);
    }) << byResult;
    QTest::newRow("flash write") << Action([](WorkerRig &rig) {
        rig.send(plainRequest(Command::WriteZeroRom, 1));
    }) << byResult;
    QTest::newRow("emergency stop motor_off") << Action([](WorkerRig &rig) {
        rig.worker->emergencyStop(1, {1, 2});
    }) << byCount;
    QTest::newRow("emergency stop motor_stop")
        << Action([](WorkerRig &rig) { rig.worker->emergencyStop(1, {}, Command::MotorStop); })
        << byCount;
    QTest::newRow("scan") << Action([](WorkerRig &rig) { rig.worker->scan(ScanOptions{}); })
                          << byCount;
    QTest::newRow("scan with baud sweep") << Action([](WorkerRig &rig) {
        ScanOptions o;
        o.sweepBauds = true;
        rig.worker->scan(o);
    }) << byCount;
    QTest::newRow("poll plan") << Action([](WorkerRig &rig) {
        PollPlan plan;
        plan.ids = {1, 2};
        rig.worker->startPolling(plan);
    }) << byCount;
    QTest::newRow("poll extras alone") << Action([](WorkerRig &rig) {
        PollPlan plan;
        plan.commands.clear();
        plan.extraCommands[1] = {Command::ReadEncoder};
        rig.worker->startPolling(plan);
    }) << byCount;
    QTest::newRow("setpoint stream")
        << Action([](WorkerRig &rig) { rig.worker->startSetpointStream(sineOn(1)); }) << byCount;
    QTest::newRow("torque (the speed watch's kind)") << Action([](WorkerRig &rig) {
        protocol::Request torque = plainRequest(Command::Torque, 1);
        torque.payload = protocol::TorqueCommand{100};
        rig.send(torque);
    }) << byResult;
}

void tst_ListenOnly::everyEntryPointWritesNothing()
{
    QFETCH(Action, action);
    QFETCH(Refused, refused);
    auto rig = listeningRig();
    QVERIFY(rig->worker->isOpen());
    QCOMPARE(rig->worker->linkMode(), LinkMode::ListenOnly);
    action(*rig);
    rig->runUntil([] { return false; }, kRunMs);
    QCOMPARE(rig->log->writtenCopy().size(), 0); // counted at the transport
    QVERIFY(refused(*rig));
    QCOMPARE(rig->worker->refusedBytes(), quint64(0)); // nothing even reached the link
    QCOMPARE(rig->transport->refusedWrites(), quint64(0));
    QCOMPARE(rig->log->readOnly, QVector<bool>{true});
    QVERIFY(rig->worker->refusedCalls() >= 1);
    QCOMPARE(rig->worker->statisticsSnapshot().listenOnlyRefusals, rig->worker->refusedCalls());
}

void tst_ListenOnly::emergencyStopSaysNothingWasSent()
{
    auto rig = listeningRig();
    QSignalSpy refused(rig->worker.get(), &BusWorker::emergencyStopRefused);
    QSignalSpy finished(rig->worker.get(), &BusWorker::emergencyStopFinished);
    rig->worker->emergencyStop(42, {3});
    QCOMPARE(refused.size(), 1);
    QCOMPARE(refused.at(0).at(0).toULongLong(), quint64(42));
    QCOMPARE(refused.at(0).at(1).value<SendRefusal>(), SendRefusal::ListenOnly);
    QCOMPARE(finished.size(), 1);
    QVERIFY(finished.at(0).at(1).value<QVector<int>>().isEmpty()); // nobody acknowledged
    const QVector<int> silent = finished.at(0).at(2).value<QVector<int>>();
    QCOMPARE(silent.size(), 32); // every ID it would have reached ...
    QCOMPARE(silent.first(), 3); // ... the caller's first
    QCOMPARE(finished.at(0).at(3).value<QVector<int>>(), silent); // and none of them was sent
    rig->runUntil([] { return false; }, kRunMs);
    QCOMPARE(rig->log->writtenCopy().size(), 0);
    QVERIFY(rig->results.isEmpty()); // no 32 refused motor_offs filling a log
}

void tst_ListenOnly::setpointStreamRefusedTyped()
{
    auto rig = listeningRig();
    QSignalSpy started(rig->worker.get(), &BusWorker::setpointStreamStarted);
    QSignalSpy stopped(rig->worker.get(), &BusWorker::setpointStreamStopped);
    rig->worker->startSetpointStream(sineOn(1));
    QCOMPARE(started.size(), 0);
    QCOMPARE(stopped.size(), 1);
    const SetpointStop stop = stopped.at(0).at(0).value<SetpointStop>();
    QCOMPARE(stop.stream, quint64(7));
    QCOMPARE(stop.reason, SetpointStopReason::Refused);
    QCOMPARE(stop.refusal, SendRefusal::ListenOnly);
    QCOMPARE(stop.emitted, qint64(0));
}

void tst_ListenOnly::takeOverThenWorksAsToday()
{
    auto rig = listeningRig();
    QSignalSpy status(rig->worker.get(), &BusWorker::connectionChanged);
    rig->send(plainRequest(Command::ReadState2, 1));
    QVERIFY(resultRefused(*rig));

    QVERIFY(rig->worker->takeOver());
    QCOMPARE(rig->worker->linkMode(), LinkMode::Active);
    QCOMPARE(rig->log->readOnly, (QVector<bool>{true, false})); // reopened read-write
    QVERIFY(!status.isEmpty());
    const ConnectionStatus s = status.last().at(0).value<ConnectionStatus>();
    QCOMPARE(s.mode, LinkMode::Active);
    QVERIFY(s.canTransmit);

    const quint64 read = rig->send(plainRequest(Command::ReadState2, 1));
    QVERIFY(rig->runUntil([&] { return rig->result(read) != nullptr; }));
    QVERIFY(rig->result(read)->ok());
    QCOMPARE(rig->writtenRequests().size(), 1);

    QSignalSpy finished(rig->worker.get(), &BusWorker::emergencyStopFinished);
    rig->worker->emergencyStop(2, {1});
    QVERIFY(rig->runUntil([&] { return !finished.isEmpty(); }));
    QVERIFY(finished.at(0).at(1).value<QVector<int>>().contains(1)); // acknowledged
    QVERIFY(rig->writtenRequests().contains(qMakePair(Command::MotorOff, 1)));
    QCOMPARE(rig->worker->refusedCalls(), quint64(1)); // only the one before the take-over
}

void tst_ListenOnly::linkDropsWritesWhileListening()
{
    auto log = std::make_shared<FakeLog>();
    TransportLink link([log](int baud) { return std::make_unique<FakeTransport>(baud, log); },
                       115200);
    QSignalSpy status(&link, &TransportLink::connectionChanged);
    link.setMode(LinkMode::ListenOnly);
    QVERIFY(link.start());
    link.report();
    QCOMPARE(status.last().at(0).value<ConnectionStatus>().mode, LinkMode::ListenOnly);
    QVERIFY(!status.last().at(0).value<ConnectionStatus>().canTransmit);
    const QByteArray frame = protocol::encodeFrame(0x9C, 1, {});
    link.write(frame);
    QCOMPARE(log->writtenCopy().size(), 0);
    QCOMPARE(link.refusedBytes(), quint64(frame.size()));
    QCOMPARE(log->readOnly, QVector<bool>{true});
}

void tst_ListenOnly::sessionListensThenTakesOver()
{
    auto log = std::make_shared<FakeLog>();
    BusSession session;
    QSignalSpy status(&session, &BusSession::connectionChanged);
    QSignalSpy stopRefused(&session, &BusSession::emergencyStopRefused);
    session.open(
        [log](int baud) {
            auto t = std::make_unique<FakeTransport>(baud, log);
            addDrives(*t);
            return t;
        },
        115200, relaxedConfig(), LinkMode::ListenOnly);
    QTRY_VERIFY(session.connection().isOpen());
    QCOMPARE(session.connection().mode, LinkMode::ListenOnly);
    QVERIFY(!session.connection().canTransmit);
    QCOMPARE(session.linkMode(), LinkMode::ListenOnly);

    PollPlan plan;
    plan.ids = {1};
    plan.commands = {Command::ReadState2};
    session.startPolling(plan);
    std::optional<RequestResult> sent;
    session.send(plainRequest(Command::ReadState2, 1), this,
                 [&sent](const RequestResult &r) { sent = r; });
    bool stopDone = false;
    QVector<int> unsent;
    session.emergencyStop({1}, Command::MotorOff, this,
                          [&](const QVector<int> &, const QVector<int> &, const QVector<int> &u) {
                              stopDone = true;
                              unsent = u;
                          });
    QTRY_VERIFY(sent.has_value() && stopDone);
    QCOMPARE(sent->refusal, SendRefusal::ListenOnly);
    QCOMPARE(stopRefused.size(), 1);
    QCOMPARE(unsent.size(), 32);
    QCOMPARE(log->writtenCopy().size(), 0);

    session.takeOver();
    QTRY_VERIFY(session.connection().canTransmit);
    QCOMPARE(session.connection().mode, LinkMode::Active);
    // The plan given while listening starts now: polls go out.
    QTRY_VERIFY(log->writtenCopy().size() >= 3);
    session.close();
}

QTEST_GUILESS_MAIN(tst_ListenOnly)
#include "tst_listenonly.moc"
