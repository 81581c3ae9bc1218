// The whole window's emergency stop against the in-process simulated bus: Esc from anywhere
// (a child widget, a modal dialog, during a scan, with the setpoint generator running) sends
// motor off to every drive, checked on the simulator's side. Its report shows at once and
// fills in; a drive said in red to be possibly moving leaves the red once it reads stopped; a
// stop pressed while disconnected goes out when the link is back.

#include "MainWindowFixture.h"

#include <drive/ControlView.h>
#include <drive/SetpointGenerator.h>
#include <main/DriveViews.h>
#include <main/EmergencyStopControl.h>
#include <main/MainWindow.h>
#include <panels/MessageBanner.h>

#include <bus/SetpointWaveform.h>

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDialog>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QVBoxLayout>

using lk::protocol::Command;
using lk::ui::ConnectionChoice;
using namespace lk::uitest;

class tst_MainWindowStop : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init() { QVERIFY(openWindow()); }
    void cleanup() { closeWindow(); }
    void escapeSendsMotorOffToAllDrives();
    void escapeWorksFromAModalDialog();
    void escapeDuringAScanStopsEveryDrive_data();
    void escapeDuringAScanStopsEveryDrive();
    void escapeHaltsTheGeneratorFirst();
    void reportShowsAtOnceAndFillsIn();
    void silentDriveLeavesTheRedOnceItReadsStopped();
    void stopWhileDisconnectedGoesOutOnReconnect();
};

