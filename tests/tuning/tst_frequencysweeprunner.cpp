// FrequencySweepRunner against the built-in simulator at 1 Mbaud (issue #25): the measured
// response against the simulator's own transfer function, refusals and silent drives that
// send nothing, and the abort path (stream halted, motor off, the read gains in RAM).
#include <bus/BusSession.h>
#include <bus/SetpointStream.h>
#include <protocol/RequestBuilder.h>
#include <sim/DrivePhysics.h>
#include <sim/PositionLoopTransfer.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <sim/SpeedLoopTransfer.h>
#include <transport/SimTransport.h>
#include <tuning/FrequencySweepRunner.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::bus;
using namespace lk::tuning;
using protocol::Command;
using protocol::Series;

namespace {

constexpr int kWaitMs = 60000; // a loaded 2-core machine; never a timing assertion
constexpr int kBaud = 1000000;

TransportFactory simFactory(const QString &spec)
{
    return [spec](int baud) -> std::unique_ptr<transport::Transport> {
        auto bus = sim::SimBus::fromSpec(*sim::SimBusSpec::parse(spec));
        auto t = std::make_unique<transport::SimTransport>(std::move(bus));
        t->setBaud(baud);
        return t;
    };
}

bool isMotion(Command c)
{
    return c == Command::Speed || c == Command::Torque ||
           (c >= Command::MultiPosition && c <= Command::IncrementPositionLimited);
}

/// A session on the simulated bus (drive 3 MF V2.3, drive 5 MG on fw 2.35, drive 7 MF without
/// Coulomb friction: its position loop is linear at any amplitude).
struct Rig {
    BusSession session;
    QSignalSpy completed{&session, &BusSession::requestCompleted};
    FrequencySweepRunner runner{session};
    QSignalSpy finished{&runner, &FrequencySweepRunner::finished};
    QSignalSpy failed{&runner, &FrequencySweepRunner::failed};
    Rig()
    {
        session.open(simFactory(QStringLiteral("3:MF,5:MG@2.35,7:MF+friction=0")), kBaud);
        (void)QTest::qWaitFor([this] { return session.connection().isOpen(); }, kWaitMs);
        identify(3);
        identify(5);
        identify(7);
    }
    /// read_model, as lkstudio and lkctl do first: the session learns series and generation.
    void identify(int id) { request(*protocol::build::plain(Command::ReadModel, id).request); }
    RequestResult request(const protocol::Request &r)
    {
        const quint64 t = session.send(r);
        std::optional<RequestResult> out;
        (void)QTest::qWaitFor(
            [&] {
                for (const auto &args : completed) {
                    const auto res = args.at(0).value<RequestResult>();
                    if (res.ticket == t)
                        out = res;
                }
                return out.has_value();
            },
            kWaitMs);
        return out.value_or(RequestResult{});
    }
    FrequencySweepResult waitForEnd()
    {
        if (!QTest::qWaitFor([this] { return finished.size() + failed.size() > 0; }, kWaitMs))
            return {};
        return (finished.isEmpty() ? failed : finished).at(0).at(0).value<FrequencySweepResult>();
    }
    int motionCount() const
    {
        int n = 0;
        for (const auto &args : completed)
            n += isMotion(args.at(0).value<RequestResult>().request.command) ? 1 : 0;
        return n;
    }
    std::optional<LoopGains> gains(int id)
    {
        const protocol::Generation g = session.knownMotors().value(id).generation;
        QVector<protocol::Reply> replies;
        for (const protocol::Request &r : LoopGains::reads(id, g)) {
            const RequestResult res = request(r);
            if (res.reply)
                replies.append(*res.reply);
        }
        return LoopGains::decode(g, replies);
    }
    double angle(int id)
    {
        const RequestResult r =
            request(*protocol::build::plain(Command::ReadMultiTurn, id).request);
        return r.reply ? std::get<protocol::MultiTurnAngle>(r.reply->payload).degrees() : 0;
    }
    protocol::State2 state(int id)
    {
        const RequestResult r = request(*protocol::build::plain(Command::ReadState2, id).request);
        return r.reply ? std::get<protocol::State2>(r.reply->payload) : protocol::State2{};
    }
};

FrequencySweepSpec quickSpec(int id)
{
    FrequencySweepSpec s;
    s.id = id;
    s.fromHz = 3;
    s.toHz = 300;
    s.points = 7;
    s.amplitude = 60;
    s.operatingPoint = 300;
    s.leadInS = 0.3;
    s.minPointS = 0.4;
    return s;
}

/// The simulated drive's own speed loop for the gains read from it (lksim saturates its gains
/// at 255, as SimParams does).
protocol::PidGains simGains(const LoopGains &g)
{
    const auto u8 = [](quint16 v) { return quint8(std::min<int>(v, 255)); };
    return {u8(g.angle.kp), u8(g.angle.ki),   u8(g.speed.kp),
            u8(g.speed.ki), u8(g.current.kp), u8(g.current.ki)};
}

sim::SpeedLoopTransfer transferFor(Series series, const LoopGains &g)
{
    return sim::SpeedLoopTransfer::forSeries(series, simGains(g),
                                             {g.angle.kd, g.speed.kd, g.current.kd});
}

/// A position sweep of 5 deg around where the drive is, inside an angle window of +-20 deg.
FrequencySweepSpec positionSpec(int id)
{
    FrequencySweepSpec s = quickSpec(id);
    s.loop = SweepLoop::Position;
    s.operatingPoint.reset(); // the runner reads it
    s.fromHz = 1;
    s.toHz = 40;
    s.points = 6;
    s.amplitude = 5;
    return s;
}

safety::SoftLimits windowAround(double deg, double halfWidth)
{
    safety::SoftLimits limits = safety::SoftLimits::defaults(Series::MF);
    limits.minAngleDeg = deg - halfWidth;
    limits.maxAngleDeg = deg + halfWidth;
    return limits;
}

} // namespace

