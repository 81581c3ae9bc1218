#include "DriveTestRig.h"

#include <drive/BrakePanel.h>
#include <drive/ConfirmDialog.h>
#include <drive/ControlView.h>

#include <QtTest/QtTest>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

using lk::drivetest::button;
using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::BrakePanel;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::ControlView;

namespace {

// Drive 1 speaks V2.3, drive 3 is an MS4015 on firmware 2.35.
const QString kBus = QStringLiteral("1:MF,3:MS4015@2.35");

std::unique_ptr<ControlView> openView(SimRig &rig, int id)
{
    return lk::drivetest::showView<ControlView>(rig, id, QSize(1200, 800));
}

bool released(SimRig &rig, int id)
{
    return rig.read<bool>(id, [](const lk::sim::SimDrive &d) { return d.brakeReleased(); });
}

// The simulated drive's motor on (0x88 turns a V2.35 motor that is off back on).
bool motorOn(SimRig &rig, int id)
{
    rig.session.send(*lk::protocol::build::plain(Command::MotorRun, id).request);
    return rig.barrier(id);
}

// A V2.35 drive powers up with its motor on and its brake released, as a real one does: the
// tests set what they start from.
bool motorOff(SimRig &rig, int id)
{
    rig.session.send(*lk::protocol::build::plain(Command::MotorOff, id).request);
    return rig.barrier(id);
}

bool engageBrake(SimRig &rig, int id)
{
    rig.session.send(*lk::protocol::build::brake(id, lk::protocol::BrakeAction::Engage).request);
    return rig.barrier(id);
}

} // namespace

/// The Control view's brake panel (0x8C) on the built-in simulated bus.
class tst_BrakePanel : public QObject {
    Q_OBJECT
private slots:
    void readEngageRelease();
    void releaseWithMotorOffNeedsASecondConfirmation();
    void declinedReleaseSendsNothing();
    void v23DriveHasNoBrake();
    void generationKnownPerLink_data();
    void generationKnownPerLink();
};

