// The conversion every motion request passes before it is sent (lkstudio and lkctl): position
// moves always carry a max speed, targets start where the drive is.

#include "SafetyTestUtil.h"

#include <protocol/RequestBuilder.h>
#include <safety/MotionPlanner.h>
#include <text/VerdictText.h>

#include <QtTest/QtTest>

using namespace lk;
using lk::test::req;
using protocol::Command;
using protocol::Series;
using safety::LimitKind;
using safety::SpeedBound;

namespace {
safety::SoftLimits limits720()
{
    safety::SoftLimits l = safety::SoftLimits::defaults(Series::MF);
    l.maxSpeedDps = 720;
    return l;
}

safety::DrivePosition at(double deg, double ratio = 1.0)
{
    safety::DrivePosition p;
    p.angleDeg = deg;
    p.gearRatio = ratio;
    return p;
}

std::optional<quint32> maxSpeedRaw(const protocol::Request &r)
{
    if (const auto *c = std::get_if<protocol::MultiPositionCommand>(&r.payload))
        return c->maxSpeedRaw;
    if (const auto *c = std::get_if<protocol::SinglePositionCommand>(&r.payload))
        return c->maxSpeedRaw;
    if (const auto *c = std::get_if<protocol::IncrementPositionCommand>(&r.payload))
        return c->maxSpeedRaw;
    return std::nullopt;
}
} // namespace

class tst_MotionPlanner : public QObject {
    Q_OBJECT
private slots:
    void unlimitedPositionsGetTheSpeedLimit_data();
    void unlimitedPositionsGetTheSpeedLimit();
    void lowerMaxSpeedIsKept();
    void higherMaxSpeedIsRefused();
    void seriesTopBelowTheLimit();
    void multiTurnNeedsTheCurrentAngle();
    void multiTurnWithinOneOutputTurn();
    void gearedDriveTurnIsLonger();
    void incrementWithinOneOutputTurn();
    void incrementInsideTheAngleRange();
    void singleTurnEndInsideTheAngleRange();
    void gearedSingleTurnSpansTheOutputTurn();
    void speedAndTorqueStayBounded();
};

void tst_MotionPlanner::unlimitedPositionsGetTheSpeedLimit_data()
{
    QTest::addColumn<protocol::Request>("request");
    QTest::addColumn<int>("limited");
    QTest::newRow("0xA3") << req(protocol::build::multiPosition(1, 100)) << 0xA4;
    QTest::newRow("0xA5") << req(protocol::build::singlePosition(
                                 1, protocol::SpinDirection::Clockwise, 90))
                          << 0xA6;
    QTest::newRow("0xA7") << req(protocol::build::incrementPosition(1, -90)) << 0xA8;
}

void tst_MotionPlanner::unlimitedPositionsGetTheSpeedLimit()
{
    QFETCH(protocol::Request, request);
    QFETCH(int, limited);
    const safety::MotionPlan p =
        safety::MotionPlanner::plan(request, Series::MF, limits720(), at(0));
    QVERIFY2(p.allowed(), qPrintable(text::VerdictText::verdict(p.verdict, Series::MF)));
    QCOMPARE(int(p.request->command), limited);
    QCOMPARE(maxSpeedRaw(*p.request), std::optional<quint32>(72000));
    QCOMPARE(p.bound, SpeedBound::SoftLimit);
    QCOMPARE(p.boundDps, 720.0);
    QVERIFY(p.limited);
    QCOMPARE(text::VerdictText::speedBound(p.bound, p.boundDps),
             QStringLiteral("max speed 720 dps (your speed limit)"));
}

void tst_MotionPlanner::lowerMaxSpeedIsKept()
{
    const safety::MotionPlan p = safety::MotionPlanner::plan(
        req(protocol::build::multiPosition(1, 100, 100)), Series::MF, limits720(), at(0));
    QVERIFY(p.allowed());
    QCOMPARE(p.request->command, Command::MultiPositionLimited);
    QCOMPARE(maxSpeedRaw(*p.request), std::optional<quint32>(10000));
    QCOMPARE(p.bound, SpeedBound::UserMaxSpeed);
    QVERIFY(!p.limited);
}

