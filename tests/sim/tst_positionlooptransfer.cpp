// The simulator's position loop against its own transfer function (issue #25): DrivePhysics
// in Position mode driven by a sine of the angle target around where the rotor is, held over
// each substep, its angle and speed fitted at each frequency, compared with
// PositionLoopTransfer; per series, at the factory gains and at stiffer ones.
#include "sim/DrivePhysics.h"
#include "sim/PositionLoopTransfer.h"

#include "motor/SeriesLimits.h"
#include "tuning/FrequencyResponse.h"

#include <QtTest/QTest>

#include <cmath>
#include <optional>

using namespace lk;
using protocol::PidGains;
using protocol::Series;
using sim::DrivePhysics;

Q_DECLARE_METATYPE(Series)

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr PidGains kDefaults{100, 100, 50, 40, 50, 50};

DrivePhysics physicsOf(Series series, const PidGains &gains)
{
    const motor::SeriesLimits &l = motor::seriesLimits(series);
    DrivePhysics p(sim::RotorParams::forSeries(series), l.maxCurrentA, l.maxSpeedDps());
    p.setSupplyVoltage(l.nominalSupplyV);
    p.setGains(gains);
    p.setPositionDeg(40);
    return p;
}

/// A sine of the angle target at `hz`, `amplitude` deg around 40 deg, held over each substep:
/// the target, the angle and the speed at every substep.
struct SineRun {
    QVector<double> t, target, angle, speed;
    double settle = 0, window = 0;
    std::optional<tuning::FrequencyPoint> measure(const QVector<double> &y, double hz) const
    {
        return tuning::FrequencyResponse::measure(t, target, t, y, hz, settle, settle + window);
    }
};

SineRun runSine(DrivePhysics &p, double hz, double amplitude)
{
    sim::LoopTarget target;
    target.mode = sim::LoopMode::Position;
    target.maxSpeedDps = 1e9;
    target.positionDeg = 40;
    p.setTarget(target);
    p.advance(0.5);
    const double T = DrivePhysics::kStepSeconds;
    SineRun run;
    run.settle = std::max(0.5, 3 / hz);
    run.window = std::ceil(std::max(0.5, 5 / hz) * hz) / hz;
    for (double t = 0; t < run.settle + run.window + T; t += T) {
        target.positionDeg = 40 + amplitude * std::sin(2 * kPi * hz * t);
        run.t.append(t);
        run.target.append(target.positionDeg);
        run.angle.append(p.positionDeg());
        run.speed.append(p.speedDps());
        p.setTarget(target);
        p.advance(T);
    }
    return run;
}

double phaseGap(double a, double b)
{
    return std::abs(std::remainder(a - b, 360.0));
}
} // namespace

class tst_PositionLoopTransfer : public QObject {
    Q_OBJECT
private slots:
    void physicsMatchesTransfer_data();
    void physicsMatchesTransfer();
    void shapeFollowsTheGains();
};

void tst_PositionLoopTransfer::physicsMatchesTransfer_data()
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<int>("angleKp");
    QTest::addColumn<int>("angleKd");
    QTest::addColumn<double>("hz");
    QTest::addColumn<QString>("plant");
    QTest::addColumn<double>("amplitude");
    QTest::addColumn<double>("toleranceDb");
    QTest::addColumn<double>("toleranceDeg");
    // Without Coulomb friction the loop is linear at any amplitude: the transfer function is
    // exact. With the series' friction, a sine of 30 deg (20 deg from 20 Hz, where 30 would
    // take the MH's current to its limit) keeps it within the 1 dB and 5 deg.
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        const QByteArray name = protocol::seriesName(s).toLatin1();
        for (double hz : {0.5, 3.0, 10.0, 30.0, 80.0}) {
            const QByteArray at = " " + QByteArray::number(hz) + " Hz";
            QTest::newRow(name + " default frictionless" + at)
                << s << 100 << 0 << hz << "friction=0" << 5.0 << 0.05 << 0.3;
            QTest::newRow(name + " kp 200 kd 60 frictionless" + at)
                << s << 200 << 60 << hz << "friction=0+resonance=150/0.1" << 5.0 << 0.05 << 0.3;
            if (hz < 50) // at 80 Hz (-24 dB) a sine large enough for friction needs the MH's
                         // whole current
                QTest::newRow(name + " default friction" + at)
                    << s << 100 << 0 << hz << "" << (hz < 20 ? 30.0 : 20.0) << 1.0 << 5.0;
        }
    }
}

