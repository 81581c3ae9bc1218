#include "BusTestUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/BusWorker.h>
#include <protocol/RequestBuilder.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <memory>
#include <optional>

Q_DECLARE_METATYPE(lk::protocol::Request)

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

Q_DECLARE_METATYPE(protocol::Command)
Q_DECLARE_METATYPE(protocol::Series)

/// BusWorker on the test thread over a scripted FakeTransport, on a clock the test advances
/// (RigTime::Manual): timeouts, quiet periods and reply delays do not depend on the machine's
/// load, and a wait of seconds costs none.
class tst_BusWorker : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void replyMatchedByCommandAndId();
    void timeoutThenRetry_data();
    void timeoutThenRetry();
    void retryRecoversAfterSilence();
    void nonIdempotentCommandsAreNeverRetried_data();
    void nonIdempotentCommandsAreNeverRetried();
    void silentCommandDoesNotStall();
    void operatorAheadOfBackground();
    void emergencyStopOvertakesEverything();
    void emergencyStopWithNoKnownIdReachesAll();
    void faultsAreCountedNotFatal_data();
    void faultsAreCountedNotFatal();
    void disconnectFailsPendingOnce();
    void localEchoIsSkipped_data();
    void localEchoIsSkipped();
    void sendWhileClosedCompletesDisconnected();
    void failedOpenReportsError();
    void unplugIsReportedOnce();
    void modelReadOutsideScanGivesSeries_data();
    void modelReadOutsideScanGivesSeries();
};

void tst_BusWorker::replyMatchedByCommandAndId()
{
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(3, Series::MF);
            t.drives().add(4, Series::MF);
            FakeTransport *tp = &t;
            t.setResponder([tp](const protocol::Frame &req, int) {
                // Another ID's reply to the same command and this ID's reply to another command
                // come first: neither may complete the request.
                protocol::Frame otherId = req;
                otherId.id = 4;
                const protocol::Frame otherCommand{quint8(Command::ReadState1), req.id, {}};
                return tp->defaultReply(otherId) + tp->defaultReply(otherCommand) +
                       tp->defaultReply(req);
            });
        },
        relaxedConfig(), 115200, RigTime::Manual);
    const quint64 ticket = rig.send(plainRequest(Command::ReadState2, 3));
    QVERIFY(rig.runUntil([&] { return rig.result(ticket); }, 5000));
    const RequestResult &r = *rig.result(ticket);
    QCOMPARE(r.status, RequestStatus::Ok);
    QCOMPARE(r.attempts, 1);
    QVERIFY(r.reply);
    QCOMPARE(r.reply->command, Command::ReadState2);
    QCOMPARE(int(r.reply->id), 3);
    const auto &s2 = std::get<protocol::State2>(r.reply->payload);
    QCOMPARE(s2.torqueRaw, qint16(1024));
    QCOMPARE(s2.speedDps, qint16(90));
    const BusStatistics st = rig.worker->statisticsSnapshot();
    QCOMPARE(st.bus.replies, quint64(1));
    QCOMPARE(st.bus.unexpectedFrames, quint64(2));
    QCOMPARE(st.perId.value(3).replies, quint64(1));
    QCOMPARE(rig.resultCount(ticket), 1);
}

void tst_BusWorker::timeoutThenRetry_data()
{
    QTest::addColumn<int>("retries");
    QTest::newRow("no retry") << 0;
    QTest::newRow("one retry") << 1;
    QTest::newRow("three retries") << 3;
}

