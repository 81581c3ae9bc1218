// The whole window against the in-process simulated bus: connect, scan, select, live values,
// plots, traffic and its export, clearing errors. Emergency stop: tst_mainwindowstop; link loss
// and reconnect: tst_mainwindowlink.

#include "MainWindowFixture.h"

#include <drive/ControlView.h>
#include <drive/DriveInfoView.h>
#include <drive/EncoderView.h>
#include <drive/TuningView.h>
#include <main/DriveViews.h>
#include <main/MainWindow.h>
#include <panels/BusPanel.h>
#include <panels/ConnectionBar.h>
#include <panels/DashboardPanel.h>
#include <panels/DriveTree.h>
#include <panels/OverviewPanel.h>
#include <panels/Readout.h>
#include <panels/StatisticsView.h>
#include <panels/StatusSummary.h>
#include <panels/TrafficModel.h>
#include <panels/TrafficPanel.h>
#include <plot/PlotPanel.h>
#include <plot/TelemetryStore.h>
#include <protocol/StreamParser.h>
#include <sim/SimBus.h>

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTableView>

using lk::protocol::Command;
using lk::ui::ConnectionChoice;
using namespace lk::uitest;

class tst_MainWindow : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init() { QVERIFY(openWindow()); }
    void cleanup() { closeWindow(); }
    void connectsToSimulator();
    void scanFindsSimulatedIds();
    void baudSweepKeepsOneBaud();
    void scanCanBeCancelled();
    void selectingADriveSelectsItEverywhere();
    void dashboardValuesUpdate();
    void plotReceivesPoints();
    void trafficFillsAndExportParses();
    void clearErrorsSendsClearErrors();
    void lowVoltageIsAWarningYouCannotMiss();
};

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

QTEST_MAIN(tst_MainWindow)
#include "tst_mainwindow.moc"
