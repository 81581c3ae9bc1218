// The limits a V2.35 drive holds itself (Max Speed, max torque current or Max Power, Max Angle):
// where read, every motion bound is the lower of it and the soft limit, and a refusal or a
// speed bound the drive's value decided names the drive's limit.

#include "SafetyTestUtil.h"

#include <protocol/RequestBuilder.h>
#include <safety/DriveLimits.h>
#include <safety/MotionPlanner.h>

#include <QtTest/QtTest>

using namespace lk;
using lk::test::req;
using protocol::Command;
using protocol::DecodeContext;
using protocol::Generation;
using protocol::ParameterValue;
using protocol::ParamId;
using protocol::Series;
using safety::DriveLimits;
using safety::LimitKind;
using safety::MotionPlanner;
using safety::SpeedBound;

namespace {
const DecodeContext kV235Mf{Series::MF, Generation::V2_35};

/// What a V2.35 MF drive with Max Speed 720 dps, max torque 248 (2 A), Max Angle 3600 deg
/// answers to 0x40.
QList<ParameterValue> params720()
{
    return {ParameterValue::int16(ParamId::MaxTorqueCurrent, 248),
            ParameterValue::int32(ParamId::MaxSpeed, 72000),
            ParameterValue::maxAngleHalf(360000, false),
            ParameterValue::maxAngleHalf(360000, true)};
}

safety::DrivePosition at(double deg)
{
    safety::DrivePosition p;
    p.angleDeg = deg;
    return p;
}
} // namespace

class tst_DriveLimits : public QObject {
    Q_OBJECT
private slots:
    void fromParams();
    void zeroBoundsNothing();
    void msMaxPowerIsPower();
    void narrowTakesTheLower();
    void speedOverTheDrivesMaxIsRefusedNamingIt();
    void positionMoveIsCappedAtTheDrivesMaxSpeed();
    void softLimitLowerStaysTheSoftLimit();
    void torqueAndAngleByTheDrive();
    void nothingReadChangesNothing();
};

void tst_DriveLimits::fromParams()
{
    const DriveLimits d = DriveLimits::fromParams(params720(), kV235Mf);
    QCOMPARE(d.maxSpeedDps, std::optional<double>(720.0));
    QCOMPARE(d.maxTorqueA, std::optional<double>(248 * 33.0 / 4096.0)); // the MF V2.35 scale
    QVERIFY(!d.maxPower);
    QCOMPARE(d.maxAngleDeg, std::optional<double>(3600.0));
    // A max angle needs both halves.
    QList<ParameterValue> half = params720();
    half.removeLast();
    QVERIFY(!DriveLimits::fromParams(half, kV235Mf).maxAngleDeg);
}

void tst_DriveLimits::zeroBoundsNothing()
{
    // Max Speed 0: the drive uses its maximum (docs/V2.35.md section 12); Max Angle 0: none.
    const DriveLimits d = DriveLimits::fromParams(
        {ParameterValue::int32(ParamId::MaxSpeed, 0),
         ParameterValue::int16(ParamId::MaxTorqueCurrent, 0),
         ParameterValue::maxAngleHalf(0, false), ParameterValue::maxAngleHalf(0, true)},
        kV235Mf);
    QVERIFY(!d.any());
}

void tst_DriveLimits::msMaxPowerIsPower()
{
    const DriveLimits d = DriveLimits::fromParams(
        {ParameterValue::int16(ParamId::MaxTorqueCurrent, 150)}, {Series::MS, Generation::V2_35});
    QCOMPARE(d.maxPower, std::optional<int>(150));
    QVERIFY(!d.maxTorqueA);
    const safety::SoftLimits soft = safety::SoftLimits::defaults(Series::MS); // power 200
    const safety::MotionPlan p =
        MotionPlanner::plan(req(protocol::build::openLoop(1, 180)), Series::MS, soft, {}, d);
    QVERIFY(!p.allowed());
    QCOMPARE(p.verdict.kind, LimitKind::SoftPower);
    QVERIFY(p.verdict.drivesOwn);
    QVERIFY2(DriveLimits::refusal(p.verdict).contains("Max Power of 150"),
             qPrintable(DriveLimits::refusal(p.verdict)));
}

void tst_DriveLimits::narrowTakesTheLower()
{
    safety::SoftLimits soft = safety::SoftLimits::defaults(Series::MF);
    soft.maxAngleDeg = 1000;
    const safety::SoftLimits l = DriveLimits::fromParams(params720(), kV235Mf).narrow(soft);
    QCOMPARE(l.maxSpeedDps, 720.0);
    QCOMPARE(l.maxTorqueA, 248 * 33.0 / 4096.0);
    QCOMPARE(l.maxAngleDeg, std::optional<double>(1000.0)); // the soft one is narrower
    QCOMPARE(l.minAngleDeg, std::optional<double>(-3600.0));
}

