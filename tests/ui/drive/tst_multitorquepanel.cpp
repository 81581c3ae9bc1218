// The Control view's multi-motor torque panel (0x280, docs/CAN.md section 4.2) in the whole
// window on the built-in simulator's CAN bus (MainWindowFixture, as tst_mainwindowcanviews):
// rows for the old CAN drives 1..4, none ticked; a send within the limits moves the simulated
// drives and says who answered; a torque over a soft limit and an unticked known drive are
// refused with nothing on the wire (the simulator's request counts); RS485, V2.36 drives,
// an unknown generation and listen-only disable it with the reason; the emergency stop and a
// connection change reset it; the Traffic view decodes the frame that went out.

#include "MainWindowFixture.h"

#include <drive/ControlView.h>
#include <drive/DriveSettingsStore.h>
#include <drive/MultiTorquePanel.h>
#include <main/DriveViews.h>
#include <panels/TrafficModel.h>
#include <panels/TrafficPanel.h>

#include <QtTest/QtTest>
#include <QtWidgets/QAbstractButton>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QLabel>

#include <cmath>

using namespace lk::uitest;
using lk::protocol::Command;
using lk::protocol::Generation;
using lk::protocol::Series;
using lk::ui::MultiTorquePanel;

class tst_MultiTorquePanel : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void rowsForTheOldCanDrivesNoneTicked();
    void sendWithinLimitsMovesTheDrivesAndSaysWhoAnswered();
    void overTheSoftLimitIsRefusedAndSendsNothing();
    void anUntickedKnownDriveIsRefused();
    void rs485HasNoSuchFrame();
    void v236DrivesHaveNoSuchFrame();
    void unknownGenerationNamesTheDriveAndWhatToChoose();
    void listenOnlySendsNothing();
    void emergencyStopResetsThePanel();
    void connectionChangeResetsThePanel();

private:
    /// The built-in simulator on CAN with `spec`, every drive of it found; `old` told as
    /// old CAN MGs and `v236` as V2.36 MFs, as the user does with the series chooser.
    bool openCan(const QString &spec, const QVector<int> &old, const QVector<int> &v236 = {},
                 bool listenOnly = false);
    MultiTorquePanel *panel() const { return m_window->driveViews()->multiTorque(); }
    QCheckBox *tick(int id) const
    {
        return panel()->findChild<QCheckBox *>(QStringLiteral("multiTorqueTick%1").arg(id));
    }
    QDoubleSpinBox *iq(int id) const
    {
        return panel()->findChild<QDoubleSpinBox *>(QStringLiteral("multiTorqueIq%1").arg(id));
    }
    QAbstractButton *button(const char *name) const
    {
        return panel()->findChild<QAbstractButton *>(QLatin1String(name));
    }
    /// Ticks drive `id` with `amps`, as the user does.
    void set(int id, double amps);
    /// A read of drive 1 answered: whatever was queued before it has been on the wire.
    bool barrier();
    int torques(int id) const { return sim()->requestCount(id, Command::Torque); }
    double simIq(int id) const;
    /// The traffic view's multi-motor torque rows, as exported (one line each).
    QString multiTorqueRows() const;
    /// Traffic captured with "Keep recording", the view hidden (tst_mainwindowcanviews).
    void captureTraffic();
};

void tst_MultiTorquePanel::init()
{
    QVERIFY(openWindow());
}

void tst_MultiTorquePanel::cleanup()
{
    closeWindow();
}

bool tst_MultiTorquePanel::openCan(const QString &spec, const QVector<int> &old,
                                   const QVector<int> &v236, bool listenOnly)
{
    m_window->controller()->setSimulatorSpec(*lk::sim::SimBusSpec::parse(spec));
    lk::ui::ConnectionChoice choice = simulatorChoice();
    choice.simulatedCan = true;
    choice.bitRate = 1000000;
    choice.listenOnly = listenOnly;
    m_window->connectTo(choice);
    const int drives = int(lk::sim::SimBusSpec::parse(spec)->drives.size());
    const bool up =
        listenOnly ? QTest::qWaitFor([this] { return model()->isListening(); }, kWaitMs)
                   : QTest::qWaitFor([this] { return model()->canSend(); }, kWaitMs) &&
                         QTest::qWaitFor(
                             [this, drives] {
                                 return model()->ids().size() == drives && model()->isPolling();
                             },
                             kWaitMs);
    if (!up)
        return false;
    // CAN has no model read: the user tells each drive's series and generation.
    auto *session = m_window->controller()->session();
    for (int id : old)
        session->setDriveIdentity({id, Series::MG, Generation::V2_3, std::nullopt});
    for (int id : v236)
        session->setDriveIdentity({id, Series::MF, Generation::V2_35, std::nullopt});
    // The panel follows the bus's echo of it.
    return QTest::qWaitFor(
        [this, old, v236] {
            for (int id : old) {
                if (id <= 4 && (!tick(id) || !tick(id)->isEnabled()))
                    return false;
            }
            for (int id : v236) {
                if (!panel()->rowRefusal(id).contains(QStringLiteral("V2.36")))
                    return false;
            }
            return true;
        },
        kWaitMs);
}