class tst_FrequencySweepRunner : public QObject {
    Q_OBJECT
private slots:
    void measuresTheSimulatorsTransfer_data();
    void measuresTheSimulatorsTransfer();
    void refusedSweepSendsNothing();
    void silentDriveSendsNothing();
    void abortHaltsRestoresAndTurnsOff();
    void positionMeasuresTheSimulatorsTransfer();
    void positionSweepBeyondALimitSendsNothing_data();
    void positionSweepBeyondALimitSendsNothing();
    void endsAtTheSpeedItWasGiven();
};

void tst_FrequencySweepRunner::measuresTheSimulatorsTransfer_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<Series>("series");
    QTest::newRow("MF V2.3") << 3 << Series::MF;
    QTest::newRow("MG V2.35") << 5 << Series::MG;
}

void tst_FrequencySweepRunner::measuresTheSimulatorsTransfer()
{
    QFETCH(int, id);
    QFETCH(Series, series);
    Rig rig;
    QVERIFY(rig.runner.start(quickSpec(id), safety::SoftLimits::defaults(series)));
    const FrequencySweepResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    QVERIFY(r.gains);
    QVERIFY(r.response.sampleRateHz > 100);
    const sim::SpeedLoopTransfer h = transferFor(series, *r.gains);
    QCOMPARE(r.response.samplesPerPeriod, FrequencyResponse::kSpeedSamplesPerPeriod);
    const double resolved = r.response.resolvedHz();
    QVERIFY(!r.response.points.isEmpty());
    for (const FrequencyPoint &p : r.response.points) {
        const double db = h.magnitudeDb(p.hz);
        const double deg = h.phaseDeg(p.hz);
        qInfo("%6.1f Hz: %6.2f dB %7.1f deg (q %.3f, %d samples) | sim %6.2f dB %7.1f deg", p.hz,
              p.magnitudeDb, p.phaseDeg, p.quality, p.samples, db, deg);
        QVERIFY(p.hz <= resolved);
        // The figure (1 dB, 5 degrees up to a quarter of the rate) is bench_freq's,
        // on lksim; here, on a host loaded by a parallel build, the last octave below the
        // resolution gets twice that (the setpoints' timing jitters by milliseconds).
        const double scale = p.hz <= resolved / 2 ? 1 : 2;
        QVERIFY2(std::abs(p.magnitudeDb - db) < 1.0 * scale, qPrintable(QString::number(p.hz)));
        QVERIFY2(std::abs(std::remainder(p.phaseDeg - deg, 360.0)) < 5.0 * scale,
                 qPrintable(QString::number(p.hz)));
        QVERIFY(p.quality > 0.2 || scale > 1); // host jitter lowers it, not the ratio
    }
    // What the rate does not resolve is dropped, with that reason.
    for (const DroppedFrequency &d : r.response.dropped)
        QVERIFY(d.reason != DroppedReason::AboveResolution || d.hz > resolved);
    QCOMPARE(r.response.points.size() + r.response.dropped.size(), 7);
    QVERIFY(r.response.figures().peakDb);
    // Back at the speed read before (0 dps) and nothing moving: as facts and in words.
    QCOMPARE(r.outcome.end, SearchEnd::Finished);
    QCOMPARE(r.outcome.drive, DriveLeft::HoldsZero);
    QVERIFY(r.outcome.gainsRestored);
    QVERIFY2(r.message.contains(QLatin1String("holds 0 dps")), qPrintable(r.message));
}