void tst_DriveLimits::speedOverTheDrivesMaxIsRefusedNamingIt()
{
    // The issue: checked against the series top speed while the drive holds 720 dps.
    const DriveLimits d = DriveLimits::fromParams(params720(), kV235Mf);
    const safety::SoftLimits soft = safety::SoftLimits::defaults(Series::MF); // 18000 dps
    const safety::MotionPlan p =
        MotionPlanner::plan(req(protocol::build::speed(1, 800)), Series::MF, soft, {}, d);
    QVERIFY(!p.allowed());
    QCOMPARE(p.verdict.kind, LimitKind::SoftSpeed);
    QCOMPARE(p.verdict.limit, 720.0);
    QVERIFY(p.verdict.drivesOwn);
    QVERIFY2(DriveLimits::refusal(p.verdict).contains("the drive's own Max Speed of 720 dps"),
             qPrintable(DriveLimits::refusal(p.verdict)));
    const safety::MotionPlan ok =
        MotionPlanner::plan(req(protocol::build::speed(1, -700)), Series::MF, soft, {}, d);
    QVERIFY(ok.allowed());
    QVERIFY(ok.drivesOwnSpeed);
    QCOMPARE(ok.boundDps, 720.0);
    QVERIFY(DriveLimits::speedBound(ok.bound, ok.boundDps).contains("drive's own Max Speed"));
}

void tst_DriveLimits::positionMoveIsCappedAtTheDrivesMaxSpeed()
{
    const DriveLimits d = DriveLimits::fromParams(params720(), kV235Mf);
    const safety::MotionPlan p =
        MotionPlanner::plan(req(protocol::build::multiPosition(1, 90)), Series::MF,
                            safety::SoftLimits::defaults(Series::MF), at(0), d);
    QVERIFY(p.allowed());
    QCOMPARE(p.request->command, Command::MultiPositionLimited);
    QCOMPARE(*std::get<protocol::MultiPositionCommand>(p.request->payload).maxSpeedRaw,
             quint32(72000)); // not 18000 dps
    QCOMPARE(p.bound, SpeedBound::SoftLimit);
    QVERIFY(p.drivesOwnSpeed);
    // A max speed the user gave above the drive's is refused as over the drive's limit (the
    // drive's Max Angle is an angle range: where the increment ends is checked too).
    QCOMPARE(MotionPlanner::plan(req(protocol::build::incrementPosition(1, 10, 1000)), Series::MF,
                                 safety::SoftLimits::defaults(Series::MF), {}, d)
                 .verdict.kind,
             LimitKind::AngleUnknown);
    const safety::MotionPlan over =
        MotionPlanner::plan(req(protocol::build::incrementPosition(1, 10, 1000)), Series::MF,
                            safety::SoftLimits::defaults(Series::MF), at(0), d);
    QCOMPARE(over.verdict.kind, LimitKind::SoftSpeed);
    QVERIFY(over.verdict.drivesOwn);
    QVERIFY(DriveLimits::refusal(over.verdict).startsWith("the max speed 1000 dps"));
}

void tst_DriveLimits::softLimitLowerStaysTheSoftLimit()
{
    const DriveLimits d = DriveLimits::fromParams(params720(), kV235Mf);
    safety::SoftLimits soft = safety::SoftLimits::defaults(Series::MF);
    soft.maxSpeedDps = 360;
    const safety::MotionPlan p =
        MotionPlanner::plan(req(protocol::build::speed(1, 400)), Series::MF, soft, {}, d);
    QCOMPARE(p.verdict.kind, LimitKind::SoftSpeed);
    QCOMPARE(p.verdict.limit, 360.0);
    QVERIFY(!p.verdict.drivesOwn); // the user's limit refused it
    const safety::MotionPlan ok =
        MotionPlanner::plan(req(protocol::build::multiPosition(1, 10)), Series::MF, soft, at(0), d);
    QVERIFY(ok.allowed());
    QVERIFY(!ok.drivesOwnSpeed);
    QCOMPARE(ok.boundDps, 360.0);
}

void tst_DriveLimits::torqueAndAngleByTheDrive()
{
    const DriveLimits d = DriveLimits::fromParams(params720(), kV235Mf); // 2 A, 3600 deg
    safety::SoftLimits soft = safety::SoftLimits::defaults(Series::MF);  // 2.25 A
    const safety::MotionPlan torque =
        MotionPlanner::plan(req(protocol::build::torque(1, 2.1, kV235Mf)), Series::MF, soft, {}, d);
    QCOMPARE(torque.verdict.kind, LimitKind::SoftTorque);
    QVERIFY(torque.verdict.drivesOwn);
    QVERIFY(DriveLimits::refusal(torque.verdict).contains("max torque current of 2.00 A"));
    const safety::MotionPlan angle = MotionPlanner::plan(
        req(protocol::build::multiPosition(1, 3700)), Series::MF, soft, at(3500), d);
    QCOMPARE(angle.verdict.kind, LimitKind::AngleAboveMax);
    QVERIFY(angle.verdict.drivesOwn);
    QVERIFY2(DriveLimits::refusal(angle.verdict).contains("Max Angle of \u00b13600\u00b0"),
             qPrintable(DriveLimits::refusal(angle.verdict)));
}

void tst_DriveLimits::nothingReadChangesNothing()
{
    const safety::SoftLimits soft = safety::SoftLimits::defaults(Series::MF);
    QVERIFY(DriveLimits{}.narrow(soft) == soft);
    const safety::MotionPlan p =
        MotionPlanner::plan(req(protocol::build::speed(1, 18000.01)), Series::MF, soft, {});
    QCOMPARE(p.verdict.kind, LimitKind::SeriesSpeed);
    QVERIFY(!p.verdict.drivesOwn);
}

QTEST_APPLESS_MAIN(tst_DriveLimits)
#include "tst_drivelimits.moc"
