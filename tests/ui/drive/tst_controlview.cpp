#include "DriveTestRig.h"

#include <drive/ControlModePanel.h>
#include <drive/ControlView.h>
#include <drive/DriveSettingsStore.h>
#include <drive/JogPanel.h>
#include <drive/SoftLimitsEditor.h>
#include <main/SettingsFile.h>

#include <QtCore/QSettings>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

#include <cmath>

using lk::drivetest::button;
using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::protocol::Series;
using lk::protocol::SpinDirection;
using lk::safety::LimitKind;
using lk::ui::ControlMode;
using lk::ui::ControlView;

namespace {

std::unique_ptr<ControlView> openView(SimRig &rig, int id)
{
    return lk::drivetest::showView<ControlView>(rig, id, QSize(1200, 800));
}

// Angles differ by at most `tol` degrees on a circle of `turn` degrees.
bool nearOnCircle(double a, double b, double tol, double turn = 360)
{
    const double d = std::fmod(std::fabs(a - b), turn);
    return std::min(d, turn - d) <= tol;
}

} // namespace

class tst_ControlView : public QObject {
    Q_OBJECT
private slots:
    void modesOfferedPerSeries_data();
    void modesOfferedPerSeries();
    void eachModeMoves_data();
    void eachModeMoves();
    void refusedCommandSendsNothing_data();
    void refusedCommandSendsNothing();
    void softLimitsPersistPerDrive();
    void positionMoveRunsAtTheSpeedLimit();
    void targetStartsAtTheDrivesAngle();
    void valueDoesNotCarryOverToAnotherDrive();
    void severalDrivesSelectedNamesTheOne();
    void damagedStoredLimitsAreNeverReplacedSilently();
    void offStopRun();
    void jogHoldAndRelease();
    void jogStep();
    void keyboardJogNotInTextField();
};

void tst_ControlView::modesOfferedPerSeries_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<bool>("openLoop");
    QTest::addColumn<bool>("torque");
    QTest::newRow("MF") << 1 << false << true;
    QTest::newRow("MG") << 2 << false << true;
    QTest::newRow("MS") << 3 << true << false;
    QTest::newRow("MH") << 4 << false << true;
}

void tst_ControlView::modesOfferedPerSeries()
{
    QFETCH(int, id);
    QFETCH(bool, openLoop);
    QFETCH(bool, torque);
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, id);
    auto *modes = view->modePanel();
    QCOMPARE(modes->isOffered(ControlMode::OpenLoop), openLoop);
    QCOMPARE(modes->isOffered(ControlMode::Torque), torque);
    for (ControlMode m : {ControlMode::Speed, ControlMode::MultiPosition,
                          ControlMode::SinglePosition, ControlMode::IncrementPosition})
        QVERIFY(modes->isOffered(m));
    QCOMPARE(modes->setMode(ControlMode::OpenLoop), openLoop);
    auto *combo = view->findChild<QComboBox *>(QStringLiteral("mode"));
    QCOMPARE(combo->count(), 5); // four common modes plus torque or open loop
    // Unknown series: neither torque nor open loop.
    lk::bus::KnownMotor unknown;
    unknown.id = 9;
    view->setDrive(9, unknown);
    QVERIFY(!modes->isOffered(ControlMode::Torque));
    QVERIFY(!modes->isOffered(ControlMode::OpenLoop));
}

