#include "ParamTestHelpers.h"

#include <drive/ConfirmDialog.h>
#include <drive/LoopPlot.h>
#include <drive/ParameterTable.h>
#include <drive/TuningSetV23.h>
#include <drive/TuningView.h>
#include <record/ParameterSet.h>
#include <sim/SimBus.h>

#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

using lk::drivetest::heldText;
using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::protocol::PidGains;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::ParameterTable;
using lk::ui::TuningView;
using V23 = lk::ui::TuningSetV23;

namespace {

/// What a V2.3 drive holds as the view shows it: the gains when all six are known.
std::optional<PidGains> drivePid(const TuningView &view)
{
    const lk::ui::HeldValues held = view.driveValues();
    lk::ui::ParamValues values;
    for (int f = V23::AngleKp; f <= V23::IqKi; ++f) {
        if (!held.value(f))
            return std::nullopt;
        values << *held.value(f);
    }
    return V23::pidOf(values);
}

std::optional<qint32> driveAccel(const TuningView &view)
{
    const std::optional<qint64> accel = view.driveValues().value(V23::Accel);
    return accel ? std::optional<qint32>(qint32(*accel)) : std::nullopt;
}

PidGains pendingPid(const TuningView &view)
{
    return V23::pidOf(*view.table()->pending());
}

qint32 pendingAccel(const TuningView &view)
{
    return qint32(view.table()->pending()->value(V23::Accel));
}

/// A view on drive `id` of the rig, shown, with its first read done.
std::unique_ptr<TuningView> openView(SimRig &rig, int id)
{
    auto view = lk::drivetest::showView<TuningView>(rig, id, QSize(1200, 700));
    if (!QTest::qWaitFor([&] { return drivePid(*view).has_value() && !view->isBusy(); }, kWaitMs))
        return nullptr;
    return view;
}

void edit(TuningView &view, int row, int value)
{
    QDoubleSpinBox *box = view.table()->editor(row);
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, QString::number(value));
    QTest::keyClick(box, Qt::Key_Enter); // keyboard tracking is off: commits on Enter
}

QPushButton *button(TuningView &view, const char *name)
{
    return view.findChild<QPushButton *>(QLatin1String(name));
}

/// Drive `id`'s next read_pid fails: both tries (BusConfig::retries = 1) lose their reply, the
/// drive still acts on them, and every other reply on the bus is answered.
void failNextPidRead(SimRig &rig, int id)
{
    rig.sim->withBus([id](lk::sim::SimBus &bus) {
        bus.faults().dropNextRepliesTo(quint8(Command::ReadPid), id, 2);
    });
}

/// Selects drive `id` and waits until its read has finished (answered or not).
bool selectAndWait(TuningView &view, SimRig &rig, int id)
{
    QSignalSpy read(&view, &TuningView::parametersRead);
    view.setDrive(id, rig.motor(id));
    return read.wait(kWaitMs) || !read.isEmpty();
}

/// Every edit field shows "unknown" and takes no input; nothing can be written.
void verifyNothingWritable(TuningView &view)
{
    QVERIFY(!view.readComplete());
    QVERIFY(!view.table()->pending());
    for (int r = 0; r < view.table()->rowCount(); ++r) {
        QDoubleSpinBox *box = view.table()->editor(r);
        QCOMPARE(box->text(), QStringLiteral("unknown"));
        QVERIFY(!box->isEnabled());
    }
    for (const char *name : {"writeRam", "writeRom", "undo", "load"})
        QVERIFY2(!button(view, name)->isEnabled(), name);
}

int writesTo(SimRig &rig, int id)
{
    return rig.count(id, Command::WritePidRam) + rig.count(id, Command::WritePidRom) +
           rig.count(id, Command::WriteAccelRam);
}

} // namespace

class tst_TuningView : public QObject {
    Q_OBJECT
private slots:
    void readsDriveOnSelection();
    void failedReadWritesNothing();
    void switchingDrivesCarriesNoEdits();
    void reconnectionNeedsFreshRead();
    void loadNeedsCompleteRead();
    void ramWriteIsLostOnRestart();
    void ignoredAccelerationIsShownAsMismatch();
    void romWriteAsksAndSurvivesRestart();
    void declinedRomWriteSendsNothing();
    void restoreNamesTimeAndAsks();
    void differencesHighlighted();
    void plotFollowsEditedLoop_data();
    void plotFollowsEditedLoop();
    void saveAndLoadParameters();
    void badFileChangesNothing_data();
    void badFileChangesNothing();
    void disconnectedDisablesWrites();
};

