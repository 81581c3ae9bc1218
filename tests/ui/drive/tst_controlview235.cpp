#include "DriveTestRig.h"

#include <drive/BrakePanel.h>
#include <drive/ConfirmDialog.h>
#include <drive/ControlLimits.h>
#include <drive/ControlModePanel.h>
#include <drive/ControlView.h>
#include <drive/DriveStateCheck.h>
#include <sim/FaultInjector.h>

#include <QtTest/QtTest>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

#include <cmath>

using lk::drivetest::button;
using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::ControlMode;
using lk::ui::ControlView;

namespace {

// Drive 1 is an MF4015 on firmware 2.35, drive 2 the same motor on V2.3, drive 3 an MG on
// V2.35, drive 5 an MS4015 on V2.35.
const QString kBus = QStringLiteral("1:MF4015@2.35,2:MF4015,3:MG@2.35,5:MS4015@2.35");

std::unique_ptr<ControlView> openView(SimRig &rig, int id)
{
    auto view = lk::drivetest::showView<ControlView>(rig, id, QSize(1200, 800));
    // The drive's state and limits are read on selection: wait for them to be in.
    rig.barrier(id);
    QCoreApplication::processEvents();
    return view;
}

QString driveState(ControlView &view)
{
    return view.findChild<QLabel *>(QStringLiteral("driveState"))->text();
}

double commandedCurrent(SimRig &rig, int id)
{
    return rig.read<double>(
        id, [](const lk::sim::SimDrive &d) { return d.physics().target().currentA; });
}

bool motorOn(SimRig &rig, int id)
{
    return rig.read<bool>(id, [](const lk::sim::SimDrive &d) { return d.motorOn(); });
}

} // namespace

/// The Control view on V2.35 drives (docs/V2.35.md): torque at the drive's own scale, a drive
/// that stays off until Motor On, the brake, and the limits the drive holds itself.
class tst_ControlView235 : public QObject {
    Q_OBJECT
private slots:
    void torqueGoesOutAtTheDrivesScale_data();
    void torqueGoesOutAtTheDrivesScale();
    void generatorTorqueAtTheDrivesScale();
    void offDriveIsRefusedUntilMotorOn();
    void driveSwitchedOffElsewhereIsReadBeforeMotion();
    void engagedBrakeWarns();
    void drivesOwnMaxSpeedBoundsMotion();
    void v23DriveHasNoStateLine();
    void corruptReplyToMotionSaysItMayHaveMoved();
};

void tst_ControlView235::torqueGoesOutAtTheDrivesScale_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<double>("amps"); // what the drive makes of 2 A as sent
    QTest::newRow("V2.35 MF: 248 x 33/4096 A") << 1 << 248 * 33.0 / 4096.0;
    QTest::newRow("V2.3 MF: 125 x 32/2000 A") << 2 << 2.0;
    QTest::newRow("V2.35 MG: 124 x 66/4096 A") << 3 << 124 * 66.0 / 4096.0;
}

void tst_ControlView235::torqueGoesOutAtTheDrivesScale()
{
    QFETCH(int, id);
    QFETCH(double, amps);
    SimRig rig(kBus);
    QVERIFY(rig.open());
    auto view = openView(rig, id);
    QVERIFY(view->modePanel()->setMode(ControlMode::Torque));
    view->modePanel()->setTorqueA(2.0);
    view->sendCommand();
    QTRY_VERIFY_WITH_TIMEOUT(view->lastOutcome().sent, kWaitMs);
    QVERIFY(rig.barrier(id));
    QVERIFY2(std::abs(commandedCurrent(rig, id) - amps) < 1e-9,
             qPrintable(QString::number(commandedCurrent(rig, id))));
    view->motorOff();
    QVERIFY(rig.barrier(id));
}

