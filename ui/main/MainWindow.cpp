#include "MainWindow.h"

#include "AppSettings.h"
#include "BusController.h"
#include "CommandedMotion.h"
#include "DriveFaultWatch.h"
#include "DriveViews.h"
#include "EmergencyStopControl.h"
#include "HelpMenu.h"
#include "LanguageMenu.h"
#include "LeaveGuard.h"
#include "LinkLossWatch.h"
#include "ListenOnlyControl.h"
#include "SpeedWatchReport.h"

#include <drive/ControlView.h>
#include <drive/DriveInfoView.h>
#include <drive/EncoderView.h>
#include <drive/TuningView.h>
#include <fleet/ParametersView.h>
#include <panels/BusModel.h>
#include <panels/BusPanel.h>
#include <panels/ConnectionBar.h>
#include <panels/DashboardPanel.h>
#include <panels/EmergencyStopButton.h>
#include <panels/MessageBanner.h>
#include <panels/OverviewPanel.h>
#include <panels/ScanControls.h>
#include <panels/StatusSummary.h>
#include <panels/ThemedIcon.h>
#include <panels/TrafficPanel.h>
#include <plot/PlotPanel.h>
#include <plot/TelemetryStore.h>
#include <recording/RecordingController.h>
#include <recording/RecordingReplay.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QTimer>
#include <QtGui/QCloseEvent>
#include <QtGui/QIcon>
#include <QtGui/QScreen>
#include <QtWidgets/QApplication>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QMenuBar>
#include <QtWidgets/QScrollArea>
#include <QtWidgets/QStatusBar>
#include <QtWidgets/QTabWidget>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
const QSize kDefaultSize(1400, 900);
constexpr int kDockShare = 33;       // the bus dock takes at most this share of the width at first
constexpr int kTrafficRows = 300000; // the black box's ring at a busy 115200-baud poll: ~4 min
} // namespace

MainWindow::MainWindow(AppSettings *settings, QWidget *parent)
    : QMainWindow(parent), m_settings(settings)
{
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(tr("LK Servo Studio"));
    setWindowIcon(QIcon(QStringLiteral(":/icons/lkstudio.svg")));
    m_model = new BusModel(this);
    m_controller = new BusController(m_model, this);
    m_store = new TelemetryStore(this);
    m_motion = new CommandedMotion(this);
    m_motion->setSession(m_controller->session());
    buildPanels();
    buildSafety();
    m_recording = new RecordingController({m_controller, m_leaveGuard, m_store, m_traffic, m_banner,
                                           this, m_settings, m_dashboard->statisticsView()},
                                          this);
    buildToolbar();
    buildMenus();
    wirePanels();
    wirePlots();
    restoreSettings();
    // Settings damage is told once, after the start-up connection has used the banner.
    QTimer::singleShot(0, this, [this] {
        if (!m_settings->damageReport().isEmpty())
            m_banner->showMessage(MessageBanner::Level::Warning, m_settings->damageReport());
    });
}

MainWindow::~MainWindow()
{
    // Join the bus thread while every panel still exists: its last signals reach them safely.
    m_controller->disconnectBus();
    // A replay's Load all worker too: what it decoded goes nowhere, the views are going.
    m_recording->replay()->abandonLoading();
}

