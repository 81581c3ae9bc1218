#include "DriveTestRig.h"

#include <drive/ConfirmDialog.h>
#include <drive/DriveSettingsStore.h>
#include <drive/EncoderView.h>
#include <main/BusController.h>
#include <main/SettingsFile.h>

#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

#include <cmath>

using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::AngleCheck;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::EncoderView;

namespace {

std::unique_ptr<EncoderView> openView(SimRig &rig, int id)
{
    return lk::drivetest::showView<EncoderView>(rig, id, QSize(1100, 650));
}

// Drive 1 speaks V2.3, drive 3 is an MS4015 on firmware 2.35 (16-bit encoder range).
const QString kV235Bus = QStringLiteral("1:MF,3:MS4015@2.35");

// Turns drive `id` at `dps` until its multi-turn angle passes `deg`, then switches it off and
// waits for it to stand still. The test sends directly: no view is under test here.
bool turnPast(SimRig &rig, int id, double dps, double deg)
{
    rig.session.send(*lk::protocol::build::speed(id, dps).request);
    const bool passed = QTest::qWaitFor([&] { return rig.multiTurnDeg(id) > deg; }, kWaitMs);
    rig.session.send(*lk::protocol::build::plain(Command::MotorOff, id).request);
    return passed && QTest::qWaitFor([&] { return std::fabs(rig.speedDps(id)) < 0.5; }, kWaitMs);
}

QString labelText(QWidget &view, const char *name)
{
    auto *l = view.findChild<QLabel *>(QLatin1String(name));
    return l ? l->text() : QString();
}

int circularDistance(int a, int b, int counts)
{
    const int d = std::abs(a - b) % counts;
    return std::min(d, counts - d);
}

} // namespace

class tst_EncoderView : public QObject {
    Q_OBJECT
private slots:
    void readsLiveWhileVisible();
    void addsPollExtrasWhileShown();
    void keepsAStepTestsFocus();
    void readsEachAngleOncePerRound();
    void resolutionAndGearFromName_data();
    void resolutionAndGearFromName();
    void resolutionAndGearPersist();
    void writeOffset();
    void offsetOutOfRangeSendsNothing();
    void clearAngleZeroesTheAngle();
    void ignoredClearAngleIsReported();
    void angleCheckOutcomes_data();
    void angleCheckOutcomes();
    void zeroToRomAppliesAfterRestart();
    void declinedZeroSendsNothing();
    void v235Ms4015StartsAt16Bits();
    void userResolutionWinsOverData();
    void clearTurnCount();
    void declinedClearTurnCountSendsNothing();
    void v23DriveHasNoClearTurnCount();
    void v235DriveHasNoEncoderOffset();
};

void tst_EncoderView::readsLiveWhileVisible()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QTRY_VERIFY_WITH_TIMEOUT(view->lastEncoder().has_value(), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(view->lastMultiTurnDeg().has_value(), kWaitMs);
    const quint16 raw =
        rig.read<quint16>(1, [](const lk::sim::SimDrive &d) { return d.encoderRaw(); });
    QVERIFY(circularDistance(view->lastEncoder()->encoderRaw, raw, 16384) <= 2);
    QVERIFY(std::fabs(*view->lastMultiTurnDeg() - rig.multiTurnDeg(1)) < 1);
    // Hidden: the live reads stop.
    view->hide();
    QVERIFY(rig.barrier(1));
    const int reads = rig.count(1, Command::ReadEncoder);
    QTest::qWait(400); // four poll periods
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::ReadEncoder), reads);
}

namespace {
/// The extra commands the bus polls now, by drive.
QMap<int, QVector<Command>> extrasOf(SimRig &rig)
{
    const std::optional<lk::bus::PollPlan> plan = rig.session.effectivePollPlan();
    return plan ? plan->extraCommands : QMap<int, QVector<Command>>{};
}
} // namespace