void tst_TuningView::readsDriveOnSelection()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QCOMPARE(*drivePid(*view), rig.ramPid(1));
    QVERIFY(view->readComplete());
    QCOMPARE(pendingPid(*view), rig.ramPid(1));
    QCOMPARE(pendingAccel(*view), 20000);
    QCOMPARE(*driveAccel(*view), 20000); // the simulator's ROM default
    QVERIFY(!view->table()->anyChanged());
    QVERIFY(!view->romWarningShown());
}

void tst_TuningView::failedReadWritesNothing()
{
    // The issue: read_pid failed, the edits showed 0 and Write to RAM sent all gains zero.
    SimRig rig;
    QVERIFY(rig.open());
    TuningView view;
    view.setSession(&rig.session);
    view.setConnected(true);
    view.show();
    failNextPidRead(rig, 1); // read_accel is answered
    QVERIFY(selectAndWait(view, rig, 1));
    QTRY_VERIFY_WITH_TIMEOUT(!view.isBusy(), kWaitMs);
    QVERIFY(!drivePid(view));
    QCOMPARE(driveAccel(view), std::optional<qint32>(20000));
    verifyNothingWritable(view);
    QCOMPARE(heldText(*view.table(), V23::SpeedKp), QStringLiteral("unknown"));
    QVERIFY2(view.statusText().contains(QStringLiteral("Could not read drive 1")),
             qPrintable(view.statusText()));

    int asked = 0;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &) { return ++asked > 0; });
    QTest::mouseClick(button(view, "writeRam"), Qt::LeftButton);
    view.writeToRam();
    view.writeToRom();
    view.restoreFirstRead();
    QCOMPARE(asked, 0);
    QVERIFY(view.statusText().contains(QStringLiteral("Nothing was sent")));
    QVERIFY(rig.barrier(1));
    QCOMPARE(writesTo(rig, 1), 0);

    // A read that completes enables everything, with the drive's values.
    QTest::mouseClick(button(view, "read"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(view.readComplete() && !view.isBusy(), kWaitMs);
    QCOMPARE(pendingPid(view), rig.ramPid(1));
    QVERIFY(button(view, "writeRam")->isEnabled());
    QVERIFY(view.table()->editor(V23::AngleKp)->isEnabled());
}

void tst_TuningView::switchingDrivesCarriesNoEdits()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    const int mine = rig.ramPid(1).speedKp == 77 ? 78 : 77;
    edit(*view, V23::SpeedKp, mine);
    QVERIFY(view->table()->isChanged(V23::SpeedKp));

    // Drive 2 does not answer read_pid: drive 1's edit must not become drive 2's.
    failNextPidRead(rig, 2);
    QVERIFY(selectAndWait(*view, rig, 2));
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy(), kWaitMs);
    verifyNothingWritable(*view);
    view->writeToRam();
    QVERIFY(rig.barrier(2));
    QCOMPARE(writesTo(rig, 2), 0);

    // Once read, drive 2 shows its own values and nothing differs.
    QTest::mouseClick(button(*view, "read"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(view->readComplete() && !view->isBusy(), kWaitMs);
    QCOMPARE(pendingPid(*view), rig.ramPid(2));
    QVERIFY(!view->table()->anyChanged());

    // Back on drive 1 the unsent edit is there again, highlighted, and still unsent.
    QVERIFY(selectAndWait(*view, rig, 1));
    QTRY_VERIFY_WITH_TIMEOUT(view->readComplete() && !view->isBusy(), kWaitMs);
    QCOMPARE(int(pendingPid(*view).speedKp), mine);
    QVERIFY(view->table()->isChanged(V23::SpeedKp));
    QVERIFY(view->table()->editor(V23::SpeedKp)->property("changed").toBool());
    QVERIFY(!view->table()->editor(V23::AngleKp)->property("changed").toBool());
    QCOMPARE(writesTo(rig, 1), 0);
}

void tst_TuningView::reconnectionNeedsFreshRead()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    edit(*view, V23::AngleKi, rig.ramPid(1).angleKi == 9 ? 10 : 9);
    view->setConnected(false);
    QVERIFY(!view->readComplete());
    QVERIFY(drivePid(*view)); // the last values read stay on show
    QVERIFY(!view->table()->editor(V23::AngleKi)->isEnabled());
    QVERIFY(!button(*view, "writeRam")->isEnabled());

    // The new connection's read fails: what was read on the old one does not count.
    failNextPidRead(rig, 1);
    QSignalSpy read(view.get(), &TuningView::parametersRead);
    view->setConnected(true);
    QVERIFY(read.wait(kWaitMs) || !read.isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy(), kWaitMs);
    verifyNothingWritable(*view);
    QVERIFY(!drivePid(*view));
    view->writeToRam();
    QVERIFY(rig.barrier(1));
    QCOMPARE(writesTo(rig, 1), 0);
}

