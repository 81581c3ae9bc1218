// The old CAN generation's multi-motor torque frame (0x280) through the bus engine, against the
// simulator's CAN front (SimTransport on CAN): one frame on the wire, each drive's reply
// matched to it and published as telemetry, a silent drive timed out alone, every refusal
// with nothing on the wire, and the speed watch stopping all the frame's drives when one of
// them runs past its limit.

#include "BusTestUtil.h"

#include <bus/BusSession.h>
#include <protocol/CanRecord.h>
#include <protocol/RequestBuilder.h>
#include <safety/SoftLimits.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <transport/SimTransport.h>

#include <QtCore/QSet>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using protocol::Command;
using protocol::Generation;
using protocol::Series;

namespace {
const protocol::DecodeContext kOldCan{Series::MG, Generation::V2_3, protocol::Link::Can};

TransportFactory simFactory(const QString &spec, protocol::Link link = protocol::Link::Can)
{
    return [spec, link](int rate) -> std::unique_ptr<transport::Transport> {
        auto bus = sim::SimBus::fromSpec(*sim::SimBusSpec::parse(spec));
        auto t = std::make_unique<transport::SimTransport>(std::move(bus));
        if (link == protocol::Link::Can)
            t->setLink(protocol::Link::Can);
        t->setBaud(rate);
        t->setWireTimeEmulation(true);
        return t;
    };
}

protocol::Request torque(int id, double a)
{
    return *protocol::build::torque(id, a, kOldCan).request;
}

/// What went on the wire: "280#..." for each multi-motor frame, the command name otherwise.
QStringList sent(const QSignalSpy &traffic)
{
    QStringList out;
    for (const auto &args : traffic) {
        for (const TrafficEvent &e : args.at(0).value<TrafficBatch>()) {
            if (e.kind != TrafficEvent::Kind::Sent)
                continue;
            const auto record = protocol::CanRecord::decode(e.bytes);
            if (record && record->canId == 0x280)
                out << record->candumpText();
            else
                out << protocol::CommandTable::name(static_cast<Command>(e.command));
        }
    }
    return out;
}

safety::SoftLimits limits(double torqueA, double speedDps = 3000)
{
    safety::SoftLimits l = safety::SoftLimits::defaults(Series::MG);
    l.maxTorqueA = torqueA;
    l.maxSpeedDps = speedDps;
    return l;
}

/// Opens `session` on `spec` with drives `old` told as old CAN MGs (2 A, 3000 dps limits).
bool openOn(BusSession &session, const QString &spec, const QVector<int> &old,
            LinkMode mode = LinkMode::Active, protocol::Link link = protocol::Link::Can)
{
    for (int id : old) {
        session.setDriveIdentity({id, Series::MG, Generation::V2_3, {}});
        session.setSoftLimits(id, limits(2.0));
    }
    session.open(simFactory(spec, link), link == protocol::Link::Can ? 1000000 : 115200, {}, mode);
    if (!QTest::qWaitFor([&] { return session.connection().isOpen(); }, 10000))
        return false;
    session.setTrafficCapture(true);
    return true;
}

MultiTorqueResult sendAndWait(BusSession &session, const QVector<protocol::Request> &torques)
{
    std::optional<MultiTorqueResult> result;
    QObject context;
    session.sendMultiTorque(MultiTorqueRequest{torques}, &context,
                            [&result](const MultiTorqueResult &r) { result = r; });
    if (!QTest::qWaitFor([&] { return result.has_value(); }, 20000))
        return {};
    return *result;
}
} // namespace

class tst_BusMultiTorque : public QObject {
    Q_OBJECT
private slots:
    void oneFrameEachReplyMatched();
    void aSilentDriveTimesOutAlone();
    void refusalSendsNothing_data();
    void refusalSendsNothing();
    void speedWatchStopsEveryDriveOfTheFrame();
};