void tst_MultiTorquePanel::set(int id, double amps)
{
    QVERIFY(tick(id) && iq(id));
    tick(id)->setChecked(true);
    iq(id)->setValue(amps);
    QCOMPARE(iq(id)->value(), amps); // within the spin box's bounds
}

bool tst_MultiTorquePanel::barrier()
{
    bool done = false;
    QObject context;
    m_window->controller()->session()->send(
        *lk::protocol::build::plain(Command::ReadState1, 1).request, &context,
        [&done](const lk::bus::RequestResult &) { done = true; });
    return QTest::qWaitFor([&done] { return done; }, kWaitMs);
}

double tst_MultiTorquePanel::simIq(int id) const
{
    double iqA = 0;
    sim()->withBus([&iqA, id](lk::sim::SimBus &bus) {
        if (auto *d = bus.drive(id))
            iqA = d->iqA();
    });
    return iqA;
}

QString tst_MultiTorquePanel::multiTorqueRows() const
{
    auto *traffic = m_window->traffic();
    traffic->flush();
    const lk::ui::TrafficModel *m = traffic->trafficModel();
    QString text;
    for (int row = 0; row < m->rowCount(); ++row) {
        if (m->commandText(row) == QLatin1String("multi_torque"))
            text += m->exportLine(row) + QLatin1Char('\n');
    }
    return text;
}

void tst_MultiTorquePanel::captureTraffic()
{
    m_window->showView(QStringLiteral("traffic"));
    auto *keep = m_window->traffic()->findChild<QAbstractButton *>(QStringLiteral("trafficRecord"));
    QVERIFY(keep);
    if (!keep->isChecked())
        keep->click();
    m_window->showView(QStringLiteral("control"));
    QVERIFY(m_window->traffic()->wantsCapture());
}

void tst_MultiTorquePanel::rowsForTheOldCanDrivesNoneTicked()
{
    // Drive 5 is on the bus too, outside the frame's slots: it has no row.
    QVERIFY(openCan(QStringLiteral("1:MG,2:MG,5:MG"), {1, 2, 5}));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->rowIds(), (QVector<int>{1, 2}), kWaitMs);
    QVERIFY2(panel()->absence().isEmpty(), qPrintable(panel()->absence()));
    // In the Control view, beside the brake.
    QVERIFY(m_window->driveViews()->control()->isAncestorOf(panel()));
    for (int id : {1, 2}) {
        QVERIFY(!tick(id)->isChecked());
        QVERIFY(tick(id)->isEnabled());
        QCOMPARE(iq(id)->value(), 0.0);
        // An MG's default torque limit is a quarter of its 14 A: the spin box stops there, in
        // whole steps of the frame (0.016 A: 3.488 A, shown 3.49 A, which the wire keeps).
        QCOMPARE(iq(id)->maximum(), 3.49);
        QCOMPARE(iq(id)->minimum(), -3.49);
        QCOMPARE(panel()->replyText(id), QStringLiteral("no reply yet")); // never a 0
    }
    QVERIFY(button("multiTorqueSend")->isEnabled());
    QVERIFY(!button("multiTorqueStop")->isEnabled()); // no frame yet
    QVERIFY(!tick(5));
}