void tst_MotionPlanner::higherMaxSpeedIsRefused()
{
    const safety::MotionPlan p = safety::MotionPlanner::plan(
        req(protocol::build::incrementPosition(1, 10, 5000)), Series::MF, limits720(), at(0));
    QVERIFY(!p.allowed());
    QCOMPARE(p.verdict.kind, LimitKind::SoftSpeed);
    QVERIFY(text::VerdictText::verdict(p.verdict, Series::MF).contains(QStringLiteral("720")));
}

void tst_MotionPlanner::seriesTopBelowTheLimit()
{
    safety::SoftLimits l = safety::SoftLimits::defaults(Series::MF); // 18000 dps
    const safety::MotionPlan p = safety::MotionPlanner::plan(
        req(protocol::build::incrementPosition(1, 10)), Series::MS, l, at(0));
    QVERIFY(p.allowed());
    QCOMPARE(p.bound, SpeedBound::SeriesTop);
    QCOMPARE(p.boundDps, 6000.0); // MS: 1000 rpm
}

void tst_MotionPlanner::multiTurnNeedsTheCurrentAngle()
{
    const safety::MotionPlan p = safety::MotionPlanner::plan(
        req(protocol::build::multiPosition(1, 0)), Series::MF, limits720(), {});
    QVERIFY(!p.allowed());
    QCOMPARE(p.verdict.kind, LimitKind::AngleUnknown);
}

void tst_MotionPlanner::multiTurnWithinOneOutputTurn()
{
    // The issue: from 11,000 deg, a target of 0 is 30 turns back.
    safety::MotionPlan p = safety::MotionPlanner::plan(req(protocol::build::multiPosition(1, 0)),
                                                       Series::MF, limits720(), at(11000));
    QVERIFY(!p.allowed());
    QCOMPARE(p.verdict.kind, LimitKind::OutputTurn);
    QCOMPARE(p.verdict.limit, 360.0);
    QVERIFY(text::VerdictText::verdict(p.verdict, Series::MF)
                .contains(QStringLiteral("one output turn")));
    p = safety::MotionPlanner::plan(req(protocol::build::multiPosition(1, 11360)), Series::MF,
                                    limits720(), at(11000));
    QVERIFY(p.allowed());
    p = safety::MotionPlanner::plan(req(protocol::build::multiPosition(1, 11360.01)), Series::MF,
                                    limits720(), at(11000));
    QVERIFY(!p.allowed());
}

void tst_MotionPlanner::gearedDriveTurnIsLonger()
{
    const safety::MotionPlan p = safety::MotionPlanner::plan(
        req(protocol::build::multiPosition(1, 3000)), Series::MG, limits720(), at(0, 10));
    QVERIFY2(p.allowed(), qPrintable(text::VerdictText::verdict(
                              p.verdict, Series::MG))); // 3600 rotor deg per output turn
}

void tst_MotionPlanner::incrementWithinOneOutputTurn()
{
    const safety::MotionPlan p = safety::MotionPlanner::plan(
        req(protocol::build::incrementPosition(1, -400)), Series::MF, limits720(), {});
    QVERIFY(!p.allowed());
    QCOMPARE(p.verdict.kind, LimitKind::OutputTurn);
    QVERIFY(safety::MotionPlanner::plan(req(protocol::build::incrementPosition(1, -360)),
                                        Series::MF, limits720(), {})
                .allowed());
}

void tst_MotionPlanner::incrementInsideTheAngleRange()
{
    safety::SoftLimits l = limits720();
    l.maxAngleDeg = 100;
    const protocol::Request r = req(protocol::build::incrementPosition(1, 50));
    QCOMPARE(safety::MotionPlanner::plan(r, Series::MF, l, {}).verdict.kind,
             LimitKind::AngleUnknown);
    QCOMPARE(safety::MotionPlanner::plan(r, Series::MF, l, at(60)).verdict.kind,
             LimitKind::AngleAboveMax);
    QVERIFY(safety::MotionPlanner::plan(r, Series::MF, l, at(40)).allowed());
}

