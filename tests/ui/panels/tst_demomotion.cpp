// lkstudio's demo motion on the built-in bus: a first run shows moving drives as soon as the
// scan has found them, and the demo gives the drives back as soon as the user commands one.
// Quitting or disconnecting while it runs stops its drives without asking (LeaveHooks).

#include "MainWindowFixture.h"

#include <DemoMotion.h>
#include <LeaveHooks.h>
#include <main/LeaveGuard.h>
#include <main/StartupOptions.h>

#include <QtWidgets/QAbstractButton>
#include <QtWidgets/QMessageBox>

using namespace lk::uitest;

namespace {
constexpr int kNever = 3600 * 1000; // a step period no test waits out

double simSpeed(const std::shared_ptr<lk::transport::SimBusHandle> &sim, int id)
{
    double speed = 0;
    sim->withBus([&](lk::sim::SimBus &bus) { speed = bus.drive(id)->speedDps(); });
    return speed;
}
} // namespace

class tst_DemoMotion : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init() { QVERIFY(openWindow()); }
    void cleanup() { closeWindow(); }
    void startsOnItsOwnOnlyOnTheDefaultBus_data();
    void startsOnItsOwnOnlyOnTheDefaultBus();
    void drivesMoveAsSoonAsTheyAreFound();
    void aCommandTakesOver();
    void emergencyStopEndsIt();
    void leavingStopsTheDemoWithoutAsking_data();
    void leavingStopsTheDemoWithoutAsking();
};

void tst_DemoMotion::startsOnItsOwnOnlyOnTheDefaultBus_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<bool>("simulator"); // the connection lkstudio opens
    QTest::addColumn<bool>("moves");
    QTest::newRow("first run") << QStringList{} << true << true;
    QTest::newRow("a port") << QStringList{} << false << false;
    QTest::newRow("--port") << QStringList{"--port", "/dev/ttyUSB0"} << false << false;
    QTest::newRow("--sim chosen drives") << QStringList{"--sim", "1:MF"} << true << false;
    QTest::newRow("--sim --sim-motion")
        << QStringList{"--sim", "1:MF", "--sim-motion"} << true << true;
}

void tst_DemoMotion::startsOnItsOwnOnlyOnTheDefaultBus()
{
    QFETCH(QStringList, arguments);
    QFETCH(bool, simulator);
    QFETCH(bool, moves);
    QString error;
    const auto options =
        lk::ui::StartupOptions::parse(QStringList{QStringLiteral("lkstudio")} + arguments, &error);
    QVERIFY2(options, qPrintable(error));
    lk::ui::ConnectionChoice choice;
    choice.kind = simulator ? lk::ui::ConnectionChoice::Kind::Simulator
                            : lk::ui::ConnectionChoice::Kind::Serial;
    QCOMPARE(DemoMotion::startsOnItsOwn(*options, choice), moves);
}

void tst_DemoMotion::drivesMoveAsSoonAsTheyAreFound()
{
    DemoMotion demo(m_window->controller(), kNever); // only the first steps can move them
    demo.start();
    QVERIFY(findAllDrives());
    QTRY_VERIFY_WITH_TIMEOUT(inState(lk::sim::SimDrive::RunState::Running) == kSimIds.size(),
                             kWaitMs);
    for (int id : kSimIds)
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(simSpeed(sim(), id)) > 10, kWaitMs);
    QVERIFY(demo.isRunning());
}

void tst_DemoMotion::aCommandTakesOver()
{
    DemoMotion demo(m_window->controller(), 200);
    QSignalSpy stopped(&demo, &DemoMotion::stopped);
    demo.start();
    QVERIFY(findAllDrives());
    for (int id : kSimIds)
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(simSpeed(sim(), id)) > 10, kWaitMs);
    // The user sets drive 2 going: the demo stops and stands the others still.
    m_window->controller()->session()->send(*lk::protocol::build::speed(2, 90).request);
    // At once, not when the command's reply is in: a step of the demo due meanwhile would
    // otherwise be queued behind the user's command and overrule it.
    QCOMPARE(stopped.count(), 1);
    QVERIFY(!demo.isRunning());
    for (int id : {1, 3, 4})
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(simSpeed(sim(), id)) < 1, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(std::abs(simSpeed(sim(), 2) - 90) < 5, kWaitMs);
    // Nothing more from the demo: drive 2 keeps what the user said, several periods on.
    const int speeds = sim()->requestCount(2, lk::protocol::Command::Speed);
    QTest::qWait(600);
    QCOMPARE(sim()->requestCount(2, lk::protocol::Command::Speed), speeds);
    QVERIFY(std::abs(simSpeed(sim(), 2) - 90) < 5);
}

void tst_DemoMotion::emergencyStopEndsIt()
{
    DemoMotion demo(m_window->controller(), kNever);
    QSignalSpy stopped(&demo, &DemoMotion::stopped);
    demo.start();
    QVERIFY(findAllDrives());
    QTRY_VERIFY_WITH_TIMEOUT(inState(lk::sim::SimDrive::RunState::Running) == kSimIds.size(),
                             kWaitMs);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(stopped.count(), 1, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(allOff(), kWaitMs);
}

void tst_DemoMotion::leavingStopsTheDemoWithoutAsking_data()
{
    QTest::addColumn<bool>("quit"); // else disconnect
    QTest::newRow("quit") << true;
    QTest::newRow("disconnect") << false;
}

void tst_DemoMotion::leavingStopsTheDemoWithoutAsking()
{
    QFETCH(bool, quit);
    DemoMotion demo(m_window->controller(), kNever);
    LeaveHooks::followDemo(*m_window, demo);
    demo.start();
    QVERIFY(findAllDrives());
    QTRY_VERIFY_WITH_TIMEOUT(inState(lk::sim::SimDrive::RunState::Running) == kSimIds.size(),
                             kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(m_window->commandedMotion()->movingIds(), kSimIds, kWaitMs);
    // A question would block in its own event loop: answer "Cancel" and remember it was asked.
    bool asked = false;
    QTimer answer;
    connect(&answer, &QTimer::timeout, this, [&asked] {
        if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
            asked = true;
            box->button(QMessageBox::Cancel)->click();
        }
    });
    answer.start(20);
    // The drives' states when the stop has been acknowledged, before the bus is let go of.
    int offWhenReported = -1;
    connect(m_window->leaveGuard(), &lk::ui::LeaveGuard::stopReported, this,
            [&] { offWhenReported = inState(lk::sim::SimDrive::RunState::Off); });
    if (quit)
        QVERIFY(m_window->close());
    else
        m_window->disconnectBus();
    QVERIFY(!asked);
    QCOMPARE(offWhenReported, int(kSimIds.size())); // before close() or disconnectBus() returned
    QVERIFY2(m_window->leaveGuard()->lastReport().contains(
                 QStringLiteral("The demo's simulated drives were stopped.")),
             qPrintable(m_window->leaveGuard()->lastReport()));
    QVERIFY(!demo.isRunning());
}

QTEST_MAIN(tst_DemoMotion)
#include "tst_demomotion.moc"
