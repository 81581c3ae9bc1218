#include "E2eUtil.h"

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <safety/MotionGuard.h>
#include <text/VerdictText.h>
#include <transport/SerialTransport.h>

#include <QtCore/QDir>
#include <QtCore/QSet>
#include <QtCore/QTemporaryDir>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <cmath>
#include <functional>

using namespace lk;
using namespace lk::bus;
using namespace lk::e2e;
using protocol::Command;
using protocol::Series;

namespace {

constexpr int kWaitMs = 30000; // generous: the machine may be loaded

/// Send and wait for the completion; nullopt only if the engine never answered (a bug).
std::optional<RequestResult> sendAndWait(BusSession &s, const protocol::Request &r,
                                         Priority p = Priority::Operator)
{
    std::optional<RequestResult> out;
    quint64 ticket = 0;
    const auto c = QObject::connect(&s, &BusSession::requestCompleted,
                                    [&out, &ticket](const RequestResult &res) {
                                        if (res.ticket == ticket)
                                            out = res;
                                    });
    ticket = s.send(r, p);
    (void)QTest::qWaitFor([&out] { return out.has_value(); }, kWaitMs);
    QObject::disconnect(c);
    return out;
}

protocol::Request plainRequest(Command c, int id)
{
    return *protocol::build::plain(c, id).request;
}

/// A reply's payload of type T, read with `command`; nullopt when the read failed.
template <typename T> std::optional<T> readValue(BusSession &s, Command command, int id)
{
    const std::optional<RequestResult> r = sendAndWait(s, plainRequest(command, id));
    if (!r || !r->ok() || !r->reply || !std::holds_alternative<T>(r->reply->payload))
        return std::nullopt;
    return std::get<T>(r->reply->payload);
}

/// One motion case: the request to send (from the start angle) and which way it must move.
struct MotionCase {
    const char *name;
    int id;
    std::function<protocol::BuildResult(double startDeg)> build;
    int direction; ///< +1 clockwise (positive speed), -1 counter-clockwise
    /// Where the motion must end, or nullopt for a continuous motion (speed, torque, power).
    std::function<std::optional<double>(double startDeg)> target;
    bool singleTurn = false; ///< the target is a single-turn angle 0..360
};

const QList<MotionCase> &motionCases()
{
    using namespace protocol::build;
    using protocol::SpinDirection;
    const auto none = [](double) { return std::optional<double>(); };
    static const QList<MotionCase> kCases{
        {"speed cw", 3, [](double) { return speed(3, 360); }, +1, none},
        {"speed ccw", 3, [](double) { return speed(3, -360); }, -1, none},
        {"torque +", 3, [](double) { return torque(3, 0.3, {}); }, +1, none},
        {"torque -", 3, [](double) { return torque(3, -0.3, {}); }, -1, none},
        {"open loop (MS)", 17, [](double) { return openLoop(17, 150); }, +1, none},
        {"speed (MG)", 32, [](double) { return speed(32, -720); }, -1, none},
        {"multi position", 3, [](double a) { return multiPosition(3, a + 90); }, +1,
         [](double a) { return std::optional<double>(a + 90); }},
        {"multi position limited", 3, [](double a) { return multiPosition(3, a - 90, 180); }, -1,
         [](double a) { return std::optional<double>(a - 90); }},
        {"increment", 3, [](double) { return incrementPosition(3, 45); }, +1,
         [](double a) { return std::optional<double>(a + 45); }},
        {"increment limited", 3, [](double) { return incrementPosition(3, -45, 180); }, -1,
         [](double a) { return std::optional<double>(a - 45); }},
        {"single position cw", 3,
         [](double) { return singlePosition(3, SpinDirection::Clockwise, 90); }, +1,
         [](double) { return std::optional<double>(90); }, true},
        {"single position limited ccw", 3,
         [](double) { return singlePosition(3, SpinDirection::CounterClockwise, 270, 180); }, -1,
         [](double) { return std::optional<double>(270); }, true},
    };
    return kCases;
}

double angleGap(double a, double b, bool singleTurn)
{
    double d = std::fabs(a - b);
    if (singleTurn)
        d = std::min(d, 360 - d);
    return d;
}

} // namespace