void MainWindow::buildPanels()
{
    auto *central = new QWidget(this);
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(4, 4, 4, 4);
    m_banner = new MessageBanner(central);
    m_views = new QTabWidget(central);
    m_views->setObjectName(QStringLiteral("views"));
    m_views->setDocumentMode(true);
    layout->addWidget(m_banner);
    layout->addWidget(m_views, 1);
    setCentralWidget(central);

    m_dashboard = new DashboardPanel(m_model, m_views);
    m_overview = new OverviewPanel(m_model, m_views);
    m_plots = new PlotPanel(m_store, m_views);
    m_traffic = new TrafficPanel(m_model, m_views, kTrafficRows);
    addView(m_dashboard, QStringLiteral("dashboard"), tr("Dashboard"),
            ThemedIcon::get(QStringLiteral(":/icons/dashboard.svg")));
    addView(m_overview, QStringLiteral("overview"), tr("Overview"),
            ThemedIcon::get(QStringLiteral(":/icons/overview.svg")));
    addView(m_plots, QStringLiteral("plots"), tr("Plots"),
            ThemedIcon::get(QStringLiteral(":/icons/plot.svg")));
    addView(m_traffic, QStringLiteral("traffic"), tr("Traffic"),
            ThemedIcon::get(QStringLiteral(":/icons/traffic.svg")));
    m_driveViews = new DriveViews(m_model, m_controller, m_store, m_settings->file(), m_views);
    m_dashboard->setEncoderResolutions(m_driveViews->encoderResolutions());
    addView(m_driveViews->tuning(), QStringLiteral("tuning"), tr("Tuning"),
            ThemedIcon::get(QStringLiteral(":/icons/motor.svg")));
    addView(m_driveViews->control(), QStringLiteral("control"), tr("Control"),
            ThemedIcon::get(QStringLiteral(":/icons/connect.svg")));
    addView(m_driveViews->encoder(), QStringLiteral("encoder"), tr("Encoder"),
            ThemedIcon::get(QStringLiteral(":/icons/port.svg")));
    addView(m_driveViews->info(), QStringLiteral("info"), tr("Drive info"),
            ThemedIcon::get(QStringLiteral(":/icons/info.svg")));
    // Every drive's parameters side by side; backup, restore and clone (ui/fleet).
    auto *parameters = new ParametersView(m_views);
    parameters->setSession(m_controller->session());
    addView(parameters, QStringLiteral("parameters"), tr("Parameters"),
            ThemedIcon::get(QStringLiteral(":/icons/export.svg")));
    connect(m_model, &BusModel::connectionChanged, parameters,
            [this, parameters] { parameters->setConnected(m_model->canSend()); });
    connect(m_model, &BusModel::drivesChanged, parameters,
            [this, parameters] { parameters->setDrives(m_model->ids()); });

    m_busPanel = new BusPanel(m_model, this);
    m_busDock = new QDockWidget(tr("Bus"), this);
    m_busDock->setObjectName(QStringLiteral("busDock"));
    m_busDock->setWidget(m_busPanel);
    m_busDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(Qt::LeftDockWidgetArea, m_busDock);

    m_status = new StatusSummary(m_model, this);
    statusBar()->addPermanentWidget(m_status, 1);
}

void MainWindow::buildSafety()
{
    m_estop = new EmergencyStopControl(m_controller, m_motion, m_banner, this);
    // Local motion sources first, so that no generator tick follows the Motor Off frames.
    connect(m_estop, &EmergencyStopControl::halting, m_driveViews, &DriveViews::haltLocalMotion);
    connect(m_driveViews, &DriveViews::emergencyStopRequested, m_estop,
            &EmergencyStopControl::stop);
    m_linkLoss = new LinkLossWatch(m_model, m_motion, m_banner, this);
    connect(m_controller->session(), &bus::BusSession::telemetryReceived, m_linkLoss,
            &LinkLossWatch::onTelemetry);
    m_leaveGuard = new LeaveGuard(m_controller, m_motion, this, this);
    connect(m_leaveGuard, &LeaveGuard::stopReported, this, [this](const QString &text, bool all) {
        m_banner->showMessage(all ? MessageBanner::Level::Info : MessageBanner::Level::Warning,
                              text);
    });
    // A new command after a logout was decided (and then cancelled) asks again at the end.
    connect(m_motion, &CommandedMotion::changed, this, [this] { m_askBeforeClose = true; });
    m_speedWatch = new SpeedWatchReport(m_controller->session(), m_model, m_banner, this);
    connect(m_speedWatch, &SpeedWatchReport::driveStopped, m_driveViews->control(),
            &ControlView::showDriveStopped);
    // After BusModel has merged the batch (BusController connected it first).
    m_faultWatch = new DriveFaultWatch(m_model, m_motion, m_banner, this);
    connect(m_controller->session(), &bus::BusSession::telemetryReceived, m_faultWatch,
            &DriveFaultWatch::onTelemetry);
    connect(m_faultWatch, &DriveFaultWatch::driveStopped, m_driveViews->control(),
            &ControlView::showDriveStopped);
    connect(m_model, &BusModel::connectionChanged, this, [this] {
        if (!m_model->connection().isOpen())
            m_store->breakLines(); // the plots never draw a line across the outage
    });
}