void tst_MultiTorquePanel::sendWithinLimitsMovesTheDrivesAndSaysWhoAnswered()
{
    QVERIFY(openCan(QStringLiteral("1:MG,2:MG"), {1, 2}));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->rowIds(), (QVector<int>{1, 2}), kWaitMs);
    captureTraffic();
    set(1, 1.6);
    set(2, -1.6);
    QSignalSpy finished(panel(), &MultiTorquePanel::frameFinished);
    QTest::mouseClick(button("multiTorqueSend"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kWaitMs);
    const auto result = finished.at(0).at(0).value<lk::bus::MultiTorqueResult>();
    QCOMPARE(result.status, lk::bus::RequestStatus::Ok);
    QCOMPARE(torques(1), 1); // one frame, taken by both drives
    QCOMPARE(torques(2), 1);
    QTRY_VERIFY_WITH_TIMEOUT(simIq(1) > 1.0 && simIq(2) < -1.0, kWaitMs);
    QVERIFY2(panel()->statusText().contains(QStringLiteral("drive 1 1.60 A, drive 2 -1.60 A")) &&
                 panel()->statusText().contains(QStringLiteral("Answered: drive(s) 1, 2.")),
             qPrintable(panel()->statusText()));
    for (int id : {1, 2})
        QVERIFY2(panel()->replyText(id).startsWith(QStringLiteral("iq ")) &&
                     panel()->replyText(id).contains(QStringLiteral("dps")),
                 qPrintable(panel()->replyText(id)));
    // Quitting and the link-loss warnings know both drives are under torque.
    QCOMPARE(m_window->commandedMotion()->movingIds(), (QVector<int>{1, 2}));
    // Nothing repeats it on its own.
    QTest::qWait(500);
    QCOMPARE(torques(1), 1);
    // The Traffic view reads the frame that went out as the multi-motor torque it is.
    QTRY_VERIFY_WITH_TIMEOUT(!multiTorqueRows().isEmpty(), kWaitMs);
    const QString rows = multiTorqueRows();
    QCOMPARE(rows.count(QLatin1Char('\n')), 1);
    QVERIFY2(rows.startsWith(QStringLiteral("280#64009CFF00000000  # ")) &&
                 rows.contains(QStringLiteral("TX multi_torque: torque current of IDs 1..4: ID 1 "
                                              "1.60 A, ID 2 -1.60 A, ID 3 0.00 A, ID 4 0.00 A")),
             qPrintable(rows));
    // Stop: Motor Stop to both drives of the frame.
    QCOMPARE(panel()->stopTargets(), (QVector<int>{1, 2}));
    QVERIFY(button("multiTorqueStop")->isEnabled());
    QTest::mouseClick(button("multiTorqueStop"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(sim()->requestCount(1, Command::MotorStop) >= 1 &&
                                 sim()->requestCount(2, Command::MotorStop) >= 1,
                             kWaitMs);
    QVERIFY(panel()->statusText().startsWith(QStringLiteral("Sent Motor Stop (0x81) to drive(s) "
                                                            "1, 2.")));
    QTRY_VERIFY_WITH_TIMEOUT(m_window->commandedMotion()->movingIds().isEmpty(), kWaitMs);
}

void tst_MultiTorquePanel::overTheSoftLimitIsRefusedAndSendsNothing()
{
    QVERIFY(openCan(QStringLiteral("1:MG,2:MG"), {1, 2}));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->rowIds(), (QVector<int>{1, 2}), kWaitMs);
    set(1, 0.5);
    set(2, 1.5);
    // Then the user lowers drive 2's torque limit in the Control view: its limits in force.
    model()->setCurrentId(2);
    auto *control = m_window->driveViews()->control();
    QTRY_COMPARE_WITH_TIMEOUT(control->driveId(), 2, kWaitMs);
    lk::safety::SoftLimits limits = control->softLimits();
    limits.maxTorqueA = 1.0;
    control->setSoftLimits(limits);
    QSignalSpy refused(panel(), &MultiTorquePanel::refused);
    QSignalSpy finished(panel(), &MultiTorquePanel::frameFinished);
    QTest::mouseClick(button("multiTorqueSend"), Qt::LeftButton);
    QCOMPARE(refused.count(), 1);
    QCOMPARE(panel()->statusText(),
             QStringLiteral("Refused: drive 2: the torque current 1.50 A is over your torque "
                            "limit of 1.00 A. Nothing sent."));
    QVERIFY(barrier());
    QCOMPARE(finished.count(), 0); // the bus was not even asked
    QCOMPARE(torques(1), 0);
    QCOMPARE(torques(2), 0);

    // A drive that is not the Control view's: its stored limits, as the Control view loads
    // them when it is selected.
    model()->setCurrentId(2);
    auto *store = m_window->driveViews()->settingsStore();
    const lk::bus::KnownMotor motor1 = m_window->controller()->session()->knownMotors().value(1);
    lk::safety::SoftLimits low = lk::safety::SoftLimits::defaults(Series::MG);
    low.maxTorqueA = 0.25;
    store->setSoftLimits(lk::ui::DriveSettingsStore::driveKey(1, motor1), low);
    iq(2)->setValue(0.5);
    panel()->send();
    QVERIFY2(panel()->statusText().contains(QStringLiteral("drive 1: the torque current 0.50 A "
                                                           "is over your torque limit of 0.25 A")),
             qPrintable(panel()->statusText()));
    QVERIFY(barrier());
    QCOMPARE(torques(1), 0);
    QCOMPARE(torques(2), 0);
}

void tst_MultiTorquePanel::anUntickedKnownDriveIsRefused()
{
    QVERIFY(openCan(QStringLiteral("1:MG,2:MG"), {1, 2}));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->rowIds(), (QVector<int>{1, 2}), kWaitMs);
    QSignalSpy refused(panel(), &MultiTorquePanel::refused);
    panel()->send(); // nothing ticked
    QVERIFY2(panel()->statusText().startsWith(QStringLiteral("Nothing is ticked")),
             qPrintable(panel()->statusText()));
    set(1, 0.5);
    panel()->send();
    QCOMPARE(refused.count(), 2);
    QVERIFY2(panel()->statusText().contains(QStringLiteral("drive 2 is on the bus and would get "
                                                           "0 A")) &&
                 panel()->statusText().contains(
                     QStringLiteral("Tick drive 2 with 0 A if zero torque is meant")),
             qPrintable(panel()->statusText()));
    QVERIFY(barrier());
    QCOMPARE(torques(1), 0);
    QCOMPARE(torques(2), 0);
    // Ticked with 0 A on purpose, it goes.
    set(2, 0.0);
    QSignalSpy finished(panel(), &MultiTorquePanel::frameFinished);
    panel()->send();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kWaitMs);
    QCOMPARE(torques(1), 1);
    QCOMPARE(torques(2), 1);
}

