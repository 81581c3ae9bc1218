#include "sim/SimDrive.h"

#include "SimDriveTestUtil.h"

#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::test;
using lk::protocol::Command;
using lk::protocol::Series;
using lk::protocol::SpinDirection;
using lk::sim::SimDrive;
namespace build = lk::protocol::build;

Q_DECLARE_METATYPE(Series)
Q_DECLARE_METATYPE(SpinDirection)

namespace {
constexpr int kId = kDriveId;
} // namespace

/// One simulated drive in motion: control modes, run state, limits, gains.
class tst_SimDrive : public QObject {
    Q_OBJECT
private slots:
    void speedReachesTarget_data();
    void speedReachesTarget();
    void speedLimitedToSeriesMax();
    void multiPositionConverges_data();
    void multiPositionConverges();
    void maxSpeedLimitsPositionMove();
    void singleTurnDirection_data();
    void singleTurnDirection();
    void incrementAdds_data();
    void incrementAdds();
    void offStopRun();
    void torqueNotLimitedByDrive();
    void openLoopOnMs();
    void unsupportedCommandsSilent_data();
    void unsupportedCommandsSilent();
    void gainsChangeResponse();
    void stableForAnyGains_data();
    void stableForAnyGains();
};

void tst_SimDrive::speedReachesTarget_data()
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<double>("target");
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        const QByteArray name = protocol::seriesName(s).toLatin1();
        QTest::newRow(name + " +360") << s << 360.0;
        QTest::newRow(name + " -1000") << s << -1000.0;
        QTest::newRow(name + " 90% max") << s << motor::seriesLimits(s).maxSpeedDps() * 0.9;
    }
}

void tst_SimDrive::speedReachesTarget()
{
    QFETCH(Series, series);
    QFETCH(double, target);
    SimDrive d = makeDrive(series);
    const auto reply = send(d, build::speed(kId, target));
    QVERIFY(reply);
    QCOMPARE(reply->command, Command::Speed);
    QVERIFY(std::holds_alternative<protocol::State2>(reply->payload));
    QCOMPARE(d.runState(), SimDrive::RunState::Running);
    d.advance(3.0);
    QVERIFY2(std::abs(d.speedDps() - target) < std::abs(target) * 0.01 + 1.0,
             qPrintable(QString::number(d.speedDps())));
    const auto s2 = readBack<protocol::State2>(d, Command::ReadState2);
    QVERIFY(std::abs(s2.speedDps - target) <= std::abs(target) * 0.01 + 1.5);
}

void tst_SimDrive::speedLimitedToSeriesMax()
{
    SimDrive d = makeDrive(Series::MF);
    const double max = d.limits().maxSpeedDps();
    send(d, build::speed(kId, max * 3));
    double peak = 0;
    for (int i = 0; i < 300; ++i) {
        d.advance(0.01);
        peak = std::max(peak, std::abs(d.speedDps()));
    }
    QVERIFY(peak <= max + 1e-6);
    QVERIFY(std::abs(d.speedDps()) > max * 0.98);
}

void tst_SimDrive::multiPositionConverges_data()
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<double>("target");
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        const QByteArray name = protocol::seriesName(s).toLatin1();
        QTest::newRow(name + " 90") << s << 90.0;
        QTest::newRow(name + " -450") << s << -450.0;
        QTest::newRow(name + " 3600") << s << 3600.0;
    }
}

void tst_SimDrive::multiPositionConverges()
{
    QFETCH(Series, series);
    QFETCH(double, target);
    SimDrive d = makeDrive(series);
    send(d, build::multiPosition(kId, target));
    runUntil(d, 20.0, [&] { return std::abs(angleDeg(d) - target) < 0.05 && d.speedDps() == 0; });
    d.advance(0.5);
    QVERIFY2(std::abs(angleDeg(d) - target) < 0.1, qPrintable(QString::number(angleDeg(d))));
    QVERIFY(std::abs(d.speedDps()) < 1.0);
    const auto mt = readBack<protocol::MultiTurnAngle>(d, Command::ReadMultiTurn);
    QVERIFY(std::abs(mt.degrees() - target) < 0.1);
}

void tst_SimDrive::maxSpeedLimitsPositionMove()
{
    SimDrive d = makeDrive(Series::MF);
    plain(d, Command::ClearAngle);
    send(d, build::multiPosition(kId, 360.0, 100.0)); // 0xA4: at most 100 dps
    double peak = 0;
    const double t = runUntil(d, 20.0, [&] {
        peak = std::max(peak, std::abs(d.speedDps()));
        return std::abs(angleDeg(d) - 360.0) < 0.1;
    });
    QVERIFY2(peak <= 100.0 * 1.05, qPrintable(QString::number(peak)));
    QVERIFY(t >= 3.5); // 360 deg at 100 dps takes at least 3.6 s of simulated time
    QVERIFY(std::abs(angleDeg(d) - 360.0) < 0.1);
}