void tst_BusWorker::timeoutThenRetry()
{
    QFETCH(int, retries);
    WorkerRig rig([](FakeTransport &t) { t.drives().add(3, Series::MF); }, relaxedConfig(), 115200,
                  RigTime::Manual);
    const quint64 silent =
        rig.send(plainRequest(Command::ReadState1, 9), Priority::Operator, retries);
    const quint64 after = rig.send(plainRequest(Command::ReadState1, 3));
    QVERIFY(rig.runUntil([&] { return rig.result(after); }, 20000));
    QCOMPARE(rig.result(silent)->status, RequestStatus::Timeout);
    QCOMPARE(rig.result(silent)->attempts, retries + 1);
    QVERIFY(!rig.result(silent)->reason.isEmpty());
    QCOMPARE(rig.result(after)->status, RequestStatus::Ok);
    QCOMPARE(rig.log->writtenCopy().size(), retries + 2);
    const BusStatistics st = rig.worker->statisticsSnapshot();
    QCOMPARE(st.perId.value(9).timeouts, quint64(retries + 1));
    QCOMPARE(st.perId.value(9).retries, quint64(retries));
    QCOMPARE(rig.resultCount(silent), 1);
}

void tst_BusWorker::retryRecoversAfterSilence()
{
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(3, Series::MF);
            FakeTransport *tp = &t;
            t.setResponder([tp](const protocol::Frame &req, int index) {
                return index == 0 ? QByteArray() : tp->defaultReply(req);
            });
        },
        relaxedConfig(), 115200, RigTime::Manual);
    const quint64 ticket = rig.send(plainRequest(Command::ReadMultiTurn, 3), Priority::Operator, 1);
    QVERIFY(rig.runUntil([&] { return rig.result(ticket); }, 10000));
    QCOMPARE(rig.result(ticket)->status, RequestStatus::Ok);
    QCOMPARE(rig.result(ticket)->attempts, 2);
    QCOMPARE(std::get<protocol::MultiTurnAngle>(rig.result(ticket)->reply->payload).raw,
             qint64(-12345));
}

void tst_BusWorker::nonIdempotentCommandsAreNeverRetried_data()
{
    QTest::addColumn<protocol::Request>("request");
    QTest::addColumn<int>("attempts");
    using namespace protocol::build;
    QTest::newRow("increment") << *incrementPosition(9, 45).request << 1;
    QTest::newRow("increment limited") << *incrementPosition(9, -45, 90).request << 1;
    QTest::newRow("write_pid_rom") << *writePid(9, {1, 2, 3, 4, 5, 6}, true).request << 1;
    QTest::newRow("write_zero_rom") << *plain(Command::WriteZeroRom, 9).request << 1;
    QTest::newRow("write_encoder_offset") << *writeEncoderOffset(9, 100).request << 1;
    // Idempotent ones keep their retries: a repeated target or read changes nothing.
    QTest::newRow("multi position") << *multiPosition(9, 45).request << 3;
    QTest::newRow("write_pid_ram") << *writePid(9, {1, 2, 3, 4, 5, 6}, false).request << 3;
}

void tst_BusWorker::nonIdempotentCommandsAreNeverRetried()
{
    QFETCH(protocol::Request, request);
    QFETCH(int, attempts);
    BusConfig c = relaxedConfig();
    c.minMarginMs = c.initialMarginMs = 10;
    WorkerRig rig({}, c, 115200, RigTime::Manual); // ID 9 is silent: every attempt times out
    const quint64 t = rig.send(request, Priority::Operator, 2);
    QVERIFY(rig.runUntil([&] { return rig.result(t); }, 10000));
    QCOMPARE(rig.result(t)->status, RequestStatus::Timeout);
    QCOMPARE(rig.result(t)->attempts, attempts);
    QCOMPARE(rig.log->writtenCopy().size(), attempts);
}

void tst_BusWorker::silentCommandDoesNotStall()
{
    // An MS drive does not answer read_state3: that is a timeout, and the queue moves on.
    WorkerRig rig([](FakeTransport &t) { t.drives().add(5, Series::MS); }, relaxedConfig(), 115200,
                  RigTime::Manual);
    const quint64 s3 = rig.send(plainRequest(Command::ReadState3, 5), Priority::Operator, 0);
    const quint64 s2 = rig.send(plainRequest(Command::ReadState2, 5));
    QVERIFY(rig.runUntil([&] { return rig.result(s2); }, 10000));
    QCOMPARE(rig.result(s3)->status, RequestStatus::Timeout);
    QCOMPARE(rig.result(s2)->status, RequestStatus::Ok);
}

