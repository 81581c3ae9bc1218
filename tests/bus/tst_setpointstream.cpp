#include "../support/ManualTimers.h"
#include "BusTestUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/BusSession.h>
#include <bus/BusWorker.h>
#include <bus/SetpointStream.h>
#include <protocol/RequestBuilder.h>
#include <safety/MotionPlanner.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <cmath>
#include <memory>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using lk::testsupport::ManualTimers;
using protocol::Command;
using protocol::Series;
using Target = SetpointWaveform::Target;
using Waveform = SetpointWaveform::Waveform;

namespace {
constexpr int kId = 3;

/// A worker over a FakeTransport whose setpoint stream runs on timers and a clock the test
/// moves by hand.
struct StreamRig {
    explicit StreamRig(int replyDelayMs = 0, const BusConfig &config = relaxedConfig())
        : rig(
              [replyDelayMs](FakeTransport &t) {
                  t.drives().add(kId, Series::MF);
                  t.setReplyDelayMs(replyDelayMs);
              },
              config)
    {
        stream().setTiming(timers.factory(), [this] { return clockS; });
    }
    SetpointStream &stream() { return rig.worker->setpointStream(); }
    /// Moves the clock to `t` and fires the tick timer.
    bool tickAt(double t)
    {
        clockS = t;
        return timers.fire(0);
    }
    QVector<Command> written() const
    {
        QVector<Command> out;
        for (const auto &r : rig.writtenRequests())
            out.append(r.first);
        return out;
    }
    // Declared before the rig: the worker's stream holds a timer of theirs until it goes.
    ManualTimers timers;
    double clockS = 0;
    WorkerRig rig;
};

safety::SoftLimits limits()
{
    safety::SoftLimits l = safety::SoftLimits::defaults(Series::MF);
    l.maxSpeedDps = 720;
    l.maxTorqueA = 2;
    return l;
}

SetpointStreamPlan plan(Target target, double offset, double amplitude, Waveform w = Waveform::Sine)
{
    SetpointStreamPlan p;
    p.stream = 7;
    p.id = kId;
    p.settings.waveform = w;
    p.settings.target = target;
    p.settings.offset = offset;
    p.settings.amplitude = amplitude;
    p.settings.periodS = 2;
    p.settings.rateHz = 20;
    p.series = Series::MF;
    p.limits = limits();
    p.position.angleDeg = 100;
    return p;
}

/// The frame the GUI's motion gate would send for `value`: the builder, then MotionPlanner.
QByteArray gateFrame(const SetpointStreamPlan &p, double value)
{
    const protocol::BuildResult built = SetpointStream::build(p, value, protocol::Generation::V2_3);
    const safety::MotionPlan planned =
        safety::MotionPlanner::plan(*built.request, p.series, p.limits, p.position);
    return planned.request->encode();
}
} // namespace

/// The setpoint stream on the bus thread: paced by its timer, every setpoint through the
/// motion limits, at most one on its way, and stopped first by an emergency stop.
class tst_SetpointStream : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void ticksSendTheGatesRequests_data();
    void ticksSendTheGatesRequests();
    void positionSetpointsAreNeverRetried();
    void refusedValueStopsWithTheVerdict_data();
    void refusedValueStopsWithTheVerdict();
    void skipsWhileThePreviousIsPending();
    void stopDropsTheQueuedSetpoint();
    void stopKeepsTheSetpointOnTheWireFromRetrying_data();
    void stopKeepsTheSetpointOnTheWireFromRetrying();
    void emergencyStopStopsTheStreamBeforeMotorOff();
    void busEventsStopTheStream_data();
    void busEventsStopTheStream();
    void closedBusStopsAtOnce();
    void sessionRunsAndRelaysTheStream();
};

void tst_SetpointStream::ticksSendTheGatesRequests_data()
{
    QTest::addColumn<int>("target");
    QTest::addColumn<double>("offset");
    QTest::addColumn<int>("command");
    QTest::newRow("speed") << int(Target::Speed) << 0.0 << int(Command::Speed);
    // A multi-turn target goes out in its limited form, capped at the speed limit.
    QTest::newRow("position") << int(Target::Position) << 100.0
                              << int(Command::MultiPositionLimited);
    QTest::newRow("torque") << int(Target::Torque) << 0.0 << int(Command::Torque);
}