void MainWindow::buildToolbar()
{
    auto *bar = new QToolBar(tr("Connection"), this);
    bar->setObjectName(QStringLiteral("connectionToolbar"));
    bar->setMovable(false);
    bar->setFloatable(false);
    bar->toggleViewAction()->setEnabled(false); // the emergency stop must never be hidden
    // The bar and the stop button are one toolbar item: a toolbar too narrow for its items
    // hides the last ones behind an arrow, and on CAN (plugin, interface, bit rate) at 1366
    // pixels the stop button was the one hidden. A toolbar never hides its first item; when
    // space is short the connection state gives up its width (ElidedLabel), never the stop.
    auto *row = new QWidget(bar);
    auto *rowLayout = new QHBoxLayout(row);
    rowLayout->setContentsMargins(0, 0, 0, 0);
    m_connectionBar = new ConnectionBar(row);
    m_stop = new EmergencyStopButton(row);
    rowLayout->addWidget(m_connectionBar, 1);
    rowLayout->addWidget(m_stop);
    bar->addWidget(row);
    addToolBar(Qt::TopToolBarArea, bar);

    // Esc anywhere (dialogs and pop-ups included) is the stop control's own application
    // filter; the button and the menu call the same stop.
    connect(m_stop, &QPushButton::clicked, m_estop, &EmergencyStopControl::stop);
    m_listen =
        new ListenOnlyControl(m_controller, m_settings, m_busPanel->seriesChooser(), m_stop, this);
    m_listen->setDriveStore(m_driveViews->settingsStore()); // gear ratios: the Encoder view's
    connect(m_connectionBar, &ConnectionBar::takeOverRequested, m_listen,
            &ListenOnlyControl::requestTakeOver);
}

void MainWindow::buildMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(ThemedIcon::get(QStringLiteral(":/icons/export.svg")),
                    tr("Export &traffic log\u2026"), m_traffic, &TrafficPanel::exportWithDialog);
    m_recording->addFileActions(file);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu *busMenu = menuBar()->addMenu(tr("&Bus"));
    busMenu->addAction(ThemedIcon::get(QStringLiteral(":/icons/scan.svg")), tr("&Scan"),
                       QKeySequence(Qt::Key_F5), m_busPanel->scanControls(),
                       &ScanControls::startScan);
    busMenu->addAction(tr("&Disconnect"), this, &MainWindow::disconnectBus);
    QAction *takeOver = busMenu->addAction(tr("&Take over the bus\u2026"), m_listen,
                                           &ListenOnlyControl::requestTakeOver);
    takeOver->setEnabled(false);
    connect(m_model, &BusModel::connectionChanged, takeOver,
            [this, takeOver] { takeOver->setEnabled(m_model->isListening()); });
    busMenu->addSeparator();
    busMenu->addAction(ThemedIcon::get(QStringLiteral(":/icons/stop.svg")),
                       tr("&Emergency stop (Esc)"), m_estop, &EmergencyStopControl::stop);

    QMenu *view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_busDock->toggleViewAction());
    for (int i = 0; i < m_views->count(); ++i) {
        QWidget *w = m_views->widget(i); // the page: the view in its scroll area
        auto *a = view->addAction(m_views->tabIcon(i), m_views->tabText(i),
                                  [this, w] { m_views->setCurrentWidget(w); });
        a->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_1 + i)));
    }
    view->addSeparator();
    view->addMenu(new LanguageMenu(m_settings, this));

    menuBar()->addMenu(new HelpMenu(m_model, m_connectionBar, this));
}