void tst_MainWindowStop::escapeSendsMotorOffToAllDrives()
{
    QVERIFY(findAllDrives());
    const QVector<int> before = motorOffCounts();
    QSignalSpy stops(m_window->controller()->session(),
                     &lk::bus::BusSession::emergencyStopFinished);
    // Esc typed into a child widget that has nothing to do with stopping.
    auto *first = m_window->findChild<QSpinBox *>(QStringLiteral("scanFirstId"));
    first->setFocus();
    QTest::keyClick(first, Qt::Key_Escape);
    for (int i = 0; i < kSimIds.size(); ++i)
        QTRY_VERIFY_WITH_TIMEOUT(sim()->requestCount(kSimIds[i], Command::MotorOff) > before[i],
                                 kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(stopReport().contains(QStringLiteral("1, 2, 3, 4")), kWaitMs);
    QTest::qWait(300);
    QCOMPARE(stops.count(), 1); // one press, one stop
    // The report stays until dismissed (it is not an 8-second Info line).
    auto *banner = m_window->banner();
    QCOMPARE(banner->entryLevel(lk::ui::EmergencyStopControl::entryKey()),
             lk::ui::MessageBanner::Level::Info);
    QVERIFY(banner->isVisible());
    QTest::mouseClick(banner->entryCloseButton(lk::ui::EmergencyStopControl::entryKey()),
                      Qt::LeftButton);
    QVERIFY(!banner->hasEntry(lk::ui::EmergencyStopControl::entryKey()));
}

void tst_MainWindowStop::escapeWorksFromAModalDialog()
{
    QVERIFY(findAllDrives());
    const QVector<int> before = motorOffCounts();
    QSignalSpy stops(m_window->controller()->session(),
                     &lk::bus::BusSession::emergencyStopFinished);
    QDialog dialog(m_window.get());
    auto *edit = new QLineEdit(&dialog);
    auto *layout = new QVBoxLayout(&dialog);
    layout->addWidget(edit);
    dialog.setModal(true);
    dialog.open();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    edit->setFocus();
    QTest::keyClick(edit, Qt::Key_Escape);
    for (int i = 0; i < kSimIds.size(); ++i)
        QTRY_VERIFY_WITH_TIMEOUT(sim()->requestCount(kSimIds[i], Command::MotorOff) > before[i],
                                 kWaitMs);
    // One press, one stop: never a second one from the key propagating to parent widgets.
    QTRY_COMPARE_WITH_TIMEOUT(stops.count(), 1, kWaitMs);
    QTest::qWait(300);
    QCOMPARE(stops.count(), 1);
    QVERIFY(!dialog.isVisible()); // and the dialog still closes on Esc
}

void tst_MainWindowStop::escapeDuringAScanStopsEveryDrive_data()
{
    QTest::addColumn<int>("delayMs");
    for (int ms : {0, 10, 30, 60, 100, 150, 200})
        QTest::newRow(qPrintable(QStringLiteral("Esc %1 ms after Scan").arg(ms))) << ms;
}

void tst_MainWindowStop::escapeDuringAScanStopsEveryDrive()
{
    QVERIFY(findAllDrives());
    // Four drives at 360 dps, Scan, then Esc before the scan has found them all: the scan
    // has emptied the known drives, and still every drive must end with its motor off.
    QFETCH(int, delayMs);
    QTRY_VERIFY_WITH_TIMEOUT(model()->isPolling(), kWaitMs);
    spinAll();
    QSignalSpy scans(m_window->controller()->session(), &lk::bus::BusSession::scanFinished);
    QSignalSpy reports(m_window->emergencyStopControl(), &lk::ui::EmergencyStopControl::reported);
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    if (delayMs > 0)
        QTest::qWait(delayMs);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(scans.count(), 1, kWaitMs);
    QVERIFY2(allOff(), qPrintable(stopReport()));
    QVERIFY2(stopReport().contains(QStringLiteral("acknowledged by drive(s) 1, 2, 3, 4")),
             qPrintable(stopReport()));
    QVERIFY(!stopReport().contains(QStringLiteral("NO answer")));
    QVERIFY(m_window->commandedMotion()->movingIds().isEmpty()); // every off was acknowledged
}

void tst_MainWindowStop::escapeHaltsTheGeneratorFirst()
{
    QVERIFY(findAllDrives());
    QTRY_VERIFY_WITH_TIMEOUT(model()->isPolling(), kWaitMs);
    model()->setCurrentId(1);
    auto *control = m_window->driveViews()->control();
    QTRY_COMPARE_WITH_TIMEOUT(control->driveId(), 1, kWaitMs);
    lk::bus::SetpointWaveform::Settings s;
    s.target = lk::bus::SetpointWaveform::Target::Speed;
    control->startGenerator(s);
    QVERIFY(control->generator()->isRunning());
    // The bus thread's stream is sending: a few setpoints have reached drive 1.
    QTRY_VERIFY_WITH_TIMEOUT(sim()->requestCount(1, Command::Speed) >= 3, kWaitMs);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QVERIFY(!control->generator()->isRunning()); // before the bus has said anything
    QTRY_VERIFY_WITH_TIMEOUT(!stopReport().isEmpty(), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(allOff(), kWaitMs);
    // And the stream on the bus thread has stopped too: no setpoint after the stop.
    const int setpoints = sim()->requestCount(1, Command::Speed);
    QTest::qWait(300); // six intervals at the default 20 Hz
    QCOMPARE(sim()->requestCount(1, Command::Speed), setpoints);
    QVERIFY2(allOff(), "a setpoint after the emergency stop turned a drive back on");
}

void tst_MainWindowStop::reportShowsAtOnceAndFillsIn()
{
    QVERIFY(findAllDrives());
    spinAll();
    QSignalSpy reports(m_window->emergencyStopControl(), &lk::ui::EmergencyStopControl::reported);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    // Before the bus has answered anything: the operator sees the stop going out.
    QVERIFY2(stopReport().contains(QStringLiteral("going out to every ID 1-32")),
             qPrintable(stopReport()));
    QVERIFY2(stopReport().contains(QStringLiteral("Waiting for drive(s) 1, 2, 3, 4.")),
             qPrintable(stopReport()));
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    QVERIFY2(stopReport().contains(QStringLiteral("acknowledged by drive(s) 1, 2, 3, 4.")),
             qPrintable(stopReport()));
}

void tst_MainWindowStop::silentDriveLeavesTheRedOnceItReadsStopped()
{
    QVERIFY(findAllDrives());
    spinAll();
    // Drive 3 hears nothing and answers nothing (a broken wire to it, say).
    QVERIFY(sim()->withBus([](lk::sim::SimBus &bus) { bus.faults().setSilenced(3, true); }));
    QSignalSpy reports(m_window->emergencyStopControl(), &lk::ui::EmergencyStopControl::reported);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    const QString key = lk::ui::EmergencyStopControl::entryKey();
    QVERIFY2(stopReport().contains(QStringLiteral("NO answer from drive(s) 3")),
             qPrintable(stopReport()));
    QCOMPARE(m_window->banner()->entryLevel(key), lk::ui::MessageBanner::Level::Error);
    // Its wire is mended: it still turns, and reads say so: the red stays.
    QVERIFY(sim()->withBus([](lk::sim::SimBus &bus) { bus.faults().setSilenced(3, false); }));
    QTest::qWait(500);
    QVERIFY2(stopReport().contains(QStringLiteral("NO answer from drive(s) 3")),
             qPrintable(stopReport()));
    // Someone stops it (its own panel, a cut power): once a read shows it stopped, the red
    // goes and the report says so.
    QVERIFY(sim()->withBus([](lk::sim::SimBus &bus) {
        lk::protocol::Request off;
        off.command = Command::MotorOff;
        off.id = 3;
        bus.drive(3)->handle(off);
    }));
    QTRY_VERIFY2_WITH_TIMEOUT(stopReport().contains(QStringLiteral("have since read stopped")),
                              qPrintable(stopReport()), kWaitMs);
    QVERIFY(!stopReport().contains(QStringLiteral("NO answer")));
    QCOMPARE(m_window->banner()->entryLevel(key), lk::ui::MessageBanner::Level::Info);
}

void tst_MainWindowStop::stopWhileDisconnectedGoesOutOnReconnect()
{
    QVERIFY(selectDrive2());
    turnDrive2AndUnplug();
    if (QTest::currentTestFailed())
        return;
    const int offsBefore = sim()->requestCount(2, Command::MotorOff);
    QSignalSpy reports(m_window->emergencyStopControl(), &lk::ui::EmergencyStopControl::reported);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    QVERIFY2(stopReport().contains(QStringLiteral("NOTHING could be sent")) &&
                 stopReport().contains(QStringLiteral("as soon as this port is connected again")),
             qPrintable(stopReport()));
    // Drive 2 still turns (a V2.35 drive of the default bus reads Running at rest: count speed).
    double speed2 = 0;
    QVERIFY(sim()->withBus([&speed2](lk::sim::SimBus &bus) { speed2 = bus.drive(2)->speedDps(); }));
    QVERIFY2(speed2 > 100, qPrintable(QString::number(speed2)));
    // The link comes back: the stop goes out by itself and the report says when it was pressed.
    auto *box = m_window->findChild<QCheckBox *>(QStringLiteral("autoReconnect"));
    QTest::mouseClick(box, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(sim()->requestCount(2, Command::MotorOff) > offsBefore, kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 2, kWaitMs);
    QVERIFY2(stopReport().contains(QStringLiteral("while the bus was not connected; sent as "
                                                  "soon as it was back")) &&
                 stopReport().contains(QStringLiteral("acknowledged by drive(s) 1, 2, 3, 4.")),
             qPrintable(stopReport()));
    QTRY_VERIFY_WITH_TIMEOUT(allOff(), kWaitMs);
}

QTEST_MAIN(tst_MainWindowStop)
#include "tst_mainwindowstop.moc"
