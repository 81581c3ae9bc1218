// How the simulator's cascaded loops answer their gains: the directions a technician expects
// from a real drive on the bench (issue #13), checked on DrivePhysics directly and through the
// protocol (gain writes and motion commands as frames on a SimBus, sampled at the rate the
// wire allows). Directions only, never exact figures: the figures are printed for the record.
#include "sim/DrivePhysics.h"
#include "sim/SimBus.h"

#include "SimTestUtil.h"
#include "motor/SeriesLimits.h"

#include <QtCore/QVector>
#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::test;
using protocol::Command;
using protocol::ParamId;
using protocol::PidGains;
using protocol::Series;
using sim::DrivePhysics;
using sim::LoopMode;
using sim::LoopTarget;
namespace build = protocol::build;

Q_DECLARE_METATYPE(Series)

namespace {

constexpr PidGains kDefaults{100, 100, 50, 40, 50, 50}; // the drives' factory gains
constexpr double kSampleS = DrivePhysics::kStepSeconds;
constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

struct Sample {
    double t = 0;
    double y = 0;  ///< speed (dps) or position (deg)
    double iq = 0; ///< A
};
using Trace = QVector<Sample>;

/// Step-response figures of a trace, computed here on purpose (not core/tuning's metrics):
/// the simulator is checked on its own.
struct StepFigures {
    double riseS = -1;       ///< 10 % to 90 % of the step; -1 = never reached 90 %
    double overshootPct = 0; ///< beyond the target, % of the step
    double finalError = 0;   ///< |mean of the last 10 % of the trace - target|, units of y
    int swings = 0;          ///< crossings of the target by more than 2 % of the step, after 90 %
    double peakIq = 0;       ///< A, largest |iq|
    double peakY = 0;        ///< largest |y|
    bool finite = true;
};

StepFigures measure(const Trace &trace, double from, double to)
{
    StepFigures f;
    const double step = to - from;
    double t10 = -1;
    double t90 = -1;
    double maxU = 0;
    int lastSide = 0;
    double tailSum = 0;
    int tailCount = 0;
    const int tailStart = trace.size() - trace.size() / 10;
    for (int i = 0; i < trace.size(); ++i) {
        const Sample &s = trace[i];
        f.finite = f.finite && std::isfinite(s.y) && std::isfinite(s.iq);
        f.peakIq = std::max(f.peakIq, std::abs(s.iq));
        f.peakY = std::max(f.peakY, std::abs(s.y));
        const double u = (s.y - from) / step;
        if (t10 < 0 && u >= 0.1)
            t10 = s.t;
        if (t90 < 0 && u >= 0.9)
            t90 = s.t;
        maxU = std::max(maxU, u);
        if (t90 >= 0 && std::abs(u - 1.0) > 0.02) {
            const int side = u > 1.0 ? 1 : -1;
            if (lastSide != 0 && side != lastSide)
                ++f.swings;
            lastSide = side;
        }
        if (i >= tailStart) {
            tailSum += s.y;
            ++tailCount;
        }
    }
    if (t10 >= 0 && t90 >= 0)
        f.riseS = t90 - t10;
    f.overshootPct = std::max(0.0, maxU - 1.0) * 100.0;
    if (tailCount > 0)
        f.finalError = std::abs(tailSum / tailCount - to);
    return f;
}

QString describe(const StepFigures &f)
{
    return QStringLiteral("rise %1 ms, overshoot %2 %, final error %3, swings %4, peak iq %5 A")
        .arg(f.riseS * 1e3, 0, 'f', 1)
        .arg(f.overshootPct, 0, 'f', 1)
        .arg(f.finalError, 0, 'f', 2)
        .arg(f.swings)
        .arg(f.peakIq, 0, 'f', 2);
}

/// One drive's physics on the bench, no acceleration limit unless asked.
struct PhysicsRig {
    Series series = Series::MF;
    PidGains gains = kDefaults;
    sim::DerivativeGains kd;
    double accelDps2 = 0;
    double loadNm = 0;
    double seconds = 0.6;
};

Trace runPhysics(const PhysicsRig &rig, LoopTarget target)
{
    const motor::SeriesLimits &l = motor::seriesLimits(rig.series);
    DrivePhysics p(sim::RotorParams::forSeries(rig.series), l.maxCurrentA, l.maxSpeedDps());
    p.setSupplyVoltage(l.nominalSupplyV);
    p.setGains(rig.gains);
    p.setDerivativeGains(rig.kd);
    p.setAccelerationDps2(rig.accelDps2);
    p.setLoadTorque(rig.loadNm);
    p.setPositionDeg(0);
    target.maxSpeedDps = l.maxSpeedDps();
    p.setTarget(target);
    Trace trace;
    const int n = static_cast<int>(rig.seconds / kSampleS);
    trace.reserve(n);
    for (int i = 1; i <= n; ++i) {
        p.advance(kSampleS);
        const double y = target.mode == LoopMode::Speed ? p.speedDps() : p.positionDeg();
        trace.append({i * kSampleS, y, p.currentA()});
    }
    return trace;
}

StepFigures speedStep(const PhysicsRig &rig, double dps)
{
    LoopTarget t;
    t.mode = LoopMode::Speed;
    t.speedDps = dps;
    return measure(runPhysics(rig, t), 0, dps);
}

StepFigures positionStep(const PhysicsRig &rig, double deg)
{
    LoopTarget t;
    t.mode = LoopMode::Position;
    t.positionDeg = deg;
    return measure(runPhysics(rig, t), 0, deg);
}

PidGains withSpeed(quint8 kp, quint8 ki)
{
    PidGains g = kDefaults;
    g.speedKp = kp;
    g.speedKi = ki;
    return g;
}

PidGains withAngleKp(quint8 kp)
{
    PidGains g = kDefaults;
    g.angleKp = kp;
    return g;
}

/// A speed step well above what friction holds back, in the linear range at the defaults.
constexpr double kSmallSpeedStep = 300.0;
/// A small position step that stays clear of the deceleration bound and the current limit.
constexpr double kSmallAngleStep = 5.0;

/// One drive on a SimBus, talked to in frames, with simulated time advancing by what each
/// transaction takes on the wire at `baud` plus the drive's turnaround: the sampling a real
/// bus gives a step test.
class BusRig {
public:
    BusRig(const sim::SimDriveModel &model, int baud) : m_baud(baud)
    {
        m_drive = m_bus.addDrive(kId, model);
        if (!m_drive)
            qFatal("cannot add the drive");
    }
    static constexpr int kId = 1;

