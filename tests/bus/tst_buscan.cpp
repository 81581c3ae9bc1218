#include "BusTestUtil.h"

#include <bus/BusSession.h>
#include <bus/LinkTiming.h>
#include <bus/UnansweredPolls.h>
#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <protocol/RequestBuilder.h>
#include <safety/SoftLimits.h>
#include <sim/SimBus.h>
#include <sim/SimCanFront.h>
#include <transport/SimTransport.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <atomic>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Generation;
using protocol::Series;

namespace {
/// Simulated drives on CAN (SimTransport over SimCanFront); drive 1 an old CAN MG, drive 2 a
/// V2.36 MF answering on 0x180+ID as its document says.
struct CanSim {
    QString spec = QStringLiteral("1:MG,2:MF@2.35");
    std::atomic<int> modelReads{0};
    std::atomic<int> writes{0};

    TransportFactory factory()
    {
        return [this](int bitRate) -> std::unique_ptr<transport::Transport> {
            auto bus = sim::SimBus::fromSpec(*sim::SimBusSpec::parse(spec));
            auto t = std::make_unique<transport::SimTransport>(std::move(bus));
            t->setLink(protocol::Link::Can);
            t->setBaud(bitRate);
            t->setWireTimeEmulation(true);
            return t;
        };
    }
};

int countSamples(const QSignalSpy &spy, int id, TelemetryField field)
{
    int n = 0;
    for (const auto &args : spy) {
        for (const TelemetrySample &s : args.at(0).value<TelemetryBatch>())
            n += (s.id == id && s.has(field)) ? 1 : 0;
    }
    return n;
}

ScanSummary scanOnce(BusSession &session, QSignalSpy &finished)
{
    const qsizetype before = finished.size();
    ScanOptions o;
    o.lastId = 8;
    o.retries = 1;       // exact whatever the machine's load
    o.sweepBauds = true; // asked for, but CAN never sweeps
    session.scan(o);
    if (!QTest::qWaitFor([&] { return finished.size() > before; }, 60000))
        return {};
    return finished.last().at(0).value<ScanSummary>();
}
} // namespace

/// The bus engine on a CAN link: the transport says the link, and the parser, the codec's
/// layouts, the timing and the scan follow it (docs/CAN.md).
class tst_BusCan : public QObject {
    Q_OBJECT
private slots:
    void scanTellsGenerationsWithoutModelRead();
    void userIdentityDecidesAndIsKept();
    void pollingDecodesBothGenerations();
    void unknownSeriesMsIsNotAskedForPhaseCurrentsForever();
    void v236SpeedNeedsItsTorqueLimit();
    void emergencyStopReachesEveryIdOnCan();
    void statisticsUseCanTiming();
    void trafficCarriesCanRecords();
};

void tst_BusCan::scanTellsGenerationsWithoutModelRead()
{
    CanSim sim;
    BusSession session;
    QSignalSpy finished(&session, &BusSession::scanFinished);
    QSignalSpy traffic(&session, &BusSession::trafficCaptured);
    session.open(sim.factory(), 1000000);
    QTRY_VERIFY(session.connection().isOpen());
    QCOMPARE(session.connection().link, protocol::Link::Can);
    session.setTrafficCapture(true);
    const ScanSummary s = scanOnce(session, finished);
    QVERIFY(s.error.isEmpty());
    QCOMPARE(s.finalBaud, 1000000); // no sweep on CAN
    QCOMPARE(s.motors.size(), 2);
    QCOMPARE(s.motors.at(0).id, 1);
    QCOMPARE(s.motors.at(0).generation, std::optional<Generation>(Generation::V2_3));
    QCOMPARE(s.motors.at(1).id, 2);
    QCOMPARE(s.motors.at(1).generation, std::optional<Generation>(Generation::V2_35));
    for (const FoundMotor &m : s.motors) {
        QCOMPARE(m.link, protocol::Link::Can);
        QVERIFY(!m.modelKnown);
        QVERIFY(!m.series); // CAN cannot read it: the user says it
        QVERIFY(m.state1);
        // Read with the layout of its own generation: a V2.36 drive's 0.01 V field read as
        // the old 0.1 V one would show ten times its supply.
        QVERIFY2(m.state1->voltageV() > 5 && m.state1->voltageV() < 60,
                 qPrintable(QString::number(m.state1->voltageV())));
    }
    // No model read went out: CAN has no 0x12.
    QTest::qWait(100);
    for (const auto &args : traffic) {
        for (const TrafficEvent &e : args.at(0).value<TrafficBatch>()) {
            if (e.kind == TrafficEvent::Kind::Sent)
                QVERIFY(e.command != quint8(Command::ReadModel));
        }
    }
    QCOMPARE(session.knownMotors().keys(), (QList<int>{1, 2}));
    QCOMPARE(session.knownMotors().value(2).generation, Generation::V2_35);
}