/// lksim on a pseudo-terminal, driven through a real QSerialPort (SerialTransport) and the
/// thread-safe BusSession, as lkstudio does.
class tst_E2eBus : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void scanFindsExactlyTheSimulatedIds();
    void readsRoundTrip_data();
    void readsRoundTrip();
    void writesRoundTrip();
    void controlModesMoveTheMotor_data();
    void controlModesMoveTheMotor();
    void romSurvivesRestartRamDoesNot();
    void faultsAreCountedAndSurvived();
    void killMidPollDisconnectsCleanlyAndReconnects();

private:
    bool startSim(const QStringList &extra = {});
    void openSession(BusSession &session);
    void declareSeries(BusSession &session);
    void bringToRest(BusSession &session, int id);

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

void tst_E2eBus::initTestCase()
{
    registerBusMetaTypes();
}

bool tst_E2eBus::startSim(const QStringList &extra)
{
    if (!m_sim)
        m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    const bool ok = m_sim->start(simArgs(m_link, extra));
    if (!ok)
        qWarning("%s", qPrintable(m_sim->errorString()));
    return ok;
}

void tst_E2eBus::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_link = m_dir->filePath(QStringLiteral("lkbus"));
    QVERIFY(startSim());
}

void tst_E2eBus::cleanup()
{
    if (m_sim)
        verifyNoCollisions(*m_sim);
    m_sim.reset();
    m_dir.reset();
}

void tst_E2eBus::openSession(BusSession &session)
{
    transport::SerialSettings s;
    s.portName = m_link; // the symlink: it follows lksim across restarts
    // Functional tests, not timing: margins wide enough for a loaded 2-core machine.
    BusConfig c;
    c.minMarginMs = 30;
    c.initialMarginMs = 100;
    session.open(transport::SerialTransport::factory(s), 115200, c);
    QTRY_VERIFY_WITH_TIMEOUT(session.connection().isOpen(), kWaitMs);
}

void tst_E2eBus::declareSeries(BusSession &session)
{
    session.setSeries(3, Series::MF);
    session.setSeries(17, Series::MS);
    session.setSeries(32, Series::MG);
}

void tst_E2eBus::bringToRest(BusSession &session, int id)
{
    // Speed 0 holds the rotor; once still, motor off leaves it there.
    QVERIFY(sendAndWait(session, *protocol::build::speed(id, 0).request)->ok());
    QVERIFY(QTest::qWaitFor(
        [&] {
            const auto s = readValue<protocol::State2>(session, Command::ReadState2, id);
            return s && std::abs(s->speedDps) < 3;
        },
        kWaitMs));
    QVERIFY(sendAndWait(session, plainRequest(Command::MotorOff, id))->ok());
}

void tst_E2eBus::scanFindsExactlyTheSimulatedIds()
{
    BusSession session;
    openSession(session);
    QSignalSpy finished(&session, &BusSession::scanFinished);
    const QSet<int> expected{3, 17, 32};

    // The default (fast) scan never reports an ID that is not there.
    session.scan();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 120000);
    const auto quick = finished.at(0).at(0).value<ScanSummary>();
    QVERIFY2(quick.error.isEmpty(), qPrintable(quick.error));
    for (const FoundMotor &m : quick.motors)
        QVERIFY(expected.contains(m.id));
    qInfo("default scan over the pty: %.0f ms, %d of 3 found", quick.elapsedS * 1e3,
          int(quick.motors.size()));

    // With a retry pass for silent IDs the result is exact whatever the machine's load.
    ScanOptions o;
    o.retries = 1;
    session.scan(o);
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 120000);
    const auto summary = finished.at(1).at(0).value<ScanSummary>();
    QSet<int> found;
    for (const FoundMotor &m : summary.motors) {
        found.insert(m.id);
        QVERIFY(m.state1);
        QVERIFY(!m.model.motorName.isEmpty());
    }
    QCOMPARE(found, expected);
    QCOMPARE(session.series(3), std::optional<Series>(Series::MF));
    QCOMPARE(session.series(17), std::optional<Series>(Series::MS));
    QCOMPARE(session.series(32), std::optional<Series>(Series::MG));
}