void tst_ControlView::eachModeMoves_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<int>("mode");
    QTest::addColumn<double>("value");
    QTest::addColumn<double>("maxSpeed"); // 0: without max speed
    QTest::addColumn<QString>("check");
    QTest::newRow("open loop MS") << 3 << int(ControlMode::OpenLoop) << 150.0 << 0.0 << "spins";
    QTest::newRow("torque MF") << 1 << int(ControlMode::Torque) << 0.5 << 0.0 << "spins";
    QTest::newRow("speed dps") << 1 << int(ControlMode::Speed) << 360.0 << 0.0 << "speed";
    QTest::newRow("speed rpm") << 4 << int(ControlMode::Speed) << -60.0 << 0.0 << "rpm";
    QTest::newRow("multi") << 1 << int(ControlMode::MultiPosition) << 300.0 << 0.0 << "multi";
    QTest::newRow("multi limited")
        << 2 << int(ControlMode::MultiPosition) << -300.0 << 720.0 << "multi";
    QTest::newRow("single") << 1 << int(ControlMode::SinglePosition) << 90.0 << 0.0 << "single";
    QTest::newRow("single limited")
        << 4 << int(ControlMode::SinglePosition) << 270.0 << 360.0 << "single";
    QTest::newRow("increment") << 1 << int(ControlMode::IncrementPosition) << 45.0 << 0.0
                               << "increment";
    QTest::newRow("increment limited")
        << 3 << int(ControlMode::IncrementPosition) << -120.0 << 360.0 << "increment";
}

void tst_ControlView::eachModeMoves()
{
    QFETCH(int, id);
    QFETCH(int, mode);
    QFETCH(double, value);
    QFETCH(double, maxSpeed);
    QFETCH(QString, check);
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, id);
    if (mode == int(ControlMode::Torque) || mode == int(ControlMode::OpenLoop)) {
        lk::safety::SoftLimits limits = view->softLimits();
        limits.maxTorqueA = 1;
        view->setSoftLimits(limits);
    }
    auto *modes = view->modePanel();
    QVERIFY(modes->setMode(ControlMode(mode)));
    const std::optional<double> max = maxSpeed > 0 ? std::optional<double>(maxSpeed) : std::nullopt;
    const double startDeg = rig.multiTurnDeg(id);
    switch (ControlMode(mode)) {
    case ControlMode::OpenLoop:
        modes->setPower(int(value));
        break;
    case ControlMode::Torque:
        modes->setTorqueA(value);
        break;
    case ControlMode::Speed:
        if (check == QLatin1String("rpm"))
            modes->setSpeedUnit(lk::ui::ControlModePanel::SpeedUnit::Rpm);
        modes->setSpeed(value);
        break;
    case ControlMode::MultiPosition:
        value += startDeg; // a target within one output turn of where the drive is
        modes->setMultiAngle(value, max);
        break;
    case ControlMode::SinglePosition:
        modes->setSingleAngle(value, SpinDirection::Clockwise, max);
        break;
    case ControlMode::IncrementPosition:
        modes->setIncrement(value, max);
        break;
    }
    QTest::mouseClick(button(*view, "send"), Qt::LeftButton);
    // A multi-turn move reads the drive's angle first.
    QTRY_VERIFY_WITH_TIMEOUT(!view->lastOutcome().pending, kWaitMs);
    QVERIFY2(view->lastOutcome().sent, qPrintable(view->statusText()));

    if (check == QLatin1String("spins")) {
        QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.speedDps(id)) > 30, kWaitMs);
    } else if (check == QLatin1String("speed")) {
        QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.speedDps(id) - value) < 0.05 * std::fabs(value),
                                 kWaitMs);
    } else if (check == QLatin1String("rpm")) {
        QTRY_VERIFY_WITH_TIMEOUT(
            std::fabs(rig.speedDps(id) - value * 6) < 0.05 * std::fabs(value * 6), kWaitMs);
    } else if (check == QLatin1String("multi")) {
        QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.multiTurnDeg(id) - value) < 2, kWaitMs);
    } else if (check == QLatin1String("single")) {
        QTRY_VERIFY_WITH_TIMEOUT(nearOnCircle(rig.singleTurnDeg(id), value, 2), kWaitMs);
    } else if (check == QLatin1String("increment")) {
        QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.multiTurnDeg(id) - (startDeg + value)) < 2, kWaitMs);
    }
    view->motorOff();
    QVERIFY(rig.barrier(id));
    QCOMPARE(rig.count(id, Command::MotorOff), 1);
}

