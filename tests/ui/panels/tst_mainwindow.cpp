// The whole window against the in-process simulated bus: connect, scan, select, live values,
// plots, traffic and its export, emergency stop (checked on the simulator's side), unplug.

#include <drive/ControlView.h>
#include <drive/DriveInfoView.h>
#include <drive/EncoderView.h>
#include <drive/TuningView.h>
#include <main/AppSettings.h>
#include <main/BusController.h>
#include <main/CommandedMotion.h>
#include <main/DriveViews.h>
#include <main/EmergencyStopControl.h>
#include <main/LinkLossWatch.h>
#include <main/MainWindow.h>
#include <panels/BusModel.h>
#include <panels/BusPanel.h>
#include <panels/ConnectionBar.h>
#include <panels/DashboardPanel.h>
#include <panels/DriveTree.h>
#include <panels/EmergencyStopButton.h>
#include <panels/MessageBanner.h>
#include <panels/OverviewPanel.h>
#include <panels/Readout.h>
#include <panels/StatisticsView.h>
#include <panels/StatusSummary.h>
#include <panels/TrafficModel.h>
#include <panels/TrafficPanel.h>
#include <plot/PlotPanel.h>
#include <plot/TelemetryStore.h>

#include <drive/SetpointGenerator.h>
#include <protocol/RequestBuilder.h>
#include <protocol/StreamParser.h>
#include <sim/SimBus.h>
#include <sim/SimDrive.h>
#include <transport/SimBusHandle.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDialog>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>
#include <QtWidgets/QVBoxLayout>

#include <memory>

using lk::protocol::Command;
using lk::ui::ConnectionChoice;
using lk::ui::MainWindow;

namespace {
constexpr int kWaitMs = 20000; // generous: a loaded 2-core CI machine
const QVector<int> kSimIds{1, 2, 3, 4};

ConnectionChoice simulatorChoice()
{
    ConnectionChoice c;
    c.kind = ConnectionChoice::Kind::Simulator;
    c.autoReconnect = false;
    return c;
}
} // namespace

class tst_MainWindow : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void connectsToSimulator();
    void scanFindsSimulatedIds();
    void baudSweepKeepsOneBaud();
    void scanCanBeCancelled();
    void selectingADriveSelectsItEverywhere();
    void dashboardValuesUpdate();
    void plotReceivesPoints();
    void trafficFillsAndExportParses();
    void escapeSendsMotorOffToAllDrives();
    void escapeWorksFromAModalDialog();
    void escapeDuringAScanStopsEveryDrive_data();
    void escapeDuringAScanStopsEveryDrive();
    void escapeHaltsTheGeneratorFirst();
    void clearErrorsSendsClearErrors();
    void lowVoltageIsAWarningYouCannotMiss();
    void unplugShowsDisconnectedAndDisablesSending();
    void reconnectsWhenAllowed();
    void openFailureIsExplainedInABanner();

private:
    lk::ui::BusModel *model() const { return m_window->busModel(); }
    std::shared_ptr<lk::transport::SimBusHandle> sim() const
    {
        return m_window->controller()->simulator();
    }
    QVector<int> motorOffCounts() const;
    QString stopReport() const
    {
        return m_window->banner()->entryText(lk::ui::EmergencyStopControl::entryKey());
    }
    /// Command every simulated drive to turn at 360 dps (as the Control view would).
    void spinAll();
    bool allOff() const;
    int inState(lk::sim::SimDrive::RunState state) const;

    // Each test gets a window of its own, with settings of its own (init/cleanup), so that
    // each runs alone and in any order; it first brings about the bus it needs.
    /// Connected to the simulated bus, auto-reconnect off.
    bool connectToSimulator();
    /// Connected, every simulated drive found and polled.
    bool findAllDrives();
    /// Every drive found, drive 2 the current one.
    bool selectDrive2();
    /// Drive 2 turning when the link drops.
    void turnDrive2AndUnplug();

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<lk::ui::AppSettings> m_settings;
    std::unique_ptr<MainWindow> m_window;
};

void tst_MainWindow::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_settings = std::make_unique<lk::ui::AppSettings>(m_dir->filePath("lkstudio.ini"));
    m_window = std::make_unique<MainWindow>(m_settings.get());
    m_window->resize(1400, 900);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void tst_MainWindow::cleanup()
{
    m_window.reset();
    m_settings.reset();
    m_dir.reset();
}