void tst_ControlView235::generatorTorqueAtTheDrivesScale()
{
    // The setpoint stream on the bus thread builds its torques for the drive's generation.
    SimRig rig(kBus);
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    lk::bus::SetpointWaveform::Settings s;
    s.waveform = lk::bus::SetpointWaveform::Waveform::Step;
    s.target = lk::bus::SetpointWaveform::Target::Torque;
    s.offset = 2.0;
    s.amplitude = 0.1;
    s.periodS = 10;
    view->startGenerator(s);
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(commandedCurrent(rig, 1) - 248 * 33.0 / 4096.0) < 1e-9,
                             kWaitMs);
    view->stopGenerator();
    view->motorOff();
    QVERIFY(rig.barrier(1));
}

void tst_ControlView235::offDriveIsRefusedUntilMotorOn()
{
    SimRig rig(kBus);
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QTRY_VERIFY_WITH_TIMEOUT(driveState(*view).contains("motor on"), kWaitMs);
    // V2.35: Run is Motor On.
    QCOMPARE(button(*view, "motorRun")->text(), QStringLiteral("Motor On"));

    view->motorOff();
    QTRY_VERIFY_WITH_TIMEOUT(driveState(*view).contains("motor OFF: Motor On first"), kWaitMs);
    QVERIFY(rig.barrier(1));
    const int speeds = rig.count(1, Command::Speed);
    view->modePanel()->setMode(ControlMode::Speed);
    view->modePanel()->setSpeed(360);
    QSignalSpy refused(view.get(), &ControlView::commandRefused);
    QTest::mouseClick(button(*view, "send"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(refused.count(), 1, kWaitMs);
    QVERIFY2(view->statusText().contains("drive 1 is off: Motor On first"),
             qPrintable(view->statusText()));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::Speed), speeds); // nothing was sent

    QTest::mouseClick(button(*view, "motorRun"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(motorOn(rig, 1), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(driveState(*view).contains("motor on"), kWaitMs);
    QTest::mouseClick(button(*view, "send"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(view->lastOutcome().sent, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(rig.speedDps(1) > 300, kWaitMs);
    view->motorOff();
    QVERIFY(rig.barrier(1));
}

void tst_ControlView235::driveSwitchedOffElsewhereIsReadBeforeMotion()
{
    // The view last read the drive on; another program switched it off since. The state is
    // read again before the command, which is refused instead of being "sent" to a drive
    // that ignores it.
    SimRig rig(kBus);
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QTRY_VERIFY_WITH_TIMEOUT(driveState(*view).contains("motor on"), kWaitMs);
    rig.session.send(*lk::protocol::build::plain(Command::MotorOff, 1).request);
    QVERIFY(rig.barrier(1));
    QVERIFY(!motorOn(rig, 1));
    const int speeds = rig.count(1, Command::Speed);
    const lk::ui::MotionOutcome first = view->sendMotion(lk::protocol::build::speed(1, 360));
    QVERIFY(first.pending);
    QTRY_VERIFY_WITH_TIMEOUT(!view->lastOutcome().pending, kWaitMs);
    QVERIFY(!view->lastOutcome().sent);
    QVERIFY2(view->lastOutcome().refusal.contains("Motor On first"),
             qPrintable(view->lastOutcome().refusal));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::Speed), speeds);
    // A command that holds the drive still is never held back.
    QVERIFY(view->sendMotion(lk::protocol::build::speed(1, 0)).sent);
}

void tst_ControlView235::engagedBrakeWarns()
{
    SimRig rig(kBus);
    QVERIFY(rig.open());
    auto view = openView(rig, 5);
    QTRY_VERIFY_WITH_TIMEOUT(driveState(*view).contains("brake released"), kWaitMs);
    QTest::mouseClick(button(*view, "brakeEngage"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(driveState(*view).contains("brake ENGAGED"), kWaitMs);
    view->modePanel()->setMode(ControlMode::Speed);
    view->modePanel()->setSpeed(180);
    view->sendCommand();
    QTRY_VERIFY_WITH_TIMEOUT(view->lastOutcome().sent, kWaitMs);
    QVERIFY2(view->statusText().contains("reads engaged: the shaft is held"),
             qPrintable(view->statusText()));
    QTest::qWait(200);
    QCOMPARE(rig.speedDps(5), 0.0); // the brake holds it
    view->motorOff();
    QVERIFY(rig.barrier(5));
}

void tst_ControlView235::drivesOwnMaxSpeedBoundsMotion()
{
    SimRig rig(kBus);
    QVERIFY(rig.open());
    // The drive holds a Max Speed of 720 dps, far below the MF series' 18000.
    rig.session.send(
        *lk::protocol::build::writeParam(1, lk::protocol::ParamId::MaxSpeed, 720, false).request);
    QVERIFY(rig.barrier(1));
    auto view = openView(rig, 1);
    QTRY_VERIFY_WITH_TIMEOUT(view->limits()->drive().maxSpeedDps == 720.0, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(driveState(*view).contains("Max Speed 720 dps"), kWaitMs);
    QCOMPARE(view->limitsInForce(nullptr)->maxSpeedDps, 720.0);

    // A speed over it is refused, naming the drive's limit (the soft limit is 18000).
    QVERIFY(view->softLimits().maxSpeedDps > 720);
    view->sendMotion(lk::protocol::build::speed(1, 800));
    QTRY_VERIFY_WITH_TIMEOUT(!view->lastOutcome().pending, kWaitMs);
    QVERIFY(!view->lastOutcome().sent);
    QVERIFY2(view->lastOutcome().refusal.contains("the drive's own Max Speed of 720 dps"),
             qPrintable(view->lastOutcome().refusal));
    // A position move goes out capped at it, and says whose bound it is.
    view->sendMotion(lk::protocol::build::incrementPosition(1, 90));
    QTRY_VERIFY_WITH_TIMEOUT(view->lastOutcome().sent, kWaitMs);
    const lk::protocol::Request sent = *view->lastOutcome().request;
    QCOMPARE(sent.command, Command::IncrementPositionLimited);
    QCOMPARE(*std::get<lk::protocol::IncrementPositionCommand>(sent.payload).maxSpeedRaw,
             quint32(72000));
    QVERIFY2(view->statusText().contains("the drive's own Max Speed"),
             qPrintable(view->statusText()));
    view->motorOff();
    QVERIFY(rig.barrier(1));
}

void tst_ControlView235::v23DriveHasNoStateLine()
{
    SimRig rig(kBus);
    QVERIFY(rig.open());
    auto view = openView(rig, 2);
    QVERIFY(view->findChild<QLabel *>(QStringLiteral("driveState"))->isHidden());
    QCOMPARE(button(*view, "motorRun")->text(), QStringLiteral("Run"));
    QVERIFY(!view->driveState()->applies());
    QVERIFY(!view->limits()->drive().any());
    // V2.3: a control command is sent at once, no state read first.
    QVERIFY(view->sendMotion(lk::protocol::build::speed(2, 90)).sent);
    view->motorOff();
    QVERIFY(rig.barrier(2));
}

void tst_ControlView235::corruptReplyToMotionSaysItMayHaveMoved()
{
    // Every reply corrupt (as fw 2.35 does to some 0xA4 replies): the drive got the command
    // and moves, and the view must not leave it at "the reply was corrupt".
    SimRig rig(kBus);
    QVERIFY(rig.open());
    auto view = openView(rig, 2);
    rig.sim->withBus([](lk::sim::SimBus &bus) {
        bus.faults().setProbability(lk::sim::Fault::CorruptReply, 1.0);
    });
    QVERIFY(view->sendMotion(lk::protocol::build::speed(2, 180)).sent);
    QTRY_VERIFY_WITH_TIMEOUT(view->statusText().contains("may be moving"), kWaitMs);
    QVERIFY2(view->statusText().contains("corrupt"), qPrintable(view->statusText()));
    QTRY_VERIFY_WITH_TIMEOUT(rig.speedDps(2) > 100, kWaitMs); // it did move
    rig.sim->withBus([](lk::sim::SimBus &bus) {
        bus.faults().setProbability(lk::sim::Fault::CorruptReply, 0.0);
    });
    view->motorOff();
    QVERIFY(rig.barrier(2));
}

QTEST_MAIN(tst_ControlView235)
#include "tst_controlview235.moc"
