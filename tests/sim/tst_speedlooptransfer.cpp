// The simulator's speed loop against its own transfer function (issue #25): DrivePhysics
// driven by a sine reference held over each substep, its speed fitted at each frequency,
// compared with SpeedLoopTransfer; per series, at the factory gains and at stiffer ones.
#include "sim/DrivePhysics.h"
#include "sim/SimBus.h"
#include "sim/SimBusSpec.h"
#include "sim/SimDrive.h"
#include "sim/SpeedLoopTransfer.h"

#include "motor/SeriesLimits.h"
#include "tuning/FrequencyResponse.h"

#include <QtTest/QTest>

#include <cmath>
#include <functional>
#include <optional>

using namespace lk;
using protocol::PidGains;
using protocol::Series;
using sim::DrivePhysics;

Q_DECLARE_METATYPE(Series)

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr PidGains kDefaults{100, 100, 50, 40, 50, 50};

/// A drive of `series` with the factory gains, as lksim makes it.
DrivePhysics physicsOf(Series series)
{
    const motor::SeriesLimits &l = motor::seriesLimits(series);
    DrivePhysics p(sim::RotorParams::forSeries(series), l.maxCurrentA, l.maxSpeedDps());
    p.setSupplyVoltage(l.nominalSupplyV);
    p.setGains(kDefaults);
    return p;
}

/// What a sine of the speed reference at `hz` around 300 dps +- 60 (the rotor never stops, so
/// friction is a constant torque), held over each substep, gave: the reference at every
/// substep and the speed at each substep `nextSample` picks (from the time of the one before).
struct SineRun {
    QVector<double> ut, uv, yt, yv;
    double settle = 0, window = 0;
    double sampleRateHz() const { return (yt.size() - 1) / (yt.last() - yt.first()); }
    std::optional<tuning::FrequencyPoint> measure(double hz) const
    {
        return tuning::FrequencyResponse::measure(ut, uv, yt, yv, hz, settle, settle + window);
    }
};

SineRun runSine(DrivePhysics &p, double hz, const std::function<double(double)> &nextSample)
{
    const double offset = 300, amplitude = 60;
    sim::LoopTarget target;
    target.mode = sim::LoopMode::Speed;
    target.maxSpeedDps = 1e9;
    target.speedDps = offset;
    p.setTarget(target);
    p.advance(0.5);
    const double T = DrivePhysics::kStepSeconds;
    SineRun run;
    run.settle = std::max(0.3, 2 / hz);
    run.window = std::ceil(std::max(0.5, 5 / hz) * hz) / hz;
    double sampleAt = 0;
    for (double t = 0; t < run.settle + run.window + T; t += T) {
        target.speedDps = offset + amplitude * std::sin(2 * kPi * hz * t);
        run.ut.append(t);
        run.uv.append(target.speedDps);
        if (t >= sampleAt) {
            run.yt.append(t); // the speed at the substep's start
            run.yv.append(p.speedDps());
            sampleAt = nextSample(t);
        }
        p.setTarget(target);
        p.advance(T);
    }
    return run;
}
} // namespace

class tst_SpeedLoopTransfer : public QObject {
    Q_OBJECT
private slots:
    void physicsMatchesTransfer_data();
    void physicsMatchesTransfer();
    void shapeFollowsTheGains();
    void unevenSamplesMatchTransfer_data();
    void unevenSamplesMatchTransfer();
    void resonanceShowsInTheTransfer();
    void plantOptionsParse_data();
    void plantOptionsParse();
    void busSpecCarriesThePlant();
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
    DrivePhysics p = physicsOf(series);
    PidGains g = kDefaults;
    g.speedKp = quint8(speedKp);
    p.setGains(g);
    sim::DerivativeGains kd;
    kd.speedKd = quint16(speedKd);
    p.setDerivativeGains(kd);
    const SineRun run = runSine(p, hz, [](double t) { return t; }); // every substep
    const auto point = run.measure(hz);
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

void tst_SpeedLoopTransfer::unevenSamplesMatchTransfer_data()
{
    // The plant with and without a resonance and encoder counts, sampled at uneven times about
    // 2 kHz apart as the bus does at 1 Mbaud, up to a quarter of that rate.
    QTest::addColumn<Series>("series");
    QTest::addColumn<QString>("plant");
    QTest::addColumn<double>("hz");
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        const QByteArray name = protocol::seriesName(s).toLatin1();
        for (const char *plant :
             {"", "resonance=120/0.08", "resonance=300/0.05/2+counts=16384+speed-res=1"}) {
            for (double hz : {5.0, 40.0, 110.0, 150.0, 300.0, 400.0})
                QTest::newRow(name + " " + plant + " " + QByteArray::number(hz) + " Hz")
                    << s << QString::fromLatin1(plant) << hz;
        }
    }
}