void tst_SetpointStream::ticksSendTheGatesRequests()
{
    QFETCH(int, target);
    QFETCH(double, offset);
    QFETCH(int, command);
    StreamRig r;
    const SetpointStreamPlan p = plan(Target(target), offset, 1);
    QSignalSpy started(&r.stream(), &SetpointStream::started);
    r.stream().start(p);
    QCOMPARE(started.size(), 1);
    QCOMPARE(started.at(0).at(0).value<quint64>(), quint64(7));
    QVERIFY(r.stream().isRunning());
    // The first setpoint at once (t = 0), the next one interval (50 ms at 20 Hz) later.
    QCOMPARE(r.timers.at(0).lastMs, 50);
    QTRY_COMPARE(r.rig.results.size(), 1);
    QVERIFY(r.tickAt(0.5)); // a quarter period: the sine's peak
    QTRY_COMPARE(r.rig.results.size(), 2);
    QVERIFY(r.tickAt(1.5)); // three quarters: its trough
    QTRY_COMPARE(r.rig.results.size(), 3);
    QVector<QByteArray> frames;
    for (const QByteArray &f : r.rig.log->writtenCopy()) {
        if (quint8(f.at(1)) != quint8(Command::ReadState2)) // the speed watch reads a torque
            frames.append(f);
    }
    QCOMPARE(frames.size(), 3);
    QCOMPARE(frames.at(0), gateFrame(p, offset));
    QCOMPARE(frames.at(1), gateFrame(p, offset + 1));
    QCOMPARE(frames.at(2), gateFrame(p, offset - 1));
    for (const QByteArray &f : frames)
        QCOMPARE(int(quint8(f.at(1))), command);
    if (Target(target) == Target::Position) {
        // 101 deg at the speed limit of 720 dps, as the gate sends a move the user gave no
        // max speed.
        QCOMPARE(frames.at(1), protocol::build::multiPosition(kId, 101, 720).request->encode());
    }
    // Their ends reach requestCompleted (CommandedMotion listens there), at Operator priority.
    for (const RequestResult &res : r.rig.results) {
        QVERIFY(SetpointStream::isSetpointTicket(res.ticket));
        QCOMPARE(res.status, RequestStatus::Ok);
        QCOMPARE(res.priority, Priority::Operator);
        QCOMPARE(int(res.request.command), command);
    }
    QCOMPARE(r.stream().emitted(), 3);
    QCOMPARE(r.stream().skipped(), 0);
    // Due times count from the start: a tick 20 ms late waits 30 ms for the next.
    QVERIFY(r.tickAt(1.57));
    QCOMPARE(r.timers.at(0).lastMs, 30);
}

void tst_SetpointStream::positionSetpointsAreNeverRetried()
{
    StreamRig r;
    SetpointStreamPlan position = plan(Target::Position, 100, 1);
    position.id = 9; // silent
    QSignalSpy failed(&r.stream(), &SetpointStream::setpointFailed);
    r.stream().start(position);
    QTRY_VERIFY_WITH_TIMEOUT(!r.rig.results.isEmpty(), 5000);
    QCOMPARE(r.rig.results.at(0).status, RequestStatus::Timeout);
    QCOMPARE(r.rig.results.at(0).attempts, 1);
    QCOMPARE(failed.count(), 1); // the one failed setpoint, said as such
    QCOMPARE(failed.at(0).at(0).value<quint64>(), position.stream);
    QCOMPARE(failed.at(0).at(1).value<RequestResult>().ticket, r.rig.results.at(0).ticket);
    QVERIFY(r.stream().isRunning()); // a lost setpoint is followed by the next one

    // Speed setpoints keep the gate's retries (BusConfig::retries).
    SetpointStreamPlan speed = plan(Target::Speed, 0, 1);
    speed.id = 9;
    r.rig.results.clear();
    r.stream().start(speed);
    QTRY_VERIFY_WITH_TIMEOUT(!r.rig.results.isEmpty(), 5000);
    QCOMPARE(r.rig.results.at(0).attempts, r.rig.worker->config().retries + 1);
}

