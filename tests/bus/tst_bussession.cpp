#include "BusTestUtil.h"

#include <bus/BusSession.h>

#include <QtCore/QThread>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <atomic>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

namespace {
/// Makes FakeTransports on the bus thread and remembers where and what it made.
struct FactoryProbe {
    std::shared_ptr<FakeLog> log = std::make_shared<FakeLog>();
    std::atomic<QThread *> thread{nullptr};
    std::atomic<FakeTransport *> transport{nullptr};
    int replyDelayMs = 0;
    QVector<int> ids{3};

    TransportFactory factory()
    {
        return [this](int baud) {
            thread = QThread::currentThread();
            auto t = std::make_unique<FakeTransport>(baud, log);
            for (int id : ids)
                t->drives().add(id, Series::MF);
            t->setReplyDelayMs(replyDelayMs);
            transport = t.get();
            return t;
        };
    }
};

const RequestResult *findTicket(const QSignalSpy &spy, quint64 ticket)
{
    for (const auto &args : spy) {
        if (args.at(0).value<RequestResult>().ticket == ticket)
            return static_cast<const RequestResult *>(args.at(0).constData());
    }
    return nullptr;
}

/// Every traffic event the spy on `trafficCaptured` has seen, in order.
QVector<TrafficEvent> capturedTraffic(const QSignalSpy &spy)
{
    QVector<TrafficEvent> out;
    for (const auto &args : spy)
        out += args.at(0).value<TrafficBatch>();
    return out;
}
} // namespace

/// BusSession: the GUI-thread face over a bus thread, with the scripted FakeTransport.
class tst_BusSession : public QObject {
    Q_OBJECT
private slots:
    void roundTripAcrossThreads();
    void scanPollAndStatistics();
    void emergencyStop();
    void closeDeliversFinalResults();
    void sendWhileClosed();
    void twoSessionsAtOnce();
    void unplugAndReconnect();
    void trafficCaptureOnlyWhenEnabled();
    void trafficCarriesTheContextOfItsMoment();
    void seriesIsVisibleAtOnce();
    void pollExtrasOutlivePlans();
};

void tst_BusSession::roundTripAcrossThreads()
{
    FactoryProbe probe;
    BusSession session;
    QSignalSpy done(&session, &BusSession::requestCompleted);
    QThread *deliveredOn = nullptr;
    connect(&session, &BusSession::requestCompleted, this,
            [&deliveredOn] { deliveredOn = QThread::currentThread(); });
    session.open(probe.factory(), 115200, relaxedConfig());
    QVERIFY(session.isRunning());
    QTRY_VERIFY(session.connection().isOpen());
    QCOMPARE(session.connection().baud, 115200);
    QVERIFY(probe.thread.load() != QThread::currentThread());

    const quint64 ticket = session.send(plainRequest(Command::ReadState2, 3));
    QTRY_VERIFY_WITH_TIMEOUT(findTicket(done, ticket), 10000);
    const RequestResult &r = *findTicket(done, ticket);
    QCOMPARE(r.status, RequestStatus::Ok);
    QVERIFY(r.latencyMs >= 0);
    QCOMPARE(std::get<protocol::State2>(r.reply->payload).encoder, quint16(4000));
    QCOMPARE(deliveredOn, QThread::currentThread());
    session.close();
    QVERIFY(!session.isRunning());
    QCOMPARE(session.connection().state, transport::Transport::State::Closed);
}

