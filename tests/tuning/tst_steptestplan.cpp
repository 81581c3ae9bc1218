#include <text/VerdictText.h>
#include <tuning/StepTestPlan.h>

#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::tuning;
using protocol::Command;
using protocol::Series;
using safety::LimitKind;
using Role = StepSetpoint::Role;

Q_DECLARE_METATYPE(lk::tuning::StepTestSpec)

namespace {
// Why a plan was refused, as lkctl and the GUI word it: the bad spec, or the setpoint and limit.
QString refusalText(const StepTestPlan &p)
{
    return p.specError().isEmpty() ? text::VerdictText::stepRefusal(p.refusal()) : p.specError();
}

StepTestSpec speedSpec(double from, double to, int periods = 1)
{
    StepTestSpec s;
    s.id = 3;
    s.loop = StepLoop::Speed;
    s.from = from;
    s.to = to;
    s.durationS = 0.5;
    s.preRollS = 0.25;
    s.periods = periods;
    return s;
}

StepTestSpec positionSpec(double from, double to, int periods = 1)
{
    StepTestSpec s = speedSpec(from, to, periods);
    s.loop = StepLoop::Position;
    return s;
}

safety::DrivePosition at(std::optional<double> angle, double gear = 1)
{
    safety::DrivePosition p;
    p.angleDeg = angle;
    p.gearRatio = gear;
    return p;
}

double speedOf(const StepSetpoint &s)
{
    return std::get<protocol::SpeedCommand>(s.request.payload).speedDps();
}

double angleOf(const StepSetpoint &s)
{
    return std::get<protocol::MultiPositionCommand>(s.request.payload).angleRaw / 100.0;
}
} // namespace

/// StepTestPlan: the setpoints' times and targets, and that every one passes MotionPlanner
/// before anything is sent.
class tst_StepTestPlan : public QObject {
    Q_OBJECT
private slots:
    void singleSpeedStepReturnsToFrom();
    void squareWaveEndsAtFrom();
    void positionMovesAreLimitedAndBounded();
    void positionHoldsItsLastTarget();
    void positionTargetsStartWhereTheDriveIs_data();
    void positionTargetsStartWhereTheDriveIs();
    void gearRatioWidensTheTurn();
    void speedOverTheLimitIsRefused_data();
    void speedOverTheLimitIsRefused();
    void angleRangeRefusesTheTarget();
    void badSpecs_data();
    void badSpecs();
};

void tst_StepTestPlan::singleSpeedStepReturnsToFrom()
{
    const StepTestPlan p =
        StepTestPlan::make(speedSpec(100, 400), Series::MF,
                           safety::SoftLimits::defaults(Series::MF), at(std::nullopt));
    QVERIFY2(p.allowed(), qPrintable(refusalText(p)));
    QCOMPARE(p.setpoints().size(), 3);
    const QVector<Role> roles{Role::PreRoll, Role::Edge, Role::Return};
    const QVector<double> times{0, 0.25, 0.75};
    const QVector<double> targets{100, 400, 100};
    for (int i = 0; i < 3; ++i) {
        const StepSetpoint &s = p.setpoints().at(i);
        QCOMPARE(s.role, roles.at(i));
        QCOMPARE(s.atS, times.at(i));
        QCOMPARE(s.target, targets.at(i));
        QCOMPARE(s.request.command, Command::Speed);
        QCOMPARE(int(s.request.id), 3);
        QCOMPARE(speedOf(s), targets.at(i));
    }
    QCOMPARE(p.setpoints().at(1).previous, 100.0);
    QCOMPARE(p.endS(), 0.75);
    QCOMPARE(p.bound(), safety::SpeedBound::Command);
}

void tst_StepTestPlan::squareWaveEndsAtFrom()
{
    const StepTestPlan p = StepTestPlan::make(speedSpec(0, -200, 3), Series::MG,
                                              safety::SoftLimits::defaults(Series::MG), at(0));
    QVERIFY2(p.allowed(), qPrintable(refusalText(p)));
    QCOMPARE(p.setpoints().size(), 7); // pre-roll + 6 edges, no return: the last edge is it
    for (int k = 0; k < 6; ++k) {
        const StepSetpoint &s = p.setpoints().at(k + 1);
        QCOMPARE(s.role, Role::Edge);
        QCOMPARE(s.atS, 0.25 + 0.5 * k);
        QCOMPARE(s.target, k % 2 == 0 ? -200.0 : 0.0);
        QCOMPARE(s.previous, k % 2 == 0 ? 0.0 : -200.0);
    }
    QCOMPARE(p.endS(), 0.25 + 6 * 0.5);
}

