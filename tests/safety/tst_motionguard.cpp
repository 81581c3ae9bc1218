// The gate in front of every motion command: series capabilities, series limits, soft limits.

#include "SafetyTestUtil.h"

#include <motor/SeriesLimits.h>
#include <protocol/RequestBuilder.h>
#include <safety/MotionGuard.h>
#include <text/VerdictText.h>

#include <QtCore/QJsonDocument>
#include <QtTest/QtTest>

using namespace lk;
using lk::test::req;
using protocol::Series;
using safety::LimitKind;

Q_DECLARE_METATYPE(std::optional<protocol::Series>)
Q_DECLARE_METATYPE(lk::protocol::Request)
Q_DECLARE_METATYPE(lk::safety::LimitKind)

class tst_MotionGuard : public QObject {
    Q_OBJECT
private slots:
    void check_data();
    void check();
    void anglesAtTheLimitPass_data();
    void anglesAtTheLimitPass();
    void defaultsAreSafe();
    void json_roundTrip();
    void json_refusesBadValues();
};

void tst_MotionGuard::check_data()
{
    QTest::addColumn<protocol::Request>("request");
    QTest::addColumn<std::optional<Series>>("series");
    QTest::addColumn<LimitKind>("expected");

    using namespace protocol::build;
    const auto MF = std::optional<Series>(Series::MF);
    const auto MS = std::optional<Series>(Series::MS);
    const std::optional<Series> unknown;
    // MF defaults: 9 A rated -> 2.25 A torque; 3000 rpm -> 18000 dps.
    QTest::newRow("read passes") << req(plain(protocol::Command::ReadState2, 1)) << unknown
                                 << LimitKind::None;
    QTest::newRow("pid rom write passes (not motion)")
        << req(writePid(1, 1, 2, 3, 4, 5, 6, true)) << unknown << LimitKind::None;
    QTest::newRow("torque within") << req(torque(1, 2.0, {})) << MF << LimitKind::None;
    QTest::newRow("torque negative within") << req(torque(1, -2.0, {})) << MF << LimitKind::None;
    QTest::newRow("torque over soft") << req(torque(1, 2.5, {})) << MF << LimitKind::SoftTorque;
    QTest::newRow("torque over series")
        << req(torque(1, -10.0, {})) << MF << LimitKind::SeriesCurrent;
    QTest::newRow("torque unknown series")
        << req(torque(1, 0.1, {})) << unknown << LimitKind::UnknownSeries;
    QTest::newRow("torque on MS") << req(torque(1, 0.1, {})) << MS << LimitKind::Unsupported;
    // A V2.35 MF drive's torque is checked at its own scale (33/4096 A per LSB): 2.2 A is
    // 273 LSB, which the V2.3 scale would read as 4.37 A.
    const protocol::DecodeContext v235Mf{Series::MF, protocol::Generation::V2_35};
    QTest::newRow("torque V2.35 MF within") << req(torque(1, 2.2, v235Mf)) << MF << LimitKind::None;
    QTest::newRow("torque V2.35 MF over soft")
        << req(torque(1, -2.3, v235Mf)) << MF << LimitKind::SoftTorque;
    QTest::newRow("open loop on MF") << req(openLoop(1, 10)) << MF << LimitKind::Unsupported;
    QTest::newRow("open loop within") << req(openLoop(1, -200)) << MS << LimitKind::None;
    QTest::newRow("open loop over") << req(openLoop(1, 201)) << MS << LimitKind::SoftPower;
    QTest::newRow("open loop unknown")
        << req(openLoop(1, 1)) << unknown << LimitKind::UnknownSeries;
    QTest::newRow("speed within") << req(speed(1, -18000)) << MF << LimitKind::None;
    QTest::newRow("speed over series") << req(speed(1, 18000.01)) << MF << LimitKind::SeriesSpeed;
    QTest::newRow("speed MS top") << req(speed(1, 6001)) << MS << LimitKind::SeriesSpeed;
    QTest::newRow("speed unknown uses slowest")
        << req(speed(1, 6001)) << unknown << LimitKind::SeriesSpeed;
    QTest::newRow("multi limited max speed over")
        << req(multiPosition(1, 90, 20000)) << MF << LimitKind::SeriesSpeed;
    QTest::newRow("multi plain") << req(multiPosition(1, -1e6)) << MF << LimitKind::None;
    QTest::newRow("single limited ok")
        << req(singlePosition(1, protocol::SpinDirection::CounterClockwise, 10, 360)) << MS
        << LimitKind::None;
    QTest::newRow("increment limited over")
        << req(incrementPosition(1, 10, 7000)) << MS << LimitKind::SeriesSpeed;
    QTest::newRow("run passes") << req(plain(protocol::Command::MotorRun, 1)) << MF
                                << LimitKind::None;
}

void tst_MotionGuard::check()
{
    QFETCH(protocol::Request, request);
    QFETCH(std::optional<Series>, series);
    QFETCH(LimitKind, expected);
    const safety::SoftLimits limits =
        safety::SoftLimits::defaults(series.value_or(protocol::Series::MF));
    const safety::Verdict v = safety::MotionGuard::check(request, series, limits);
    QCOMPARE(v.kind, expected);
    QCOMPARE(v.allowed(), expected == LimitKind::None);
    QCOMPARE(text::VerdictText::verdict(v, series).isEmpty(), expected == LimitKind::None);
}