void MainWindow::wirePanels()
{
    auto *bar = m_connectionBar;
    auto *scan = m_busPanel->scanControls();
    connect(bar, &ConnectionBar::connectRequested, this,
            [this](const ConnectionChoice &c) { connectTo(c); });
    connect(bar, &ConnectionBar::disconnectRequested, this, &MainWindow::disconnectBus);
    connect(bar, &ConnectionBar::portsChanged, m_controller, &BusController::onPortsChanged);
    connect(m_controller->session(), &bus::BusSession::errorOccurred, bar,
            &ConnectionBar::showPortError);
    connect(bar, &ConnectionBar::choiceChanged, this, [this](const ConnectionChoice &c) {
        m_controller->setAutoReconnect(c.autoReconnect);
        m_settings->setConnection(c);
    });
    connect(m_model, &BusModel::connectionChanged, this,
            [this] { m_connectionBar->setConnectionStatus(m_model->connection()); });
    connect(m_model, &BusModel::canConditionChanged, this, [this] {
        m_connectionBar->setCanCondition(m_model->canCondition(), m_model->canConditionMessage());
    });

    connect(scan, &ScanControls::scanRequested, m_controller, &BusController::scan);
    connect(scan, &ScanControls::cancelRequested, m_controller, &BusController::cancelScan);
    connect(scan, &ScanControls::rangeChanged, this, [this](int first, int last, bool sweep) {
        m_settings->setScanRange(first, last, sweep);
    });
    connect(m_controller, &BusController::scanStarted, scan, &ScanControls::onScanStarted);
    connect(m_controller->session(), &bus::BusSession::scanProgress, scan,
            &ScanControls::onScanProgress);
    connect(m_controller->session(), &bus::BusSession::scanFinished, scan,
            &ScanControls::onScanFinished);
    connect(m_controller, &BusController::readyToScan, scan, &ScanControls::startScan);

    connect(m_dashboard, &DashboardPanel::clearErrorsRequested, m_controller,
            &BusController::clearErrors);
    // The Traffic view shows the black box's ring (RecordingController), not the session's
    // own capture: traffic is kept while the view is closed.
    connect(m_controller, &BusController::message, m_banner, &MessageBanner::showMessage);
    connect(m_views, &QTabWidget::currentChanged, this, [this] {
        if (QWidget *w = viewAt(m_views->currentIndex()))
            m_settings->setCurrentView(w->objectName());
    });
}

void MainWindow::wirePlots()
{
    connect(m_controller->session(), &bus::BusSession::telemetryReceived, m_store,
            &TelemetryStore::append);
    connect(m_plots, &PlotPanel::pollRateRequested, this, [this](double hz) {
        m_controller->setPollRate(hz);
        m_settings->setPollRateHz(hz);
    });
    connect(m_controller, &BusController::busLimitChanged, m_plots, &PlotPanel::setBusLimit);
    auto syncDrives = [this] {
        for (int id : m_model->ids()) {
            if (const DriveRecord *d = m_model->drive(id); d && d->series)
                m_plots->setDriveSeries(id, *d->series);
        }
        m_plots->setDrives(m_model->selectedIds());
    };
    connect(m_model, &BusModel::drivesChanged, this, syncDrives);
    connect(m_model, &BusModel::selectionChanged, this, syncDrives);
}

void MainWindow::addView(QWidget *view, const QString &name, const QString &title,
                         const QIcon &icon)
{
    view->setObjectName(name);
    // Each view scrolls when the window is smaller than the view's minimum: a 1366x768
    // screen (or a large font) must not push the window past the screen.
    auto *page = new QScrollArea(m_views);
    page->setObjectName(name + QStringLiteral("Page"));
    page->setFrameShape(QFrame::NoFrame);
    page->setWidgetResizable(true);
    page->setWidget(view);
    m_views->addTab(page, icon, title);
}

