#pragma once

#include "EmergencyStopReport.h"

#include <bus/ConnectionStatus.h>
#include <bus/TelemetrySample.h>

#include <QtCore/QHash>
#include <QtCore/QObject>
#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>
#include <utility>

namespace lk::ui {

class BusController;
class CommandedMotion;
class EmergencyKeyFilter;
class MessageBanner;

/// lkstudio's one emergency stop. It owns Esc for the whole application (an application
/// event filter, which also sees Esc inside modal dialogs and open pop-ups); the toolbar
/// button and the menu call stop(). A stop first tells local motion sources to halt
/// (halting: setpoint generator, jog), then has the bus send Motor Off to the known and
/// commanded drives first and to every other ID 1..32, whatever the scan or connection state
/// (the bus ends a running scan in the same call). Its report is a banner entry, shown at once
/// and filled in as the acknowledgements come, that stays until dismissed: who acknowledged
/// and, in red, the known or commanded IDs that did not, until a state read shows them
/// stopped. A stop pressed while disconnected says that nothing could be sent and which
/// drives were last commanded, and goes out when the same port is connected again (unless
/// the report was dismissed first). While the link listens only, a stop sends nothing and the
/// red entry says exactly that, and that the machine's own emergency stop must stop it.
class EmergencyStopControl : public QObject {
    Q_OBJECT
public:
    /// The banner entry key of the report.
    static QString entryKey() { return QStringLiteral("emergencyStop"); }

    /// Installs its Esc filter on the application; none of the arguments is owned.
    EmergencyStopControl(BusController *controller, CommandedMotion *motion, MessageBanner *banner,
                         QObject *parent = nullptr);
    ~EmergencyStopControl() override;

public slots:
    void stop();
    /// State reads: a drive the report says may be moving that reads stopped leaves the red.
    void onTelemetry(const lk::bus::TelemetryBatch &batch);

signals:
    /// Emitted before anything is sent: whatever sends motion by itself must stop now, so
    /// that no setpoint can follow the Motor Off frames.
    void halting(const QString &reason);
    /// The report is shown (the bus has an answer, or silence, from every ID).
    void reported();

private:
    using Pending = EmergencyStopReport::Context;
    using Outcome = EmergencyStopReport::Outcome;
    void send(const Pending &p);
    void onProgress(quint64 ticket, const QVector<int> &acknowledged, const QVector<int> &silent,
                    int remaining);
    void onFinished(quint64 ticket, const QVector<int> &acknowledged, const QVector<int> &silent,
                    const QVector<int> &unsent);
    void onConnectionChanged(const lk::bus::ConnectionStatus &status);
    void report(const Pending &p, const Outcome &outcome);
    /// The stop sent nothing because the link listens only (the red entry says so).
    void showListenOnly();
    /// The port of a connection description ("/dev/ttyUSB0 @ 115200" -> "/dev/ttyUSB0").
    static QString portOf(const QString &description);

    BusController *m_controller;
    CommandedMotion *m_motion;
    MessageBanner *m_banner;
    EmergencyKeyFilter *m_keys;
    QHash<quint64, Pending> m_pending;
    /// The last finished stop's report, while it is shown (drives leave its red as they
    /// read stopped).
    std::optional<std::pair<Pending, Outcome>> m_shown;
    /// A stop that could send nothing, to go out when m_resendPort is connected again.
    std::optional<Pending> m_resend;
    QString m_resendPort;
    QString m_lastPort; ///< the port of the last open connection
};

} // namespace lk::ui