void tst_BusSession::scanPollAndStatistics()
{
    FactoryProbe probe;
    probe.ids = {2, 6};
    BusSession session;
    QSignalSpy finished(&session, &BusSession::scanFinished);
    QSignalSpy telemetry(&session, &BusSession::telemetryReceived);
    QSignalSpy stats(&session, &BusSession::statisticsUpdated);
    QSignalSpy motors(&session, &BusSession::knownMotorsChanged);
    BusConfig c = relaxedConfig();
    c.minMarginMs = c.initialMarginMs = 30;
    session.open(probe.factory(), 115200, c);
    ScanOptions o;
    o.lastId = 8;
    o.retries = 1;
    session.scan(o);
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
    QCOMPARE(finished.at(0).at(0).value<ScanSummary>().motors.size(), 2);
    QTRY_COMPARE(session.knownMotors().keys(), (QList<int>{2, 6}));
    QCOMPARE(session.series(6), std::optional<Series>(Series::MF));
    QVERIFY(!motors.isEmpty());

    session.startPolling(PollPlan::standard({2, 6}));
    QTRY_VERIFY_WITH_TIMEOUT(telemetry.size() >= 3, 20000);
    QTRY_VERIFY_WITH_TIMEOUT(
        !stats.isEmpty() && stats.last().at(0).value<BusStatistics>().bus.replies > 10, 20000);
    const BusStatistics s = stats.last().at(0).value<BusStatistics>();
    QVERIFY(s.perId.contains(2));
    QVERIFY(s.pollLimitPerSecond > 0);
    QCOMPARE(s.baud, 115200);
    session.stopPolling();
}

void tst_BusSession::emergencyStop()
{
    FactoryProbe probe;
    probe.ids = {3, 9};
    BusSession session;
    QSignalSpy finished(&session, &BusSession::emergencyStopFinished);
    session.open(probe.factory(), 115200, relaxedConfig());
    session.setSeries(3, Series::MF);
    const quint64 ticket = session.emergencyStop({9});
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
    QCOMPARE(finished.at(0).at(0).toULongLong(), ticket);
    QCOMPARE(finished.at(0).at(1).value<QVector<int>>(), (QVector<int>{3, 9}));
}

void tst_BusSession::closeDeliversFinalResults()
{
    FactoryProbe probe;
    probe.replyDelayMs = 2000; // nothing answers before close()
    BusSession session;
    QSignalSpy done(&session, &BusSession::requestCompleted);
    session.open(probe.factory(), 115200, relaxedConfig());
    QTRY_VERIFY(session.connection().isOpen());
    QVector<quint64> tickets;
    for (int i = 0; i < 3; ++i)
        tickets.append(session.send(plainRequest(Command::ReadState1, 3)));
    QTRY_VERIFY(!probe.log->writtenCopy().isEmpty());
    session.close();
    // Delivered before close() returned, once each.
    QCOMPARE(done.size(), 3);
    for (quint64 t : tickets) {
        QVERIFY(findTicket(done, t));
        QCOMPARE(findTicket(done, t)->status, RequestStatus::Cancelled);
    }
    QCOMPARE(session.connection().state, transport::Transport::State::Closed);
    QTest::qWait(100);
    QCOMPARE(done.size(), 3);
}

void tst_BusSession::sendWhileClosed()
{
    BusSession session;
    QSignalSpy done(&session, &BusSession::requestCompleted);
    QSignalSpy scan(&session, &BusSession::scanFinished);
    const quint64 t = session.send(plainRequest(Command::ReadState1, 3));
    QCOMPARE(done.size(), 0); // the caller gets the ticket first
    QTRY_COMPARE(done.size(), 1);
    QCOMPARE(done.at(0).at(0).value<RequestResult>().ticket, t);
    QCOMPARE(done.at(0).at(0).value<RequestResult>().status, RequestStatus::Disconnected);
    session.scan();
    QTRY_COMPARE(scan.size(), 1);
    QVERIFY(!scan.at(0).at(0).value<ScanSummary>().error.isEmpty());
}

void tst_BusSession::twoSessionsAtOnce()
{
    FactoryProbe pa, pb;
    pa.ids = {1};
    pb.ids = {2};
    BusSession a, b;
    QSignalSpy doneA(&a, &BusSession::requestCompleted);
    QSignalSpy doneB(&b, &BusSession::requestCompleted);
    a.open(pa.factory(), 115200, relaxedConfig());
    b.open(pb.factory(), 57600, relaxedConfig());
    const quint64 ta = a.send(plainRequest(Command::ReadState1, 1));
    const quint64 tb = b.send(plainRequest(Command::ReadState1, 2));
    QTRY_VERIFY_WITH_TIMEOUT(findTicket(doneA, ta) && findTicket(doneB, tb), 10000);
    QCOMPARE(findTicket(doneA, ta)->status, RequestStatus::Ok);
    QCOMPARE(findTicket(doneB, tb)->status, RequestStatus::Ok);
    QVERIFY(pa.thread.load() != pb.thread.load());
    a.close();
    const quint64 tb2 = b.send(plainRequest(Command::ReadState2, 2));
    QTRY_VERIFY_WITH_TIMEOUT(findTicket(doneB, tb2), 10000);
    QCOMPARE(findTicket(doneB, tb2)->status, RequestStatus::Ok);
    QCOMPARE(b.connection().baud, 57600);
}