void tst_MultiTorquePanel::rs485HasNoSuchFrame()
{
    QVERIFY(findAllDrives()); // the built-in simulator on RS485, drives 1..4
    QVERIFY2(panel()->absence().startsWith(QStringLiteral("No such frame on RS485")),
             qPrintable(panel()->absence()));
    QVERIFY(!button("multiTorqueSend")->isEnabled());
    QVERIFY(panel()->rowIds().isEmpty() || !tick(1)->isVisibleTo(panel()));
    panel()->send();
    QVERIFY(barrier());
    QCOMPARE(torques(1), 0);
}

void tst_MultiTorquePanel::v236DrivesHaveNoSuchFrame()
{
    QVERIFY(openCan(QStringLiteral("1:MF@2.35,2:MF@2.35"), {}, {1, 2}));
    QTRY_VERIFY2_WITH_TIMEOUT(panel()->absence().contains(QStringLiteral(
                                  "speaks CAN V2.36, which documents no multi-motor frame")),
                              qPrintable(panel()->absence()), kWaitMs);
    QVERIFY(!button("multiTorqueSend")->isEnabled());
    QCOMPARE(panel()->rowRefusal(1), QStringLiteral("CAN V2.36 documents no multi-motor frame"));
    panel()->send();
    QVERIFY(barrier());
    QCOMPARE(torques(1), 0);

    // Beside an old drive, a V2.36 one at ID 1..4 cannot be named, and leaving it out would
    // give it 0 A: the frame is refused, naming it.
    closeWindow();
    QVERIFY(openWindow());
    QVERIFY(openCan(QStringLiteral("1:MG,2:MF@2.35"), {1}, {2}));
    QTRY_VERIFY2_WITH_TIMEOUT(panel()->absence().isEmpty(), qPrintable(panel()->absence()),
                              kWaitMs);
    QVERIFY(!tick(2)->isEnabled());
    set(1, 0.5);
    panel()->send();
    QVERIFY2(panel()->statusText().contains(QStringLiteral("drive 2 is on the bus")) &&
                 panel()->statusText().contains(QStringLiteral("cannot be ticked: CAN V2.36")),
             qPrintable(panel()->statusText()));
    QVERIFY(barrier());
    QCOMPARE(torques(1), 0);
}