void tst_StepTestPlan::positionMovesAreLimitedAndBounded()
{
    safety::SoftLimits limits = safety::SoftLimits::defaults(Series::MF);
    limits.maxSpeedDps = 720;
    const StepTestPlan p = StepTestPlan::make(positionSpec(10, 100, 2), Series::MF, limits, at(5));
    QVERIFY2(p.allowed(), qPrintable(refusalText(p)));
    QCOMPARE(p.setpoints().size(), 5);
    for (const StepSetpoint &s : p.setpoints()) {
        QCOMPARE(s.request.command, Command::MultiPositionLimited);
        QCOMPARE(angleOf(s), s.target);
        const auto &c = std::get<protocol::MultiPositionCommand>(s.request.payload);
        QCOMPARE(c.maxSpeedRaw, std::optional<quint32>(72000));
    }
    QCOMPARE(p.bound(), safety::SpeedBound::SoftLimit);
    QCOMPARE(p.boundDps(), 720.0);

    // A lower max speed of the user's own goes out as given.
    StepTestSpec slow = positionSpec(10, 100);
    slow.maxSpeedDps = 90;
    const StepTestPlan q = StepTestPlan::make(slow, Series::MF, limits, at(5));
    QVERIFY(q.allowed());
    QCOMPARE(q.bound(), safety::SpeedBound::UserMaxSpeed);
    QCOMPARE(
        std::get<protocol::MultiPositionCommand>(q.setpoints().at(1).request.payload).maxSpeedRaw,
        std::optional<quint32>(9000));
    // ... and one above the speed limit is refused.
    slow.maxSpeedDps = 1000;
    const StepTestPlan r = StepTestPlan::make(slow, Series::MF, limits, at(5));
    QVERIFY(!r.allowed());
    QCOMPARE(r.verdict().kind, LimitKind::SoftSpeed);
}

void tst_StepTestPlan::positionHoldsItsLastTarget()
{
    const StepTestPlan p = StepTestPlan::make(positionSpec(0, 90), Series::MF,
                                              safety::SoftLimits::defaults(Series::MF), at(0));
    QVERIFY(p.allowed());
    QCOMPARE(p.setpoints().size(), 2); // no return: the position test stays at TO
    QCOMPARE(p.setpoints().last().target, 90.0);
    QCOMPARE(p.endS(), 0.75);
}

void tst_StepTestPlan::positionTargetsStartWhereTheDriveIs_data()
{
    QTest::addColumn<std::optional<double>>("angle");
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("setpoint");
    QTest::newRow("angle unknown") << std::optional<double>() << 0.0 << 90.0
                                   << int(LimitKind::AngleUnknown) << "setpoint 1 of 2";
    QTest::newRow("FROM over a turn from the drive")
        << std::optional<double>(0) << 400.0 << 500.0 << int(LimitKind::OutputTurn)
        << "setpoint 1 of 2";
    QTest::newRow("TO over a turn from FROM") << std::optional<double>(0) << 100.0 << 500.0
                                              << int(LimitKind::OutputTurn) << "setpoint 2 of 2";
    QTest::newRow("square: every edge checked") << std::optional<double>(-300) << 0.0 << -361.0
                                                << int(LimitKind::OutputTurn) << "setpoint 2 of 5";
}

void tst_StepTestPlan::positionTargetsStartWhereTheDriveIs()
{
    QFETCH(std::optional<double>, angle);
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(int, kind);
    QFETCH(QString, setpoint);
    const int periods = QString::fromLatin1(QTest::currentDataTag()).startsWith("square") ? 2 : 1;
    const StepTestPlan p = StepTestPlan::make(positionSpec(from, to, periods), Series::MF,
                                              safety::SoftLimits::defaults(Series::MF), at(angle));
    QVERIFY(!p.allowed());
    QVERIFY(p.setpoints().isEmpty());
    QCOMPARE(int(p.verdict().kind), kind);
    QVERIFY2(refusalText(p).startsWith(setpoint), qPrintable(refusalText(p)));
    QVERIFY(refusalText(p).contains(text::VerdictText::verdict(p.verdict(), Series::MF)));
    QCOMPARE(p.refusal().series, std::optional<Series>(Series::MF));
}