void tst_BusCan::userIdentityDecidesAndIsKept()
{
    CanSim sim;
    BusSession session;
    QSignalSpy finished(&session, &BusSession::scanFinished);
    session.setDriveIdentity({1, Series::MG, Generation::V2_3, 36.0});
    session.setDriveIdentity({2, Series::MF, Generation::V2_35, {}});
    session.open(sim.factory(), 1000000);
    QTRY_VERIFY(session.connection().isOpen());
    QTRY_VERIFY(session.knownMotors().value(1).identityChosen);
    const ScanSummary s = scanOnce(session, finished);
    QCOMPARE(s.motors.size(), 2);
    QCOMPARE(s.motors.at(0).series, std::optional<Series>(Series::MG));
    QCOMPARE(s.motors.at(1).series, std::optional<Series>(Series::MF));
    // A complete scan keeps what the user said of the drives that answered.
    QTRY_COMPARE(session.series(1), std::optional<Series>(Series::MG));
    QCOMPARE(session.knownMotors().value(1).gearRatio, std::optional<double>(36.0));
    QCOMPARE(session.knownMotors().value(2).generation, Generation::V2_35);
    // And the session gives it to the next link.
    session.close();
    session.open(sim.factory(), 1000000);
    QTRY_VERIFY(session.connection().isOpen());
    QTRY_COMPARE(session.series(2), std::optional<Series>(Series::MF));
    QVERIFY(session.driveIdentity(2));
    QVERIFY(!session.driveIdentity(3));
}

void tst_BusCan::pollingDecodesBothGenerations()
{
    CanSim sim;
    BusSession session;
    QSignalSpy telemetry(&session, &BusSession::telemetryReceived);
    session.setDriveIdentity({1, Series::MG, Generation::V2_3, {}});
    session.setDriveIdentity({2, Series::MF, Generation::V2_35, {}});
    session.open(sim.factory(), 1000000);
    PollPlan p = PollPlan::standard({1, 2});
    session.startPolling(p);
    QTRY_VERIFY_WITH_TIMEOUT(countSamples(telemetry, 2, TelemetryField::MultiTurn) >= 10, 30000);
    QVERIFY(countSamples(telemetry, 1, TelemetryField::Speed) > 0);
    QVERIFY(countSamples(telemetry, 2, TelemetryField::IqA) > 0);
    // The supply each reports decodes in its generation's scale.
    double v1 = 0;
    double v2 = 0;
    for (const auto &args : telemetry) {
        for (const TelemetrySample &s : args.at(0).value<TelemetryBatch>()) {
            if (s.has(TelemetryField::Voltage))
                (s.id == 1 ? v1 : v2) = s.voltageV;
        }
    }
    QVERIFY2(v1 > 5 && v1 < 60, qPrintable(QString::number(v1)));
    QVERIFY2(v2 > 5 && v2 < 60, qPrintable(QString::number(v2)));
    session.stopPolling();
}