void tst_E2eBus::readsRoundTrip_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<int>("command");
    QTest::addColumn<bool>("answers");
    const QList<Command> reads{
        Command::ReadModel,   Command::ReadPid,       Command::ReadAccel,
        Command::ReadEncoder, Command::ReadMultiTurn, Command::ReadSingleTurn,
        Command::ReadState1,  Command::ReadState2,    Command::ReadState3};
    for (int id : {3, 17, 32}) {
        for (Command c : reads) {
            // MS drives have no phase-current readout: like real ones they stay silent.
            const bool answers = !(id == 17 && c == Command::ReadState3);
            QTest::addRow("%s ID %d", qPrintable(protocol::CommandTable::name(c)), id)
                << id << int(c) << answers;
        }
    }
}

void tst_E2eBus::readsRoundTrip()
{
    QFETCH(int, id);
    QFETCH(int, command);
    QFETCH(bool, answers);
    BusSession session;
    openSession(session);
    declareSeries(session);
    const std::optional<RequestResult> r =
        sendAndWait(session, plainRequest(static_cast<Command>(command), id));
    QVERIFY(r);
    if (!answers) {
        QCOMPARE(r->status, RequestStatus::Timeout);
        QVERIFY(r->reason.contains(QStringLiteral("ID %1").arg(id)));
        return;
    }
    QVERIFY2(r->ok(), qPrintable(r->reason));
    QCOMPARE(int(r->reply->command), command);
    QCOMPARE(int(r->reply->id), id);
    if (command == int(Command::ReadState2)) {
        const auto &s2 = std::get<protocol::State2>(r->reply->payload);
        QCOMPARE(s2.isPower, id == 17); // MS replies carry power, decoded as such
    }
    if (command == int(Command::ReadState1))
        QVERIFY(std::get<protocol::State1>(r->reply->payload).voltageV() > 5);
}

void tst_E2eBus::writesRoundTrip()
{
    BusSession session;
    openSession(session);
    declareSeries(session);
    using namespace protocol::build;

    const protocol::PidGains gains{11, 22, 33, 44, 55, 66};
    QVERIFY(sendAndWait(session, *writePid(3, gains, false).request)->ok());
    QVERIFY(readValue<protocol::PidGains>(session, Command::ReadPid, 3) == gains);

    QVERIFY(sendAndWait(session, *writeAcceleration(17, 12345).request)->ok());
    const auto accel = readValue<protocol::Acceleration>(session, Command::ReadAccel, 17);
    QVERIFY(accel);
    QCOMPARE(accel->dps2, 12345);

    QVERIFY(sendAndWait(session, *writeEncoderOffset(32, 4321).request)->ok());
    const auto enc = readValue<protocol::EncoderReading>(session, Command::ReadEncoder, 32);
    QVERIFY(enc);
    QCOMPARE(enc->encoderOffset, quint16(4321));

    // clear_angle: the current position becomes zero (until power-off).
    QVERIFY(sendAndWait(session, plainRequest(Command::ClearAngle, 3))->ok());
    const auto multi = readValue<protocol::MultiTurnAngle>(session, Command::ReadMultiTurn, 3);
    QVERIFY(multi);
    QVERIFY2(std::fabs(multi->degrees()) < 1, qPrintable(QString::number(multi->degrees())));

    const auto cleared = readValue<protocol::State1>(session, Command::ClearErrors, 3);
    QVERIFY(cleared);
    QCOMPARE(cleared->errorState, quint8(0));
}

void tst_E2eBus::controlModesMoveTheMotor_data()
{
    QTest::addColumn<int>("index");
    for (int i = 0; i < motionCases().size(); ++i)
        QTest::newRow(motionCases().at(i).name) << i;
}