void tst_TuningView::loadNeedsCompleteRead()
{
    SimRig rig;
    QVERIFY(rig.open());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    lk::record::ParameterSet set;
    set.pid = PidGains{1, 2, 3, 4, 5, 6};
    set.accelDps2 = 1000;
    QCOMPARE(set.save(path), QString());

    TuningView view;
    view.setSession(&rig.session);
    view.setConnected(true);
    failNextPidRead(rig, 3);
    QVERIFY(selectAndWait(view, rig, 3));
    QTRY_VERIFY_WITH_TIMEOUT(!view.isBusy(), kWaitMs);
    const QString error = view.loadParameters(path);
    QVERIFY2(error.contains(QStringLiteral("read the drive")), qPrintable(error));
    QVERIFY(!view.table()->pending());
    verifyNothingWritable(view);
}

void tst_TuningView::ramWriteIsLostOnRestart()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    const PidGains rom = rig.romPid(1);
    edit(*view, V23::SpeedKp, 77);
    edit(*view, V23::Accel, 15000);
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(rig.ramPid(1).speedKp, 77, kWaitMs);
    // Read back: the view shows what the drive holds now.
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && drivePid(*view)->speedKp == 77, kWaitMs);
    QCOMPARE(*driveAccel(*view), 15000);
    QVERIFY(view->mismatchText().isEmpty());
    QVERIFY(view->romWarningShown()); // RAM written, not in ROM
    QCOMPARE(rig.count(1, Command::WritePidRom), 0);
    QCOMPARE(rig.romPid(1), rom);

    rig.restartDrive(1);
    QCOMPARE(rig.ramPid(1), rom);
}

void tst_TuningView::ignoredAccelerationIsShownAsMismatch()
{
    // Firmware that acknowledges 0x34 and reads 0 with 0x33 (docs/ERRATA.md): the acknowledgement
    // looks fine, only the read-back tells, and the technician must see it.
    SimRig rig(QStringLiteral("1:MF+accel-ignored"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QCOMPARE(*driveAccel(*view), 0);
    edit(*view, V23::SpeedKp, 66);
    edit(*view, V23::Accel, 15000);
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && !view->mismatchText().isEmpty(), kWaitMs);
    QVERIFY2(
        view->mismatchText().contains(QStringLiteral("acceleration 0 dps/s after 15000 dps/s")),
        qPrintable(view->mismatchText()));
    QVERIFY2(view->mismatchText().contains(QStringLiteral("(see docs/ERRATA.md)")),
             qPrintable(view->mismatchText()));
    QVERIFY(!view->mismatchText().contains(QStringLiteral("gains"))); // the gains did land
    QCOMPARE(drivePid(*view)->speedKp, 66);
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
    edit(*view, V23::AngleKp, 88);
    QTest::mouseClick(button(*view, "writeRom"), Qt::LeftButton);
    QCOMPARE(asked.size(), 1);
    QCOMPARE(asked.first().key, QStringLiteral("write_pid_rom"));
    QVERIFY(asked.first().reason.contains(QStringLiteral("wear")));
    QVERIFY(asked.first().reason.contains(QStringLiteral("cannot be checked")));
    QTRY_COMPARE_WITH_TIMEOUT(rig.romPid(2).angleKp, 88, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy(), kWaitMs);
    // Says what the read-back proved and what it cannot: V2.3 has no ROM read.
    QVERIFY2(view->statusText().contains(QStringLiteral("Verified: the gains read back from RAM "
                                                        "equal what was sent")),
             qPrintable(view->statusText()));
    QVERIFY2(view->statusText().contains(QStringLiteral("Not verifiable")) &&
                 view->statusText().contains(QStringLiteral("cannot read ROM")),
             qPrintable(view->statusText()));
    QVERIFY(!view->romWarningShown()); // RAM equals what was written to ROM
    QVERIFY(rig.barrier(2));
    QCOMPARE(rig.count(2, Command::WritePidRom), 1); // exactly once

    rig.restartDrive(2);
    QCOMPARE(rig.ramPid(2).angleKp, 88);

    // A later RAM-only change brings the warning up again.
    edit(*view, V23::AngleKp, 90);
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && drivePid(*view)->angleKp == 90, kWaitMs);
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
    edit(*view, V23::IqKi, 12);
    QTest::mouseClick(button(*view, "writeRom"), Qt::LeftButton);
    QCOMPARE(asked, 1);
    QVERIFY(view->statusText().contains(QStringLiteral("nothing was sent")));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::WritePidRom), 0);
    QCOMPARE(rig.count(1, Command::WritePidRam), 0);
    QCOMPARE(rig.count(1, Command::WriteAccelRam), 0);
    QCOMPARE(rig.ramPid(1), before);
    QVERIFY(view->table()->isChanged(V23::IqKi)); // the edit is kept
}