void tst_BusCan::unknownSeriesMsIsNotAskedForPhaseCurrentsForever()
{
    // A CAN drive has no model read: until the user chooses its series, an MS (no 0x9D) is
    // asked for phase currents with the rest. It answers everything else, so after
    // UnansweredPolls::kMisses timeouts in a row 0x9D is polled no more: not tens of
    // timeouts a second, each with the quiet after it, for as long as the plots run.
    CanSim sim;
    sim.spec = QStringLiteral("1:MS");
    BusSession session;
    QSignalSpy telemetry(&session, &BusSession::telemetryReceived);
    QSignalSpy stats(&session, &BusSession::statisticsUpdated);
    session.open(sim.factory(), 1000000);
    PollPlan p = PollPlan::standard({1});
    p.commands = {Command::ReadState1, Command::ReadState2, Command::ReadState3};
    session.startPolling(p);
    QTRY_VERIFY_WITH_TIMEOUT(countSamples(telemetry, 1, TelemetryField::Speed) >= 200, 30000);
    const auto timeouts = [&] {
        stats.clear();
        return stats.wait(5000) ? stats.last().at(0).value<BusStatistics>().bus.timeouts
                                : quint64(999);
    };
    QCOMPARE(timeouts(), quint64(lk::bus::UnansweredPolls::kMisses));
    const int before = countSamples(telemetry, 1, TelemetryField::Speed);
    QTRY_VERIFY_WITH_TIMEOUT(countSamples(telemetry, 1, TelemetryField::Speed) >= before + 200,
                             30000);
    QCOMPARE(timeouts(), quint64(lk::bus::UnansweredPolls::kMisses)); // and no more since
    QCOMPARE(countSamples(telemetry, 1, TelemetryField::PhaseCurrents), 0);
    session.stopPolling();
}

void tst_BusCan::v236SpeedNeedsItsTorqueLimit()
{
    CanSim sim;
    BusSession session;
    QSignalSpy done(&session, &BusSession::requestCompleted);
    QSignalSpy traffic(&session, &BusSession::trafficCaptured);
    session.setDriveIdentity({2, Series::MF, Generation::V2_35, {}});
    session.open(sim.factory(), 1000000);
    QTRY_VERIFY(session.connection().isOpen());
    session.setTrafficCapture(true);
    // The plain speed request has no torque limit: a V2.36 0xA2 is never sent without one.
    const protocol::BuildResult bare = protocol::build::speed(2, 90);
    QVERIFY(bare.ok());
    session.send(*bare.request);
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), 1, 10000);
    const RequestResult refused = done.at(0).at(0).value<RequestResult>();
    QCOMPARE(refused.status, RequestStatus::Error);
    QVERIFY2(refused.reason.contains(QStringLiteral("not sent")), qPrintable(refused.reason));
    // Once the drive has soft limits, the engine gives any speed their torque: 2 A at MF's
    // 33/4096 A per LSB, rounded down (never more than allowed), in B2-B3.
    safety::SoftLimits limits;
    limits.maxTorqueA = 2.0;
    session.setSoftLimits(2, limits);
    session.send(*bare.request);
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), 2, 10000);
    QCOMPARE(done.at(1).at(0).value<RequestResult>().status, RequestStatus::Ok);
    // A speed built with the limit keeps its own.
    const protocol::DecodeContext ctx{Series::MF, Generation::V2_35, protocol::Link::Can};
    const protocol::BuildResult limited = protocol::build::speed(2, 90, ctx, 1.0);
    QVERIFY(limited.ok());
    session.send(*limited.request);
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), 3, 10000);
    QCOMPARE(done.at(2).at(0).value<RequestResult>().status, RequestStatus::Ok);
    QTest::qWait(100);
    QVector<int> sentLimits;
    for (const auto &args : traffic) {
        for (const TrafficEvent &e : args.at(0).value<TrafficBatch>()) {
            if (e.kind != TrafficEvent::Kind::Sent || e.command != quint8(Command::Speed))
                continue;
            const auto record = protocol::CanRecord::decode(e.bytes);
            QVERIFY(record);
            sentLimits << qint16(quint8(record->data[2]) | (quint8(record->data[3]) << 8));
        }
    }
    // The refused one never reached the wire.
    QCOMPARE(sentLimits, (QVector<int>{248, 124}));
    session.emergencyStop({2});
}