void tst_BusWorker::operatorAheadOfBackground()
{
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            t.setReplyDelayMs(20);
        },
        relaxedConfig(), 115200, RigTime::Manual);
    rig.send(plainRequest(Command::ReadState1, 1), Priority::Background);
    rig.runUntil([&] { return rig.log->writtenCopy().size() == 1; }, 5000);
    QCOMPARE(rig.log->writtenCopy().size(), 1); // on the wire, waiting for its reply
    for (int i = 0; i < 3; ++i)
        rig.send(plainRequest(Command::ReadState3, 1), Priority::Background);
    const quint64 op = rig.send(plainRequest(Command::ReadState2, 1), Priority::Operator);
    QVERIFY(rig.runUntil([&] { return rig.results.size() == 5; }, 10000));
    const auto order = rig.writtenRequests();
    QCOMPARE(order.size(), 5);
    QCOMPARE(order.at(1).first, Command::ReadState2);
    for (int i = 2; i < 5; ++i)
        QCOMPARE(order.at(i).first, Command::ReadState3);
    QCOMPARE(rig.result(op)->status, RequestStatus::Ok);
}

void tst_BusWorker::emergencyStopOvertakesEverything()
{
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(3, Series::MF);
            t.drives().add(17, Series::MS);
            t.setReplyDelayMs(20);
        },
        relaxedConfig(), 115200, RigTime::Manual);
    rig.worker->setSeries(3, Series::MF);
    rig.worker->setSeries(17, Series::MS);
    QSignalSpy finished(rig.worker.get(), &BusWorker::emergencyStopFinished);
    rig.send(plainRequest(Command::ReadState1, 3));
    rig.runUntil([&] { return rig.log->writtenCopy().size() == 1; }, 5000);
    QCOMPARE(rig.log->writtenCopy().size(), 1);
    const quint64 bg = rig.send(plainRequest(Command::ReadState2, 17), Priority::Background);
    protocol::Request speed = plainRequest(Command::Speed, 3);
    speed.payload = protocol::SpeedCommand{10000};
    const quint64 motion = rig.send(speed);
    const quint64 op = rig.send(plainRequest(Command::ReadState1, 17));
    rig.worker->emergencyStop(99, {});

    rig.runUntil([&] { return finished.size() == 1; }, 20000);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(0).toULongLong(), quint64(99));
    QCOMPARE(finished.at(0).at(1).value<QVector<int>>(), (QVector<int>{3, 17}));
    QCOMPARE(finished.at(0).at(2).value<QVector<int>>().size(), 30); // every other ID
    QCOMPARE(rig.result(motion)->status, RequestStatus::Cancelled);
    QCOMPARE(rig.resultCount(99), 32);
    QVERIFY(rig.runUntil([&] { return rig.result(bg) && rig.result(op); }, 5000));
    const auto order = rig.writtenRequests();
    // In flight first (waited for only until its reply could have left the wire: its reply,
    // 20 ms late, comes during the stop), then motor_off to both known IDs, then to every
    // other ID (once each: they are not known), then the read in flight again, the operator
    // read, then polls.
    QCOMPARE(order.at(1), qMakePair(Command::MotorOff, 3));
    QCOMPARE(order.at(2), qMakePair(Command::MotorOff, 17));
    for (int i = 3; i < 33; ++i)
        QCOMPARE(order.at(i).first, Command::MotorOff);
    QCOMPARE(order.at(33), qMakePair(Command::ReadState1, 3));
    QCOMPARE(order.at(34), qMakePair(Command::ReadState1, 17));
    QCOMPARE(order.at(35), qMakePair(Command::ReadState2, 17));
    for (const auto &w : order)
        QVERIFY(w.first != Command::Speed);
}