void tst_MotionGuard::anglesAtTheLimitPass_data()
{
    // A target or increment exactly at its limit is allowed: 36090 x 0.01 is
    // 360.90000000000003 in floating point, which a product comparison would read as over a
    // limit of 360.9 (the max speed had the same bug, fixed the same way: divide by 100).
    QTest::addColumn<protocol::Request>("request");
    QTest::addColumn<LimitKind>("expected");
    using namespace protocol::build;
    QTest::newRow("target at max") << req(multiPosition(1, 360.9)) << LimitKind::None;
    QTest::newRow("target at min") << req(multiPosition(1, -360.9)) << LimitKind::None;
    QTest::newRow("limited target at max") << req(multiPosition(1, 360.9, 100)) << LimitKind::None;
    QTest::newRow("target over max") << req(multiPosition(1, 360.91)) << LimitKind::AngleAboveMax;
    QTest::newRow("target under min") << req(multiPosition(1, -360.91)) << LimitKind::AngleBelowMin;
    QTest::newRow("increment at max") << req(incrementPosition(1, 360.9)) << LimitKind::None;
    QTest::newRow("increment at max, back") << req(incrementPosition(1, -360.9)) << LimitKind::None;
    QTest::newRow("increment over")
        << req(incrementPosition(1, 360.91)) << LimitKind::SoftIncrement;
}

void tst_MotionGuard::anglesAtTheLimitPass()
{
    QFETCH(protocol::Request, request);
    QFETCH(LimitKind, expected);
    safety::SoftLimits limits = safety::SoftLimits::defaults(protocol::Series::MF);
    limits.minAngleDeg = -360.9;
    limits.maxAngleDeg = 360.9;
    limits.maxIncrementDeg = 360.9;
    const safety::Verdict v = safety::MotionGuard::check(request, protocol::Series::MF, limits);
    QCOMPARE(v.kind, expected);
}

void tst_MotionGuard::defaultsAreSafe()
{
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        const auto d = safety::SoftLimits::defaults(s);
        const auto &series = motor::seriesLimits(s);
        QVERIFY(d.maxTorqueA > 0);
        QVERIFY(d.maxTorqueA <= series.maxCurrentA * 0.5);
        QVERIFY(d.maxPower <= 250);
        QCOMPARE(d.maxSpeedDps, series.maxSpeedDps());
    }
    // User angle range and step limit.
    safety::SoftLimits l = safety::SoftLimits::defaults(Series::MG);
    l.minAngleDeg = -90;
    l.maxAngleDeg = 90;
    l.maxIncrementDeg = 45;
    using namespace protocol::build;
    const auto MG = std::optional<Series>(Series::MG);
    QCOMPARE(safety::MotionGuard::check(req(multiPosition(2, -90.01)), MG, l).kind,
             LimitKind::AngleBelowMin);
    QCOMPARE(safety::MotionGuard::check(req(multiPosition(2, 90.01)), MG, l).kind,
             LimitKind::AngleAboveMax);
    QCOMPARE(safety::MotionGuard::check(req(multiPosition(2, 90)), MG, l).kind, LimitKind::None);
    QCOMPARE(safety::MotionGuard::check(req(incrementPosition(2, -45.01)), MG, l).kind,
             LimitKind::SoftIncrement);
    l.maxSpeedDps = 100;
    const auto v = safety::MotionGuard::check(req(speed(2, 150)), MG, l);
    QCOMPARE(v.kind, LimitKind::SoftSpeed);
    QCOMPARE(v.limit, 100.0);
    QVERIFY(text::VerdictText::verdict(v, MG).contains(QLatin1String("100")));
}

void tst_MotionGuard::json_roundTrip()
{
    safety::SoftLimits l = safety::SoftLimits::defaults(Series::MH);
    l.minAngleDeg = -720;
    l.maxIncrementDeg = 30;
    const auto back = safety::SoftLimits::fromJson(l.toJson(), safety::SoftLimits{});
    QVERIFY(back);
    QVERIFY(*back == l);
}

void tst_MotionGuard::json_refusesBadValues()
{
    const safety::SoftLimits fallback = safety::SoftLimits::defaults(Series::MF);
    QString error;
    QVERIFY(!safety::SoftLimits::fromJson(QJsonObject{{"max_torque_a", -1}}, fallback, &error));
    QVERIFY(error.contains(QLatin1String("max_torque_a")));
    QVERIFY(!safety::SoftLimits::fromJson(QJsonObject{{"max_speed_dps", "fast"}}, fallback));
    QVERIFY(!safety::SoftLimits::fromJson(
        QJsonObject{{"min_angle_deg", 10}, {"max_angle_deg", -10}}, fallback, &error));
    const auto partial = safety::SoftLimits::fromJson(QJsonObject{{"max_power", 50}}, fallback);
    QVERIFY(partial);
    QCOMPARE(partial->maxPower, 50);
    QCOMPARE(partial->maxTorqueA, fallback.maxTorqueA);
}

QTEST_APPLESS_MAIN(tst_MotionGuard)
#include "tst_motionguard.moc"