void tst_BrakePanel::readEngageRelease()
{
    SimRig rig(kBus);
    QVERIFY(rig.open());
    QVERIFY(engageBrake(rig, 3));
    QVERIFY(motorOn(rig, 3));
    auto view = openView(rig, 3);
    BrakePanel *brake = view->brakePanel();
    QVERIFY(brake->absence().isEmpty());
    QVERIFY(rig.barrier(3));
    const int brakes = rig.count(3, Command::Brake); // the engage, the view's own state read
    QStringList asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q.key;
        return true;
    });

    QTest::mouseClick(button(*view, "brakeRead"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(brake->lastState().has_value(), kWaitMs);
    QVERIFY(!brake->lastState()->released());
    QVERIFY(view->findChild<QLabel *>(QStringLiteral("brakeState"))->text().contains("engaged"));

    QSignalSpy changed(brake, &BrakePanel::changeFinished);
    QTest::mouseClick(button(*view, "brakeRelease"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(changed.count(), 1, kWaitMs);
    QCOMPARE(changed.at(0).at(0).toBool(), true);
    QCOMPARE(asked, QStringList{QStringLiteral("brake_release")}); // the motor is on: one question
    QTRY_VERIFY_WITH_TIMEOUT(brake->statusText().contains("Read back"), kWaitMs);
    QVERIFY(released(rig, 3));
    QVERIFY(brake->lastState()->released());
    QVERIFY2(brake->statusText().contains("release (0x8C 0x01)") &&
                 brake->statusText().contains("answered: released"),
             qPrintable(brake->statusText()));

    asked.clear();
    QTest::mouseClick(button(*view, "brakeEngage"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(changed.count(), 2, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(brake->statusText().contains("Read back"), kWaitMs);
    QVERIFY(asked.isEmpty()); // engaging holds the load: nothing to ask
    QVERIFY(!released(rig, 3));
    QVERIFY(!brake->lastState()->released());
    QVERIFY(rig.barrier(3));
    // read, release + read-back, engage + read-back
    QCOMPARE(rig.count(3, Command::Brake) - brakes, 5);
}

void tst_BrakePanel::releaseWithMotorOffNeedsASecondConfirmation()
{
    SimRig rig(kBus);
    QVERIFY(rig.open());
    QVERIFY(engageBrake(rig, 3));
    QVERIFY(motorOff(rig, 3));
    auto view = openView(rig, 3);
    BrakePanel *brake = view->brakePanel();
    QVERIFY(rig.barrier(3));
    const int states = rig.count(3, Command::ReadState1);
    const int brakes = rig.count(3, Command::Brake);
    QStringList asked;
    {
        ConfirmDialog::ScopedPolicy firstOnly([&](const ConfirmRequest &q) {
            asked << q.key;
            return q.key == QLatin1String("brake_release");
        });
        QTest::mouseClick(button(*view, "brakeRelease"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(brake->statusText().startsWith("Refused"), kWaitMs);
    }
    QCOMPARE(asked, (QStringList{QStringLiteral("brake_release"),
                                 QStringLiteral("brake_release_motor_off")}));
    QVERIFY(brake->statusText().contains("motor is off"));
    QVERIFY(rig.barrier(3));
    QCOMPARE(rig.count(3, Command::ReadState1), states + 2); // the motor's state, the barrier
    QCOMPARE(rig.count(3, Command::Brake), brakes);
    QVERIFY(!released(rig, 3));

    // Both warnings confirmed: released.
    asked.clear();
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q.key;
        return true;
    });
    QSignalSpy changed(brake, &BrakePanel::changeFinished);
    QTest::mouseClick(button(*view, "brakeRelease"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(changed.count(), 1, kWaitMs);
    QCOMPARE(asked.size(), 2);
    QTRY_VERIFY_WITH_TIMEOUT(released(rig, 3), kWaitMs);
}

void tst_BrakePanel::declinedReleaseSendsNothing()
{
    SimRig rig(kBus);
    QVERIFY(rig.open());
    QVERIFY(engageBrake(rig, 3));
    auto view = openView(rig, 3);
    QVERIFY(rig.barrier(3));
    const int states = rig.count(3, Command::ReadState1);
    const int brakes = rig.count(3, Command::Brake);
    ConfirmDialog::ScopedPolicy no([](const ConfirmRequest &) { return false; });
    QTest::mouseClick(button(*view, "brakeRelease"), Qt::LeftButton);
    QVERIFY(view->brakePanel()->statusText().startsWith("Cancelled"));
    QVERIFY(rig.barrier(3));
    QCOMPARE(rig.count(3, Command::Brake), brakes);
    QCOMPARE(rig.count(3, Command::ReadState1), states + 1); // the barrier only
    QVERIFY(!released(rig, 3));
}

void tst_BrakePanel::v23DriveHasNoBrake()
{
    SimRig rig(kBus);
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    BrakePanel *brake = view->brakePanel();
    QVERIFY2(brake->absence().contains("v2.3") && brake->absence().contains("no brake control"),
             qPrintable(brake->absence()));
    QCOMPARE(view->findChild<QLabel *>(QStringLiteral("brakeState"))->text(), brake->absence());
    for (const char *name : {"brakeRead", "brakeEngage", "brakeRelease"})
        QVERIFY(!button(*view, name)->isEnabled());
    QStringList asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q.key;
        return true;
    });
    brake->readState();
    brake->engage();
    brake->release();
    QVERIFY(asked.isEmpty());
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::Brake), 0);
    // Another drive of the same view: the V2.35 one offers the brake.
    view->setDrive(3, rig.motor(3));
    QVERIFY(brake->absence().isEmpty());
    QVERIFY(button(*view, "brakeRead")->isEnabled());
}

void tst_BrakePanel::generationKnownPerLink_data()
{
    QTest::addColumn<bool>("onCan");
    QTest::addColumn<bool>("v235");       // V2.35 on RS485, V2.36 on CAN
    QTest::addColumn<QString>("knownBy"); // "", "model", "chosen", "seen"
    QTest::addColumn<QString>("absence"); // a word of the reason; empty: offered
    // RS485: the model read tells the generation; nothing else does.
    QTest::newRow("RS485 V2.35, model read") << false << true << "model"
                                             << "";
    QTest::newRow("RS485 V2.35, chosen only") << false << true << "chosen"
                                              << "model was not read";
    // CAN has no model read: the user's choice or a reply tells it, and the dialect decides.
    QTest::newRow("CAN V2.36, chosen") << true << true << "chosen"
                                       << "";
    QTest::newRow("CAN V2.36, seen in a reply") << true << true << "seen"
                                                << "";
    QTest::newRow("CAN old, seen") << true << false << "seen"
                                   << "CAN (old)";
    QTest::newRow("CAN, not known yet") << true << true << ""
                                        << "not known yet";
}

void tst_BrakePanel::generationKnownPerLink()
{
    using lk::protocol::Generation;
    QFETCH(bool, onCan);
    QFETCH(bool, v235);
    QFETCH(QString, knownBy);
    QFETCH(QString, absence);
    lk::bus::KnownMotor motor;
    motor.id = 2;
    motor.generation = v235 ? Generation::V2_35 : Generation::V2_3;
    if (knownBy == QLatin1String("model")) {
        motor.model = lk::protocol::ModelInfo{};
        motor.model->generation = motor.generation;
    }
    motor.identityChosen = knownBy == QLatin1String("chosen");
    motor.generationSeen = knownBy == QLatin1String("seen");
    const auto link = onCan ? lk::protocol::Link::Can : lk::protocol::Link::Rs485;
    BrakePanel panel;
    int sent = 0;
    panel.setSender([&sent](const lk::protocol::Request &, lk::ui::RequestTracker::Callback, int) {
        return quint64(++sent);
    });
    panel.setDrive(2, motor, true, link);
    auto *read = panel.findChild<QPushButton *>(QStringLiteral("brakeRead"));
    QVERIFY(read);
    if (absence.isEmpty()) {
        QVERIFY2(panel.absence().isEmpty(), qPrintable(panel.absence()));
        QVERIFY(read->isEnabled());
        panel.readState();
        QCOMPARE(sent, 1);
    } else {
        QVERIFY2(panel.absence().contains(absence), qPrintable(panel.absence()));
        QVERIFY(!read->isEnabled());
        panel.readState();
        QCOMPARE(sent, 0);
    }
}

QTEST_MAIN(tst_BrakePanel)
#include "tst_brakepanel.moc"