void tst_BusCan::emergencyStopReachesEveryIdOnCan()
{
    CanSim sim;
    BusSession session;
    QSignalSpy stopped(&session, &BusSession::emergencyStopFinished);
    session.open(sim.factory(), 1000000);
    QTRY_VERIFY(session.connection().isOpen());
    session.emergencyStop();
    QTRY_COMPARE_WITH_TIMEOUT(stopped.size(), 1, 30000);
    const QVector<int> acked = stopped.at(0).at(1).value<QVector<int>>();
    const QVector<int> silent = stopped.at(0).at(2).value<QVector<int>>();
    QVERIFY(acked.contains(1));
    QVERIFY(acked.contains(2));
    QCOMPARE(acked.size() + silent.size(), 32);
}

void tst_BusCan::statisticsUseCanTiming()
{
    CanSim sim;
    BusSession session;
    QSignalSpy stats(&session, &BusSession::statisticsUpdated);
    session.setDriveIdentity({1, Series::MG, Generation::V2_3, {}});
    session.open(sim.factory(), 500000);
    PollPlan p = PollPlan::standard({1});
    p.commands = {Command::ReadState2};
    session.startPolling(p);
    QTRY_VERIFY_WITH_TIMEOUT(!stats.isEmpty() &&
                                 stats.last().at(0).value<BusStatistics>().pollLimitPerSecond > 0,
                             10000);
    const BusStatistics s = stats.last().at(0).value<BusStatistics>();
    QCOMPARE(s.link, protocol::Link::Can);
    QCOMPARE(s.baud, 500000);
    // The limit counts CAN frames (0.54 ms of wire a transaction at 500 kbit/s), not 8N1
    // bytes at "500000 baud" (0.3 ms): with the same turnaround it is the CAN figure.
    const double turnaroundS = s.turnaroundMs * 1e-3;
    const double can =
        LinkTiming::can(500000).transactionsPerSecond({Command::ReadState2}, turnaroundS);
    QVERIFY2(qAbs(s.pollLimitPerSecond - can) < 1e-6 * can,
             qPrintable(QStringLiteral("%1 vs %2").arg(s.pollLimitPerSecond).arg(can)));
    QCOMPARE(s.bus.checksumErrors, quint64(0));
    session.stopPolling();
}

void tst_BusCan::trafficCarriesCanRecords()
{
    CanSim sim;
    BusSession session;
    QSignalSpy traffic(&session, &BusSession::trafficCaptured);
    QSignalSpy done(&session, &BusSession::requestCompleted);
    session.open(sim.factory(), 1000000);
    QTRY_VERIFY(session.connection().isOpen());
    session.setTrafficCapture(true);
    session.send(plainRequest(Command::ReadState2, 2));
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), 1, 10000);
    QCOMPARE(done.at(0).at(0).value<RequestResult>().status, RequestStatus::Ok);
    QTRY_VERIFY_WITH_TIMEOUT(!traffic.isEmpty(), 5000);
    QTest::qWait(100);
    QStringList lines;
    for (const auto &args : traffic) {
        for (const TrafficEvent &e : args.at(0).value<TrafficBatch>()) {
            if (e.kind != TrafficEvent::Kind::Sent && e.kind != TrafficEvent::Kind::Frame)
                continue;
            QCOMPARE(e.context.link, protocol::Link::Can);
            QCOMPARE(e.id, 2);
            lines << protocol::CanRecord::decode(e.bytes)->candumpText();
        }
    }
    QCOMPARE(lines.value(0), QStringLiteral("142#9C00000000000000"));
    QVERIFY2(lines.value(1).startsWith(QStringLiteral("182#9C")), qPrintable(lines.join(' ')));
}

QTEST_GUILESS_MAIN(tst_BusCan)
#include "tst_buscan.moc"