void tst_BusSession::unplugAndReconnect()
{
    FactoryProbe probe;
    BusSession session;
    QSignalSpy errors(&session, &BusSession::errorOccurred);
    QSignalSpy done(&session, &BusSession::requestCompleted);
    session.open(probe.factory(), 115200, relaxedConfig());
    QTRY_VERIFY(session.connection().isOpen());
    FakeTransport *t = probe.transport;
    QMetaObject::invokeMethod(
        t, [t] { t->unplug(); }, Qt::QueuedConnection);
    QTRY_COMPARE(session.connection().state, transport::Transport::State::Disconnected);
    QCOMPARE(session.connection().reason, QStringLiteral("The fake adapter was unplugged."));
    QCOMPARE(errors.size(), 0); // an unplug is a state, not an error
    const quint64 lost = session.send(plainRequest(Command::ReadState1, 3));
    QTRY_VERIFY(findTicket(done, lost));
    QCOMPARE(findTicket(done, lost)->status, RequestStatus::Disconnected);

    session.reconnect();
    QTRY_VERIFY(session.connection().isOpen());
    const quint64 back = session.send(plainRequest(Command::ReadState1, 3));
    QTRY_VERIFY_WITH_TIMEOUT(findTicket(done, back), 10000);
    QCOMPARE(findTicket(done, back)->status, RequestStatus::Ok);
}

void tst_BusSession::trafficCaptureOnlyWhenEnabled()
{
    FactoryProbe probe;
    BusSession session;
    QSignalSpy traffic(&session, &BusSession::trafficCaptured);
    QSignalSpy done(&session, &BusSession::requestCompleted);
    session.open(probe.factory(), 115200, relaxedConfig());
    session.send(plainRequest(Command::ReadState1, 3));
    QTRY_COMPARE(done.size(), 1);
    QTest::qWait(150);
    QCOMPARE(traffic.size(), 0);

    session.setTrafficCapture(true);
    const quint64 t = session.send(plainRequest(Command::ReadState2, 3));
    QTRY_VERIFY(findTicket(done, t));
    QSet<int> kinds;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            kinds.clear();
            for (const TrafficEvent &e : capturedTraffic(traffic))
                kinds.insert(int(e.kind));
            return kinds.contains(int(TrafficEvent::Kind::Sent)) &&
                   kinds.contains(int(TrafficEvent::Kind::Frame));
        }(),
        5000);
    const TrafficEvent first = traffic.at(0).at(0).value<TrafficBatch>().at(0);
    QCOMPARE(first.kind, TrafficEvent::Kind::Sent);
    QCOMPARE(first.bytes, plainRequest(Command::ReadState2, 3).encode());
}

void tst_BusSession::trafficCarriesTheContextOfItsMoment()
{
    // Each request and reply is parsed once on the bus thread and carries how its ID decoded
    // then: a series set between two exchanges changes the second, not the first.
    FactoryProbe probe;
    BusSession session;
    QSignalSpy traffic(&session, &BusSession::trafficCaptured);
    QSignalSpy done(&session, &BusSession::requestCompleted);
    session.open(probe.factory(), 115200, relaxedConfig());
    session.setTrafficCapture(true);
    const quint64 first = session.send(plainRequest(Command::ReadState2, 3));
    QTRY_VERIFY(findTicket(done, first));
    session.setSeries(3, Series::MS);
    const quint64 second = session.send(plainRequest(Command::ReadState2, 3));
    QTRY_VERIFY(findTicket(done, second));
    QVector<TrafficEvent> events;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            events.clear();
            for (const TrafficEvent &e : capturedTraffic(traffic)) {
                if (e.kind == TrafficEvent::Kind::Sent || e.kind == TrafficEvent::Kind::Frame)
                    events << e;
            }
            return events.size() >= 4;
        }(),
        5000);
    QCOMPARE(events.size(), 4);
    const TrafficEvent::Kind order[] = {TrafficEvent::Kind::Sent, TrafficEvent::Kind::Frame,
                                        TrafficEvent::Kind::Sent, TrafficEvent::Kind::Frame};
    for (int i = 0; i < 4; ++i) {
        const TrafficEvent &e = events.at(i);
        QCOMPARE(e.kind, order[i]);
        QCOMPARE(e.frame.encode(), e.bytes); // the parsed frame is the one on the wire
        QCOMPARE(int(e.frame.id), 3);
        QCOMPARE(e.frame.command, quint8(Command::ReadState2));
        QCOMPARE(e.context.series, i < 2 ? Series::MF : Series::MS);
    }
}

