#pragma once

#include "DriveRecord.h"

#include <bus/BusStatistics.h>
#include <bus/ConnectionStatus.h>
#include <bus/KnownMotor.h>
#include <bus/ListenStatistics.h>
#include <bus/PollPlan.h>
#include <bus/ScanTypes.h>
#include <bus/TelemetrySample.h>
#include <protocol/Series.h>
#include <transport/CanTransport.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QMap>
#include <QtCore/QObject>

namespace lk::ui {

/// The GUI's mirror of one bus: connection, drives found, their latest values, statistics
/// and the selected drive. Panels read it and redraw on their own timers; only the bus
/// controller writes it. Selecting a drive here selects it in every view.
class BusModel : public QObject {
    Q_OBJECT
public:
    explicit BusModel(QObject *parent = nullptr);

    // Connection.
    const bus::ConnectionStatus &connection() const { return m_connection; }
    bool isSimulated() const { return m_simulated; }
    /// The link is open and may transmit (ConnectionStatus::canTransmit): actions that send
    /// may be enabled. Every view derives its sending from this one capability.
    bool canSend() const { return m_connection.isOpen() && m_connection.canTransmit; }
    /// The link is open listen-only: drives come from what another master makes them say.
    bool isListening() const { return m_connection.isOpen() && !m_connection.canTransmit; }
    /// Why actions that send are disabled, a sentence for their tooltips; empty: they are not.
    QString sendBlockedReason() const;
    void setConnection(const bus::ConnectionStatus &status, bool simulated);
    /// The link the connection is made over (chosen at connect; RS485 until then).
    protocol::Link link() const { return m_link; }
    /// The CAN interface's name as candump writes it ("can0"); empty on RS485.
    QString canInterface() const { return m_canInterface; }
    /// `canInterface`: the interface as chosen (a virtualcan URL keeps its last part).
    void setLink(protocol::Link link, const QString &canInterface = {});
    /// The CAN bus's condition on the open link (Good otherwise) and the transport's sentence
    /// about it, with its fix. A frame from a drive ends bus-off and no acknowledgement (as
    /// it does in CanTransport); a new connection starts Good.
    transport::CanBusCondition canCondition() const { return m_canCondition; }
    QString canConditionMessage() const { return m_canMessage; }
    void setCanCondition(transport::CanBusCondition condition, const QString &message = {});

    // Drives.
    QVector<int> ids() const { return m_drives.keys().toVector(); }
    const DriveRecord *drive(int id) const;
    bool isEmpty() const { return m_drives.isEmpty(); }
    void clearDrives();
    void addFound(const bus::FoundMotor &found);
    /// What the bus learnt about its drives (BusSession::knownMotorsChanged): series and
    /// models update the drives shown; while listening, drives seen answering are added.
    void applyKnownMotors(const bus::KnownMotors &motors);
    /// The gear ratio the user chose for drive `id` (no model name to read it from).
    void setChosenGearRatio(int id, double ratio);
    /// The generation the user chose for drive `id` (CAN), shown until the bus reports it.
    void setLinkGeneration(int id, protocol::Generation generation);
    /// Values for the drives shown; while listening, an ID seen answering becomes a drive.
    void applyTelemetry(const bus::TelemetryBatch &batch);
    /// Host clock the field timestamps use (ms since the model was made).
    qint64 nowMs() const { return m_clock.elapsed(); }

    // Polling and statistics.
    const bus::BusStatistics &statistics() const { return m_statistics; }
    void setStatistics(const bus::BusStatistics &statistics);
    /// What the other master did, while listening (BusSession::listenStatisticsUpdated).
    const bus::ListenStatistics &listenStatistics() const { return m_listenStatistics; }
    void setListenStatistics(const bus::ListenStatistics &statistics);
    const bus::PollPlan &pollPlan() const { return m_pollPlan; }
    bool isPolling() const { return m_polling; }
    void setPolling(const bus::PollPlan &plan, bool active);
    /// Transactions per second the poll plan asks for (0 = as fast as the bus allows).
    double requestedTransactionsPerSecond() const;

    // Selection. It outlives clearDrives(): when the drives come back (a rescan, a
    // reconnect), the drive the user chose is current again and the drives picked with it
    // are picked again; until it answers, the first drive found stands in.
    int currentId() const { return m_currentId; } ///< 0: none
    /// The user (or a view) chose drive `id` (0: none).
    void setCurrentId(int id);
    /// Drives picked together (plots show them all); the current drive when none.
    QVector<int> selectedIds() const;
    void setSelectedIds(const QVector<int> &ids);

signals:
    void connectionChanged();
    void canConditionChanged();
    void drivesChanged(); ///< the set of drives or their identities changed
    void telemetryChanged();
    void statisticsChanged();
    void listenStatisticsChanged();
    void pollingChanged();
    void currentDriveChanged(int id);
    void selectionChanged();

private:
    void setCurrent(int id);
    /// A drive seen answering while listening, added at the link's baud; no signal.
    DriveRecord &addObserved(int id);
    /// Drive `id` was just added: current or selected again if the user had chosen it.
    void selectArrived(int id);

    bus::ConnectionStatus m_connection;
    bool m_simulated = false;
    protocol::Link m_link = protocol::Link::Rs485;
    QString m_canInterface;
    transport::CanBusCondition m_canCondition = transport::CanBusCondition::Good;
    QString m_canMessage;
    QMap<int, DriveRecord> m_drives;
    bus::BusStatistics m_statistics;
    bus::ListenStatistics m_listenStatistics;
    bus::PollPlan m_pollPlan;
    bool m_polling = false;
    int m_currentId = 0;
    QVector<int> m_selected;
    int m_wantedCurrent = 0;         ///< the drive chosen last, current again when found
    QVector<int> m_wantedSelection;  ///< the drives picked with it when the drives went
    bool m_currentIsStandIn = false; ///< current only until m_wantedCurrent is found
    QElapsedTimer m_clock;
};

} // namespace lk::ui