void tst_SimDrive::singleTurnDirection_data()
{
    QTest::addColumn<double>("target");
    QTest::addColumn<SpinDirection>("direction");
    QTest::addColumn<double>("expectedMove");
    QTest::newRow("90 cw") << 90.0 << SpinDirection::Clockwise << 90.0;
    QTest::newRow("90 ccw") << 90.0 << SpinDirection::CounterClockwise << -270.0;
    QTest::newRow("270 cw") << 270.0 << SpinDirection::Clockwise << 270.0;
    QTest::newRow("270 ccw") << 270.0 << SpinDirection::CounterClockwise << -90.0;
    QTest::newRow("0 cw stays") << 0.0 << SpinDirection::Clockwise << 0.0;
}

void tst_SimDrive::singleTurnDirection()
{
    QFETCH(double, target);
    QFETCH(SpinDirection, direction);
    QFETCH(double, expectedMove);
    SimDrive d = makeDrive(Series::MF);
    plain(d, Command::ClearAngle); // single-turn angle 0 here
    QCOMPARE(d.singleTurnRaw(), 0u);
    double lowest = 0, highest = 0;
    send(d, build::singlePosition(kId, direction, target));
    runUntil(d, 10.0, [&] {
        lowest = std::min(lowest, angleDeg(d));
        highest = std::max(highest, angleDeg(d));
        return std::abs(angleDeg(d) - expectedMove) < 0.05 && d.speedDps() == 0;
    });
    QVERIFY2(std::abs(angleDeg(d) - expectedMove) < 0.1, qPrintable(QString::number(angleDeg(d))));
    // It went the requested way: no excursion of more than a degree the other way.
    if (expectedMove > 0)
        QVERIFY(lowest > -1.0);
    if (expectedMove < 0)
        QVERIFY(highest < 1.0);
    const double single = d.singleTurnRaw() * 0.01;
    QVERIFY(std::min(std::abs(single - target), 360.0 - std::abs(single - target)) < 0.1);
}

void tst_SimDrive::incrementAdds_data()
{
    QTest::addColumn<double>("first");
    QTest::addColumn<double>("second");
    QTest::newRow("+90 +90") << 90.0 << 90.0;
    QTest::newRow("-45 -720") << -45.0 << -720.0;
    QTest::newRow("+30 -30") << 30.0 << -30.0;
}

void tst_SimDrive::incrementAdds()
{
    QFETCH(double, first);
    QFETCH(double, second);
    SimDrive d = makeDrive(Series::MF);
    const double start = angleDeg(d);
    send(d, build::incrementPosition(kId, first));
    d.advance(5.0);
    QVERIFY(std::abs(angleDeg(d) - (start + first)) < 0.1);
    send(d, build::incrementPosition(kId, second, 500.0));
    d.advance(5.0);
    QVERIFY(std::abs(angleDeg(d) - (start + first + second)) < 0.1);
    // Two increments in quick succession add up (the second adds to the running target).
    send(d, build::incrementPosition(kId, 10.0));
    d.advance(0.001);
    send(d, build::incrementPosition(kId, 10.0));
    d.advance(5.0);
    QVERIFY(std::abs(angleDeg(d) - (start + first + second + 20.0)) < 0.1);
}

void tst_SimDrive::offStopRun()
{
    SimDrive d = makeDrive(Series::MF);
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    send(d, build::speed(kId, 720.0));
    d.advance(1.0);
    QVERIFY(d.speedDps() > 700);

    // Stop: output off (coasts to rest), command kept.
    const auto ack = d.handle(req(build::plain(Command::MotorStop, kId)));
    QVERIFY(ack && std::holds_alternative<protocol::Acknowledged>(ack->payload));
    QCOMPARE(d.runState(), SimDrive::RunState::Stopped);
    d.advance(3.0);
    QCOMPARE(d.speedDps(), 0.0);
    QCOMPARE(d.iqA(), 0.0);
    QCOMPARE(d.activeCommand(), std::optional<Command>(Command::Speed));

    // Run resumes the kept command.
    plain(d, Command::MotorRun);
    QCOMPARE(d.runState(), SimDrive::RunState::Running);
    d.advance(1.0);
    QVERIFY(std::abs(d.speedDps() - 720.0) < 8.0);

    // Off clears the command: run afterwards does not move the motor.
    plain(d, Command::MotorOff);
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    QVERIFY(!d.activeCommand());
    d.advance(3.0);
    QCOMPARE(d.speedDps(), 0.0);
    const qint64 rest = d.multiTurnRaw();
    plain(d, Command::MotorRun);
    d.advance(1.0);
    QCOMPARE(d.speedDps(), 0.0);
    QCOMPARE(d.multiTurnRaw(), rest);
}