void tst_BusSession::seriesIsVisibleAtOnce()
{
    FactoryProbe probe;
    BusSession session;
    QSignalSpy motors(&session, &BusSession::knownMotorsChanged);
    session.open(probe.factory(), 115200, relaxedConfig());
    session.setSeries(4, Series::MS);
    QCOMPARE(session.series(4), std::optional<Series>(Series::MS));
    QCOMPARE(session.series(5), std::nullopt);
    QTRY_VERIFY(!motors.isEmpty());
    QVERIFY(motors.last().at(0).value<KnownMotors>().contains(4));
    session.forgetMotors();
    QCOMPARE(session.series(4), std::nullopt);
}

void tst_BusSession::pollExtrasOutlivePlans()
{
    // A view's extra reads survive every plan (a step test's focus, its end, a rescan's stop)
    // and go with their handle; without a plan the bus polls them alone; close() drops them.
    FactoryProbe probe;
    BusSession session;
    QSignalSpy telemetry(&session, &BusSession::telemetryReceived);
    session.open(probe.factory(), 115200, relaxedConfig());
    QTRY_VERIFY(session.connection().isOpen());
    QVERIFY(!session.effectivePollPlan());
    const quint64 a = session.addPollExtras(3, {Command::ReadEncoder, Command::ReadMultiTurn});
    const quint64 b = session.addPollExtras(3, {Command::ReadMultiTurn, Command::ReadSingleTurn});
    QVERIFY(a && b && a != b);
    QVERIFY(!session.pollPlan());
    std::optional<PollPlan> p = session.effectivePollPlan();
    QVERIFY(p && p->ids.isEmpty() && p->commands.isEmpty());
    QCOMPARE(
        p->extraCommands.value(3),
        (QVector<Command>{Command::ReadEncoder, Command::ReadMultiTurn, Command::ReadSingleTurn}));
    // The worker polls them: a 0x90 reply arrives whole in the telemetry.
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            for (const auto &args : telemetry) {
                for (const TelemetrySample &s : args.at(0).value<TelemetryBatch>()) {
                    if (s.id == 3 && s.source == Command::ReadEncoder && s.encoderReading)
                        return true;
                }
            }
            return false;
        }(),
        5000);

    const PollPlan dashboard = PollPlan::standard({1, 3});
    session.startPolling(dashboard.focusedOn(1, {Command::ReadState2}));
    QVERIFY(session.pollPlan()->extraCommands.isEmpty()); // the plan as given
    p = session.effectivePollPlan();
    QCOMPARE(p->focusId, 1);
    QCOMPARE(p->ids, dashboard.ids);
    QCOMPARE(p->commands, dashboard.commands);
    QCOMPARE(p->extraCommands.value(3).size(), 3);
    session.startPolling(dashboard);
    session.removePollExtras(a);
    QVERIFY(!session.hasPollExtras(a) && session.hasPollExtras(b));
    QCOMPARE(session.effectivePollPlan()->extraCommands.value(3),
             (QVector<Command>{Command::ReadMultiTurn, Command::ReadSingleTurn}));
    session.stopPolling();
    QVERIFY(!session.pollPlan());
    QCOMPARE(session.effectivePollPlan()->extraCommands.keys(), QList<int>{3});
    session.close();
    QVERIFY(!session.hasPollExtras(b));
    QVERIFY(!session.effectivePollPlan());
    session.removePollExtras(b); // a dropped handle is ignored
}

QTEST_GUILESS_MAIN(tst_BusSession)
#include "tst_bussession.moc"