void tst_MotionPlanner::singleTurnEndInsideTheAngleRange()
{
    safety::SoftLimits l = limits720();
    l.minAngleDeg = -360;
    l.maxAngleDeg = 360;
    // From 350 deg, "90 deg clockwise" ends at 450 (through 360): outside the range. The same
    // target counter-clockwise ends at 90: inside. Without a range no angle is needed.
    const protocol::Request cw =
        req(protocol::build::singlePosition(1, protocol::SpinDirection::Clockwise, 90));
    const protocol::Request ccw =
        req(protocol::build::singlePosition(1, protocol::SpinDirection::CounterClockwise, 90));
    QVERIFY(safety::MotionPlanner::needsAngle(cw, l));
    QCOMPARE(safety::MotionPlanner::plan(cw, Series::MF, l, {}).verdict.kind,
             LimitKind::AngleUnknown);
    const safety::MotionPlan out = safety::MotionPlanner::plan(cw, Series::MF, l, at(350));
    QCOMPARE(out.verdict.kind, LimitKind::AngleAboveMax);
    QCOMPARE(out.verdict.value, 450.0);
    QVERIFY(safety::MotionPlanner::plan(ccw, Series::MF, l, at(350)).allowed());
    // From -350 deg (10 deg within the turn) counter-clockwise to 90 ends at -630.
    QCOMPARE(safety::MotionPlanner::plan(ccw, Series::MF, l, at(-350)).verdict.kind,
             LimitKind::AngleBelowMin);
    QVERIFY(!safety::MotionPlanner::needsAngle(cw, limits720()));
    QVERIFY(safety::MotionPlanner::plan(cw, Series::MF, limits720(), {}).allowed());
}

// The single-turn angle of a geared drive spans one output turn (0..36000 x ratio - 1: ERRATA,
// docs/V2.35.md, docs/CAN.md): a target may lie up to ratio rotor turns away.
void tst_MotionPlanner::gearedSingleTurnSpansTheOutputTurn()
{
    safety::SoftLimits l = limits720();
    l.minAngleDeg = -1000;
    l.maxAngleDeg = 1000;
    const safety::DrivePosition geared = at(400, 10); // within an output turn of 3600 deg
    const protocol::Request cw =
        req(protocol::build::singlePosition(1, protocol::SpinDirection::Clockwise, 350));
    const safety::MotionPlan out = safety::MotionPlanner::plan(cw, Series::MG, l, geared);
    QCOMPARE(out.verdict.kind, LimitKind::AngleAboveMax); // 3550 deg on, not 310
    QCOMPARE(out.verdict.value, 3950.0);
    const protocol::Request ccw =
        req(protocol::build::singlePosition(1, protocol::SpinDirection::CounterClockwise, 350));
    QVERIFY(safety::MotionPlanner::plan(ccw, Series::MG, l, geared).allowed()); // ends at 350
}

void tst_MotionPlanner::speedAndTorqueStayBounded()
{
    safety::MotionPlan p = safety::MotionPlanner::plan(req(protocol::build::speed(1, 800)),
                                                       Series::MF, limits720(), {});
    QCOMPARE(p.verdict.kind, LimitKind::SoftSpeed);
    p = safety::MotionPlanner::plan(req(protocol::build::speed(1, 700)), Series::MF, limits720(),
                                    {});
    QVERIFY(p.allowed());
    QCOMPARE(p.bound, SpeedBound::Command);
    QCOMPARE(p.request->command, Command::Speed);
    p = safety::MotionPlanner::plan(req(protocol::build::torque(1, 5, {})), Series::MF, limits720(),
                                    {});
    QCOMPARE(p.verdict.kind, LimitKind::SoftTorque);
}

QTEST_GUILESS_MAIN(tst_MotionPlanner)
#include "tst_motionplanner.moc"