void tst_SpeedLoopTransfer::unevenSamplesMatchTransfer()
{
    QFETCH(Series, series);
    QFETCH(QString, plant);
    QFETCH(double, hz);
    DrivePhysics p = physicsOf(series);
    const auto options = sim::PlantOptions::parse(plant);
    QVERIFY(options);
    p.setPlantOptions(*options);
    // 0.4 to 0.6 ms apart: the substep grid with an uneven stride (a fixed sequence).
    quint32 lcg = 7;
    const SineRun run = runSine(p, hz, [&](double t) {
        lcg = lcg * 1664525u + 1013904223u;
        return t + 0.0004 + 0.0002 * double(lcg >> 8) / double(1u << 24);
    });
    const double rate = run.sampleRateHz();
    QVERIFY(hz <= rate / 4);
    const auto point = run.measure(hz);
    QVERIFY(point);
    const sim::SpeedLoopTransfer h = sim::SpeedLoopTransfer::of(p);
    const double db = h.magnitudeDb(hz);
    const double deg = h.phaseDeg(hz);
    qInfo("%5.0f Hz (%.0f samples/s): measured %6.2f dB %7.1f deg, transfer %6.2f dB %7.1f deg", hz,
          rate, point->magnitudeDb, point->phaseDeg, db, deg);
    QVERIFY2(std::abs(point->magnitudeDb - db) < 1, qPrintable(QString::number(db)));
    QVERIFY2(std::abs(std::remainder(point->phaseDeg - deg, 360.0)) < 5,
             qPrintable(QString::number(deg)));
}

void tst_SpeedLoopTransfer::resonanceShowsInTheTransfer()
{
    // A lightly damped resonance at 150 Hz: the loop's response rises towards it and its phase
    // turns fast there; far below it nothing changes.
    const sim::RotorParams rotor = sim::RotorParams::forSeries(Series::MF);
    DrivePhysics p(rotor, 10, 3000);
    p.setGains(kDefaults);
    const sim::SpeedLoopTransfer rigid = sim::SpeedLoopTransfer::of(p);
    p.setPlantOptions(*sim::PlantOptions::parse(QStringLiteral("resonance=150/0.02")));
    const sim::SpeedLoopTransfer resonant = sim::SpeedLoopTransfer::of(p);
    QVERIFY(std::abs(resonant.magnitudeDb(2) - rigid.magnitudeDb(2)) < 0.1);
    QVERIFY(resonant.magnitudeDb(150) > rigid.magnitudeDb(150) + 6);
    QVERIFY(std::abs(std::remainder(resonant.phaseDeg(170) - resonant.phaseDeg(130), 360.0)) >
            std::abs(std::remainder(rigid.phaseDeg(170) - rigid.phaseDeg(130), 360.0)) + 30);
}

void tst_SpeedLoopTransfer::plantOptionsParse_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<QString>("back");
    QTest::newRow("empty") << "" << true << "";
    QTest::newRow("resonance") << "resonance=120" << true << "resonance=120/0.05/1";
    QTest::newRow("all") << "resonance=80/0.1/2+counts=16384+speed-res=0.5" << true
                         << "resonance=80/0.1/2+counts=16384+speed-res=0.5";
    QTest::newRow("frictionless") << "friction=0" << true << "friction=0";
    QTest::newRow("friction") << "counts=4096+friction=0.02" << true << "counts=4096+friction=0.02";
    QTest::newRow("negative friction") << "friction=-1" << false << "";
    QTest::newRow("too low") << "resonance=1" << false << "";
    QTest::newRow("no damping") << "resonance=100/0" << false << "";
    QTest::newRow("bad ratio") << "resonance=100/0.1/100" << false << "";
    QTest::newRow("few counts") << "counts=3" << false << "";
    QTest::newRow("bad speed") << "speed-res=x" << false << "";
    QTest::newRow("unknown") << "stiction=3" << false << "";
}

void tst_SpeedLoopTransfer::plantOptionsParse()
{
    QFETCH(QString, text);
    QFETCH(bool, ok);
    QFETCH(QString, back);
    QString error;
    const auto parsed = sim::PlantOptions::parse(text, &error);
    QCOMPARE(parsed.has_value(), ok);
    if (ok)
        QCOMPARE(parsed->toString(), back);
    else
        QVERIFY(error.contains(text.section(QLatin1Char('+'), 0, 0)));
}

void tst_SpeedLoopTransfer::busSpecCarriesThePlant()
{
    // lksim --motors, lkctl/lkstudio --sim: "+resonance=...", "+counts=..." per drive.
    const QString text = QStringLiteral("3:MF+resonance=120/0.05/1+counts=16384,4:MG");
    const auto spec = sim::SimBusSpec::parse(text);
    QVERIFY(spec);
    QCOMPARE(spec->toString(), text);
    const auto bus = sim::SimBus::fromSpec(*spec);
    QCOMPARE(bus->drive(3)->physics().plantOptions(),
             *sim::PlantOptions::parse(QStringLiteral("resonance=120/0.05+counts=16384")));
    QCOMPARE(bus->drive(4)->physics().plantOptions(), sim::PlantOptions{});
    QString error;
    QVERIFY(!sim::SimBusSpec::parse(QStringLiteral("3:MF+resonance=1"), &error));
    QVERIFY2(error.contains(QLatin1String("resonance must be")), qPrintable(error));
}

QTEST_APPLESS_MAIN(tst_SpeedLoopTransfer)
#include "tst_speedlooptransfer.moc"