    /// Sends a request frame; returns the decoded reply (nullopt: the drive stayed silent).
    std::optional<protocol::Reply> transact(const protocol::BuildResult &build)
    {
        const QByteArray request = req(build).encode();
        m_now += sim::SimBus::wireSeconds(request.size(), m_baud);
        const QList<sim::SimReply> replies = m_bus.receive(request, m_now);
        if (replies.isEmpty()) {
            m_now += 0.001; // the host's timeout, shortened
            return std::nullopt;
        }
        const QByteArray &bytes = replies.first().bytes;
        m_now += replies.first().delaySeconds + sim::SimBus::wireSeconds(bytes.size(), m_baud);
        m_bus.advanceTo(m_now);
        for (const protocol::ParseEvent &e : parseAll(bytes)) {
            if (e.isFrame)
                return protocol::decodeReply(e.frame, m_drive->context()).reply;
        }
        return std::nullopt;
    }

    /// The multi-turn angle (0x92), degrees.
    double angleDeg()
    {
        return payloadOf<protocol::MultiTurnAngle>(
                   transact(build::plain(Command::ReadMultiTurn, kId)))
            .degrees();
    }

    /// Polls `read` back to back for `seconds`; y from the reply. Time 0 = the call.
    Trace poll(Command read, double seconds)
    {
        Trace trace;
        const double start = m_now;
        while (m_now - start < seconds) {
            const auto reply = transact(build::plain(read, kId));
            if (!reply)
                continue;
            Sample s;
            s.t = m_now - start;
            if (const auto *st = std::get_if<protocol::State2>(&reply->payload)) {
                s.y = st->speedDps;
                s.iq = st->isPower ? 0.0 : st->iqA();
            } else if (const auto *mt = std::get_if<protocol::MultiTurnAngle>(&reply->payload)) {
                s.y = mt->degrees();
            }
            trace.append(s);
        }
        return trace;
    }

private:
    sim::SimBus m_bus;
    sim::SimDrive *m_drive = nullptr;
    int m_baud;
    double m_now = 0;
};

sim::SimDriveModel modelFor(Series s, bool v235)
{
    sim::SimDriveModel m = sim::SimDriveModel::forSeries(s);
    if (v235)
        m.useFirmware235();
    return m;
}

/// Writes speed Kp/Ki (and Kd on V2.35) the way each generation does: 0x31 with all six gains,
/// or 0x42 on the speed-loop parameter. No acceleration limit unless asked.
void writeSpeedGains(BusRig &rig, bool v235, int kp, int ki, int kd = 0)
{
    constexpr int id = BusRig::kId;
    if (v235) {
        QVERIFY(rig.transact(build::writeParamPid(id, ParamId::SpeedPid, kp, ki, kd, false)));
        QVERIFY(rig.transact(build::writeParam(id, ParamId::SpeedRamp, 0, false)));
    } else {
        const PidGains g = withSpeed(quint8(kp), quint8(ki));
        QVERIFY(rig.transact(build::writePid(id, g, false)));
        QVERIFY(rig.transact(build::writeAcceleration(id, 0)));
    }
}

/// Rows per series: physics alone (no protocol), through both generations, or V2.35 only.
enum class Through { Physics, BothGenerations, V235 };

void addSeriesRows(Through through)
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<bool>("v235");
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        const QByteArray name = protocol::seriesName(s).toLatin1();
        if (through == Through::Physics)
            QTest::newRow(name) << s << false;
        if (through == Through::BothGenerations)
            QTest::newRow(name + " V2.3") << s << false;
        if (through != Through::Physics)
            QTest::newRow(name + " V2.35") << s << true;
    }
}

} // namespace