void tst_FrequencySweepRunner::refusedSweepSendsNothing()
{
    Rig rig;
    const std::optional<LoopGains> before = rig.gains(3);
    QVERIFY(before);
    safety::SoftLimits limits = safety::SoftLimits::defaults(Series::MF);
    limits.maxSpeedDps = 200; // the sine's peak (300 + 60) is beyond it
    QVERIFY(rig.runner.start(quickSpec(3), limits));
    const FrequencySweepResult r = rig.waitForEnd();
    QCOMPARE(r.failure, StepTestFailure::Refused);
    QVERIFY(!r.refusal.allowed());
    QCOMPARE(r.refusedDps, 300.0); // the centre, the first extreme checked
    QCOMPARE(rig.motionCount(), 0);
    QCOMPARE(r.outcome.end, SearchEnd::Refused);
    // The acceleration limit, lifted before the plan was checked, is back as read.
    QCOMPARE(r.outcome.drive,
             before->accelerationDps2 != 0 ? DriveLeft::NoStepSent : DriveLeft::Untouched);
    QVERIFY(r.outcome.gainsRestored);
    QCOMPARE(rig.gains(3), before);
}

void tst_FrequencySweepRunner::silentDriveSendsNothing()
{
    Rig rig;
    QVERIFY(rig.runner.start(quickSpec(9), safety::SoftLimits::defaults(Series::MF)));
    const FrequencySweepResult r = rig.waitForEnd();
    QCOMPARE(r.failure, StepTestFailure::Silent);
    QVERIFY2(r.message.contains(QLatin1String("gains could not be read")), qPrintable(r.message));
    QCOMPARE(rig.motionCount(), 0);
    QCOMPARE(r.outcome.end, SearchEnd::FailedToRead);
    QCOMPARE(r.outcome.drive, DriveLeft::Untouched);
}

void tst_FrequencySweepRunner::abortHaltsRestoresAndTurnsOff()
{
    Rig rig;
    const std::optional<LoopGains> before = rig.gains(3);
    QVERIFY(before);
    FrequencySweepSpec spec = quickSpec(3);
    spec.minPointS = 3; // long enough to abort in the middle
    QVERIFY(rig.runner.start(spec, safety::SoftLimits::defaults(Series::MF)));
    // Mid-sweep: setpoints are flowing.
    QVERIFY(QTest::qWaitFor([&] { return rig.motionCount() > 200; }, kWaitMs));
    rig.runner.abort();
    const FrequencySweepResult r = rig.waitForEnd();
    QCOMPARE(r.failure, StepTestFailure::Aborted);
    QVERIFY2(r.message.contains(QLatin1String("drive 3 is off")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("are back in RAM")), qPrintable(r.message));
    QCOMPARE(r.outcome.end, SearchEnd::AbortedByUser);
    QCOMPARE(r.outcome.drive, DriveLeft::Off);
    QVERIFY(r.outcome.gainsRestored);
    const int motions = rig.motionCount();
    QTest::qWait(200);
    QCOMPARE(rig.motionCount(), motions); // no setpoint after the abort
    QCOMPARE(rig.gains(3), before);
    // Motor off: no current, and the rotor coasts down.
    QCOMPARE(rig.state(3).iqA(), 0.0);
}

void tst_FrequencySweepRunner::positionMeasuresTheSimulatorsTransfer()
{
    // The position loop of a frictionless MF against PositionLoopTransfer: 1 dB and 5 degrees
    // up to a sixteenth of the sample rate (FrequencyResponse::kPositionSamplesPerPeriod).
    Rig rig;
    const double start = rig.angle(7);
    QVERIFY(rig.runner.start(positionSpec(7), windowAround(start, 20)));
    const FrequencySweepResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    QVERIFY(r.gains && r.startAngle);
    QCOMPARE(*r.startAngle, start); // the sine is centred where the drive was
    QCOMPARE(r.spec.centre(), start);
    const auto g = *r.gains;
    const sim::PositionLoopTransfer h = sim::PositionLoopTransfer::forSeries(
        Series::MF, simGains(g), {g.angle.kd, g.speed.kd, g.current.kd});
    QCOMPARE(r.response.samplesPerPeriod, FrequencyResponse::kPositionSamplesPerPeriod);
    const double resolved = r.response.resolvedHz();
    // Every planned frequency is measured, or dropped because this host's rate does not
    // resolve it for the position loop (at 1 Mbaud an idle host reaches about 750 samples/s,
    // 47 Hz; a loaded one or a sanitizer build less), overall or within its own window (a
    // host that stalled during it: too few samples).
    QCOMPARE(r.response.points.size() + r.response.dropped.size(), 6);
    for (const DroppedFrequency &d : r.response.dropped) {
        QVERIFY2(d.reason == DroppedReason::TooFewSamples ||
                     (d.reason == DroppedReason::AboveResolution && d.hz > resolved),
                 qPrintable(QString::number(d.hz)));
    }
    QVERIFY2(r.response.points.size() >= 4, qPrintable(QString::number(resolved)));
    for (const FrequencyPoint &p : r.response.points) {
        qInfo("%6.1f Hz: %6.2f dB %7.1f deg (q %.3f, %d samples) | sim %6.2f dB %7.1f deg", p.hz,
              p.magnitudeDb, p.phaseDeg, p.quality, p.samples, h.magnitudeDb(p.hz),
              h.phaseDeg(p.hz));
        QVERIFY(p.hz <= resolved);
        // As for the speed loop: the 1 dB / 5 degrees is bench_tuning's figure; on a
        // host loaded by parallel builds the setpoints' timing jitters by milliseconds, which
        // lowers a point's fit quality, and such a point gets twice that here.
        const double scale = p.quality >= 0.95 ? 1 : 2;
        QVERIFY2(std::abs(p.magnitudeDb - h.magnitudeDb(p.hz)) < 1.0 * scale,
                 qPrintable(QString::number(p.hz)));
        QVERIFY2(std::abs(std::remainder(p.phaseDeg - h.phaseDeg(p.hz), 360.0)) < 5.0 * scale,
                 qPrintable(QString::number(p.hz)));
    }
    QVERIFY2(r.message.contains(QLatin1String("holds the angle it started at")),
             qPrintable(r.message));
    QCOMPARE(r.outcome.drive, DriveLeft::HoldsAngle);
    QCOMPARE(r.outcome.angleDeg, start);
    // Every setpoint stayed inside the window.
    for (double v : r.setpoint)
        QVERIFY(std::abs(v - start) <= 5.01);
}

