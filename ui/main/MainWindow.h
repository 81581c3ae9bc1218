#pragma once

#include <QtWidgets/QMainWindow>

class QDockWidget;
class QTabWidget;

namespace lk::ui {

class AppSettings;
class BusController;
class BusModel;
class BusPanel;
class CommandedMotion;
class ConnectionBar;
class DashboardPanel;
class DriveFaultWatch;
class EmergencyStopButton;
class EmergencyStopControl;
class LeaveGuard;
class LinkLossWatch;
class ListenOnlyControl;
class MessageBanner;
class OverviewPanel;
class PlotPanel;
class RecordingController;
class SpeedWatchReport;
class StatusSummary;
class TelemetryStore;
class TrafficPanel;
class DriveViews;
struct ConnectionChoice;

/// lkstudio's main window. It assembles the panels and wires them to the bus controller;
/// the panels do the work. Views are tabs (addView): Dashboard, Overview, Plots, Traffic,
/// with room for more (tuning, control, encoder, info).
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// `settings` is not owned and must outlive the window.
    explicit MainWindow(AppSettings *settings, QWidget *parent = nullptr);
    ~MainWindow() override;

    /// Add a central view as a tab; `name` is its object name (settings, --view).
    void addView(QWidget *view, const QString &name, const QString &title, const QIcon &icon);
    /// Show the view with this object name; false when there is none.
    bool showView(const QString &name);
    QStringList viewNames() const;
    /// The view shown on tab `index` (the tab itself is a scroll area around it).
    QWidget *viewAt(int index) const;
    QWidget *currentView() const;

    /// Connect as if the user picked `choice` in the connection bar; `remember` stores it as
    /// the last choice.
    void connectTo(const ConnectionChoice &choice, bool remember = true);

    BusController *controller() const { return m_controller; }
    BusModel *busModel() const { return m_model; }
    TelemetryStore *telemetryStore() const { return m_store; }
    ConnectionBar *connectionBar() const { return m_connectionBar; }
    BusPanel *busPanel() const { return m_busPanel; }
    DashboardPanel *dashboard() const { return m_dashboard; }
    OverviewPanel *overview() const { return m_overview; }
    PlotPanel *plots() const { return m_plots; }
    TrafficPanel *traffic() const { return m_traffic; }
    DriveViews *driveViews() const { return m_driveViews; }
    MessageBanner *banner() const { return m_banner; }
    StatusSummary *statusSummary() const { return m_status; }
    EmergencyStopButton *emergencyStopButton() const { return m_stop; }
    EmergencyStopControl *emergencyStopControl() const { return m_estop; }
    CommandedMotion *commandedMotion() const { return m_motion; }
    LinkLossWatch *linkLossWatch() const { return m_linkLoss; }
    SpeedWatchReport *speedWatchReport() const { return m_speedWatch; }
    LeaveGuard *leaveGuard() const { return m_leaveGuard; }
    DriveFaultWatch *faultWatch() const { return m_faultWatch; }
    ListenOnlyControl *listenOnlyControl() const { return m_listen; }
    QTabWidget *views() const { return m_views; }
    RecordingController *recording() const { return m_recording; }

public slots:
    /// The application's one emergency stop (EmergencyStopControl::stop): Esc, button, menu.
    void emergencyStop();
    /// Disconnect the bus (the connection bar, the Bus menu); drives commanded to move are
    /// stopped first, or left running at the user's choice (LeaveGuard).
    void disconnectBus();
    /// Close for a termination signal (SIGTERM, SIGINT): drives commanded to move are stopped
    /// without asking.
    void closeWithoutAsking();
    /// A logout is coming (QGuiApplication::commitDataRequest): asks as a quit does when
    /// `mayAsk`, else stops without asking. False: the user wants to stay (cancel it).
    bool prepareLogout(bool mayAsk);

protected:
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void buildPanels();
    void buildSafety();
    void buildToolbar();
    void buildMenus();
    void wirePanels();
    void wirePlots();
    void restoreSettings();
    void saveSettings();

    AppSettings *m_settings;
    BusModel *m_model = nullptr;
    BusController *m_controller = nullptr;
    TelemetryStore *m_store = nullptr;
    ConnectionBar *m_connectionBar = nullptr;
    EmergencyStopButton *m_stop = nullptr;
    MessageBanner *m_banner = nullptr;
    QTabWidget *m_views = nullptr;
    QDockWidget *m_busDock = nullptr;
    BusPanel *m_busPanel = nullptr;
    DashboardPanel *m_dashboard = nullptr;
    OverviewPanel *m_overview = nullptr;
    PlotPanel *m_plots = nullptr;
    TrafficPanel *m_traffic = nullptr;
    DriveViews *m_driveViews = nullptr;
    StatusSummary *m_status = nullptr;
    CommandedMotion *m_motion = nullptr;
    EmergencyStopControl *m_estop = nullptr;
    LinkLossWatch *m_linkLoss = nullptr;
    SpeedWatchReport *m_speedWatch = nullptr;
    LeaveGuard *m_leaveGuard = nullptr;
    DriveFaultWatch *m_faultWatch = nullptr;
    RecordingController *m_recording = nullptr;
    ListenOnlyControl *m_listen = nullptr;
    bool m_askBeforeClose = true; ///< false: a signal or a logout already decided
    bool m_stateRestored = false; ///< a saved layout was applied (else size the dock once)
    bool m_firstShow = true;
};

} // namespace lk::ui