void tst_StepTestPlan::gearRatioWidensTheTurn()
{
    // One output turn of a 1:10 gear is 3600 rotor degrees.
    const StepTestPlan p = StepTestPlan::make(positionSpec(0, 3000), Series::MG,
                                              safety::SoftLimits::defaults(Series::MG), at(0, 10));
    QVERIFY2(p.allowed(), qPrintable(refusalText(p)));
}

void tst_StepTestPlan::speedOverTheLimitIsRefused_data()
{
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<QString>("setpoint");
    QTest::newRow("TO") << 0.0 << 800.0 << "setpoint 2 of 3";
    QTest::newRow("FROM") << -900.0 << 0.0 << "setpoint 1 of 3";
}

void tst_StepTestPlan::speedOverTheLimitIsRefused()
{
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(QString, setpoint);
    safety::SoftLimits limits = safety::SoftLimits::defaults(Series::MF);
    limits.maxSpeedDps = 720;
    const StepTestPlan p = StepTestPlan::make(speedSpec(from, to), Series::MF, limits, at(0));
    QVERIFY(!p.allowed());
    QVERIFY(p.setpoints().isEmpty());
    QCOMPARE(p.verdict().kind, LimitKind::SoftSpeed);
    QCOMPARE(p.verdict().limit, 720.0);
    QVERIFY2(refusalText(p).startsWith(setpoint), qPrintable(refusalText(p)));
}

void tst_StepTestPlan::angleRangeRefusesTheTarget()
{
    safety::SoftLimits limits = safety::SoftLimits::defaults(Series::MF);
    limits.maxAngleDeg = 45;
    const StepTestPlan p = StepTestPlan::make(positionSpec(0, 90), Series::MF, limits, at(0));
    QVERIFY(!p.allowed());
    QCOMPARE(p.verdict().kind, LimitKind::AngleAboveMax);
    QVERIFY(p.setpoints().isEmpty());
}

void tst_StepTestPlan::badSpecs_data()
{
    QTest::addColumn<StepTestSpec>("spec");
    QTest::addColumn<QString>("problem");
    StepTestSpec s = speedSpec(100, 100);
    QTest::newRow("no step") << s << "no step";
    s = speedSpec(0, 100);
    s.durationS = 0;
    QTest::newRow("duration 0") << s << "duration";
    s = speedSpec(0, 100);
    s.durationS = 61;
    QTest::newRow("duration 61") << s << "duration";
    s = speedSpec(0, 100);
    s.preRollS = 0;
    QTest::newRow("no pre-roll") << s << "pre-roll";
    s = speedSpec(0, 100, 0);
    QTest::newRow("periods 0") << s << "periods";
    s = speedSpec(0, 100, 101);
    QTest::newRow("periods 101") << s << "periods";
    s = speedSpec(0, std::nan(""));
    QTest::newRow("NaN") << s << "numbers";
    s = speedSpec(0, 100);
    s.maxSpeedDps = 50;
    QTest::newRow("max speed on a speed test") << s << "position test only";
    s = speedSpec(0, 3e9);
    QTest::newRow("beyond the wire") << s << "speed_dps";
}

void tst_StepTestPlan::badSpecs()
{
    QFETCH(StepTestSpec, spec);
    QFETCH(QString, problem);
    const StepTestPlan p =
        StepTestPlan::make(spec, Series::MF, safety::SoftLimits::defaults(Series::MF), at(0));
    QVERIFY(!p.allowed());
    QVERIFY(p.setpoints().isEmpty());
    QVERIFY(p.verdict().allowed()); // not a limit: the spec itself
    QVERIFY2(p.specError().contains(problem), qPrintable(p.specError()));
    QCOMPARE(refusalText(p), p.specError());
    QVERIFY(text::VerdictText::stepRefusal(p.refusal()).isEmpty()); // no setpoint refused
}

QTEST_APPLESS_MAIN(tst_StepTestPlan)
#include "tst_steptestplan.moc"