void tst_EncoderView::addsPollExtrasWhileShown()
{
    // The live reads are the poll plan's while the view is shown for its drive; no GUI timer.
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    for (const QTimer *t : view->findChildren<QTimer *>())
        QVERIFY2(!t->isActive(), qPrintable(t->objectName()));
    using Extras = QMap<int, QVector<Command>>;
    const Extras drive1{{1, EncoderView::liveCommands()}};
    QCOMPARE(
        EncoderView::liveCommands(),
        (QVector<Command>{Command::ReadEncoder, Command::ReadMultiTurn, Command::ReadSingleTurn}));
    QCOMPARE(extrasOf(rig), drive1);
    QVERIFY(view->pollExtrasHandle() != 0);
    view->hide();
    QCOMPARE(extrasOf(rig), Extras{});
    QCOMPARE(view->pollExtrasHandle(), quint64(0));
    QVERIFY(!rig.session.effectivePollPlan()); // nothing else polled here
    view->show();
    QCOMPARE(extrasOf(rig), drive1);
    view->setDrive(2, rig.motor(2));
    QCOMPARE(extrasOf(rig), (Extras{{2, EncoderView::liveCommands()}}));
    view->clearDrive();
    QCOMPARE(extrasOf(rig), Extras{});
    view->setDrive(1, rig.motor(1));
    QCOMPARE(extrasOf(rig), drive1);
    view->setConnected(false);
    QCOMPARE(extrasOf(rig), Extras{});
    view->setConnected(true);
    QCOMPARE(extrasOf(rig), drive1);
    view->setSession(nullptr);
    QCOMPARE(extrasOf(rig), Extras{});
    view->setSession(&rig.session);
    QCOMPARE(extrasOf(rig), drive1);
    view.reset();
    QCOMPARE(extrasOf(rig), Extras{});
}

void tst_EncoderView::keepsAStepTestsFocus()
{
    // The view adds to the plan through the session; it never replaces the plan, so a
    // step test's focus stays while the view comes and goes.
    SimRig rig;
    QVERIFY(rig.open());
    const lk::bus::PollPlan focus =
        lk::ui::BusController::pollPlanFor({1, 2}, 0).focusedOn(2, {Command::ReadState2});
    rig.session.startPolling(focus);
    auto view = openView(rig, 1);
    QCOMPARE(rig.session.pollPlan()->focusId, 2);
    QCOMPARE(rig.session.effectivePollPlan()->focusId, 2);
    QCOMPARE(rig.session.effectivePollPlan()->ids, focus.ids);
    QCOMPARE(extrasOf(rig).value(1), EncoderView::liveCommands());
    QTRY_VERIFY_WITH_TIMEOUT(view->lastEncoder().has_value(), kWaitMs);
    view->hide();
    QCOMPARE(rig.session.effectivePollPlan()->focusId, 2);
    QVERIFY(rig.session.effectivePollPlan()->extraCommands.isEmpty());
}

void tst_EncoderView::readsEachAngleOncePerRound()
{
    // With the dashboard's plan (0x92 and 0x94 in every round) the view adds 0x90 only: the
    // angles are not read a second time for it.
    SimRig rig;
    QVERIFY(rig.open());
    rig.session.startPolling(lk::ui::BusController::pollPlanFor({1}, 0));
    auto view = openView(rig, 1);
    QTRY_VERIFY_WITH_TIMEOUT(view->lastEncoder().has_value(), kWaitMs);
    QVERIFY(view->lastMultiTurnDeg().has_value());
    QVERIFY(rig.barrier(1));
    const int encoder0 = rig.count(1, Command::ReadEncoder);
    const int multi0 = rig.count(1, Command::ReadMultiTurn);
    const int single0 = rig.count(1, Command::ReadSingleTurn);
    QVERIFY(QTest::qWaitFor([&] { return rig.count(1, Command::ReadEncoder) >= encoder0 + 20; },
                            kWaitMs));
    view->hide();
    rig.session.stopPolling();
    QVERIFY(rig.barrier(1));
    const int encoders = rig.count(1, Command::ReadEncoder) - encoder0;
    const int multis = rig.count(1, Command::ReadMultiTurn) - multi0;
    const int singles = rig.count(1, Command::ReadSingleTurn) - single0;
    QVERIFY2(
        std::abs(multis - encoders) <= 2 && std::abs(singles - encoders) <= 2,
        qPrintable(
            QStringLiteral("0x90 %1, 0x92 %2, 0x94 %3").arg(encoders).arg(multis).arg(singles)));
}

void tst_EncoderView::resolutionAndGearFromName_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<int>("bits");
    QTest::addColumn<double>("ratio");
    QTest::newRow("MF default") << "1:MF" << 14 << 1.0;
    QTest::newRow("MF 18-bit by name") << "1:MF4015-18bit" << 18 << 1.0;
    QTest::newRow("MG geared") << "1:MG" << 18 << 10.0;
    QTest::newRow("MG i36") << "1:MG5010E-i36" << 18 << 36.0;
    QTest::newRow("MS") << "1:MS" << 12 << 1.0;
}

void tst_EncoderView::resolutionAndGearFromName()
{
    QFETCH(QString, spec);
    QFETCH(int, bits);
    QFETCH(double, ratio);
    SimRig rig(spec);
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QCOMPARE(view->encoderBits(), bits);
    QCOMPARE(view->gearRatio(), ratio);
    QCOMPARE(view->countsPerTurn(), 1 << std::min(bits, 16));
}