void tst_ControlView::refusedCommandSendsNothing_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<int>("mode");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("softLimit"); // which soft limit the row sets first
    QTest::addColumn<int>("limit");         // LimitKind, or -1 for a builder (FieldError) refusal
    QTest::addColumn<int>("command");
    QTest::newRow("torque over soft") << 1 << int(ControlMode::Torque) << 3.0 << ""
                                      << int(LimitKind::SoftTorque) << int(Command::Torque);
    QTest::newRow("torque over series") << 4 << int(ControlMode::Torque) << 5.0 << "torque 20"
                                        << int(LimitKind::SeriesCurrent) << int(Command::Torque);
    QTest::newRow("torque out of range")
        << 1 << int(ControlMode::Torque) << 40.0 << "" << -1 << int(Command::Torque);
    QTest::newRow("power over soft") << 3 << int(ControlMode::OpenLoop) << 500.0 << ""
                                     << int(LimitKind::SoftPower) << int(Command::OpenLoop);
    QTest::newRow("power out of range")
        << 3 << int(ControlMode::OpenLoop) << 1500.0 << "" << -1 << int(Command::OpenLoop);
    QTest::newRow("speed over series") << 3 << int(ControlMode::Speed) << 7000.0 << "speed 0"
                                       << int(LimitKind::SeriesSpeed) << int(Command::Speed);
    QTest::newRow("speed over soft") << 1 << int(ControlMode::Speed) << 500.0 << "speed 100"
                                     << int(LimitKind::SoftSpeed) << int(Command::Speed);
    QTest::newRow("angle above range")
        << 1 << int(ControlMode::MultiPosition) << 200.0 << "angle 100"
        << int(LimitKind::AngleAboveMax) << int(Command::MultiPositionLimited);
    QTest::newRow("single angle out of range") << 1 << int(ControlMode::SinglePosition) << 400.0
                                               << "" << -1 << int(Command::SinglePosition);
    QTest::newRow("step over soft")
        << 1 << int(ControlMode::IncrementPosition) << 90.0 << "step 10"
        << int(LimitKind::SoftIncrement) << int(Command::IncrementPosition);
}

void tst_ControlView::refusedCommandSendsNothing()
{
    QFETCH(int, id);
    QFETCH(int, mode);
    QFETCH(double, value);
    QFETCH(QString, softLimit);
    QFETCH(int, limit);
    QFETCH(int, command);
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, id);
    lk::safety::SoftLimits limits = view->softLimits();
    const QStringList parts = softLimit.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    if (parts.size() == 2) {
        const double v = parts[1].toDouble();
        if (parts[0] == QLatin1String("torque"))
            limits.maxTorqueA = v;
        else if (parts[0] == QLatin1String("speed"))
            limits.maxSpeedDps = v;
        else if (parts[0] == QLatin1String("angle"))
            limits.maxAngleDeg = v;
        else if (parts[0] == QLatin1String("step"))
            limits.maxIncrementDeg = v;
        view->setSoftLimits(limits);
    }
    auto *modes = view->modePanel();
    QVERIFY(modes->setMode(ControlMode(mode)));
    modes->setPower(int(value));
    modes->setTorqueA(value);
    modes->setSpeed(value);
    modes->setMultiAngle(value);
    modes->setSingleAngle(value, SpinDirection::Clockwise);
    modes->setIncrement(value);
    QSignalSpy refused(view.get(), &ControlView::commandRefused);
    QTest::mouseClick(button(*view, "send"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->lastOutcome().pending, kWaitMs);
    const lk::ui::MotionOutcome out = view->lastOutcome();
    QVERIFY(!out.sent);
    QCOMPARE(refused.count(), 1);
    if (limit < 0)
        QVERIFY(out.fieldError.has_value());
    else
        QCOMPARE(int(out.limit), limit);
    QVERIFY(!view->statusText().isEmpty());
    QVERIFY(view->statusText().startsWith(QStringLiteral("Refused")));
    QVERIFY(rig.barrier(id));
    QCOMPARE(rig.count(id, Command(command)), 0);
}