void tst_E2eBus::controlModesMoveTheMotor()
{
    QFETCH(int, index);
    const MotionCase &c = motionCases().at(index);
    BusSession session;
    openSession(session);
    declareSeries(session);
    bringToRest(session, c.id);
    const Command angleRead = c.singleTurn ? Command::ReadSingleTurn : Command::ReadMultiTurn;
    const auto angle = [&]() -> std::optional<double> {
        if (c.singleTurn) {
            const auto a = readValue<protocol::SingleTurnAngle>(session, angleRead, c.id);
            return a ? std::optional<double>(a->degrees()) : std::nullopt;
        }
        const auto a = readValue<protocol::MultiTurnAngle>(session, angleRead, c.id);
        return a ? std::optional<double>(a->degrees()) : std::nullopt;
    };
    const std::optional<double> start = angle();
    QVERIFY(start);

    const protocol::BuildResult built = c.build(*start);
    QVERIFY(built.ok());
    const Series series = *session.series(c.id);
    const safety::Verdict v =
        safety::MotionGuard::check(*built.request, series, safety::SoftLimits::defaults(series));
    QVERIFY2(v.allowed(), qPrintable(lk::text::VerdictText::verdict(
                              v, series))); // the gate every motion command passes
    const std::optional<RequestResult> sent = sendAndWait(session, *built.request);
    QVERIFY(sent);
    // A reply lost to a stall of the loaded machine is not retried for an increment (it
    // would move twice); lksim got the command all the same, as the motion below shows.
    QVERIFY2(sent->ok() || sent->status == RequestStatus::Timeout, qPrintable(sent->reason));

    double fastest = 0; // the speed seen with the largest magnitude: its sign is the way
    const std::optional<double> target = c.target(*start);
    const bool reached = QTest::qWaitFor(
        [&] {
            const auto s = readValue<protocol::State2>(session, Command::ReadState2, c.id);
            if (s && std::abs(s->speedDps) > std::abs(fastest))
                fastest = s->speedDps;
            if (!target)
                return std::abs(fastest) > 20;
            const std::optional<double> now = angle();
            return now && s && angleGap(*now, *target, c.singleTurn) < 1.5 &&
                   std::abs(s->speedDps) < 20;
        },
        kWaitMs);
    const std::optional<double> end = angle();
    QVERIFY(sendAndWait(session, plainRequest(Command::MotorOff, c.id))->ok());
    QVERIFY2(reached, qPrintable(QStringLiteral("start %1, end %2, target %3, fastest %4 dps")
                                     .arg(*start)
                                     .arg(end.value_or(NAN))
                                     .arg(target.value_or(NAN))
                                     .arg(fastest)));
    QCOMPARE(fastest > 0 ? 1 : -1, c.direction);
}

void tst_E2eBus::romSurvivesRestartRamDoesNot()
{
    const QString romDir = m_dir->filePath(QStringLiteral("rom"));
    QVERIFY(QDir().mkpath(romDir));
    QVERIFY(startSim({QStringLiteral("--rom-dir"), romDir}));
    BusSession session;
    openSession(session);
    declareSeries(session);
    using namespace protocol::build;
    const protocol::PidGains rom{90, 80, 70, 60, 50, 40};
    const protocol::PidGains ram{1, 2, 3, 4, 5, 6};
    const auto original = readValue<protocol::PidGains>(session, Command::ReadPid, 17);
    QVERIFY(original);
    QVERIFY(sendAndWait(session, *writePid(3, rom, true).request)->ok());   // ROM (and RAM)
    QVERIFY(sendAndWait(session, *writePid(3, ram, false).request)->ok());  // RAM on top
    QVERIFY(sendAndWait(session, *writePid(17, ram, false).request)->ok()); // RAM only
    QVERIFY(readValue<protocol::PidGains>(session, Command::ReadPid, 3) == ram);

    // Power cycle: stop lksim, start it again on the same link with the same ROM directory.
    m_sim->stop();
    QTRY_VERIFY_WITH_TIMEOUT(!session.connection().isOpen(), kWaitMs);
    QVERIFY(startSim({QStringLiteral("--rom-dir"), romDir}));
    session.reconnect();
    QTRY_VERIFY_WITH_TIMEOUT(session.connection().isOpen(), kWaitMs);
    QVERIFY(readValue<protocol::PidGains>(session, Command::ReadPid, 3) == rom);
    QVERIFY(readValue<protocol::PidGains>(session, Command::ReadPid, 17) == original);
}