void tst_SetpointStream::refusedValueStopsWithTheVerdict_data()
{
    QTest::addColumn<int>("target");
    QTest::addColumn<double>("offset");
    QTest::addColumn<double>("amplitude");
    QTest::addColumn<bool>("angleKnown");
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("emitted");
    QTest::addColumn<bool>("fieldError");
    using K = safety::LimitKind;
    // The first value is refused at once; a sine ramps into a refusal on a later tick.
    QTest::newRow("speed over the limit")
        << int(Target::Speed) << 800.0 << 0.0 << true << int(K::SoftSpeed) << 0 << false;
    QTest::newRow("speed grows over it")
        << int(Target::Speed) << 0.0 << 1000.0 << true << int(K::SoftSpeed) << 1 << false;
    QTest::newRow("position a turn away")
        << int(Target::Position) << 500.0 << 0.0 << true << int(K::OutputTurn) << 0 << false;
    QTest::newRow("position, angle unknown")
        << int(Target::Position) << 100.0 << 0.0 << false << int(K::AngleUnknown) << 0 << false;
    QTest::newRow("torque over the limit")
        << int(Target::Torque) << 3.0 << 0.0 << true << int(K::SoftTorque) << 0 << false;
    QTest::newRow("torque out of the field")
        << int(Target::Torque) << 40.0 << 0.0 << true << int(K::None) << 0 << true;
}

void tst_SetpointStream::refusedValueStopsWithTheVerdict()
{
    QFETCH(int, target);
    QFETCH(double, offset);
    QFETCH(double, amplitude);
    QFETCH(bool, angleKnown);
    QFETCH(int, kind);
    QFETCH(int, emitted);
    QFETCH(bool, fieldError);
    StreamRig r;
    SetpointStreamPlan p = plan(Target(target), offset, amplitude);
    if (!angleKnown)
        p.position.angleDeg.reset();
    QSignalSpy stopped(&r.stream(), &SetpointStream::stopped);
    r.stream().start(p);
    if (emitted > 0) {
        QTRY_COMPARE(r.rig.results.size(), emitted);
        QVERIFY(r.tickAt(0.5));
    }
    QCOMPARE(stopped.size(), 1);
    const SetpointStop s = stopped.at(0).at(0).value<SetpointStop>();
    QCOMPARE(s.stream, quint64(7));
    QCOMPARE(s.reason, SetpointStopReason::Refused);
    QCOMPARE(int(s.verdict.kind), kind);
    QCOMPARE(s.fieldError.has_value(), fieldError);
    QCOMPARE(s.emitted, qint64(emitted));
    QVERIFY(!r.stream().isRunning());
    QVERIFY(!r.timers.at(0).active);
    // The refused value was not sent, nor anything after it.
    QTest::qWait(50);
    QCOMPARE(r.rig.log->writtenCopy().size(), emitted);
    QVERIFY(!r.tickAt(1));
}

void tst_SetpointStream::skipsWhileThePreviousIsPending()
{
    // Each reply takes 400 ms (well inside the timeout): time enough to tick meanwhile.
    BusConfig patient = relaxedConfig();
    patient.minMarginMs = patient.initialMarginMs = 2000;
    patient.maxMarginMs = 4000;
    StreamRig r(400, patient);
    // A slow read is on the wire: the first setpoint waits in the queue behind it.
    const quint64 read = r.rig.send(plainRequest(Command::ReadState1, kId));
    QTRY_COMPARE(r.rig.log->writtenCopy().size(), 1);
    r.stream().start(plan(Target::Speed, 10, 0));
    QCOMPARE(r.stream().emitted(), 1);
    QVERIFY(r.tickAt(0.05)); // queued
    QCOMPARE(r.stream().skipped(), 1);
    QTRY_VERIFY(r.rig.result(read));
    QTRY_COMPARE(r.rig.log->writtenCopy().size(), 2);
    QVERIFY(r.tickAt(0.10)); // in flight
    QVERIFY(r.tickAt(0.15));
    QCOMPARE(r.stream().skipped(), 3);
    QCOMPARE(r.stream().emitted(), 1);
    QTRY_COMPARE(r.rig.results.size(), 2);
    QVERIFY(r.tickAt(0.20)); // answered: the next one goes
    QCOMPARE(r.stream().emitted(), 2);
    QTRY_COMPARE(r.rig.log->writtenCopy().size(), 3);
    QCOMPARE(r.written(), (QVector<Command>{Command::ReadState1, Command::Speed, Command::Speed}));
}