void tst_ControlView::softLimitsPersistPerDrive()
{
    SimRig rig;
    QVERIFY(rig.open());
    QTemporaryDir dir;
    const QString ini = dir.filePath(QStringLiteral("limits.ini"));
    {
        lk::ui::SettingsFile file(ini);
        lk::ui::IniDriveStore store(file.settings());
        auto view = openView(rig, 1);
        view->setSettingsStore(&store);
        // Defaults: a quarter of the MF's 9 A.
        QCOMPARE(view->softLimits(), lk::safety::SoftLimits::defaults(Series::MF));
        auto *torque = view->findChild<QDoubleSpinBox *>(QStringLiteral("limitTorque"));
        torque->setValue(1.5);
        view->findChild<QCheckBox *>(QStringLiteral("limitMaxAngleOn"))->setChecked(true);
        view->findChild<QDoubleSpinBox *>(QStringLiteral("limitMaxAngle"))->setValue(3600);
        QTest::mouseClick(button(*view, "applyLimits"), Qt::LeftButton);
        QCOMPARE(view->softLimits().maxTorqueA, 1.5);
        store.sync();
    }
    lk::ui::SettingsFile file(ini);
    lk::ui::IniDriveStore store(file.settings());
    auto view = openView(rig, 1);
    view->setSettingsStore(&store);
    QCOMPARE(view->softLimits().maxTorqueA, 1.5);
    QCOMPARE(view->softLimits().maxAngleDeg, std::optional<double>(3600));
    // Another drive keeps its own defaults.
    view->setDrive(4, rig.motor(4));
    QCOMPARE(view->softLimits(), lk::safety::SoftLimits::defaults(Series::MH));
}

void tst_ControlView::positionMoveRunsAtTheSpeedLimit()
{
    // The issue: "Speed at most" 720 dps, 0xA3 with "Limit speed to" unticked, peak 9,500 dps.
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    lk::safety::SoftLimits limits = view->softLimits();
    limits.maxSpeedDps = 720;
    view->setSoftLimits(limits);
    auto *modes = view->modePanel();
    QVERIFY(modes->setMode(ControlMode::MultiPosition));
    const double target = rig.multiTurnDeg(1) + 350;
    modes->setMultiAngle(target); // no max speed of its own
    QTest::mouseClick(button(*view, "send"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(view->lastOutcome().sent, kWaitMs);
    QVERIFY2(view->statusText().contains(QStringLiteral("max speed 720 dps (your speed limit)")),
             qPrintable(view->statusText()));
    double peak = 0;
    QTRY_VERIFY_WITH_TIMEOUT((peak = std::max(peak, std::fabs(rig.speedDps(1))),
                              std::fabs(rig.multiTurnDeg(1) - target) < 2),
                             kWaitMs);
    // The speed loop may overshoot a little; unbounded, an MF rotor heads for 18000 dps.
    QVERIFY2(peak <= 720 * 1.25, qPrintable(QString::number(peak)));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::MultiPosition), 0);
    QCOMPARE(rig.count(1, Command::MultiPositionLimited), 1);
}

void tst_ControlView::targetStartsAtTheDrivesAngle()
{
    SimRig rig;
    QVERIFY(rig.open());
    QVERIFY(rig.windAway(1)); // several turns away from 0
    auto view = openView(rig, 1);
    auto *modes = view->modePanel();
    QVERIFY(modes->setMode(ControlMode::MultiPosition));
    auto *target = view->findChild<QDoubleSpinBox *>(QStringLiteral("multiAngle"));
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(target->value() - rig.multiTurnDeg(1)) < 1, kWaitMs);
    // 0 absolute is several turns back: refused, naming the rule, nothing sent.
    modes->setMultiAngle(0);
    QTest::mouseClick(button(*view, "send"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->lastOutcome().pending, kWaitMs);
    QVERIFY(!view->lastOutcome().sent);
    QCOMPARE(view->lastOutcome().limit, LimitKind::OutputTurn);
    QVERIFY2(view->statusText().contains(QStringLiteral("one output turn")),
             qPrintable(view->statusText()));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::MultiPosition) + rig.count(1, Command::MultiPositionLimited), 0);
}