void tst_FrequencySweepRunner::positionSweepBeyondALimitSendsNothing_data()
{
    QTest::addColumn<double>("amplitude");
    QTest::addColumn<double>("toHz");
    QTest::addColumn<double>("window");
    QTest::addColumn<double>("maxSpeed");
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("refused");
    // 2 pi x 40 Hz x 5 deg = 1257 dps: over a 1000 dps limit.
    QTest::newRow("peak speed") << 5.0 << 40.0 << 20.0 << 1000.0
                                << int(safety::LimitKind::SoftSpeed)
                                << 2 * 3.14159265358979323846 * 40 * 5;
    // +-5 deg around the start in a window of +-3 deg.
    QTest::newRow("angle window") << 5.0 << 10.0 << 3.0 << 6000.0
                                  << int(safety::LimitKind::AngleAboveMax) << 5.0;
}

void tst_FrequencySweepRunner::positionSweepBeyondALimitSendsNothing()
{
    QFETCH(double, amplitude);
    QFETCH(double, toHz);
    QFETCH(double, window);
    QFETCH(double, maxSpeed);
    QFETCH(int, kind);
    QFETCH(double, refused);
    Rig rig;
    FrequencySweepSpec spec = positionSpec(7);
    spec.amplitude = amplitude;
    spec.toHz = toHz;
    const double start = rig.angle(7);
    safety::SoftLimits limits = windowAround(start, window);
    limits.maxSpeedDps = maxSpeed;
    QVERIFY(rig.runner.start(spec, limits));
    const FrequencySweepResult r = rig.waitForEnd();
    QCOMPARE(r.failure, StepTestFailure::Refused);
    QCOMPARE(int(r.refusal.kind), kind);
    QCOMPARE(r.refusedDps - (kind == int(safety::LimitKind::SoftSpeed) ? 0 : start), refused);
    QCOMPARE(rig.motionCount(), 0);
}

void tst_FrequencySweepRunner::endsAtTheSpeedItWasGiven()
{
    // The drive turns at 150 dps; a sweep told so ends with a speed command of exactly 150
    // dps, whatever its own read of the turning rotor says, so that sweeps in a row do not
    // wander off it.
    Rig rig;
    QVERIFY(rig.request(*protocol::build::speed(3, 150).request).ok());
    QVERIFY(QTest::qWaitFor([&] { return std::abs(rig.state(3).speedDps - 150) < 10; }, kWaitMs));
    FrequencySweepSpec spec = quickSpec(3);
    spec.toHz = 20;
    spec.points = 2;
    spec.returnSpeedDps = 150;
    QVERIFY(rig.runner.start(spec, safety::SoftLimits::defaults(Series::MF)));
    const FrequencySweepResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.outcome.drive, DriveLeft::BackAtSpeed);
    QCOMPARE(r.outcome.speedDps, 150.0);
    std::optional<double> last;
    for (const auto &args : rig.completed) {
        const protocol::Request req = args.at(0).value<RequestResult>().request;
        if (const auto *s = std::get_if<protocol::SpeedCommand>(&req.payload))
            last = s->speedDps();
    }
    QVERIFY(last && *last == 150.0);
}

QTEST_GUILESS_MAIN(tst_FrequencySweepRunner)
#include "tst_frequencysweeprunner.moc"