void tst_SetpointStream::stopDropsTheQueuedSetpoint()
{
    StreamRig r(100);
    const quint64 read = r.rig.send(plainRequest(Command::ReadState1, kId));
    QTRY_COMPARE(r.rig.log->writtenCopy().size(), 1);
    QSignalSpy stopped(&r.stream(), &SetpointStream::stopped);
    r.stream().start(plan(Target::Speed, 10, 0));
    r.rig.worker->stopSetpointStream();
    QCOMPARE(stopped.size(), 1);
    QCOMPARE(stopped.at(0).at(0).value<SetpointStop>().reason, SetpointStopReason::Requested);
    QCOMPARE(stopped.at(0).at(0).value<SetpointStop>().emitted, qint64(1));
    // The queued setpoint ends Cancelled, unsent: a motor_stop sent next is the last word.
    QCOMPARE(r.rig.results.size(), 1);
    QVERIFY(SetpointStream::isSetpointTicket(r.rig.results.at(0).ticket));
    QCOMPARE(r.rig.results.at(0).status, RequestStatus::Cancelled);
    QCOMPARE(r.rig.results.at(0).attempts, 0);
    QTRY_VERIFY(r.rig.result(read));
    QTest::qWait(50);
    QCOMPARE(r.written(), QVector<Command>{Command::ReadState1});
    QVERIFY(!r.tickAt(1));
}

void tst_SetpointStream::stopKeepsTheSetpointOnTheWireFromRetrying_data()
{
    QTest::addColumn<bool>("reopen");
    QTest::newRow("stopSetpointStream") << false;
    QTest::newRow("reopen at another baud") << true;
}

