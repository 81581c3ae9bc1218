#pragma once

#include <panels/ConnectionBar.h>
#include <panels/ConnectionChoice.h>
#include <panels/MessageBanner.h>

#include <bus/BusSession.h>
#include <sim/SimBusSpec.h>
#include <transport/CanTransport.h>

#include <QtCore/QObject>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

class QTimer;

namespace lk::transport {
class SimBusHandle;
}

namespace lk::ui {

class BusModel;

/// Runs one bus for the GUI: opens the chosen link (serial port or the built-in simulator)
/// as its master or listen-only, scans and polls what it found, reconnects after an
/// unplug when allowed, takes a listened bus over when the user confirmed it, and sends the
/// operator's one-off commands (clear errors, emergency stop). It writes BusModel, which the panels
/// read; it never draws anything. The session's own signals (telemetry, traffic,
/// emergencyStopFinished, ...) are not repeated here: listeners connect to session().
class BusController : public QObject {
    Q_OBJECT
public:
    explicit BusController(BusModel *model, QObject *parent = nullptr);
    ~BusController() override;

    bus::BusSession *session() const { return m_session; }
    BusModel *model() const { return m_model; }

    /// The drives of the built-in simulated bus (before connecting to it).
    void setSimulatorSpec(const sim::SimBusSpec &spec);
    /// Faults the built-in simulated bus injects (FaultInjector syntax; empty: none).
    void setSimulatorFaults(const QString &spec) { m_simFaults = spec; }
    /// The simulated bus of the current connection; null when on a serial port.
    std::shared_ptr<transport::SimBusHandle> simulator() const { return m_sim; }
    /// Wraps each connection's transport factory: the black box records through one, tests
    /// count bytes through another. Every wrapper added applies, in the order added, each
    /// around the factory the ones before made (the last added is what the session uses).
    using FactoryWrapper =
        std::function<bus::TransportFactory(bus::TransportFactory, const ConnectionChoice &)>;
    void addFactoryWrapper(FactoryWrapper wrapper) { m_wrappers.push_back(std::move(wrapper)); }
    /// Scan by itself once each new connection is open (default on; never while listening).
    void setScanOnConnect(bool on) { m_scanOnConnect = on; }
    /// The port the connection is for, as settings key it: "/dev/ttyUSB0", "simulator", or
    /// "can:socketcan:can0" for a CAN interface.
    QString portKey() const;
    double pollRateHz() const { return m_pollRateHz; }
    /// Commands of the poll plan the dashboard needs (standard mix plus single-turn angle).
    static bus::PollPlan pollPlanFor(const QVector<int> &ids, double rateHz);
    /// How a CAN choice opens: plugin, interface and bit rate (set through Qt except on
    /// virtualcan, which has none).
    static transport::CanSettings canSettings(const ConnectionChoice &choice);
    /// Motor Off to `first` and every drive the bus knows, then to every other ID 1..32
    /// (see BusSession::emergencyStop); returns the stop's ticket. lkstudio's stop is
    /// EmergencyStopControl, which reports the outcome.
    quint64 emergencyStop(const QVector<int> &first);

public slots:
    void connectTo(const lk::ui::ConnectionChoice &choice);
    void disconnectBus();
    void setAutoReconnect(bool on);
    void onPortsChanged(const QList<lk::ui::PortEntry> &ports);
    void scan(const lk::bus::ScanOptions &options);
    void cancelScan();
    void clearErrors(int id);
    /// Reopen a listen-only link read-write as the bus master, then poll the drives seen.
    /// Only on the user's confirmed request (MainWindow asks): never on its own.
    void takeOver();
    /// The user says which series drive `id` is (no 0x12 reply told): decode by it.
    void setSeries(int id, protocol::Series series);
    /// The user's word on a drive no model read tells (CAN): series, generation, gear ratio
    /// (bus::BusSession::setDriveIdentity); no reply overrides it.
    void setDriveIdentity(const lk::bus::DriveIdentity &identity);
    void setPollRate(double hz);
    void setTrafficCapture(bool on);

signals:
    void message(lk::ui::MessageBanner::Level level, const QString &text);
    /// A new connection came up: a good moment to scan (when scanning on connect).
    void readyToScan();
    void scanStarted();
    /// The bus limit of the poll plan, from the bus thread's statistics (~2 Hz, on change).
    void busLimitChanged(double transactionsPerSecond, double cycleLimitHz);

private:
    void wireSession();
    void onConnectionChanged(const bus::ConnectionStatus &status);
    void onError(const transport::TransportError &error);
    /// A CAN link's bus condition or refused frame: a state and a warning, not a failure.
    /// False when `error` is none of those (an open failure).
    bool onCanCondition(const transport::TransportError &error);
    QString linkName() const; ///< "/dev/ttyUSB0", "socketcan:can0", "the simulator"
    void onScanFinished(const bus::ScanSummary &summary);
    void onCleared(const bus::RequestResult &result); ///< the end of a clearErrors()
    void onTookOver(); ///< the link that listened is the bus master now
    void keepDrivesAt(const bus::ScanSummary &summary);
    void startPolling();
    void tryReconnect();
    bool portPresent() const;

    BusModel *m_model;
    bus::BusSession *m_session;
    QTimer *m_reconnectTimer;
    ConnectionChoice m_choice;
    sim::SimBusSpec m_simSpec;
    QString m_simFaults;
    std::shared_ptr<transport::SimBusHandle> m_sim;
    double m_pollRateHz = 0;
    bool m_scanOnConnect = true;
    bool m_awaitingFirstOpen = false;
    bool m_wasOpen = false;
    bool m_reconnecting = false;
    bool m_traffic = false;
    std::vector<FactoryWrapper> m_wrappers;
    bool m_wasListening = false;                  ///< the last open status listened only
    std::pair<double, double> m_busLimit{-1, -1}; ///< last busLimitChanged (tx/s, rounds/s)
};

} // namespace lk::ui
