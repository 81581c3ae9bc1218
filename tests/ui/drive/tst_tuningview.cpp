#include "DriveTestRig.h"

#include <drive/ConfirmDialog.h>
#include <drive/LoopPlot.h>
#include <drive/ParameterTable.h>
#include <drive/TuningView.h>
#include <plot/TelemetryStore.h>
#include <record/ParameterSet.h>

#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>

using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::protocol::PidGains;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::ParameterTable;
using lk::ui::TuningView;

namespace {

/// A view on drive `id` of the rig, shown, with its first read done.
std::unique_ptr<TuningView> openView(SimRig &rig, int id)
{
    auto view = std::make_unique<TuningView>();
    view->resize(1200, 700);
    view->setSession(&rig.session);
    view->setConnected(true);
    view->setDrive(id, rig.motor(id));
    view->show();
    if (!QTest::qWaitFor([&] { return view->drivePid().has_value() && !view->isBusy(); }, kWaitMs))
        return nullptr;
    return view;
}

void edit(TuningView &view, ParameterTable::Row row, int value)
{
    QSpinBox *box = view.table()->editor(row);
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, QString::number(value));
    QTest::keyClick(box, Qt::Key_Enter); // keyboard tracking is off: commits on Enter
}

QPushButton *button(TuningView &view, const char *name)
{
    return view.findChild<QPushButton *>(QLatin1String(name));
}

} // namespace

class tst_TuningView : public QObject {
    Q_OBJECT
private slots:
    void readsDriveOnSelection();
    void ramWriteIsLostOnRestart();
    void ignoredAccelerationIsShownAsMismatch();
    void romWriteAsksAndSurvivesRestart();
    void declinedRomWriteSendsNothing();
    void undoRestoresSelectionValues();
    void differencesHighlighted();
    void plotFollowsEditedLoop_data();
    void plotFollowsEditedLoop();
    void saveAndLoadParameters();
    void corruptFileChangesNothing_data();
    void corruptFileChangesNothing();
    void disconnectedDisablesWrites();
};

void tst_TuningView::readsDriveOnSelection()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QCOMPARE(*view->drivePid(), rig.ramPid(1));
    QCOMPARE(view->table()->pendingPid(), rig.ramPid(1));
    QCOMPARE(*view->driveAccel(), 20000); // the simulator's ROM default
    QVERIFY(!view->table()->anyChanged());
    QVERIFY(!view->romWarningShown());
}

void tst_TuningView::ramWriteIsLostOnRestart()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    const PidGains rom = rig.romPid(1);
    edit(*view, ParameterTable::SpeedKp, 77);
    edit(*view, ParameterTable::Accel, 15000);
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(rig.ramPid(1).speedKp, 77, kWaitMs);
    // Read back: the view shows what the drive holds now.
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && view->drivePid()->speedKp == 77, kWaitMs);
    QCOMPARE(*view->driveAccel(), 15000);
    QVERIFY(view->mismatchText().isEmpty());
    QVERIFY(view->romWarningShown()); // RAM written, not in ROM
    QCOMPARE(rig.count(1, Command::WritePidRom), 0);
    QCOMPARE(rig.romPid(1), rom);

    rig.restartDrive(1);
    QCOMPARE(rig.ramPid(1), rom);
}