void tst_MultiTorquePanel::unknownGenerationNamesTheDriveAndWhatToChoose()
{
    // Found by the scan, nothing told: its replies on 0x141 say the old generation, but CAN
    // has no model read, so its series (and its current, its torque) is not known.
    QVERIFY(openCan(QStringLiteral("1:MG"), {}));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->rowIds(), QVector<int>{1}, kWaitMs);
    QCOMPARE(panel()->rowRefusal(1), QStringLiteral("series not known: select drive 1 in the "
                                                    "drive list and choose its series below it"));
    QVERIFY(!tick(1)->isEnabled());
    QVERIFY(!iq(1)->isEnabled());
    QCOMPARE(panel()->replyText(1), panel()->rowRefusal(1));
    tick(1)->setChecked(true); // not by a click: the box is disabled; the guard refuses it
    panel()->send();
    QCOMPARE(panel()->statusText(), QStringLiteral("Refused: the series of drive 1 is not known: "
                                                   "choose it below the drive list. Nothing "
                                                   "sent."));
    QVERIFY(barrier());
    QCOMPARE(torques(1), 0);
}

void tst_MultiTorquePanel::listenOnlySendsNothing()
{
    // Drives declared, the link listen-only: the rows are there, nothing can go out.
    QVERIFY(openCan(QStringLiteral("1:MG,2:MG"), {1, 2}, {}, true));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->rowIds(), (QVector<int>{1, 2}), kWaitMs);
    QVERIFY2(panel()
                 ->findChild<QLabel *>(QStringLiteral("multiTorqueReason"))
                 ->text()
                 .startsWith(QStringLiteral("Listen-only")),
             qPrintable(panel()->findChild<QLabel *>(QStringLiteral("multiTorqueReason"))->text()));
    QVERIFY(!button("multiTorqueSend")->isEnabled());
    QVERIFY(!button("multiTorqueStop")->isEnabled());
    set(1, 0.5);
    set(2, 0.5);
    QSignalSpy finished(panel(), &MultiTorquePanel::frameFinished);
    panel()->send();
    panel()->stop();
    QTest::qWait(300);
    QCOMPARE(finished.count(), 0);
    QCOMPARE(model()->statistics().listenOnlyRefusals, quint64(0)); // the bus was not asked
    QCOMPARE(torques(1), 0);
}

void tst_MultiTorquePanel::emergencyStopResetsThePanel()
{
    QVERIFY(openCan(QStringLiteral("1:MG,2:MG"), {1, 2}));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->rowIds(), (QVector<int>{1, 2}), kWaitMs);
    set(1, 1.0);
    set(2, 1.0);
    QSignalSpy finished(panel(), &MultiTorquePanel::frameFinished);
    panel()->send();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kWaitMs);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_VERIFY2_WITH_TIMEOUT(
        stopReport().contains(QStringLiteral("acknowledged by drive(s) 1, 2")),
        qPrintable(stopReport()), kWaitMs);
    QTRY_VERIFY2_WITH_TIMEOUT(
        panel()->statusText().startsWith(QStringLiteral("Stopped by the emergency stop.")),
        qPrintable(panel()->statusText()), kWaitMs);
    for (int id : {1, 2}) {
        QVERIFY(!tick(id)->isChecked());
        QCOMPARE(iq(id)->value(), 0.0);
        QCOMPARE(panel()->replyText(id), QStringLiteral("no reply yet"));
    }
    QVERIFY(panel()->stopTargets().isEmpty());
    // Nothing goes out again on its own after it.
    QTest::qWait(300);
    QCOMPARE(torques(1), 1);
}

void tst_MultiTorquePanel::connectionChangeResetsThePanel()
{
    QVERIFY(openCan(QStringLiteral("1:MG,2:MG"), {1, 2}));
    QTRY_COMPARE_WITH_TIMEOUT(panel()->rowIds(), (QVector<int>{1, 2}), kWaitMs);
    set(1, 1.0);
    set(2, -1.0);
    QVERIFY(sim()->requestDisconnect());
    QTRY_VERIFY_WITH_TIMEOUT(!model()->canSend(), kWaitMs);
    QVERIFY(!button("multiTorqueSend")->isEnabled());
    for (int id : {1, 2}) {
        QVERIFY(!tick(id)->isChecked());
        QCOMPARE(iq(id)->value(), 0.0);
    }
    QVERIFY2(panel()->statusText().startsWith(QStringLiteral("The connection changed")),
             qPrintable(panel()->statusText()));
    QSignalSpy finished(panel(), &MultiTorquePanel::frameFinished);
    panel()->send();
    QTest::qWait(200);
    QCOMPARE(finished.count(), 0); // nothing was handed to the bus
}

QTEST_MAIN(tst_MultiTorquePanel)
#include "tst_multitorquepanel.moc"