/// Speed and position loops, current limit, acceleration and derivative terms of the
/// simulated drives: the directions, per series, at and around the factory gains.
class tst_SimLoopResponse : public QObject {
    Q_OBJECT
private slots:
    void defaultsAreWellDamped_data() { addSeriesRows(Through::Physics); }
    void defaultsAreWellDamped();
    void speedKpSpeedsUpThenOvershoots_data() { addSeriesRows(Through::Physics); }
    void speedKpSpeedsUpThenOvershoots();
    void speedKiRemovesSteadyStateError_data() { addSeriesRows(Through::Physics); }
    void speedKiRemovesSteadyStateError();
    void veryHighGainRingsButStaysBounded_data() { addSeriesRows(Through::Physics); }
    void veryHighGainRingsButStaysBounded();
    void angleKpSpeedsUpThenOvershoots_data() { addSeriesRows(Through::Physics); }
    void angleKpSpeedsUpThenOvershoots();
    void bigStepSaturatesAtTheCurrentLimit_data() { addSeriesRows(Through::Physics); }
    void bigStepSaturatesAtTheCurrentLimit();
    void derivativeTermsDamp_data() { addSeriesRows(Through::Physics); }
    void derivativeTermsDamp();
    void gainsThroughTheProtocol_data() { addSeriesRows(Through::BothGenerations); }
    void gainsThroughTheProtocol();
    void accelerationSlowsTheRise_data() { addSeriesRows(Through::BothGenerations); }
    void accelerationSlowsTheRise();
    void derivativeGainsThroughParameterTable_data() { addSeriesRows(Through::V235); }
    void derivativeGainsThroughParameterTable();
};

void tst_SimLoopResponse::defaultsAreWellDamped()
{
    QFETCH(Series, series);
    PhysicsRig rig;
    rig.series = series;
    const StepFigures speed = speedStep(rig, kSmallSpeedStep);
    qInfo("speed step %g dps at the defaults: %s", kSmallSpeedStep, qPrintable(describe(speed)));
    QVERIFY2(speed.overshootPct < 10.0, qPrintable(describe(speed)));
    QVERIFY2(speed.swings <= 1, qPrintable(describe(speed)));
    QVERIFY2(speed.finalError < kSmallSpeedStep * 0.02, qPrintable(describe(speed)));
    rig.seconds = 1.5;
    const StepFigures pos = positionStep(rig, kSmallAngleStep);
    qInfo("position step %g deg at the defaults: %s", kSmallAngleStep, qPrintable(describe(pos)));
    QVERIFY2(pos.overshootPct < 10.0, qPrintable(describe(pos)));
    QVERIFY2(pos.swings <= 1, qPrintable(describe(pos)));
    QVERIFY2(pos.finalError < kSmallAngleStep * 0.02, qPrintable(describe(pos)));
}