void tst_TuningView::ignoredAccelerationIsShownAsMismatch()
{
    // Firmware that acknowledges 0x34 and reads 0 with 0x33 (ERRATA): the acknowledgement
    // looks fine, only the read-back tells, and the technician must see it.
    SimRig rig(QStringLiteral("1:MF+accel-ignored"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QCOMPARE(*view->driveAccel(), 0);
    edit(*view, ParameterTable::SpeedKp, 66);
    edit(*view, ParameterTable::Accel, 15000);
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && !view->mismatchText().isEmpty(), kWaitMs);
    QVERIFY2(
        view->mismatchText().contains(QStringLiteral("acceleration 0 dps/s after 15000 dps/s")),
        qPrintable(view->mismatchText()));
    QVERIFY(!view->mismatchText().contains(QStringLiteral("gains"))); // the gains did land
    QCOMPARE(view->drivePid()->speedKp, 66);
    QCOMPARE(rig.count(1, Command::WriteAccelRam), 1);
}

void tst_TuningView::romWriteAsksAndSurvivesRestart()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 2);
    QVERIFY(view);
    QList<ConfirmRequest> asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked.append(q);
        return true;
    });
    edit(*view, ParameterTable::AngleKp, 88);
    QTest::mouseClick(button(*view, "writeRom"), Qt::LeftButton);
    QCOMPARE(asked.size(), 1);
    QCOMPARE(asked.first().key, QStringLiteral("write_pid_rom"));
    QVERIFY(asked.first().reason.contains(QStringLiteral("wear")));
    QTRY_COMPARE_WITH_TIMEOUT(rig.romPid(2).angleKp, 88, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy(), kWaitMs);
    QVERIFY(!view->romWarningShown()); // RAM equals what was written to ROM
    QVERIFY(rig.barrier(2));
    QCOMPARE(rig.count(2, Command::WritePidRom), 1); // exactly once

    rig.restartDrive(2);
    QCOMPARE(rig.ramPid(2).angleKp, 88);

    // A later RAM-only change brings the warning up again.
    edit(*view, ParameterTable::AngleKp, 90);
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && view->drivePid()->angleKp == 90, kWaitMs);
    QVERIFY(view->romWarningShown());
    QCOMPARE(asked.size(), 1);
}

void tst_TuningView::declinedRomWriteSendsNothing()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    int asked = 0;
    ConfirmDialog::ScopedPolicy no([&](const ConfirmRequest &) {
        ++asked;
        return false;
    });
    const PidGains before = rig.ramPid(1);
    edit(*view, ParameterTable::IqKi, 12);
    QTest::mouseClick(button(*view, "writeRom"), Qt::LeftButton);
    QCOMPARE(asked, 1);
    QVERIFY(view->statusText().contains(QStringLiteral("nothing was sent")));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::WritePidRom), 0);
    QCOMPARE(rig.count(1, Command::WritePidRam), 0);
    QCOMPARE(rig.count(1, Command::WriteAccelRam), 0);
    QCOMPARE(rig.ramPid(1), before);
    QVERIFY(view->table()->isChanged(ParameterTable::IqKi)); // the edit is kept
}

void tst_TuningView::undoRestoresSelectionValues()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 4);
    QVERIFY(view);
    const PidGains original = rig.ramPid(4);
    edit(*view, ParameterTable::SpeedKi, 5);
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(rig.ramPid(4).speedKi, 5, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy(), kWaitMs);
    // Selecting another drive and coming back keeps the first values as the undo target.
    view->setDrive(1, rig.motor(1));
    QTRY_VERIFY_WITH_TIMEOUT(view->drivePid().has_value() && !view->isBusy(), kWaitMs);
    view->setDrive(4, rig.motor(4));
    QTRY_VERIFY_WITH_TIMEOUT(view->drivePid().has_value() && !view->isBusy(), kWaitMs);
    QCOMPARE(view->drivePid()->speedKi, 5);
    QTest::mouseClick(button(*view, "undo"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(rig.ramPid(4), original, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && *view->drivePid() == original, kWaitMs);
}

void tst_TuningView::differencesHighlighted()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QSpinBox *box = view->table()->editor(ParameterTable::AngleKi);
    QVERIFY(!box->property("changed").toBool());
    edit(*view, ParameterTable::AngleKi, box->value() + 1);
    QVERIFY(view->table()->isChanged(ParameterTable::AngleKi));
    QVERIFY(box->property("changed").toBool());
    QVERIFY(!view->table()->isChanged(ParameterTable::AngleKp));
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && !view->table()->anyChanged(), kWaitMs);
    QVERIFY(!box->property("changed").toBool());
}

void tst_TuningView::plotFollowsEditedLoop_data()
{
    QTest::addColumn<int>("row");
    QTest::addColumn<int>("loop");
    QTest::newRow("angle Kp") << int(ParameterTable::AngleKp) << int(lk::ui::TunedLoop::Angle);
    QTest::newRow("speed Ki") << int(ParameterTable::SpeedKi) << int(lk::ui::TunedLoop::Speed);
    QTest::newRow("iq Kp") << int(ParameterTable::IqKp) << int(lk::ui::TunedLoop::Current);
    QTest::newRow("accel") << int(ParameterTable::Accel) << int(lk::ui::TunedLoop::Speed);
}