void tst_SimDrive::torqueNotLimitedByDrive()
{
    SimDrive d = makeDrive(Series::MF);
    d.setRotorLocked(true);
    const double max = d.limits().maxCurrentA; // 9 A
    send(d, build::torque(kId, max * 1.5, {}));
    d.advance(0.05);
    QVERIFY2(d.iqA() > max * 1.4, qPrintable(QString::number(d.iqA())));
    const auto s2 = readBack<protocol::State2>(d, Command::ReadState2);
    QVERIFY(s2.iqA() > max * 1.4);
    QVERIFY(!s2.isPower);

    // The closed loops are limited: a stalled speed loop saturates at the series maximum.
    send(d, build::speed(kId, 1000.0));
    for (int i = 0; i < 50; ++i) {
        d.advance(0.01);
        QVERIFY(std::abs(d.iqA()) <= max + 1e-9);
    }
    QVERIFY(d.iqA() > max * 0.99);
}

void tst_SimDrive::openLoopOnMs()
{
    SimDrive d = makeDrive(Series::MS);
    const auto reply = send(d, build::openLoop(kId, 300));
    QVERIFY(reply);
    QVERIFY(payloadOf<protocol::State2>(reply).isPower);
    d.advance(1.0);
    QVERIFY(d.speedDps() > 100);
    QCOMPARE(d.powerRaw(), qint16(300));
    send(d, build::openLoop(kId, -300));
    d.advance(2.0);
    QVERIFY(d.speedDps() < -100);
    QCOMPARE(d.state2().torqueRaw, qint16(-300));
}

void tst_SimDrive::unsupportedCommandsSilent_data()
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<int>("which"); // 0 open loop, 1 torque, 2 read_state3
    QTest::addColumn<bool>("answers");
    QTest::newRow("MS open loop") << Series::MS << 0 << true;
    QTest::newRow("MS torque") << Series::MS << 1 << false;
    QTest::newRow("MS state3") << Series::MS << 2 << false;
    for (Series s : {Series::MF, Series::MG, Series::MH}) {
        const QByteArray name = protocol::seriesName(s).toLatin1();
        QTest::newRow(name + " open loop") << s << 0 << false;
        QTest::newRow(name + " torque") << s << 1 << true;
        QTest::newRow(name + " state3") << s << 2 << true;
    }
}

void tst_SimDrive::unsupportedCommandsSilent()
{
    QFETCH(Series, series);
    QFETCH(int, which);
    QFETCH(bool, answers);
    SimDrive d = makeDrive(series);
    const protocol::BuildResult r = which == 0   ? build::openLoop(kId, 200)
                                    : which == 1 ? build::torque(kId, 1.0, {})
                                                 : build::plain(Command::ReadState3, kId);
    QCOMPARE(d.handle(req(r)).has_value(), answers);
    if (!answers)
        QCOMPARE(d.runState(), SimDrive::RunState::Off); // and it did not act on it
    // A request for another ID is never answered.
    QVERIFY(!d.handle(req(build::plain(Command::ReadState2, kId + 1))));
}

void tst_SimDrive::gainsChangeResponse()
{
    // No acceleration limit, so the speed loop gain alone decides how fast speed builds up.
    auto speedAfter = [](quint8 speedKp, quint8 iqGain) {
        SimDrive d = makeDrive(Series::MF);
        d.handle(req(build::writeAcceleration(kId, 0)));
        d.handle(req(build::writePid(kId, 100, 100, speedKp, 0, iqGain, iqGain, false)));
        d.handle(req(build::speed(kId, 2000.0)));
        d.advance(0.004);
        return d.speedDps();
    };
    const double soft = speedAfter(10, 50);
    const double stiff = speedAfter(100, 50);
    QVERIFY2(stiff > soft * 1.5, qPrintable(QStringLiteral("%1 vs %2").arg(stiff).arg(soft)));
    QVERIFY(speedAfter(100, 5) < stiff); // a weak current loop slows everything down
    QCOMPARE(speedAfter(0, 50), 0.0);    // no speed gain: no torque
}

void tst_SimDrive::stableForAnyGains_data()
{
    QTest::addColumn<int>("angle");
    QTest::addColumn<int>("speed");
    QTest::addColumn<int>("iq");
    const int values[] = {0, 1, 50, 255};
    for (int a : values)
        for (int s : values)
            for (int i : values)
                QTest::addRow("a%d s%d i%d", a, s, i) << a << s << i;
}

void tst_SimDrive::stableForAnyGains()
{
    QFETCH(int, angle);
    QFETCH(int, speed);
    QFETCH(int, iq);
    for (Series series : {Series::MS, Series::MG}) {
        SimDrive d = makeDrive(series);
        send(d, build::writePid(kId, angle, angle, speed, speed, iq, iq, false));
        send(d, build::multiPosition(kId, 5000.0));
        for (int i = 0; i < 40; ++i) {
            d.advance(0.05); // the largest step the brief allows
            QVERIFY(std::isfinite(d.speedDps()) && std::isfinite(d.iqA()));
            QVERIFY(std::abs(d.speedDps()) <= d.limits().maxSpeedDps() + 1e-6);
            QVERIFY(std::abs(d.iqA()) <= d.limits().maxCurrentA + 1e-6);
            QVERIFY(std::isfinite(d.temperatureC()));
        }
    }
}

QTEST_APPLESS_MAIN(tst_SimDrive)
#include "tst_simdrive.moc"