void tst_SimLoopResponse::speedKpSpeedsUpThenOvershoots()
{
    QFETCH(Series, series);
    PhysicsRig rig;
    rig.series = series;
    auto at = [&](quint8 kp) {
        rig.gains = withSpeed(kp, kDefaults.speedKi);
        const StepFigures f = speedStep(rig, kSmallSpeedStep);
        qInfo("speed Kp %3d Ki %d: %s", kp, kDefaults.speedKi, qPrintable(describe(f)));
        return f;
    };
    at(10); // the sweep, for the record: low Kp with the default Ki swings slowly
    const StepFigures soft = at(25);
    const StepFigures normal = at(kDefaults.speedKp);
    const StepFigures stiff = at(120);
    at(200);
    const StepFigures harsh = at(255);
    const QString all = describe(soft) + " | " + describe(normal) + " | " + describe(stiff) +
                        " | " + describe(harsh);
    QVERIFY2(soft.riseS > normal.riseS && normal.riseS > stiff.riseS && stiff.riseS > harsh.riseS &&
                 harsh.riseS > 0,
             qPrintable(all));
    // Past a point the loop runs into its delays (current loop, speed filter): overshoot.
    QVERIFY2(stiff.overshootPct > normal.overshootPct, qPrintable(all));
    QVERIFY2(harsh.overshootPct > stiff.overshootPct + 10.0, qPrintable(all));
}

void tst_SimLoopResponse::speedKiRemovesSteadyStateError()
{
    QFETCH(Series, series);
    PhysicsRig rig;
    rig.series = series;
    const motor::SeriesLimits &l = motor::seriesLimits(series);
    rig.loadNm = 0.3 * l.maxCurrentA * sim::RotorParams::forSeries(series).torqueConstant;
    rig.seconds = 1.5;
    rig.gains = withSpeed(kDefaults.speedKp, 0);
    const StepFigures pOnly = speedStep(rig, kSmallSpeedStep);
    rig.gains = kDefaults;
    const StepFigures pi = speedStep(rig, kSmallSpeedStep);
    const QString all = describe(pOnly) + " | " + describe(pi);
    QVERIFY2(pOnly.finalError > kSmallSpeedStep * 0.05, qPrintable(all));
    QVERIFY2(pi.finalError < kSmallSpeedStep * 0.01, qPrintable(all));
    // Friction alone, no load: still an error without Ki.
    rig.loadNm = 0;
    rig.gains = withSpeed(kDefaults.speedKp, 0);
    const StepFigures friction = speedStep(rig, kSmallSpeedStep);
    QVERIFY2(friction.finalError > 0.5, qPrintable(describe(friction)));
}

void tst_SimLoopResponse::veryHighGainRingsButStaysBounded()
{
    QFETCH(Series, series);
    PhysicsRig rig;
    rig.series = series;
    rig.gains = withSpeed(255, 255);
    rig.seconds = 1.0;
    const StepFigures f = speedStep(rig, kSmallSpeedStep);
    qInfo("speed Kp 255 Ki 255: %s", qPrintable(describe(f)));
    QVERIFY(f.finite);
    QVERIFY2(f.swings >= 3, qPrintable(describe(f)));
    const motor::SeriesLimits &l = motor::seriesLimits(series);
    QVERIFY2(f.peakY < l.maxSpeedDps() + 1e-6 && f.peakY < kSmallSpeedStep * 4,
             qPrintable(describe(f)));
    QVERIFY(f.peakIq <= l.maxCurrentA + 1e-6);
    // The same with the position loop on top, all gains at their maximum.
    rig.gains = PidGains{255, 255, 255, 255, 255, 255};
    const StepFigures p = positionStep(rig, kSmallAngleStep);
    QVERIFY(p.finite);
    QVERIFY2(p.peakY < kSmallAngleStep * 4, qPrintable(describe(p)));
    QVERIFY(p.peakIq <= l.maxCurrentA + 1e-6);
}

void tst_SimLoopResponse::angleKpSpeedsUpThenOvershoots()
{
    QFETCH(Series, series);
    PhysicsRig rig;
    rig.series = series;
    rig.seconds = 1.5;
    auto at = [&](quint8 kp) {
        rig.gains = withAngleKp(kp);
        const StepFigures f = positionStep(rig, kSmallAngleStep);
        qInfo("angle Kp %3d Ki %d: %s", kp, kDefaults.angleKi, qPrintable(describe(f)));
        return f;
    };
    at(10); // the sweep, for the record
    const StepFigures soft = at(30);
    const StepFigures normal = at(kDefaults.angleKp);
    at(150);
    at(200);
    const StepFigures harsh = at(255);
    const QString all = describe(soft) + " | " + describe(normal) + " | " + describe(harsh);
    QVERIFY2(soft.riseS > normal.riseS && normal.riseS > harsh.riseS && harsh.riseS > 0,
             qPrintable(all));
    QVERIFY2(harsh.overshootPct > normal.overshootPct + 5.0, qPrintable(all));
}