QVector<int> tst_MainWindow::motorOffCounts() const
{
    QVector<int> counts;
    for (int id : kSimIds)
        counts << sim()->requestCount(id, Command::MotorOff);
    return counts;
}

void tst_MainWindow::spinAll()
{
    for (int id : kSimIds)
        m_window->controller()->session()->send(*lk::protocol::build::speed(id, 360).request);
    QTRY_VERIFY_WITH_TIMEOUT(inState(lk::sim::SimDrive::RunState::Running) == kSimIds.size() &&
                                 m_window->commandedMotion()->movingIds() == kSimIds,
                             kWaitMs);
}

int tst_MainWindow::inState(lk::sim::SimDrive::RunState state) const
{
    int n = 0;
    sim()->withBus([&n, state](lk::sim::SimBus &bus) {
        for (int id : kSimIds)
            n += bus.drive(id)->runState() == state ? 1 : 0;
    });
    return n;
}

bool tst_MainWindow::allOff() const
{
    return inState(lk::sim::SimDrive::RunState::Off) == kSimIds.size();
}

bool tst_MainWindow::connectToSimulator()
{
    if (model()->canSend() && model()->isSimulated())
        return true;
    m_window->connectTo(simulatorChoice());
    return QTest::qWaitFor([this] { return model()->canSend(); }, kWaitMs);
}

bool tst_MainWindow::findAllDrives()
{
    // Scanning on connect is on by default: the scan finds the four drives, then polls them.
    return connectToSimulator() &&
           QTest::qWaitFor([this] { return model()->ids() == kSimIds && model()->isPolling(); },
                           kWaitMs);
}

bool tst_MainWindow::selectDrive2()
{
    if (!findAllDrives())
        return false;
    if (model()->currentId() != 2)
        model()->setCurrentId(2);
    return true;
}

void tst_MainWindow::turnDrive2AndUnplug()
{
    m_window->controller()->session()->send(*lk::protocol::build::speed(2, 360).request);
    QTRY_COMPARE_WITH_TIMEOUT(m_window->commandedMotion()->movingIds(), QVector<int>{2}, kWaitMs);
    QVERIFY(sim()->requestDisconnect());
    QTRY_COMPARE_WITH_TIMEOUT(model()->connection().state,
                              lk::transport::Transport::State::Disconnected, kWaitMs);
}

void tst_MainWindow::connectsToSimulator()
{
    m_window->connectTo(simulatorChoice());
    QTRY_VERIFY_WITH_TIMEOUT(model()->canSend(), kWaitMs);
    QVERIFY(model()->isSimulated());
    QVERIFY(m_window->statusSummary()->isSimulatedBadgeShown());
    QVERIFY(m_window->statusSummary()->linkText().contains(QStringLiteral("Simulated bus")));
    QVERIFY(sim());
    QCOMPARE(m_settings->connection().kind, ConnectionChoice::Kind::Simulator); // remembered
}