void tst_PositionLoopTransfer::physicsMatchesTransfer()
{
    // The angle measured against angleDiscrete() over the hold, and the speed over jw (what
    // a sweep on the bus measures) against response(), with the series' friction on.
    QFETCH(Series, series);
    QFETCH(int, angleKp);
    QFETCH(int, angleKd);
    QFETCH(double, hz);
    QFETCH(QString, plant);
    QFETCH(double, amplitude);
    QFETCH(double, toleranceDb);
    QFETCH(double, toleranceDeg);
    PidGains g = kDefaults;
    g.angleKp = quint8(angleKp);
    DrivePhysics p = physicsOf(series, g);
    p.setPlantOptions(*sim::PlantOptions::parse(plant));
    sim::DerivativeGains kd;
    kd.angleKd = quint16(angleKd);
    p.setDerivativeGains(kd);
    const SineRun run = runSine(p, hz, amplitude);
    const sim::PositionLoopTransfer h = sim::PositionLoopTransfer::of(p);
    const auto angle = run.measure(run.angle, hz);
    const auto speed = run.measure(run.speed, hz);
    QVERIFY(angle && speed);
    const std::complex<double> a = h.angleDiscrete(hz) / sim::SpeedLoopTransfer::substepHold(hz);
    const double angleDb = 20 * std::log10(std::abs(a));
    const double angleDeg = std::arg(a) * 180 / kPi;
    // The speed's sine over jw: magnitude over w (deg/s per deg -> deg per deg), phase - 90.
    const double viaSpeedDb = speed->magnitudeDb - 20 * std::log10(2 * kPi * hz);
    const double viaSpeedDeg = speed->phaseDeg - 90;
    qInfo("%5.1f Hz: angle %6.2f dB %7.1f deg (transfer %6.2f %7.1f); via speed %6.2f dB %7.1f "
          "deg (transfer %6.2f %7.1f)",
          hz, angle->magnitudeDb, angle->phaseDeg, angleDb, angleDeg, viaSpeedDb, viaSpeedDeg,
          h.magnitudeDb(hz), h.phaseDeg(hz));
    QVERIFY2(std::abs(angle->magnitudeDb - angleDb) < toleranceDb,
             qPrintable(QString::number(angleDb)));
    QVERIFY2(phaseGap(angle->phaseDeg, angleDeg) < toleranceDeg,
             qPrintable(QString::number(angleDeg)));
    QVERIFY2(std::abs(viaSpeedDb - h.magnitudeDb(hz)) < toleranceDb,
             qPrintable(QString::number(h.magnitudeDb(hz))));
    QVERIFY2(phaseGap(viaSpeedDeg, h.phaseDeg(hz)) < toleranceDeg,
             qPrintable(QString::number(h.phaseDeg(hz))));
}

void tst_PositionLoopTransfer::shapeFollowsTheGains()
{
    // Unity at low frequency (the angle loop has an integrator), falling past its bandwidth;
    // a stiffer angle loop reaches further.
    DrivePhysics p = physicsOf(Series::MF, kDefaults);
    const sim::PositionLoopTransfer normal = sim::PositionLoopTransfer::of(p);
    QVERIFY(std::abs(normal.magnitudeDb(0.05)) < 0.1);
    QVERIFY(std::abs(normal.phaseDeg(0.05)) < 3);
    QVERIFY(normal.magnitudeDb(100) < -10);
    PidGains stiff = kDefaults;
    stiff.angleKp = 200;
    p.setGains(stiff);
    const sim::PositionLoopTransfer fast = sim::PositionLoopTransfer::of(p);
    QVERIFY(fast.magnitudeDb(20) > normal.magnitudeDb(20));
    // The speed loop's transfer is the inner part: position and speed loops differ.
    QVERIFY(std::abs(normal.magnitudeDb(20) - sim::SpeedLoopTransfer::of(p).magnitudeDb(20)) > 1);
}

QTEST_APPLESS_MAIN(tst_PositionLoopTransfer)
#include "tst_positionlooptransfer.moc"