void tst_TuningView::restoreNamesTimeAndAsks()
{
    SimRig rig;
    QVERIFY(rig.open());
    const QTime before = QTime::currentTime().addSecs(-1);
    auto view = openView(rig, 4);
    QVERIFY(view);
    const PidGains original = rig.ramPid(4);
    // Named for what it does: the time of the read it restores.
    QPushButton *restore = button(*view, "undo");
    const QString text = restore->text();
    QVERIFY2(text.startsWith(QStringLiteral("Restore values read at ")), qPrintable(text));
    const QTime at = QTime::fromString(text.mid(23, 8), QStringLiteral("HH:mm:ss"));
    QVERIFY2(at.isValid() && at >= before.addSecs(-1), qPrintable(text));

    edit(*view, V23::SpeedKi, original.speedKi == 5 ? 6 : 5);
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(rig.ramPid(4).speedKi != original.speedKi, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy(), kWaitMs);
    // Selecting another drive and coming back keeps the first read as the restore target.
    QVERIFY(selectAndWait(*view, rig, 1));
    QTRY_VERIFY_WITH_TIMEOUT(view->readComplete() && !view->isBusy(), kWaitMs);
    QVERIFY(selectAndWait(*view, rig, 4));
    QTRY_VERIFY_WITH_TIMEOUT(view->readComplete() && !view->isBusy(), kWaitMs);
    QCOMPARE(restore->text(), text);
    const int writes = writesTo(rig, 4);

    // It asks, saying that it writes to the drive's RAM; declining sends nothing.
    QList<ConfirmRequest> asked;
    bool answer = false;
    ConfirmDialog::ScopedPolicy policy([&](const ConfirmRequest &q) {
        asked.append(q);
        return answer;
    });
    QTest::mouseClick(restore, Qt::LeftButton);
    QCOMPARE(asked.size(), 1);
    QCOMPARE(asked.first().key, QStringLiteral("restore_first_read"));
    QVERIFY2(asked.first().question.contains(QStringLiteral("to its RAM")),
             qPrintable(asked.first().question));
    QVERIFY(asked.first().reason.contains(QStringLiteral("This writes to the drive")));
    QVERIFY(view->statusText().contains(QStringLiteral("nothing was sent")));
    QVERIFY(rig.barrier(4));
    QCOMPARE(writesTo(rig, 4), writes);
    QVERIFY(rig.ramPid(4) != original);

    answer = true;
    QTest::mouseClick(restore, Qt::LeftButton);
    QCOMPARE(asked.size(), 2);
    QTRY_COMPARE_WITH_TIMEOUT(rig.ramPid(4), original, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && *drivePid(*view) == original, kWaitMs);
}

void tst_TuningView::differencesHighlighted()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QDoubleSpinBox *box = view->table()->editor(V23::AngleKi);
    QVERIFY(!box->property("changed").toBool());
    edit(*view, V23::AngleKi, int(box->value()) + 1);
    QVERIFY(view->table()->isChanged(V23::AngleKi));
    QVERIFY(box->property("changed").toBool());
    QVERIFY(!view->table()->isChanged(V23::AngleKp));
    QTest::mouseClick(button(*view, "writeRam"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && !view->table()->anyChanged(), kWaitMs);
    QVERIFY(!box->property("changed").toBool());
}