void tst_SetpointStream::stopKeepsTheSetpointOnTheWireFromRetrying()
{
    // A speed setpoint keeps the gate's retries while the stream runs; stopped while it is on
    // the wire to a silent drive, its timeout must not send it again ahead of what follows.
    QFETCH(bool, reopen);
    StreamRig r;
    SetpointStreamPlan speed = plan(Target::Speed, 0, 1);
    speed.id = 9; // silent
    r.stream().start(speed);
    QTRY_COMPARE(r.rig.log->writtenCopy().size(), 1);
    if (reopen)
        QVERIFY(r.rig.worker->reopenAt(57600));
    else
        r.rig.worker->stopSetpointStream();
    QVERIFY(!r.stream().isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(!r.rig.results.isEmpty(), 5000);
    QCOMPARE(r.rig.results.at(0).attempts, 1);
    QTest::qWait(100);
    QCOMPARE(r.written(), QVector<Command>{Command::Speed});
}

void tst_SetpointStream::emergencyStopStopsTheStreamBeforeMotorOff()
{
    StreamRig r(30);
    QVector<QVector<Command>> writtenAtStop;
    connect(&r.stream(), &SetpointStream::stopped, this, [&](const SetpointStop &s) {
        QCOMPARE(s.reason, SetpointStopReason::EmergencyStop);
        writtenAtStop.append(r.written());
    });
    r.stream().start(plan(Target::Speed, 10, 0));
    QTRY_COMPARE(r.rig.results.size(), 1);
    QVERIFY(r.tickAt(0.05));
    QTRY_COMPARE(r.written().size(), 2); // the second setpoint is on the wire
    QSignalSpy finished(r.rig.worker.get(), &BusWorker::emergencyStopFinished);
    r.rig.worker->emergencyStop(99, {kId});
    // Stopped inside the call, before any motor_off could be written.
    QCOMPARE(writtenAtStop.size(), 1);
    QVERIFY(!writtenAtStop.at(0).contains(Command::MotorOff));
    QVERIFY(!r.stream().isRunning());
    QVERIFY(!r.timers.at(0).active);
    QVERIFY(!r.tickAt(0.10));
    QTRY_VERIFY(r.written().contains(Command::MotorOff));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
    // No setpoint after the first motor_off.
    const QVector<Command> w = r.written();
    const qsizetype firstOff = w.indexOf(Command::MotorOff);
    QCOMPARE(w.lastIndexOf(Command::Speed), firstOff - 1);
    QCOMPARE(r.rig.writtenRequests().at(firstOff).second, kId); // the known drive first
}

void tst_SetpointStream::busEventsStopTheStream_data()
{
    QTest::addColumn<int>("event");
    QTest::addColumn<int>("reason");
    QTest::newRow("disconnect") << 0 << int(SetpointStopReason::Disconnected);
    QTest::newRow("shutdown") << 1 << int(SetpointStopReason::Closed);
    QTest::newRow("reopen at another baud") << 2 << int(SetpointStopReason::BusChanged);
}

void tst_SetpointStream::busEventsStopTheStream()
{
    QFETCH(int, event);
    QFETCH(int, reason);
    StreamRig r(50);
    QSignalSpy stopped(&r.stream(), &SetpointStream::stopped);
    r.stream().start(plan(Target::Speed, 10, 0));
    QTRY_COMPARE(r.written().size(), 1);
    if (event == 0)
        r.rig.transport->unplug();
    else if (event == 1)
        r.rig.worker->shutdown(QStringLiteral("test"));
    else
        r.rig.worker->reopenAt(57600);
    QCOMPARE(stopped.size(), 1);
    QCOMPARE(int(stopped.at(0).at(0).value<SetpointStop>().reason), reason);
    QVERIFY(!r.stream().isRunning());
    QVERIFY(!r.timers.at(0).active);
    QTest::qWait(100);
    QCOMPARE(r.written(), QVector<Command>{Command::Speed});
}

void tst_SetpointStream::closedBusStopsAtOnce()
{
    StreamRig r;
    r.rig.worker->shutdown(QStringLiteral("test"));
    QSignalSpy started(&r.stream(), &SetpointStream::started);
    QSignalSpy stopped(&r.stream(), &SetpointStream::stopped);
    r.stream().start(plan(Target::Speed, 10, 0));
    QCOMPARE(started.size(), 1);
    QCOMPARE(stopped.size(), 1);
    QCOMPARE(stopped.at(0).at(0).value<SetpointStop>().reason, SetpointStopReason::Disconnected);
    QCOMPARE(stopped.at(0).at(0).value<SetpointStop>().emitted, qint64(0));
    QVERIFY(r.rig.log->writtenCopy().isEmpty());
}

void tst_SetpointStream::sessionRunsAndRelaysTheStream()
{
    auto log = std::make_shared<FakeLog>();
    BusSession session;
    QSignalSpy started(&session, &BusSession::setpointStreamStarted);
    QSignalSpy stopped(&session, &BusSession::setpointStreamStopped);
    QSignalSpy completed(&session, &BusSession::requestCompleted);
    session.open(
        [log](int baud) {
            auto t = std::make_unique<FakeTransport>(baud, log);
            t->drives().add(kId, Series::MF);
            return t;
        },
        115200, relaxedConfig());
    QTRY_VERIFY(session.connection().isOpen());
    const quint64 first = session.startSetpointStream(plan(Target::Speed, 10, 0));
    const quint64 second = session.startSetpointStream(plan(Target::Speed, 20, 0));
    QVERIFY(first != second);
    QTRY_COMPARE(started.size(), 2);
    QCOMPARE(started.at(1).at(0).value<quint64>(), second);
    // The first was replaced by the second; the second runs on the bus thread's timer.
    QTRY_COMPARE(stopped.size(), 1);
    QCOMPARE(stopped.at(0).at(0).value<SetpointStop>().stream, first);
    QCOMPARE(stopped.at(0).at(0).value<SetpointStop>().reason, SetpointStopReason::Replaced);
    QTRY_VERIFY_WITH_TIMEOUT(completed.size() >= 4, 5000);
    for (const QList<QVariant> &c : completed)
        QVERIFY(SetpointStream::isSetpointTicket(c.at(0).value<RequestResult>().ticket));
    session.stopSetpointStream();
    QTRY_COMPARE(stopped.size(), 2);
    const SetpointStop s = stopped.at(1).at(0).value<SetpointStop>();
    QCOMPARE(s.stream, second);
    QCOMPARE(s.reason, SetpointStopReason::Requested);
    QVERIFY(s.emitted >= 3);
    // A closed session ends a stream at once.
    session.close();
    const quint64 closed = session.startSetpointStream(plan(Target::Speed, 10, 0));
    QTRY_COMPARE(stopped.size(), 3);
    QCOMPARE(stopped.at(2).at(0).value<SetpointStop>().stream, closed);
    QCOMPARE(stopped.at(2).at(0).value<SetpointStop>().reason, SetpointStopReason::Closed);
}

QTEST_GUILESS_MAIN(tst_SetpointStream)
#include "tst_setpointstream.moc"