void tst_EncoderView::resolutionAndGearPersist()
{
    SimRig rig;
    QVERIFY(rig.open());
    QTemporaryDir dir;
    const QString ini = dir.filePath(QStringLiteral("drives.ini"));
    {
        lk::ui::SettingsFile file(ini);
        lk::ui::IniDriveStore store(file.settings());
        auto view = openView(rig, 1);
        view->setSettingsStore(&store);
        view->setEncoderBits(16);
        view->setGearRatio(6);
        store.sync();
    }
    lk::ui::SettingsFile file(ini);
    lk::ui::IniDriveStore store(file.settings());
    auto view = openView(rig, 1);
    view->setSettingsStore(&store);
    QCOMPARE(view->encoderBits(), 16);
    QCOMPARE(view->gearRatio(), 6.0);
    view->setDrive(4, rig.motor(4)); // other drive: its own inference
    QCOMPARE(view->encoderBits(), 14);
    QCOMPARE(view->gearRatio(), 1.0);
}

void tst_EncoderView::writeOffset()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QStringList asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q.key;
        return true;
    });
    QSignalSpy done(view.get(), &EncoderView::offsetWriteFinished);
    view->writeOffset(1234);
    QCOMPARE(asked, QStringList{QStringLiteral("write_encoder_offset")});
    QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, kWaitMs);
    QCOMPARE(done.first().first().toBool(), true);
    QCOMPARE(rig.read<quint16>(1, [](const lk::sim::SimDrive &d) { return d.encoderOffset(); }),
             quint16(1234));
    QCOMPARE(view->lastEncoder()->encoderOffset, quint16(1234));
}

void tst_EncoderView::offsetOutOfRangeSendsNothing()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1); // MF: 14 bit, 0..16383
    int asked = 0;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &) {
        ++asked;
        return true;
    });
    view->writeOffset(16384);
    QCOMPARE(asked, 0);
    QVERIFY(view->statusText().contains(QStringLiteral("0..16383")));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::WriteEncoderOffset), 0);
}

void tst_EncoderView::clearAngleZeroesTheAngle()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    const double before = rig.multiTurnDeg(1);
    QVERIFY(std::fabs(before) > 10); // the simulator starts drives at different angles
    ConfirmDialog::ScopedPolicy yes([](const ConfirmRequest &) { return true; });
    QSignalSpy checked(view.get(), &EncoderView::angleCheckFinished);
    QTest::mouseClick(view->findChild<QPushButton *>(QStringLiteral("clearAngle")), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(checked.count(), 1, kWaitMs);
    QCOMPARE(view->lastAngleCheck()->outcome, AngleCheck::Outcome::Cleared);
    QVERIFY(std::fabs(rig.multiTurnDeg(1)) < 1);
    QCOMPARE(rig.count(1, Command::ClearAngle), 1);
    QVERIFY(view->statusText().contains(QStringLiteral("cleared")));
}