QWidget *MainWindow::currentView() const
{
    return viewAt(m_views->currentIndex());
}

QWidget *MainWindow::viewAt(int index) const
{
    auto *page = qobject_cast<QScrollArea *>(m_views->widget(index));
    return page ? page->widget() : nullptr;
}

bool MainWindow::showView(const QString &name)
{
    for (int i = 0; i < m_views->count(); ++i) {
        if (viewAt(i)->objectName() == name) {
            m_views->setCurrentIndex(i);
            return true;
        }
    }
    return false;
}

QStringList MainWindow::viewNames() const
{
    QStringList names;
    for (int i = 0; i < m_views->count(); ++i)
        names << viewAt(i)->objectName();
    return names;
}

void MainWindow::connectTo(const ConnectionChoice &choice, bool remember)
{
    // Another bus replaces this one: what was set moving here is stopped first.
    if (m_controller->session()->isRunning() &&
        !m_leaveGuard->prepare(LeaveGuard::Leaving::Disconnect))
        return;
    m_banner->clearMessage();
    {
        // Showing the choice must not store it (setChoice toggles widgets that report).
        const QSignalBlocker block(m_connectionBar);
        m_connectionBar->setChoice(choice);
    }
    if (remember)
        m_settings->setConnection(choice);
    m_store->clear();
    m_controller->connectTo(choice);
}

void MainWindow::emergencyStop()
{
    m_estop->stop();
}

void MainWindow::disconnectBus()
{
    if (m_leaveGuard->prepare(LeaveGuard::Leaving::Disconnect))
        m_controller->disconnectBus();
}

void MainWindow::closeWithoutAsking()
{
    if (m_askBeforeClose && !m_leaveGuard->prepare(LeaveGuard::Leaving::Signal))
        return; // never: a signal does not ask
    m_askBeforeClose = false;
    close();
}

bool MainWindow::prepareLogout(bool mayAsk)
{
    if (!m_leaveGuard->prepare(mayAsk ? LeaveGuard::Leaving::Quit : LeaveGuard::Leaving::Signal))
        return false;
    m_askBeforeClose = false; // the window closes next: decided already
    return true;
}

void MainWindow::restoreSettings()
{
    m_connectionBar->setChoice(m_settings->connection());
    m_controller->setAutoReconnect(m_settings->connection().autoReconnect);
    m_busPanel->scanControls()->setRange(m_settings->scanFirstId(), m_settings->scanLastId(),
                                         m_settings->scanSweepBauds());
    const double rate = m_settings->pollRateHz();
    m_controller->setPollRate(rate);
    m_plots->setPollRate(rate);
    if (!restoreGeometry(m_settings->windowGeometry())) {
        // Never larger than the screen's free area: a 1366x768 laptop has no 900 rows to give.
        QSize size = kDefaultSize;
        if (const QScreen *s = screen())
            size = size.boundedTo(s->availableGeometry().size());
        resize(size);
    }
    m_stateRestored = restoreState(m_settings->windowState());
    showView(m_settings->currentView());
}

void MainWindow::saveSettings()
{
    m_settings->setWindow(saveGeometry(), saveState());
    m_settings->sync();
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    if (m_firstShow && !m_stateRestored) {
        // First run: docks can be sized only once the window is laid out. On a small screen
        // (1366 wide) the views need the room more than the drive list does.
        QTimer::singleShot(0, this, [this] {
            const int wanted = qMin(m_busPanel->sizeHint().width(), width() * kDockShare / 100);
            resizeDocks({m_busDock}, {wanted}, Qt::Horizontal);
        });
    }
    m_firstShow = false;
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (m_askBeforeClose && !m_leaveGuard->prepare(LeaveGuard::Leaving::Quit)) {
        event->ignore();
        return;
    }
    saveSettings();
    m_controller->disconnectBus();
    event->accept();
}

} // namespace lk::ui