void tst_MainWindow::scanFindsSimulatedIds()
{
    QVERIFY(connectToSimulator());
    // Scanning on connect is on by default; the scan of IDs 1..32 finds the four drives.
    QTRY_COMPARE_WITH_TIMEOUT(model()->ids(), kSimIds, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(model()->isPolling(), kWaitMs);
    const QList<lk::protocol::Series> series{lk::protocol::Series::MF, lk::protocol::Series::MG,
                                             lk::protocol::Series::MS, lk::protocol::Series::MH};
    for (int i = 0; i < kSimIds.size(); ++i) {
        const auto *d = model()->drive(kSimIds[i]);
        QVERIFY(d && d->model);
        QCOMPARE(d->series, std::optional(series[i]));
    }
    QCOMPARE(m_window->busPanel()->tree()->topLevelItem(0)->childCount(), 4);
    QCOMPARE(m_window->controller()->session()->series(3), std::optional(lk::protocol::Series::MS));

    // A second scan from the button, with a narrower range, finds the same drives again.
    auto *first = m_window->findChild<QSpinBox *>(QStringLiteral("scanFirstId"));
    auto *last = m_window->findChild<QSpinBox *>(QStringLiteral("scanLastId"));
    first->setValue(2);
    last->setValue(3);
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(model()->ids(), (QVector<int>{2, 3}), kWaitMs);
    QCOMPARE(m_settings->scanFirstId(), 2);
    first->setValue(1);
    last->setValue(32);
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(model()->ids(), kSimIds, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(model()->isPolling(), kWaitMs);
}

void tst_MainWindow::baudSweepKeepsOneBaud()
{
    QVERIFY(findAllDrives());
    // The simulated bus answers at every baud: a sweep finds each drive nine times, and the
    // list must still hold each drive once, at the baud the port stays at.
    auto *last = m_window->findChild<QSpinBox *>(QStringLiteral("scanLastId"));
    auto *sweep = m_window->findChild<QCheckBox *>(QStringLiteral("scanSweepBauds"));
    last->setValue(4);
    sweep->setChecked(true);
    QSignalSpy finished(m_window->controller()->session(), &lk::bus::BusSession::scanFinished);
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kWaitMs * 3);
    const auto summary = finished.at(0).at(0).value<lk::bus::ScanSummary>();
    QCOMPARE(summary.motors.size(), 4 * 10);
    QCOMPARE(model()->ids(), kSimIds);
    for (int id : kSimIds)
        QCOMPARE(model()->drive(id)->baud, summary.finalBaud);
    QCOMPARE(m_window->connectionBar()->choice().baud, summary.finalBaud);
    sweep->setChecked(false);
    last->setValue(32);
    QTRY_VERIFY_WITH_TIMEOUT(model()->isPolling(), kWaitMs);
}

void tst_MainWindow::scanCanBeCancelled()
{
    QVERIFY(findAllDrives());
    // A sweep over ten bauds takes seconds: long enough to cancel it half way.
    auto *sweep = m_window->findChild<QCheckBox *>(QStringLiteral("scanSweepBauds"));
    auto *cancel = m_window->findChild<QPushButton *>(QStringLiteral("scanCancelButton"));
    auto *progress = m_window->findChild<QProgressBar *>(QStringLiteral("scanProgress"));
    sweep->setChecked(true);
    QSignalSpy finished(m_window->controller()->session(), &lk::bus::BusSession::scanFinished);
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(progress->value() > 2, kWaitMs);
    QVERIFY(cancel->isEnabled());
    QCOMPARE(progress->maximum(), 32 * 10); // the progress covers every baud
    QTest::mouseClick(cancel, Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kWaitMs);
    QVERIFY(finished.at(0).at(0).value<lk::bus::ScanSummary>().cancelled);
    const QString status = m_window->findChild<QLabel *>(QStringLiteral("scanStatus"))->text();
    QVERIFY2(status.contains(QStringLiteral("cancelled")), qPrintable(status));
    QVERIFY(!cancel->isEnabled());
    sweep->setChecked(false);
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(model()->ids(), kSimIds, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(model()->isPolling(), kWaitMs);
}

void tst_MainWindow::selectingADriveSelectsItEverywhere()
{
    QVERIFY(findAllDrives());
    m_window->showView(QStringLiteral("dashboard"));
    auto *tree = m_window->busPanel()->tree();
    QTreeWidgetItem *item = tree->itemForId(2);
    QVERIFY(item);
    tree->scrollToItem(item);
    const QRect rect = tree->visualItemRect(item);
    // The ID column, which is always in view (the row may be wider than the dock).
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {},
                      QPoint(rect.left() + 4, rect.center().y()));
    QCOMPARE(model()->currentId(), 2);
    QCOMPARE(m_window->plots()->drives(), QVector<int>{2});
    QCOMPARE(m_window->overview()->view()->currentIndex().row(), 1);
    // The views that change a drive follow the selection too.
    QTRY_COMPARE(m_window->driveViews()->tuning()->driveId(), 2);
    QCOMPARE(m_window->driveViews()->control()->driveId(), 2);
    QCOMPARE(m_window->driveViews()->encoder()->driveId(), 2);
    QCOMPARE(m_window->driveViews()->info()->driveId(), 2);
    m_window->dashboard()->refresh();
    QVERIFY(m_window->dashboard()
                ->findChild<QLabel *>(QStringLiteral("driveIdentity"))
                ->text()
                .contains(QStringLiteral("Drive 2")));
}

void tst_MainWindow::dashboardValuesUpdate()
{
    QVERIFY(selectDrive2());
    auto *dash = m_window->dashboard();
    for (const char *name : {"temperature", "voltage", "torque", "speedDps", "encoder", "multiTurn",
                             "singleTurn", "phaseA"}) {
        auto *r = dash->readout(QLatin1String(name));
        QVERIFY2(r, name);
        QTRY_VERIFY2_WITH_TIMEOUT(!r->isStale(), name, kWaitMs);
    }
    // The values keep coming: the statistics show replies from the selected drive.
    auto *stats = dash->statisticsView();
    QTRY_VERIFY_WITH_TIMEOUT(stats->figure(QStringLiteral("rate"), 1).toDouble() > 0, kWaitMs);
    QCOMPARE(stats->figure(QStringLiteral("timeouts"), 1), QStringLiteral("0"));
    QTRY_VERIFY_WITH_TIMEOUT(model()->statistics().pollLimitPerSecond > 0, kWaitMs);
}

void tst_MainWindow::plotReceivesPoints()
{
    QVERIFY(selectDrive2());
    m_window->showView(QStringLiteral("plots"));
    auto *store = m_window->telemetryStore();
    const qsizetype before = store->count(2, lk::ui::TelemetryChannel::Speed);
    QTRY_VERIFY_WITH_TIMEOUT(store->count(2, lk::ui::TelemetryChannel::Speed) > before + 10,
                             kWaitMs);
    QVERIFY(store->count(3, lk::ui::TelemetryChannel::Torque) > 0);
    QCOMPARE(store->torqueIsPower(3), std::optional(true)); // MS reports power
    QTRY_VERIFY_WITH_TIMEOUT(m_window->plots()->redrawCount() > 0, kWaitMs);
}

void tst_MainWindow::trafficFillsAndExportParses()
{
    QVERIFY(findAllDrives());
    auto *traffic = m_window->traffic();
    QVERIFY(!traffic->wantsCapture());
    m_window->showView(QStringLiteral("traffic"));
    QVERIFY(traffic->wantsCapture());
    QTRY_VERIFY_WITH_TIMEOUT(traffic->trafficModel()->rowCount() > 50, kWaitMs);
    const auto *m = traffic->trafficModel();
    bool sawReply = false;
    for (int row = 0; row < m->rowCount() && !sawReply; ++row)
        sawReply = m->directionText(row) == QLatin1String("RX") && !m->fieldsText(row).isEmpty();
    QVERIFY(sawReply);

    const QString file = m_dir->filePath("traffic.txt");
    traffic->flush();
    QVERIFY(traffic->exportTo(file));
    QFile in(file);
    QVERIFY(in.open(QIODevice::ReadOnly | QIODevice::Text));
    QByteArray bytes;
    int lines = 0;
    while (!in.atEnd()) {
        QByteArray line = in.readLine();
        const int hash = line.indexOf('#');
        if (hash >= 0)
            line.truncate(hash);
        bytes += QByteArray::fromHex(line.simplified().replace(' ', QByteArray()));
        ++lines;
    }
    QVERIFY(lines > 50);
    int frames = 0;
    int faults = 0;
    lk::protocol::StreamParser parser;
    const auto sink = [&](const lk::protocol::ParseEvent &e) { (e.isFrame ? frames : faults)++; };
    parser.feed(bytes, sink);
    parser.finish(sink);
    QVERIFY(frames > 50);
    QCOMPARE(faults, 0); // the simulator injects no faults here

    m_window->showView(QStringLiteral("dashboard"));
    QVERIFY(!traffic->wantsCapture()); // capture runs only while the view is shown
}

void tst_MainWindow::escapeSendsMotorOffToAllDrives()
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

void tst_MainWindow::escapeWorksFromAModalDialog()
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

void tst_MainWindow::escapeDuringAScanStopsEveryDrive_data()
{
    QTest::addColumn<int>("delayMs");
    for (int ms : {0, 10, 30, 60, 100, 150, 200})
        QTest::newRow(qPrintable(QStringLiteral("Esc %1 ms after Scan").arg(ms))) << ms;
}

void tst_MainWindow::escapeDuringAScanStopsEveryDrive()
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
    // Leave the bus as the next test expects it: every drive found and polled.
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(model()->ids(), kSimIds, kWaitMs);
}