void tst_TuningView::plotFollowsEditedLoop()
{
    QFETCH(int, row);
    QFETCH(int, loop);
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QApplication::setActiveWindow(view.get());
    // Start from another loop so that the switch is visible.
    view->plot()->setLoop(loop == int(lk::ui::TunedLoop::Angle) ? lk::ui::TunedLoop::Current
                                                                : lk::ui::TunedLoop::Angle);
    if (QWidget *focus = QApplication::focusWidget())
        focus->clearFocus(); // the first field may hold the focus since the window opened
    view->table()->editor(ParameterTable::Row(row))->setFocus();
    QTRY_COMPARE(int(view->plot()->loop()), loop);
    // The plot draws what the session's telemetry brings for the drive.
    rig.session.startPolling(lk::bus::PollPlan::standard({1}, 50));
    QTRY_VERIFY_WITH_TIMEOUT(view->plot()->store()->count(1, lk::ui::TelemetryChannel::Speed) > 0,
                             kWaitMs);
    const quint64 before = view->plot()->redrawCount();
    QTRY_VERIFY_WITH_TIMEOUT(view->plot()->redrawCount() > before, kWaitMs);
}

void tst_TuningView::saveAndLoadParameters()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    QCOMPARE(view->saveParameters(path), QString());
    QString error;
    const auto set = lk::record::ParameterSet::load(path, &error);
    QVERIFY2(set, qPrintable(error));
    QCOMPARE(set->pid, rig.ramPid(1));
    QCOMPARE(set->motorName, rig.motor(1).model->motorName);
    QCOMPARE(set->driveId, 1);
    QVERIFY(set->savedAt.isValid());

    // Load a file with other values: pending edit changes, nothing is written.
    lk::record::ParameterSet other = *set;
    other.pid.speedKp = 11;
    other.accelDps2 = 1234;
    const QString otherPath = dir.filePath(QStringLiteral("other.json"));
    QCOMPARE(other.save(otherPath), QString());
    QCOMPARE(view->loadParameters(otherPath), QString());
    QCOMPARE(view->table()->pendingPid().speedKp, 11);
    QCOMPARE(view->table()->pendingAccel(), 1234);
    QVERIFY(view->table()->isChanged(ParameterTable::SpeedKp));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::WritePidRam), 0);
    QCOMPARE(rig.count(1, Command::WriteAccelRam), 0);
}

void tst_TuningView::corruptFileChangesNothing_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::newRow("empty") << QByteArray();
    QTest::newRow("not json") << QByteArray("PID=1,2,3");
    QTest::newRow("truncated") << QByteArray(R"({"format":"lkstudio-parameters","version":1,"dr)");
    QTest::newRow("other format") << QByteArray(R"({"format":"something","version":1})");
    QTest::newRow("gain out of range")
        << QByteArray(R"({"format":"lkstudio-parameters","version":1,"drive":{"id":1},)"
                      R"("pid":{"angle_kp":300,"angle_ki":1,"speed_kp":1,"speed_ki":1,)"
                      R"("iq_kp":1,"iq_ki":1}})");
    QTest::newRow("gain missing") << QByteArray(
        R"({"format":"lkstudio-parameters","version":1,"drive":{"id":1},)"
        R"("pid":{"angle_kp":3}})");
}

void tst_TuningView::corruptFileChangesNothing()
{
    QFETCH(QByteArray, content);
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(content);
    f.close();
    const PidGains pending = view->table()->pendingPid();
    const qint32 accel = view->table()->pendingAccel();
    QVERIFY(!view->loadParameters(path).isEmpty());
    QCOMPARE(view->table()->pendingPid(), pending);
    QCOMPARE(view->table()->pendingAccel(), accel);
    QVERIFY(view->statusText().contains(QStringLiteral("Nothing was changed")));
}

void tst_TuningView::disconnectedDisablesWrites()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QVERIFY(button(*view, "writeRam")->isEnabled());
    view->setConnected(false);
    for (const char *name : {"read", "writeRam", "writeRom", "undo"})
        QVERIFY2(!button(*view, name)->isEnabled(), name);
    QVERIFY(button(*view, "save")->isEnabled()); // the last values read can still be saved
    view->writeToRam();                          // ignored while disconnected
    view->setConnected(true);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy(), kWaitMs);
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::WritePidRam), 0);
}

QTEST_MAIN(tst_TuningView)
#include "tst_tuningview.moc"