void tst_TuningView::plotFollowsEditedLoop_data()
{
    QTest::addColumn<int>("row");
    QTest::addColumn<int>("loop");
    QTest::newRow("angle Kp") << int(V23::AngleKp) << int(lk::ui::TunedLoop::Angle);
    QTest::newRow("speed Ki") << int(V23::SpeedKi) << int(lk::ui::TunedLoop::Speed);
    QTest::newRow("iq Kp") << int(V23::IqKp) << int(lk::ui::TunedLoop::Current);
    QTest::newRow("accel") << int(V23::Accel) << int(lk::ui::TunedLoop::Speed);
}

void tst_TuningView::plotFollowsEditedLoop()
{
    QFETCH(int, row);
    QFETCH(int, loop);
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QApplication::setActiveWindow(view.get()); // from another loop, so that the switch shows
    view->plot()->setLoop(loop == int(lk::ui::TunedLoop::Angle) ? lk::ui::TunedLoop::Current
                                                                : lk::ui::TunedLoop::Angle);
    if (QWidget *focus = QApplication::focusWidget())
        focus->clearFocus(); // the first field may hold the focus since the window opened
    view->table()->editor(row)->setFocus();
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
    lk::record::ParameterFileError error;
    const auto set = lk::record::ParameterSet::load(path, &error);
    QVERIFY2(set, qPrintable(error.key));
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
    QCOMPARE(pendingPid(*view).speedKp, 11);
    QCOMPARE(pendingAccel(*view), 1234);
    QVERIFY(view->table()->isChanged(V23::SpeedKp));
    QVERIFY(view->table()->editor(V23::SpeedKp)->property("changed").toBool());
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::WritePidRam), 0);
    QCOMPARE(rig.count(1, Command::WriteAccelRam), 0);
}

void tst_TuningView::badFileChangesNothing_data()
{
    // Each refusal names the key and what it must hold (type and range).
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("says");
    const QByteArray head = R"({"format":"lkstudio-parameters","version":1,"drive":{"id":1},)";
    const QByteArray gains = R"("angle_ki":1,"speed_kp":1,"speed_ki":1,"iq_kp":1,"iq_ki":1)";
    QTest::newRow("empty") << QByteArray() << "not valid JSON";
    QTest::newRow("not json") << QByteArray("PID=1,2,3") << "not valid JSON";
    QTest::newRow("truncated") << QByteArray(R"({"format":"lkstudio-parameters","version":1,"dr)")
                               << "not valid JSON";
    QTest::newRow("other format") << QByteArray(R"({"format":"something","version":1})")
                                  << "not an LK Servo Studio parameter file";
    QTest::newRow("gain missing") << head + R"("pid":{"angle_kp":3}})"
                                  << "pid.angle_ki is missing: it must be an integer in 0..255";
    QTest::newRow("unknown key") << head + R"("pid":{"angle_kp":1,)" + gains + R"(,"iq_kd":4}})"
                                 << "pid.iq_kd is not a key of a parameter file";
    QTest::newRow("duplicate key")
        << head + R"("pid":{"angle_kp":1,)" + gains + R"(,"angle_kp":200}})"
        << "pid.angle_kp is given twice";
    QTest::newRow("wrong type") << head + R"("pid":{"angle_kp":"1",)" + gains + "}}"
                                << "pid.angle_kp is \"1\": it must be an integer in 0..255";
    QTest::newRow("out of range")
        << head + R"("pid":{"angle_kp":300,)" + gains + "}}"
        << "pid.angle_kp is 300, out of range: it must be an integer in 0..255";
    QTest::newRow("accel out of range")
        << head + R"("pid":{"angle_kp":1,)" + gains + R"(},"accel_dps2":-1})"
        << "accel_dps2 is -1, out of range: it must be an integer in 0..2147483647";
}

void tst_TuningView::badFileChangesNothing()
{
    QFETCH(QByteArray, content);
    QFETCH(QString, says);
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
    const PidGains pending = pendingPid(*view);
    const qint32 accel = pendingAccel(*view);
    const QString error = view->loadParameters(path);
    QVERIFY2(error.contains(says), qPrintable(error));
    QVERIFY2(view->statusText().contains(says), qPrintable(view->statusText()));
    QVERIFY(view->statusText().contains(QStringLiteral("Nothing was changed")));
    QCOMPARE(pendingPid(*view), pending);
    QCOMPARE(pendingAccel(*view), accel);
}

void tst_TuningView::disconnectedDisablesWrites()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(view);
    QVERIFY(button(*view, "writeRam")->isEnabled());
    view->setConnected(false);
    for (const char *name : {"read", "writeRam", "writeRom", "undo", "load"})
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