void tst_BusWorker::emergencyStopWithNoKnownIdReachesAll()
{
    BusConfig c = relaxedConfig();
    c.minMarginMs = c.initialMarginMs = 15;
    WorkerRig rig([](FakeTransport &t) { t.drives().add(7, Series::MF); }, c, 115200,
                  RigTime::Manual);
    QSignalSpy finished(rig.worker.get(), &BusWorker::emergencyStopFinished);
    rig.worker->emergencyStop(5, {});
    rig.runUntil([&] { return finished.size() == 1; }, 30000);
    QCOMPARE(finished.size(), 1);
    const auto acked = finished.at(0).at(1).value<QVector<int>>();
    const auto silent = finished.at(0).at(2).value<QVector<int>>();
    QCOMPARE(acked.size() + silent.size(), 32);
    QVERIFY(acked.contains(7));
    QSet<int> reached;
    const auto written = rig.writtenRequests();
    for (const auto &w : written) {
        QCOMPARE(w.first, Command::MotorOff);
        reached.insert(w.second);
    }
    QCOMPARE(reached.size(), 32);
    // Every ID hears its first "off" before any silent one is asked again.
    QSet<int> first;
    for (int i = 0; i < 32; ++i)
        first.insert(written.at(i).second);
    QCOMPARE(first.size(), 32);
    QVERIFY(written.size() > 32); // the silent ones were retried
}

void tst_BusWorker::faultsAreCountedNotFatal_data()
{
    QTest::addColumn<QByteArray>("prefix");
    QTest::addColumn<bool>("corruptFirstReply");
    QTest::addColumn<int>("garbage");
    QTest::addColumn<int>("checksum");
    QTest::addColumn<int>("parse");
    QTest::addColumn<int>("attempts");
    QTest::newRow("garbage") << QByteArray("\x01\x02\xFF", 3) << false << 3 << 0 << 0 << 1;
    QTest::newRow("bad header checksum")
        << QByteArray("\x3E\x9C\x03\x07\x00", 5) << false << 0 << 1 << 0 << 1;
    QTest::newRow("unknown command")
        << protocol::encodeFrame(0x55, 3, QByteArray("\x01", 1)) << false << 0 << 0 << 1 << 1;
    QTest::newRow("bad data checksum retries at once") << QByteArray() << true << 0 << 1 << 0 << 2;
}

void tst_BusWorker::faultsAreCountedNotFatal()
{
    QFETCH(QByteArray, prefix);
    QFETCH(bool, corruptFirstReply);
    QFETCH(int, garbage);
    QFETCH(int, checksum);
    QFETCH(int, parse);
    QFETCH(int, attempts);
    WorkerRig rig(
        [&](FakeTransport &t) {
            t.drives().add(3, Series::MF);
            FakeTransport *tp = &t;
            t.setResponder([tp, prefix, corruptFirstReply](const protocol::Frame &req, int index) {
                QByteArray reply = tp->defaultReply(req);
                if (corruptFirstReply && index == 0)
                    reply[reply.size() - 1] = char(reply.at(reply.size() - 1) ^ 0x5A);
                return index == 0 ? prefix + reply : reply;
            });
        },
        relaxedConfig(), 115200, RigTime::Manual);
    const quint64 ticket = rig.send(plainRequest(Command::ReadState2, 3), Priority::Operator, 1);
    QVERIFY(rig.runUntil([&] { return rig.result(ticket); }, 10000));
    QCOMPARE(rig.result(ticket)->status, RequestStatus::Ok);
    QCOMPARE(rig.result(ticket)->attempts, attempts);
    const BusStatistics st = rig.worker->statisticsSnapshot();
    QCOMPARE(st.bus.garbageBytes, quint64(garbage));
    QCOMPARE(st.bus.checksumErrors, quint64(checksum));
    QCOMPARE(st.bus.parseErrors, quint64(parse));
    QCOMPARE(st.bus.timeouts, quint64(0)); // the corrupt reply was retried, not waited out
    if (corruptFirstReply)
        QCOMPARE(st.perId.value(3).checksumErrors, quint64(1));
    QVERIFY(rig.worker->isOpen());
}