void tst_E2eBus::faultsAreCountedAndSurvived()
{
    QVERIFY(startSim({QStringLiteral("--faults"),
                      QStringLiteral("drop=0.05,corrupt=0.05,garbage=0.05,length=0.02,seed=5")}));
    BusSession session;
    QSignalSpy stats(&session, &BusSession::statisticsUpdated);
    QSignalSpy telemetry(&session, &BusSession::telemetryReceived);
    QSignalSpy errors(&session, &BusSession::errorOccurred);
    openSession(session);
    declareSeries(session);
    session.startPolling(PollPlan::standard({3, 17, 32}));
    QTRY_VERIFY_WITH_TIMEOUT(
        !stats.isEmpty() && stats.last().at(0).value<BusStatistics>().bus.replies >= 600, 120000);
    const BusStatistics s = stats.last().at(0).value<BusStatistics>();
    qInfo("faults over the pty: %llu replies, %llu checksum errors, %llu garbage bytes, %llu "
          "parse errors, %llu timeouts",
          s.bus.replies, s.bus.checksumErrors, s.bus.garbageBytes, s.bus.parseErrors,
          s.bus.timeouts);
    QVERIFY(s.bus.checksumErrors > 0);
    QVERIFY(s.bus.garbageBytes > 0);
    QVERIFY(s.bus.parseErrors > 0);
    QVERIFY(s.bus.timeouts > 0); // dropped replies (and MS's silence on 0x9D is skipped)
    QVERIFY(session.connection().isOpen());
    QCOMPARE(errors.size(), 0);
    // Still polling after all that.
    telemetry.clear();
    QTRY_VERIFY_WITH_TIMEOUT(telemetry.size() >= 3, kWaitMs);
    session.stopPolling();
}

void tst_E2eBus::killMidPollDisconnectsCleanlyAndReconnects()
{
    BusSession session;
    QSignalSpy done(&session, &BusSession::requestCompleted);
    QSignalSpy telemetry(&session, &BusSession::telemetryReceived);
    QSignalSpy polling(&session, &BusSession::pollingChanged);
    QSignalSpy errors(&session, &BusSession::errorOccurred);
    openSession(session);
    declareSeries(session);
    session.startPolling(PollPlan::standard({3, 17, 32}));
    QTRY_VERIFY_WITH_TIMEOUT(telemetry.size() >= 3, kWaitMs);

    // Queue operator reads, then pull the plug while they and the polls are pending.
    QSet<quint64> tickets;
    for (int i = 0; i < 20; ++i)
        tickets.insert(session.send(plainRequest(Command::ReadState1, 3)));
    m_sim->kill();
    QTRY_COMPARE_WITH_TIMEOUT(session.connection().state, transport::Transport::State::Disconnected,
                              kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), tickets.size(), kWaitMs); // every request ended once
    QSet<quint64> ended;
    for (const auto &args : done) {
        const RequestResult r = args.at(0).value<RequestResult>();
        QVERIFY(tickets.contains(r.ticket));
        QVERIFY(!ended.contains(r.ticket));
        ended.insert(r.ticket);
        QVERIFY2(r.status == RequestStatus::Ok || r.status == RequestStatus::Disconnected ||
                     r.status == RequestStatus::Timeout,
                 requestStatusName(r.status));
    }
    QCOMPARE(polling.last().at(0).toBool(), false);
    QCOMPARE(errors.size(), 0); // an unplug is a state, not an error
    QVERIFY2(session.connection().reason.contains(QStringLiteral("unplugged")),
             qPrintable(session.connection().reason));
    const std::optional<RequestResult> whileDown =
        sendAndWait(session, plainRequest(Command::ReadPid, 3));
    QVERIFY(whileDown);
    QCOMPARE(whileDown->status, RequestStatus::Disconnected);

    // The adapter comes back on the same path: reconnect, and the poll plan resumes.
    QVERIFY(startSim());
    session.reconnect();
    QTRY_VERIFY_WITH_TIMEOUT(session.connection().isOpen(), kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(polling.last().at(0).toBool(), true, kWaitMs);
    telemetry.clear();
    QTRY_VERIFY_WITH_TIMEOUT(telemetry.size() >= 3, kWaitMs);
    const std::optional<RequestResult> after =
        sendAndWait(session, plainRequest(Command::ReadPid, 3));
    QVERIFY(after && after->ok());
    session.close();
}

QTEST_GUILESS_MAIN(tst_E2eBus)
#include "tst_e2ebus.moc"