void tst_BusMultiTorque::oneFrameEachReplyMatched()
{
    BusSession session;
    QSignalSpy traffic(&session, &BusSession::trafficCaptured);
    QSignalSpy telemetry(&session, &BusSession::telemetryReceived);
    QSignalSpy ended(&session, &BusSession::multiTorqueCompleted);
    QVERIFY(openOn(session, QStringLiteral("1:MG,2:MG"), {1, 2}));
    const MultiTorqueResult r = sendAndWait(session, {torque(2, -1.6), torque(1, 1.6)});
    QCOMPARE(r.status, RequestStatus::Ok);
    QCOMPARE(r.attempts, 1);
    QCOMPARE(r.drives.size(), 2);
    for (int i = 0; i < 2; ++i) {
        const RequestResult &d = r.drives.at(i);
        QCOMPARE(d.request.id, quint8(i + 1)); // ascending ID
        QCOMPARE(d.status, RequestStatus::Ok);
        QVERIFY(d.reply);
        QCOMPARE(d.reply->id, quint8(i + 1));
        QCOMPARE(d.reply->command, Command::Torque);
    }
    QCOMPARE(ended.size(), 1);
    // Each drive's reply is telemetry, as a 0xA1 reply is.
    const auto speedsFrom = [&telemetry] {
        QSet<int> ids;
        for (const auto &args : telemetry) {
            for (const TelemetrySample &s : args.at(0).value<TelemetryBatch>()) {
                if (s.has(TelemetryField::Speed))
                    ids.insert(s.id);
            }
        }
        return ids;
    };
    QTRY_VERIFY_WITH_TIMEOUT(speedsFrom().contains(1) && speedsFrom().contains(2), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(sent(traffic).contains(QStringLiteral("280#64009CFF00000000")), 5000);
    QCOMPARE(sent(traffic).count(QStringLiteral("280#64009CFF00000000")), 1);
    // Its drives are under torque, watched; the emergency stop reaches both.
    std::optional<QVector<int>> acknowledged;
    QObject context;
    session.emergencyStop({}, Command::MotorOff, &context,
                          [&](const QVector<int> &a, const QVector<int> &, const QVector<int> &) {
                              acknowledged = a;
                          });
    QTRY_VERIFY_WITH_TIMEOUT(acknowledged.has_value(), 20000);
    QVERIFY(acknowledged->contains(1) && acknowledged->contains(2));
}

void tst_BusMultiTorque::aSilentDriveTimesOutAlone()
{
    BusSession session;
    QSignalSpy stats(&session, &BusSession::statisticsUpdated);
    QVERIFY(openOn(session, QStringLiteral("1:MG"), {1, 3})); // no drive 3 on this bus
    const MultiTorqueResult r = sendAndWait(session, {torque(1, 0.5), torque(3, 0.5)});
    QCOMPARE(r.status, RequestStatus::Timeout);
    QCOMPARE(r.attempts, 1);
    QVERIFY2(r.reason.contains(QStringLiteral("drive(s) 3 ")), qPrintable(r.reason));
    QCOMPARE(r.drives.at(0).status, RequestStatus::Ok);
    QCOMPARE(r.drives.at(1).status, RequestStatus::Timeout);
    // Counted against drive 3, never drive 1. Drive 3 may have taken the frame without its
    // reply reaching us, so the speed watch goes on reading it (each read another timeout).
    QTRY_VERIFY_WITH_TIMEOUT(
        !stats.isEmpty() && stats.last().at(0).value<BusStatistics>().perId.value(3).timeouts >= 1,
        10000);
    const BusStatistics s = stats.last().at(0).value<BusStatistics>();
    QCOMPARE(s.perId.value(1).timeouts, quint64(0));
    session.emergencyStop({1});
}

void tst_BusMultiTorque::refusalSendsNothing_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QVector<int>>("old"); ///< told as old CAN MGs, 2 A limit
    QTest::addColumn<bool>("v236");        ///< drive 2 told as CAN V2.36
    QTest::addColumn<double>("iq2");       ///< drive 2's torque
    QTest::addColumn<bool>("rs485");       ///< the link is RS485
    QTest::addColumn<bool>("listenOnly");  ///< the session listens only
    QTest::addColumn<QString>("words");
    QTest::newRow("over drive 2's torque limit")
        << "1:MG,2:MG" << QVector<int>{1, 2} << false << 2.4 << false << false
        << "drive 2: |iq| 2.4 A is over its torque limit 2 A";
    QTest::newRow("drive 2's generation unknown")
        << "1:MG,2:MG" << QVector<int>{1} << false << 0.5 << false << false
        << "drive 2: its series and CAN generation are not known";
    QTest::newRow("drive 2 is V2.36") << "1:MG,2:MG@2.35" << QVector<int>{1} << true << 0.5 << false
                                      << false << "drive 2 speaks CAN V2.36";
    QTest::newRow("drive 3 known, not named")
        << "1:MG,2:MG,3:MG" << QVector<int>{1, 2, 3} << false << 0.5 << false << false
        << "drive 3 is on the bus and would get 0 A";
    QTest::newRow("RS485") << "1:MG,2:MG" << QVector<int>{1, 2} << false << 0.5 << true << false
                           << "exists on CAN only";
    QTest::newRow("listen-only") << "1:MG,2:MG" << QVector<int>{1, 2} << false << 0.5 << false
                                 << true << "listen-only: nothing was sent";
}