void tst_MainWindow::escapeHaltsTheGeneratorFirst()
{
    QVERIFY(findAllDrives());
    QTRY_VERIFY_WITH_TIMEOUT(model()->isPolling(), kWaitMs);
    model()->setCurrentId(1);
    auto *control = m_window->driveViews()->control();
    QTRY_COMPARE_WITH_TIMEOUT(control->driveId(), 1, kWaitMs);
    lk::ui::SetpointGenerator::Settings s;
    s.target = lk::ui::SetpointGenerator::Target::Speed;
    control->startGenerator(s);
    QVERIFY(control->generator()->isRunning());
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QVERIFY(!control->generator()->isRunning()); // before the bus has said anything
    QTRY_VERIFY_WITH_TIMEOUT(!stopReport().isEmpty(), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(allOff(), kWaitMs);
    model()->setCurrentId(2); // what the next tests expect
}

void tst_MainWindow::clearErrorsSendsClearErrors()
{
    QVERIFY(selectDrive2());
    const int before = sim()->requestCount(2, Command::ClearErrors);
    auto *button = m_window->findChild<QPushButton *>(QStringLiteral("clearErrorsButton"));
    QVERIFY(button->isEnabled());
    QTest::mouseClick(button, Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(sim()->requestCount(2, Command::ClearErrors), before + 1, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(m_window->banner()->text().contains(QStringLiteral("Drive 2")),
                             kWaitMs);
}

void tst_MainWindow::lowVoltageIsAWarningYouCannotMiss()
{
    QVERIFY(findAllDrives());
    // Drive 4 (MH, 12..24 V) loses its supply: the drive raises its low-voltage flag.
    QVERIFY(sim()->withBus([](lk::sim::SimBus &bus) { bus.drive(4)->setSupplyVoltage(9.0); }));
    auto *tree = m_window->busPanel()->tree();
    QTRY_COMPARE_WITH_TIMEOUT(tree->itemForId(4)->text(lk::ui::DriveTree::ErrorsCol),
                              QStringLiteral("Low voltage"), kWaitMs);
    QVERIFY(!tree->itemForId(4)->icon(lk::ui::DriveTree::ErrorsCol).isNull());
    QCOMPARE(tree->itemForId(1)->text(lk::ui::DriveTree::ErrorsCol), QStringLiteral("No errors"));
    auto *summary = m_window->overview()->findChild<QLabel *>(QStringLiteral("overviewSummary"));
    m_window->showView(QStringLiteral("overview"));
    QTRY_VERIFY_WITH_TIMEOUT(
        summary->text().contains(QStringLiteral("1 drive(s) with error flags")), kWaitMs);
    // Supply back: Clear Errors on drive 4 clears the flag.
    QVERIFY(sim()->withBus([](lk::sim::SimBus &bus) { bus.drive(4)->setSupplyVoltage(24.0); }));
    model()->setCurrentId(4);
    m_window->showView(QStringLiteral("dashboard"));
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("clearErrorsButton")),
                      Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(tree->itemForId(4)->text(lk::ui::DriveTree::ErrorsCol),
                              QStringLiteral("No errors"), kWaitMs);
    model()->setCurrentId(2);
}

void tst_MainWindow::unplugShowsDisconnectedAndDisablesSending()
{
    QVERIFY(selectDrive2());
    auto *dash = m_window->dashboard();
    dash->refresh();
    const QString temperature = dash->readout(QStringLiteral("temperature"))->value();
    turnDrive2AndUnplug();
    if (QTest::currentTestFailed())
        return;
    QVERIFY(!model()->canSend());
    QTRY_VERIFY_WITH_TIMEOUT(
        !m_window->findChild<QPushButton *>(QStringLiteral("clearErrorsButton"))->isEnabled(),
        kWaitMs);
    QVERIFY(!m_window->findChild<QPushButton *>(QStringLiteral("scanButton"))->isEnabled());
    QVERIFY(m_window->statusSummary()->linkText().startsWith(QStringLiteral("Disconnected")));
    QCOMPARE(m_window->banner()->level(), lk::ui::MessageBanner::Level::Warning);
    QVERIFY(m_window->banner()->isVisible());
    // What may still be moving is said, per drive, and stays.
    const QString warning = m_window->banner()->entryText(lk::ui::LinkLossWatch::entryKey(2));
    QVERIFY2(warning.contains(QStringLiteral("Drive 2 may still be moving")) &&
                 warning.contains(QStringLiteral("speed 360 dps")) &&
                 warning.contains(QStringLiteral("input-timeout protection")),
             qPrintable(warning));
    QCOMPARE(m_window->linkLossWatch()->warnedIds(), QVector<int>{2});
    QCOMPARE(m_window->driveViews()->control()->statusText(),
             QStringLiteral("Disconnected: nothing can be sent."));
    // Esc while disconnected: nothing can be sent, and the report says so and names drive 2.
    QSignalSpy reports(m_window->emergencyStopControl(), &lk::ui::EmergencyStopControl::reported);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    QVERIFY2(stopReport().contains(QStringLiteral("NOTHING could be sent")) &&
                 stopReport().contains(QStringLiteral("Drive 2 (speed 360 dps")) &&
                 !stopReport().contains(QStringLiteral("acknowledged")),
             qPrintable(stopReport()));
    QCOMPARE(m_window->banner()->entryLevel(lk::ui::EmergencyStopControl::entryKey()),
             lk::ui::MessageBanner::Level::Error);
    QVERIFY(m_window->banner()->hasEntry(lk::ui::LinkLossWatch::entryKey(2)));
    // Everything stays on screen, greyed once stale.
    QCOMPARE(model()->ids(), kSimIds);
    QCOMPARE(dash->readout(QStringLiteral("temperature"))->value(), temperature);
    QTRY_VERIFY_WITH_TIMEOUT(dash->readout(QStringLiteral("temperature"))->isStale(), kWaitMs);
    // Auto-reconnect is off in this test: it stays down.
    QTest::qWait(1500);
    QCOMPARE(model()->connection().state, lk::transport::Transport::State::Disconnected);
    QVERIFY(m_window->emergencyStopButton()->isEnabled()); // never disabled
}

void tst_MainWindow::reconnectsWhenAllowed()
{
    if (model()->connection().state != lk::transport::Transport::State::Disconnected) {
        QVERIFY(selectDrive2());
        turnDrive2AndUnplug();
        if (QTest::currentTestFailed())
            return;
    }
    auto *box = m_window->findChild<QCheckBox *>(QStringLiteral("autoReconnect"));
    QVERIFY(!box->isChecked());
    QTest::mouseClick(box, Qt::LeftButton);
    QVERIFY(box->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(model()->canSend(), kWaitMs);
    // The offline notice goes with the outage.
    QTRY_VERIFY_WITH_TIMEOUT(m_window->driveViews()->control()->statusText() !=
                                 QStringLiteral("Disconnected: nothing can be sent."),
                             kWaitMs);
    // Drive 2's warning stays until a state read shows it stopped: stop it, and it goes.
    QSignalSpy reports(m_window->emergencyStopControl(), &lk::ui::EmergencyStopControl::reported);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    QVERIFY2(stopReport().contains(QStringLiteral("acknowledged by")), qPrintable(stopReport()));
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->banner()->hasEntry(lk::ui::LinkLossWatch::entryKey(2)),
                             kWaitMs);
    QVERIFY(m_window->linkLossWatch()->warnedIds().isEmpty());
    // Polling resumes by itself: values come back to life.
    QTRY_VERIFY_WITH_TIMEOUT(
        !m_window->dashboard()->readout(QStringLiteral("temperature"))->isStale(), kWaitMs);
    QVERIFY(m_window->findChild<QPushButton *>(QStringLiteral("clearErrorsButton"))->isEnabled());
    QCOMPARE(model()->ids(), kSimIds);
}

void tst_MainWindow::openFailureIsExplainedInABanner()
{
    ConnectionChoice c;
    c.kind = ConnectionChoice::Kind::Serial;
    c.port = m_dir->filePath("no-such-adapter");
    c.autoReconnect = false;
    m_window->connectTo(c);
    // The message line (reports of earlier tests may stay below it until dismissed).
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->banner()->text().isEmpty(), kWaitMs);
    QVERIFY(m_window->banner()->isVisible());
    QCOMPARE(m_window->banner()->level(), lk::ui::MessageBanner::Level::Error);
    QVERIFY2(m_window->banner()->text().contains(QStringLiteral("does not exist")),
             qPrintable(m_window->banner()->text()));
    QVERIFY(!model()->canSend());
    QVERIFY(!m_window->statusSummary()->isSimulatedBadgeShown());
    QVERIFY(model()->ids().isEmpty());
}

QTEST_MAIN(tst_MainWindow)
#include "tst_mainwindow.moc"