void tst_BusWorker::disconnectFailsPendingOnce()
{
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            t.setReplyDelayMs(50);
        },
        relaxedConfig(), 115200, RigTime::Manual);
    QSignalSpy conn(rig.worker.get(), &BusWorker::connectionChanged);
    QSignalSpy errors(rig.worker.get(), &BusWorker::errorOccurred);
    rig.worker->startPolling(PollPlan::standard({1}));
    const quint64 a = rig.send(plainRequest(Command::ReadState1, 1));
    const quint64 b = rig.send(plainRequest(Command::ReadState2, 1));
    const quint64 c = rig.send(plainRequest(Command::ReadPid, 1), Priority::Background);
    QVERIFY(rig.runUntil([&] { return !rig.log->writtenCopy().isEmpty(); }, 5000));
    rig.transport->unplug();
    for (quint64 t : {a, b, c}) {
        QVERIFY(rig.result(t));
        QCOMPARE(rig.result(t)->status, RequestStatus::Disconnected);
        QVERIFY(rig.result(t)->reason.contains(QStringLiteral("unplugged")));
    }
    QCOMPARE(errors.size(), 0); // an unplug is a state (below), not an error
    QVERIFY(!conn.isEmpty());
    QCOMPARE(conn.last().at(0).value<ConnectionStatus>().state,
             transport::Transport::State::Disconnected);
    // Nothing goes out while disconnected; polls are suspended, not lost.
    const int writes = rig.log->writtenCopy().size();
    rig.timers->advance(200);
    QCOMPARE(rig.log->writtenCopy().size(), writes);
    for (quint64 t : {a, b, c})
        QCOMPARE(rig.resultCount(t), 1);

    rig.worker->reconnect();
    QVERIFY(rig.worker->isOpen());
    const quint64 d = rig.send(plainRequest(Command::ReadState1, 1));
    QVERIFY(rig.runUntil([&] { return rig.result(d); }, 10000));
    QCOMPARE(rig.result(d)->status, RequestStatus::Ok);
    QVERIFY(rig.runUntil([&] { return rig.log->writtenCopy().size() > writes + 3; },
                         5000)); // polling resumed
}

void tst_BusWorker::localEchoIsSkipped_data()
{
    QTest::addColumn<protocol::Request>("request");
    QTest::addColumn<bool>("echoConfigured");
    QTest::newRow("read: request layout is never a reply")
        << plainRequest(Command::ReadState2, 2) << false;
    QTest::newRow("motor_off: echo reply, adapter echo configured")
        << plainRequest(Command::MotorOff, 2) << true;
    protocol::Request pid = plainRequest(Command::WritePidRam, 2);
    pid.payload = protocol::PidGains{10, 20, 30, 40, 50, 60};
    QTest::newRow("write_pid_ram: echo reply with data") << pid << true;
}

void tst_BusWorker::localEchoIsSkipped()
{
    QFETCH(protocol::Request, request);
    QFETCH(bool, echoConfigured);
    BusConfig c = relaxedConfig();
    c.localEcho = echoConfigured;
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(2, Series::MF);
            t.setLocalEcho(true);
            t.setReplyDelayMs(20); // the drive answers after the adapter's echo
        },
        c, 115200, RigTime::Manual);
    const quint64 ticket = rig.send(request);
    const quint64 next = rig.send(plainRequest(Command::ReadState1, 2));
    QVERIFY(rig.runUntil([&] { return rig.result(next); }, 10000));
    QCOMPARE(rig.result(ticket)->status, RequestStatus::Ok);
    QCOMPARE(rig.result(next)->status, RequestStatus::Ok);
    const BusStatistics st = rig.worker->statisticsSnapshot();
    QCOMPARE(st.localEchoes, quint64(2));
    QCOMPARE(st.bus.unexpectedFrames, quint64(0));
}