void tst_BusMultiTorque::refusalSendsNothing()
{
    QFETCH(QString, spec);
    QFETCH(QVector<int>, old);
    QFETCH(bool, v236);
    QFETCH(double, iq2);
    QFETCH(bool, rs485);
    QFETCH(bool, listenOnly);
    QFETCH(QString, words);
    BusSession session;
    QSignalSpy traffic(&session, &BusSession::trafficCaptured);
    if (v236) {
        session.setDriveIdentity({2, Series::MG, Generation::V2_35, {}});
        session.setSoftLimits(2, limits(2.0));
    }
    QVERIFY(openOn(session, spec, old, listenOnly ? LinkMode::ListenOnly : LinkMode::Active,
                   rs485 ? protocol::Link::Rs485 : protocol::Link::Can));
    const MultiTorqueResult r = sendAndWait(session, {torque(1, 0.5), torque(2, iq2)});
    QCOMPARE(r.status, RequestStatus::Error);
    QCOMPARE(r.attempts, 0);
    QVERIFY(r.refused());
    QCOMPARE(r.refusal, listenOnly ? SendRefusal::ListenOnly : SendRefusal::None);
    QVERIFY2(r.reason.contains(words), qPrintable(r.reason));
    for (const RequestResult &d : r.drives)
        QCOMPARE(d.attempts, 0);
    // A read after it goes out alone: the refusal left nothing on the wire before it.
    if (!listenOnly) {
        QObject context;
        bool read = false;
        session.send(bustest::plainRequest(Command::ReadState1, 1), &context,
                     [&read](const RequestResult &) { read = true; });
        QTRY_VERIFY_WITH_TIMEOUT(read, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!sent(traffic).isEmpty(), 5000);
        QCOMPARE(sent(traffic), QStringList{QStringLiteral("read_state1")});
    } else {
        QTest::qWait(200);
        QCOMPARE(sent(traffic), QStringList{});
    }
}

void tst_BusMultiTorque::speedWatchStopsEveryDriveOfTheFrame()
{
    BusSession session;
    QSignalSpy trips(&session, &BusSession::speedWatchTripped);
    QSignalSpy done(&session, &BusSession::requestCompleted);
    QVERIFY(openOn(session, QStringLiteral("1:MG,2:MG"), {1, 2}));
    // Drive 1 speeds up past 60 dps; drive 2 turns slowly under a small torque.
    session.setSoftLimits(1, limits(2.0, 60));
    session.setSoftLimits(2, limits(2.0, 18000));
    const MultiTorqueResult r = sendAndWait(session, {torque(1, 1.6), torque(2, 0.05)});
    QCOMPARE(r.status, RequestStatus::Ok);
    QTRY_COMPARE_WITH_TIMEOUT(trips.size(), 1, 20000);
    QCOMPARE(trips.at(0).at(0).value<SpeedWatchTrip>().id, 1);
    // Motor Stop to both drives of the frame, acknowledged.
    const auto stopped = [&done](int id) {
        for (const auto &args : done) {
            const RequestResult res = args.at(0).value<RequestResult>();
            if (res.request.command == Command::MotorStop && res.request.id == id && res.ok())
                return true;
        }
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(stopped(1) && stopped(2), 20000);
    session.emergencyStop({1, 2});
}

QTEST_GUILESS_MAIN(tst_BusMultiTorque)
#include "tst_busmultitorque.moc"