void tst_ControlView::valueDoesNotCarryOverToAnotherDrive()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    auto *modes = view->modePanel();
    QVERIFY(modes->setMode(ControlMode::Speed));
    modes->setSpeed(500);
    view->setDrive(4, rig.motor(4));
    QCOMPARE(view->findChild<QDoubleSpinBox *>(QStringLiteral("speed"))->value(), 0.0);
    QTest::mouseClick(button(*view, "send"), Qt::LeftButton);
    QVERIFY(rig.barrier(4));
    QCOMPARE(rig.speedDps(4), 0.0);
}

void tst_ControlView::severalDrivesSelectedNamesTheOne()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    auto *note = view->findChild<QLabel *>(QStringLiteral("selectionNote"));
    QVERIFY(note);
    QVERIFY(!note->isVisible());
    view->setSelectedDrives({1, 4});
    QVERIFY(note->isVisible());
    QVERIFY2(note->text().contains(QStringLiteral("2 drives are selected")) &&
                 note->text().contains(view->driveTitle()),
             qPrintable(note->text()));
    view->setSelectedDrives({1});
    QVERIFY(!note->isVisible());
}

void tst_ControlView::damagedStoredLimitsAreNeverReplacedSilently()
{
    SimRig rig;
    QVERIFY(rig.open());
    QTemporaryDir dir;
    const QString ini = dir.filePath(QStringLiteral("limits.ini"));
    const QString key =
        lk::ui::IniDriveStore::softLimitsKey(lk::ui::DriveSettingsStore::driveKey(1, rig.motor(1)));
    lk::ui::SettingsFile file(ini);
    lk::ui::IniDriveStore store(file.settings());
    auto view = openView(rig, 1);
    view->setSettingsStore(&store);
    lk::safety::SoftLimits mine = view->softLimits();
    mine.maxTorqueA = 1;
    mine.maxSpeedDps = 720;
    view->setSoftLimits(mine);
    store.sync();
    const auto damage = [&] {
        QSettings s(ini, QSettings::IniFormat);
        s.setValue(key, QStringLiteral(R"({"max_speed": 720})"));
        s.sync();
        store.sync();
    };
    // Damaged while shown: the limits in force stay (not 2.25 A / 18000 dps) and it says so.
    damage();
    view->setDrive(1, rig.motor(1)); // reads the entry again
    QCOMPARE(view->softLimits(), mine);
    QVERIFY2(view->statusText().contains(QStringLiteral("max_speed")),
             qPrintable(view->statusText()));
    // Damaged before it is shown: nothing moves until the user applies limits.
    damage();
    auto fresh = openView(rig, 1);
    fresh->setSettingsStore(&store);
    auto *modes = fresh->modePanel();
    QVERIFY(modes->setMode(ControlMode::Speed));
    modes->setSpeed(500);
    QTest::mouseClick(button(*fresh, "send"), Qt::LeftButton);
    QVERIFY(!fresh->lastOutcome().sent);
    QVERIFY2(fresh->statusText().contains(QStringLiteral("damaged")) &&
                 fresh->statusText().contains(QStringLiteral("unknown key \"max_speed\"")),
             qPrintable(fresh->statusText()));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::Speed), 0);
    QTest::mouseClick(button(*fresh, "applyLimits"), Qt::LeftButton);
    QTest::mouseClick(button(*fresh, "send"), Qt::LeftButton);
    QVERIFY2(fresh->lastOutcome().sent, qPrintable(fresh->statusText()));
}

