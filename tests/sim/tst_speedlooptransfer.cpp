// The simulator's speed loop against its own transfer function (issue #25): DrivePhysics
// driven by a sine reference held over each substep, its speed fitted at each frequency,
// compared with SpeedLoopTransfer; per series, at the factory gains and at stiffer ones.
#include "sim/DrivePhysics.h"
#include "sim/SpeedLoopTransfer.h"

#include "motor/SeriesLimits.h"
#include "tuning/FrequencyResponse.h"

#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using protocol::PidGains;
using protocol::Series;
using sim::DrivePhysics;

Q_DECLARE_METATYPE(Series)

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr PidGains kDefaults{100, 100, 50, 40, 50, 50};
} // namespace

class tst_SpeedLoopTransfer : public QObject {
    Q_OBJECT
private slots:
    void physicsMatchesTransfer_data();
    void physicsMatchesTransfer();
    void shapeFollowsTheGains();
};

void tst_SpeedLoopTransfer::physicsMatchesTransfer_data()
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<int>("speedKp");
    QTest::addColumn<int>("speedKd");
    QTest::addColumn<double>("hz");
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        const QByteArray name = protocol::seriesName(s).toLatin1();
        for (double hz : {2.0, 20.0, 60.0, 200.0}) {
            QTest::newRow(name + " default " + QByteArray::number(hz) + " Hz")
                << s << 50 << 0 << hz;
            QTest::newRow(name + " kp 150 kd 100 " + QByteArray::number(hz) + " Hz")
                << s << 150 << 100 << hz;
        }
    }
}

void tst_SpeedLoopTransfer::physicsMatchesTransfer()
{
    QFETCH(Series, series);
    QFETCH(int, speedKp);
    QFETCH(int, speedKd);
    QFETCH(double, hz);
    const motor::SeriesLimits &l = motor::seriesLimits(series);
    DrivePhysics p(sim::RotorParams::forSeries(series), l.maxCurrentA, l.maxSpeedDps());
    p.setSupplyVoltage(l.nominalSupplyV);
    PidGains g = kDefaults;
    g.speedKp = quint8(speedKp);
    p.setGains(g);
    sim::DerivativeGains kd;
    kd.speedKd = quint16(speedKd);
    p.setDerivativeGains(kd);
    // Around 300 dps +- 60: the rotor never stops, so friction is a constant torque.
    const double offset = 300, amplitude = 60;
    sim::LoopTarget target;
    target.mode = sim::LoopMode::Speed;
    target.maxSpeedDps = l.maxSpeedDps();
    target.speedDps = offset;
    p.setTarget(target);
    p.advance(0.5);
    const double T = DrivePhysics::kStepSeconds;
    const double settle = std::max(0.3, 2 / hz);
    const double window = std::ceil(std::max(0.5, 5 / hz) * hz) / hz;
    QVector<double> ut, uv, yt, yv;
    for (double t = 0; t < settle + window + T; t += T) {
        // The reference held over this substep; the speed sampled at its start.
        target.speedDps = offset + amplitude * std::sin(2 * kPi * hz * t);
        yt.append(t);
        yv.append(p.speedDps());
        ut.append(t);
        uv.append(target.speedDps);
        p.setTarget(target);
        p.advance(T);
    }
    const auto point =
        tuning::FrequencyResponse::measure(ut, uv, yt, yv, hz, settle, settle + window);
    QVERIFY(point);
    const sim::SpeedLoopTransfer h = sim::SpeedLoopTransfer::of(p);
    const double db = h.magnitudeDb(hz);
    const double deg = h.phaseDeg(hz);
    qInfo("%5.0f Hz: measured %6.2f dB %7.1f deg, transfer %6.2f dB %7.1f deg", hz,
          point->magnitudeDb, point->phaseDeg, db, deg);
    QVERIFY2(std::abs(point->magnitudeDb - db) < 0.05, qPrintable(QString::number(db)));
    QVERIFY2(std::abs(std::remainder(point->phaseDeg - deg, 360.0)) < 0.3,
             qPrintable(QString::number(deg)));
    QVERIFY(point->quality > 0.999);
}

void tst_SpeedLoopTransfer::shapeFollowsTheGains()
{
    // Unity at low frequency; a stiffer loop has more bandwidth; the current loop and the
    // speed estimate add lag with frequency.
    const sim::RotorParams rotor = sim::RotorParams::forSeries(Series::MF);
    DrivePhysics p(rotor, 10, 3000);
    p.setGains(kDefaults);
    const sim::SpeedLoopTransfer normal = sim::SpeedLoopTransfer::of(p);
    QVERIFY(std::abs(normal.magnitudeDb(0.1)) < 0.01);
    QVERIFY(std::abs(normal.phaseDeg(0.1)) < 2);
    PidGains stiff = kDefaults;
    stiff.speedKp = 150;
    p.setGains(stiff);
    const sim::SpeedLoopTransfer fast = sim::SpeedLoopTransfer::of(p);
    QVERIFY(fast.magnitudeDb(60) > normal.magnitudeDb(60));
    QVERIFY(normal.phaseDeg(100) < normal.phaseDeg(20));
}

QTEST_APPLESS_MAIN(tst_SpeedLoopTransfer)
#include "tst_speedlooptransfer.moc"
