// The control view's setpoint generator against the simulated bus: it starts where the drive
// is, stops on Stop, a drive or connection change and changed limits, keeps its pace while the
// GUI thread is busy, and a halt cancels a start still waiting for the angle.

#include "DriveTestRig.h"

#include <bus/SetpointWaveform.h>
#include <drive/ControlView.h>
#include <drive/SetpointGenerator.h>
#include <drive/SetpointPanel.h>

#include <QtCore/QThread>
#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QPushButton>

#include <cmath>

using lk::bus::SetpointWaveform;
using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::ControlView;

namespace {

std::unique_ptr<ControlView> openView(SimRig &rig, int id)
{
    return lk::drivetest::showView<ControlView>(rig, id, QSize(1200, 800));
}

/// A speed waveform with the panel's defaults: a square of +-90 dps around 0, 2 s, 20 Hz.
SetpointWaveform::Settings speedWave()
{
    SetpointWaveform::Settings s;
    s.target = SetpointWaveform::Target::Speed;
    return s;
}

/// Nothing more of `command` reaches drive `id` over several generator periods.
bool noMoreSent(SimRig &rig, int id, Command command)
{
    const int sent = rig.count(id, command);
    QTest::qWait(300);
    return rig.barrier(id) && rig.count(id, command) == sent;
}

} // namespace

class tst_ControlGenerator : public QObject {
    Q_OBJECT
private slots:
    void generatorPositionCentredOnTheDrive();
    void generatorStartsAndStopStops();
    void generatorStopsOnDriveChange();
    void generatorKeepsPaceWhileTheGuiIsBusy();
    void generatorStopsWhenTheLimitsChange();
    void haltWhileTheAngleIsReadCancelsThePositionStart();
};

void tst_ControlGenerator::generatorPositionCentredOnTheDrive()
{
    SimRig rig;
    QVERIFY(rig.open());
    QVERIFY(rig.windAway(1));
    auto view = openView(rig, 1);
    auto *target = view->findChild<QComboBox *>(QStringLiteral("target"));
    target->setCurrentIndex(target->findData(int(SetpointWaveform::Target::Position)));
    QTRY_VERIFY_WITH_TIMEOUT(
        std::fabs(view->setpointPanel()->settings().offset - rig.multiTurnDeg(1)) < 1, kWaitMs);
    // A waveform around 0 absolute is turns away: the first setpoint is refused, none sent.
    SetpointWaveform::Settings far = view->setpointPanel()->settings();
    far.offset = 0;
    view->startGenerator(far);
    QTRY_VERIFY_WITH_TIMEOUT(view->statusText().contains(QStringLiteral("one output turn")),
                             kWaitMs);
    QVERIFY(!view->generator()->isRunning());
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::MultiPosition) + rig.count(1, Command::MultiPositionLimited), 0);
}

void tst_ControlGenerator::generatorStartsAndStopStops()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    SetpointWaveform::Settings s = speedWave();
    s.waveform = SetpointWaveform::Waveform::Square;
    s.periodS = 0.5;
    view->startGenerator(s);
    QVERIFY(view->generator()->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(rig.count(1, Command::Speed) >= 3, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(std::fabs(rig.speedDps(1)) > 30, kWaitMs);
    QTest::mouseClick(view->findChild<QPushButton *>(QStringLiteral("stopGenerator")),
                      Qt::LeftButton);
    QVERIFY(!view->generator()->isRunning());
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::MotorStop), 1);
    QVERIFY(noMoreSent(rig, 1, Command::Speed));
}

void tst_ControlGenerator::generatorStopsOnDriveChange()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    const SetpointWaveform::Settings s = speedWave();
    view->startGenerator(s);
    QTRY_VERIFY_WITH_TIMEOUT(rig.count(1, Command::Speed) >= 2, kWaitMs);
    view->setDrive(2, rig.motor(2));
    QVERIFY(!view->generator()->isRunning());
    QTRY_COMPARE_WITH_TIMEOUT(rig.count(1, Command::MotorStop), 1, kWaitMs);
    QVERIFY(rig.barrier(2));
    QCOMPARE(rig.count(2, Command::Speed), 0);

    view->setDrive(1, rig.motor(1));
    view->startGenerator(s);
    QVERIFY(view->generator()->isRunning());
    view->setConnected(false);
    QVERIFY(!view->generator()->isRunning());
}

void tst_ControlGenerator::generatorKeepsPaceWhileTheGuiIsBusy()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    view->startGenerator(speedWave());
    QTRY_VERIFY_WITH_TIMEOUT(rig.count(1, Command::Speed) >= 1, kWaitMs);
    // The GUI thread is busy for 600 ms (12 ticks at 20 Hz): the bus thread paces setpoints
    // on its own, so they keep going out meanwhile instead of waiting for the GUI.
    const int before = rig.count(1, Command::Speed);
    QThread::msleep(600);
    QVERIFY2(rig.count(1, Command::Speed) - before >= 4,
             qPrintable(QString::number(rig.count(1, Command::Speed) - before)));
    view->stopGenerator();
    QVERIFY(!view->generator()->isRunning());
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::MotorStop), 1);
}

void tst_ControlGenerator::generatorStopsWhenTheLimitsChange()
{
    // The bus thread checks setpoints against the limits the generator started with: lowered
    // limits stop it (and the drive) rather than leaving it to run under the old ones.
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    view->startGenerator(speedWave());
    QTRY_VERIFY_WITH_TIMEOUT(rig.count(1, Command::Speed) >= 2, kWaitMs);
    QSignalSpy stopped(view->generator(), &lk::ui::SetpointGenerator::stopped);
    lk::safety::SoftLimits lower = view->softLimits();
    lower.maxSpeedDps = 30;
    view->setSoftLimits(lower);
    QVERIFY(!view->generator()->isRunning());
    QCOMPARE(stopped.size(), 1);
    QVERIFY(stopped.at(0).at(0).toString().contains(QStringLiteral("soft limits")));
    QTRY_COMPARE_WITH_TIMEOUT(rig.count(1, Command::MotorStop), 1, kWaitMs);
    QVERIFY(noMoreSent(rig, 1, Command::Speed));
}

void tst_ControlGenerator::haltWhileTheAngleIsReadCancelsThePositionStart()
{
    // A position waveform starts once the drive's angle is read; Stop pressed meanwhile (as an
    // emergency stop would) cancels that start: nothing follows the stop.
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    SetpointWaveform::Settings s;
    s.target = SetpointWaveform::Target::Position;
    s.offset = rig.multiTurnDeg(1);
    s.amplitude = 5;
    view->startGenerator(s); // reads the angle first
    view->motorStop();
    QTest::qWait(300);
    QVERIFY(rig.barrier(1));
    QVERIFY(!view->generator()->isRunning());
    QCOMPARE(rig.count(1, Command::MotorStop), 1);
    QCOMPARE(rig.count(1, Command::MultiPosition) + rig.count(1, Command::MultiPositionLimited), 0);
}

QTEST_MAIN(tst_ControlGenerator)
#include "tst_controlgenerator.moc"