void tst_ControlView::offStopRun()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    view->modePanel()->setMode(ControlMode::Speed);
    view->modePanel()->setSpeed(180);
    QTest::mouseClick(button(*view, "send"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.speedDps(1) - 180) < 10, kWaitMs);
    using RunState = lk::sim::SimDrive::RunState;
    auto state = [&] {
        return rig.read<RunState>(1, [](const lk::sim::SimDrive &d) { return d.runState(); });
    };
    QTest::mouseClick(button(*view, "motorStop"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(state(), RunState::Stopped, kWaitMs);
    QTest::mouseClick(button(*view, "motorRun"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(state(), RunState::Running, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.speedDps(1) - 180) < 10, kWaitMs);
    QTest::mouseClick(button(*view, "motorOff"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(state(), RunState::Off, kWaitMs);
}

void tst_ControlView::jogHoldAndRelease()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    view->jogPanel()->setSpeedDps(120);
    QPushButton *hold = view->jogPanel()->holdButton(+1);
    QTest::mousePress(hold, Qt::LeftButton);
    QVERIFY(view->isJogging());
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.speedDps(1) - 120) < 10, kWaitMs);
    QTest::mouseRelease(hold, Qt::LeftButton);
    QVERIFY(!view->isJogging());
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.speedDps(1)) < 2, kWaitMs);
    QCOMPARE(rig.count(1, Command::Speed), 2); // run, then speed 0

    // Counter-clockwise, and a jog over the soft speed limit is refused outright.
    QTest::mousePress(view->jogPanel()->holdButton(-1), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(rig.speedDps(1) < -100, kWaitMs);
    QTest::mouseRelease(view->jogPanel()->holdButton(-1), Qt::LeftButton);
    lk::safety::SoftLimits limits = view->softLimits();
    limits.maxSpeedDps = 50;
    view->setSoftLimits(limits);
    QTest::mousePress(hold, Qt::LeftButton);
    QVERIFY(!view->isJogging());
    QCOMPARE(view->lastOutcome().limit, LimitKind::SoftSpeed);
    QTest::mouseRelease(hold, Qt::LeftButton);
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::Speed), 4);
}

void tst_ControlView::jogStep()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    view->jogPanel()->setStepDeg(30);
    view->jogPanel()->setSpeedDps(360);
    const double start = rig.multiTurnDeg(1);
    QTest::mouseClick(view->jogPanel()->stepButton(+1), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.multiTurnDeg(1) - (start + 30)) < 2, kWaitMs);
    QTest::mouseClick(view->jogPanel()->stepButton(-1), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.multiTurnDeg(1) - start) < 2, kWaitMs);
    QCOMPARE(rig.count(1, Command::IncrementPositionLimited), 2);
}

void tst_ControlView::keyboardJogNotInTextField()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QApplication::setActiveWindow(view.get());
    QVERIFY(QTest::qWaitForWindowActive(view.get()));
    view->jogPanel()->setSpeedDps(100);
    view->jogPanel()->setKeyboardJog(true);

    // Focus in a text field: arrows edit the field, the motor stays put.
    auto *speedField = view->findChild<QDoubleSpinBox *>(QStringLiteral("jogSpeed"));
    speedField->setFocus();
    QTRY_VERIFY(speedField->hasFocus());
    QTest::keyPress(QApplication::focusWidget(), Qt::Key_Right);
    QTest::keyRelease(QApplication::focusWidget(), Qt::Key_Right);
    QVERIFY(!view->isJogging());
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::Speed), 0);

    // Focus on the view itself: Right runs while held, release stops.
    view->setFocus();
    QTRY_VERIFY(view->hasFocus());
    QTest::keyPress(view.get(), Qt::Key_Right);
    QVERIFY(view->isJogging());
    QTRY_VERIFY_WITH_TIMEOUT(rig.speedDps(1) > 80, kWaitMs);
    QTest::keyRelease(view.get(), Qt::Key_Right);
    QVERIFY(!view->isJogging());
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.speedDps(1)) < 2, kWaitMs);

    // Off by default: a fresh switch-off ignores arrows.
    view->jogPanel()->setKeyboardJog(false);
    QTest::keyPress(view.get(), Qt::Key_Left);
    QTest::keyRelease(view.get(), Qt::Key_Left);
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::Speed), 2);
}

QTEST_MAIN(tst_ControlView)
#include "tst_controlview.moc"