void tst_EncoderView::ignoredClearAngleIsReported()
{
    // Firmware that acknowledges 0x95 and keeps its angle (ERRATA): the view reads the angle
    // back with 0x92 and says so instead of reporting success.
    SimRig rig(QStringLiteral("1:MF+clear-angle-ignored"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    const double before = rig.multiTurnDeg(1);
    QVERIFY(std::fabs(before) > 10);
    ConfirmDialog::ScopedPolicy yes([](const ConfirmRequest &) { return true; });
    QSignalSpy checked(view.get(), &EncoderView::angleCheckFinished);
    QTest::mouseClick(view->findChild<QPushButton *>(QStringLiteral("clearAngle")), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(checked.count(), 1, kWaitMs);
    QCOMPARE(view->lastAngleCheck()->outcome, AngleCheck::Outcome::Unchanged);
    QCOMPARE(rig.count(1, Command::ClearAngle), 1);
    QVERIFY2(view->statusText().contains(QStringLiteral("did not change")),
             qPrintable(view->statusText()));
}

void tst_EncoderView::angleCheckOutcomes_data()
{
    QTest::addColumn<double>("before");
    QTest::addColumn<double>("after");
    QTest::addColumn<int>("outcome");
    QTest::newRow("cleared") << 137.5 << 0.0 << int(AngleCheck::Outcome::Cleared);
    QTest::newRow("cleared within tolerance") << -500.0 << 0.4 << int(AngleCheck::Outcome::Cleared);
    QTest::newRow("ignored by firmware") << 137.5 << 137.5 << int(AngleCheck::Outcome::Unchanged);
    QTest::newRow("already zero") << 0.2 << 0.0 << int(AngleCheck::Outcome::AlreadyZero);
    QTest::newRow("moving") << 100.0 << 40.0 << int(AngleCheck::Outcome::ChangedNotZero);
}

void tst_EncoderView::angleCheckOutcomes()
{
    QFETCH(double, before);
    QFETCH(double, after);
    QFETCH(int, outcome);
    QCOMPARE(int(AngleCheck::classify(before, after).outcome), outcome);
}

void tst_EncoderView::zeroToRomAppliesAfterRestart()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QList<ConfirmRequest> asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q;
        return true;
    });
    QSignalSpy done(view.get(), &EncoderView::zeroWriteFinished);
    const quint16 raw =
        rig.read<quint16>(1, [](const lk::sim::SimDrive &d) { return d.encoderRaw(); });
    QVERIFY(circularDistance(raw, 0, 16384) > 100); // not at zero already
    view->writeZeroToRom();
    QCOMPARE(asked.size(), 1);
    QVERIFY(asked.first().reason.contains(QStringLiteral("power")));
    QVERIFY(asked.first().reason.contains(QStringLiteral("wears")));
    QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, kWaitMs);
    QCOMPARE(done.first().first().toBool(), true);
    QVERIFY(view->statusText().contains(QStringLiteral("Power the drive off and on")));
    // Not applied before the power cycle...
    QCOMPARE(rig.read<quint16>(1, [](const lk::sim::SimDrive &d) { return d.encoderOffset(); }),
             quint16(0));
    // ...and applied after it: the present position reads as encoder zero.
    rig.restartDrive(1);
    const quint16 encoder =
        rig.read<quint16>(1, [](const lk::sim::SimDrive &d) { return d.encoder(); });
    QVERIFY2(circularDistance(encoder, 0, 16384) <= 2, qPrintable(QString::number(encoder)));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::WriteZeroRom), 1);
}

void tst_EncoderView::declinedZeroSendsNothing()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    ConfirmDialog::ScopedPolicy no([](const ConfirmRequest &) { return false; });
    view->writeZeroToRom();
    view->clearAngle();
    view->writeOffset(10);
    QVERIFY(view->statusText().contains(QStringLiteral("nothing was sent")));
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::WriteZeroRom), 0);
    QCOMPARE(rig.count(1, Command::ClearAngle), 0);
    QCOMPARE(rig.count(1, Command::WriteEncoderOffset), 0);
}

void tst_EncoderView::v235Ms4015StartsAt16Bits()
{
    // docs/V2.35.md section 12: an MS4015 on firmware 2.35 reports 16 bits. The view starts
    // there, not at the MS series' 12 bits raised to 14 by the first value (which showed
    // "6437 of 16384 (14-bit, from data) (141.44 deg)" beside "single-turn 35.36 deg").
    SimRig rig(kV235Bus);
    QVERIFY(rig.open());
    auto view = openView(rig, 3);
    QCOMPARE(view->encoderBits(), 16);
    QCOMPARE(view->countsPerTurn(), 65536);
    QTRY_VERIFY_WITH_TIMEOUT(view->lastEncoder().has_value(), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(labelText(*view, "singleTurn") != QStringLiteral("\u2013"), kWaitMs);
    const QString encoder = labelText(*view, "encoderValue");
    QVERIFY2(encoder.contains(" of 65536 (16-bit, protocol V2.35)"), qPrintable(encoder));
    // The encoder's angle is the single-turn angle (both start at the encoder zero).
    const double single = labelText(*view, "singleTurn").chopped(1).toDouble();
    const double fromEncoder = 360.0 * view->lastEncoder()->encoder / 65536.0;
    QVERIFY2(std::fabs(single - fromEncoder) < 1.0,
             qPrintable(QStringLiteral("%1 vs %2").arg(encoder, labelText(*view, "singleTurn"))));
    QVERIFY(encoder.contains(QStringLiteral("(%1\u00b0)").arg(fromEncoder, 0, 'f', 2)));
    const auto *combo = view->findChild<QComboBox *>(QStringLiteral("encoderBits"));
    QCOMPARE(combo->currentData().toInt(), 16);
}

void tst_EncoderView::userResolutionWinsOverData()
{
    SimRig rig(kV235Bus);
    QVERIFY(rig.open());
    auto view = openView(rig, 3);
    QTRY_VERIFY_WITH_TIMEOUT(view->encoderBits() >= 14, kWaitMs);
    auto *combo = view->findChild<QComboBox *>(QStringLiteral("encoderBits"));
    combo->setCurrentIndex(combo->findData(18));
    emit combo->activated(combo->currentIndex());
    QCOMPARE(view->encoderBits(), 18);
    QVERIFY(turnPast(rig, 3, 720, 400));
    QTRY_VERIFY_WITH_TIMEOUT(labelText(*view, "encoderValue").contains("(18-bit, your setting)"),
                             kWaitMs);
    QCOMPARE(view->encoderBits(), 18);
}

void tst_EncoderView::clearTurnCount()
{
    SimRig rig(kV235Bus);
    QVERIFY(rig.open());
    QVERIFY(turnPast(rig, 3, 720, 800)); // more than two turns
    const double before = rig.multiTurnDeg(3);
    auto view = openView(rig, 3);
    auto *clear = view->findChild<QPushButton *>(QStringLiteral("clearTurns"));
    QTRY_VERIFY_WITH_TIMEOUT(clear->isEnabled(), kWaitMs);
    QStringList asked;
    QString reason;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q.key;
        reason = q.reason;
        return true;
    });
    QSignalSpy done(view.get(), &EncoderView::turnCountCleared);
    QTest::mouseClick(clear, Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, kWaitMs);
    QCOMPARE(done.at(0).at(0).toBool(), true);
    QCOMPARE(asked, QStringList{QStringLiteral("clear_turn_count")});
    QVERIFY(reason.contains("RAM or ROM"));
    QCOMPARE(rig.count(3, Command::ClearTurnCount), 1);
    const double after = rig.multiTurnDeg(3);
    QVERIFY(std::fabs(after) < 360);
    // Only whole turns went: the angle within the turn stays.
    QVERIFY(std::fabs(std::fmod(before, 360.0) - after) < 0.5);
    QVERIFY2(view->statusText().contains("cleared") &&
                 view->statusText().contains(QString::number(after, 'f', 2)),
             qPrintable(view->statusText()));
    QCOMPARE(*view->lastMultiTurnDeg(), after); // read back, not assumed
}