void tst_BusWorker::sendWhileClosedCompletesDisconnected()
{
    WorkerRig rig;
    rig.worker->shutdown(QStringLiteral("test"));
    const quint64 t = rig.send(plainRequest(Command::ReadState1, 1));
    QVERIFY(rig.result(t));
    QCOMPARE(rig.result(t)->status, RequestStatus::Disconnected);
}

void tst_BusWorker::failedOpenReportsError()
{
    auto worker = std::make_unique<BusWorker>(
        [](int b) {
            auto t = std::make_unique<FakeTransport>(b);
            t->setFailOpen(true);
            return t;
        },
        115200, relaxedConfig());
    QSignalSpy errors(worker.get(), &BusWorker::errorOccurred);
    QSignalSpy conn(worker.get(), &BusWorker::connectionChanged);
    worker->start();
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors.at(0).at(0).value<transport::TransportError>().kind,
             transport::TransportError::Kind::NoSuchPort);
    QVERIFY(!worker->isOpen());
    QVERIFY(!conn.isEmpty());
    QVERIFY(conn.last().at(0).value<ConnectionStatus>().reason.contains(QStringLiteral("fake")));
}

void tst_BusWorker::unplugIsReportedOnce()
{
    // One unplug, one report: the Disconnected state with the adapter's words as its reason
    // (one traffic note), and no error besides it.
    WorkerRig rig([](FakeTransport &t) { t.drives().add(1, Series::MF); }, relaxedConfig(), 115200,
                  RigTime::Manual);
    QSignalSpy conn(rig.worker.get(), &BusWorker::connectionChanged);
    QSignalSpy errors(rig.worker.get(), &BusWorker::errorOccurred);
    QSignalSpy traffic(rig.worker.get(), &BusWorker::trafficCaptured);
    rig.worker->setTrafficCapture(true);
    rig.transport->unplug();
    QVERIFY(rig.runUntil([&] { return !traffic.isEmpty(); }, 1000));
    QCOMPARE(errors.size(), 0);
    QCOMPARE(conn.size(), 1);
    const ConnectionStatus s = conn.first().first().value<ConnectionStatus>();
    QCOMPARE(s.state, transport::Transport::State::Disconnected);
    QCOMPARE(s.reason, QStringLiteral("The fake adapter was unplugged."));
    int notes = 0;
    for (const QList<QVariant> &args : std::as_const(traffic)) {
        for (const TrafficEvent &e : args.first().value<TrafficBatch>())
            notes +=
                e.kind == TrafficEvent::Kind::Note && e.text.contains(QStringLiteral("unplugged"));
    }
    QCOMPARE(notes, 1);
}

void tst_BusWorker::modelReadOutsideScanGivesSeries_data()
{
    QTest::addColumn<Series>("series");
    QTest::newRow("MS") << Series::MS;
    QTest::newRow("MF") << Series::MF;
    QTest::newRow("MG") << Series::MG;
    QTest::newRow("MH") << Series::MH;
}

void tst_BusWorker::modelReadOutsideScanGivesSeries()
{
    // lkctl info, the drive-info view: a model read by hand tells the series as a scan does,
    // so that the drive's replies decode as its series (power on MS, iq on the others).
    QFETCH(Series, series);
    WorkerRig rig([series](FakeTransport &t) { t.drives().add(5, series); }, relaxedConfig(),
                  115200, RigTime::Manual);
    QVERIFY(!rig.worker->seriesOf(5));
    const quint64 ticket = rig.send(plainRequest(Command::ReadModel, 5));
    QVERIFY(rig.runUntil([&] { return rig.result(ticket); }, 5000));
    QCOMPARE(rig.result(ticket)->status, RequestStatus::Ok);
    QVERIFY(rig.worker->knownMotors().value(5).model);
    QCOMPARE(rig.worker->seriesOf(5), std::optional<Series>(series));
}

QTEST_GUILESS_MAIN(tst_BusWorker)
#include "tst_busworker.moc"