void tst_SimLoopResponse::bigStepSaturatesAtTheCurrentLimit()
{
    QFETCH(Series, series);
    const motor::SeriesLimits &l = motor::seriesLimits(series);
    const sim::RotorParams rotor = sim::RotorParams::forSeries(series);
    PhysicsRig rig;
    rig.series = series;
    LoopTarget t;
    t.mode = LoopMode::Speed;
    t.speedDps = 0.8 * l.maxSpeedDps();
    const Trace trace = runPhysics(rig, t);
    // Time at the limit, and the acceleration while there.
    double saturatedS = 0;
    double firstT = -1, firstY = 0, lastT = -1, lastY = 0;
    for (const Sample &s : trace) {
        if (std::abs(s.iq) >= 0.98 * l.maxCurrentA) {
            saturatedS += kSampleS;
            if (firstT < 0) {
                firstT = s.t;
                firstY = s.y;
            }
            lastT = s.t;
            lastY = s.y;
        }
    }
    const StepFigures f = measure(trace, 0, t.speedDps);
    QVERIFY2(f.peakIq <= l.maxCurrentA + 1e-6, qPrintable(describe(f)));
    QVERIFY2(saturatedS > 0.002, qPrintable(QString::number(saturatedS)));
    QVERIFY(lastT > firstT);
    const double accelDps2 = (lastY - firstY) / (lastT - firstT);
    const double bound = rotor.torqueConstant * l.maxCurrentA / rotor.inertia / kRadPerDeg;
    qInfo("at the current limit for %.1f ms, %.0f dps/s of at most %.0f", saturatedS * 1e3,
          accelDps2, bound);
    QVERIFY(accelDps2 <= bound);
    QVERIFY(accelDps2 > 0.7 * bound); // friction and back-EMF take little of it
    QVERIFY2(f.finalError < t.speedDps * 0.01, qPrintable(describe(f)));
}

void tst_SimLoopResponse::derivativeTermsDamp()
{
    QFETCH(Series, series);
    PhysicsRig rig;
    rig.series = series;
    // Speed loop pushed into overshoot, then its Kd added.
    rig.gains = withSpeed(200, kDefaults.speedKi);
    const StepFigures speedNoKd = speedStep(rig, kSmallSpeedStep);
    rig.kd.speedKd = 200;
    const StepFigures speedKd = speedStep(rig, kSmallSpeedStep);
    QVERIFY2(speedKd.overshootPct < speedNoKd.overshootPct - 5.0,
             qPrintable(describe(speedNoKd) + " | " + describe(speedKd)));
    // Position loop likewise.
    rig.kd = {};
    rig.seconds = 1.5;
    rig.gains = withAngleKp(255);
    const StepFigures posNoKd = positionStep(rig, kSmallAngleStep);
    rig.kd.angleKd = 200;
    const StepFigures posKd = positionStep(rig, kSmallAngleStep);
    QVERIFY2(posKd.overshootPct < posNoKd.overshootPct - 5.0,
             qPrintable(describe(posNoKd) + " | " + describe(posKd)));
    QVERIFY2(posKd.finalError < kSmallAngleStep * 0.02, qPrintable(describe(posKd)));
    // Current loop Kd: damps the current loop; it must not break the speed loop above it.
    rig.kd = {};
    rig.kd.iqKd = 200;
    rig.seconds = 0.6;
    rig.gains = kDefaults;
    const StepFigures iqKd = speedStep(rig, kSmallSpeedStep);
    QVERIFY2(iqKd.finite && iqKd.finalError < kSmallSpeedStep * 0.02, qPrintable(describe(iqKd)));
}