void tst_EncoderView::declinedClearTurnCountSendsNothing()
{
    SimRig rig(kV235Bus);
    QVERIFY(rig.open());
    auto view = openView(rig, 3);
    ConfirmDialog::ScopedPolicy no([](const ConfirmRequest &) { return false; });
    QTest::mouseClick(view->findChild<QPushButton *>(QStringLiteral("clearTurns")), Qt::LeftButton);
    QVERIFY(view->statusText().contains(QStringLiteral("nothing was sent")));
    QVERIFY(rig.barrier(3));
    QCOMPARE(rig.count(3, Command::ClearTurnCount), 0);
}

void tst_EncoderView::v23DriveHasNoClearTurnCount()
{
    SimRig rig(kV235Bus);
    QVERIFY(rig.open());
    auto view = openView(rig, 1);
    QVERIFY(!view->findChild<QPushButton *>(QStringLiteral("clearTurns"))->isEnabled());
    QVERIFY2(labelText(*view, "clearTurnsNote").contains("v2.3") &&
                 labelText(*view, "clearTurnsNote").contains("no clear turn count"),
             qPrintable(labelText(*view, "clearTurnsNote")));
    QStringList asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q.key;
        return true;
    });
    view->clearTurnCount();
    QVERIFY(asked.isEmpty());
    QVERIFY(rig.barrier(1));
    QCOMPARE(rig.count(1, Command::ClearTurnCount), 0);
}

// V2.35 drives do not answer 0x91 (docs/V2.35.md): the offset is not offered, says why, and a
// write sends nothing (it used to go out and time out, the message blaming the wiring).
void tst_EncoderView::v235DriveHasNoEncoderOffset()
{
    SimRig rig(kV235Bus);
    QVERIFY(rig.open());
    auto view = openView(rig, 3);
    QVERIFY(!view->findChild<QPushButton *>(QStringLiteral("writeOffset"))->isEnabled());
    QStringList asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q.key;
        return true;
    });
    view->writeOffset(100);
    QVERIFY(asked.isEmpty());
    QVERIFY2(view->statusText().contains(QStringLiteral("has no encoder offset command")),
             qPrintable(view->statusText()));
    QVERIFY(rig.barrier(3));
    QCOMPARE(rig.count(3, Command::WriteEncoderOffset), 0);
    // The V2.3 drive beside it still has it.
    auto v23 = openView(rig, 1);
    QVERIFY(v23->findChild<QPushButton *>(QStringLiteral("writeOffset"))->isEnabled());
}

QTEST_MAIN(tst_EncoderView)
#include "tst_encoderview.moc"