void tst_SimLoopResponse::gainsThroughTheProtocol()
{
    // 0x31 (V2.3) or 0x42 (V2.35) then 0xA2 and 0xA4, sampled with 0x9C / 0x92 at 1 Mbaud.
    QFETCH(Series, series);
    QFETCH(bool, v235);
    auto speedRun = [&](int kp) {
        BusRig rig(modelFor(series, v235), 1000000);
        writeSpeedGains(rig, v235, kp, kDefaults.speedKi);
        rig.transact(build::speed(BusRig::kId, kSmallSpeedStep));
        return measure(rig.poll(Command::ReadState2, 0.5), 0, kSmallSpeedStep);
    };
    const StepFigures normal = speedRun(kDefaults.speedKp);
    const StepFigures harsh = speedRun(255);
    const QString all = describe(normal) + " | " + describe(harsh);
    QVERIFY2(normal.riseS > harsh.riseS && harsh.riseS > 0, qPrintable(all));
    QVERIFY2(harsh.overshootPct > normal.overshootPct + 10.0, qPrintable(all));

    auto positionRun = [&](int kp) {
        BusRig rig(modelFor(series, v235), 1000000);
        const double start = rig.angleDeg();
        if (v235) {
            rig.transact(build::writeParamPid(BusRig::kId, ParamId::AnglePid, kp, 100, 0, false));
            rig.transact(build::writeParam(BusRig::kId, ParamId::SpeedRamp, 0, false));
        } else {
            rig.transact(build::writePid(BusRig::kId, withAngleKp(quint8(kp)), false));
            rig.transact(build::writeAcceleration(BusRig::kId, 0));
        }
        rig.transact(build::multiPosition(BusRig::kId, start + kSmallAngleStep));
        return measure(rig.poll(Command::ReadMultiTurn, 1.0), start, start + kSmallAngleStep);
    };
    const StepFigures slow = positionRun(kDefaults.angleKp);
    const StepFigures fast = positionRun(255);
    const QString moves = describe(slow) + " | " + describe(fast);
    QVERIFY2(slow.riseS > fast.riseS && fast.riseS > 0, qPrintable(moves));
    QVERIFY2(fast.overshootPct > slow.overshootPct, qPrintable(moves));
}

void tst_SimLoopResponse::accelerationSlowsTheRise()
{
    QFETCH(Series, series);
    QFETCH(bool, v235);
    const double step = 0.3 * motor::seriesLimits(series).maxSpeedDps();
    auto run = [&](qint64 accel) {
        BusRig rig(modelFor(series, v235), 1000000);
        if (v235)
            rig.transact(build::writeParam(BusRig::kId, ParamId::SpeedRamp, double(accel), false));
        else
            rig.transact(build::writeAcceleration(BusRig::kId, accel));
        rig.transact(build::speed(BusRig::kId, step));
        return measure(rig.poll(Command::ReadState2, 1.5), 0, step);
    };
    const StepFigures unlimited = run(0);
    const StepFigures gentle = run(20000);
    const StepFigures slow = run(5000);
    const QString all = describe(unlimited) + " | " + describe(gentle) + " | " + describe(slow);
    QVERIFY2(unlimited.riseS > 0 && gentle.riseS > unlimited.riseS && slow.riseS > gentle.riseS,
             qPrintable(all));
    // A ramp-limited rise takes 80 % of the step at the ramp's rate.
    QVERIFY2(std::abs(slow.riseS - 0.8 * step / 5000.0) < 0.2 * (0.8 * step / 5000.0),
             qPrintable(all));
    QVERIFY2(slow.overshootPct < 5.0, qPrintable(all));
}

void tst_SimLoopResponse::derivativeGainsThroughParameterTable()
{
    // V2.35: Kd is the third gain of 0x97 / 0x96, written with 0x42.
    QFETCH(Series, series);
    auto speedRun = [&](int kd) {
        BusRig rig(modelFor(series, true), 1000000);
        writeSpeedGains(rig, true, 200, kDefaults.speedKi, kd);
        rig.transact(build::speed(BusRig::kId, kSmallSpeedStep));
        return measure(rig.poll(Command::ReadState2, 0.5), 0, kSmallSpeedStep);
    };
    const StepFigures none = speedRun(0);
    const StepFigures damped = speedRun(200);
    QVERIFY2(damped.overshootPct < none.overshootPct - 5.0,
             qPrintable(describe(none) + " | " + describe(damped)));

    auto positionRun = [&](int kd) {
        BusRig rig(modelFor(series, true), 1000000);
        const double start = rig.angleDeg();
        rig.transact(build::writeParamPid(BusRig::kId, ParamId::AnglePid, 255, 100, kd, false));
        rig.transact(build::writeParam(BusRig::kId, ParamId::SpeedRamp, 0, false));
        rig.transact(build::multiPosition(BusRig::kId, start + kSmallAngleStep));
        return measure(rig.poll(Command::ReadMultiTurn, 1.0), start, start + kSmallAngleStep);
    };
    const StepFigures ringing = positionRun(0);
    const StepFigures calm = positionRun(200);
    QVERIFY2(calm.overshootPct < ringing.overshootPct - 5.0,
             qPrintable(describe(ringing) + " | " + describe(calm)));
}

QTEST_APPLESS_MAIN(tst_SimLoopResponse)
#include "tst_simloopresponse.moc"
