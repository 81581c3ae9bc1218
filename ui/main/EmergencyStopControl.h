#pragma once

#include "EmergencyStopReport.h"

#include <QtCore/QHash>
#include <QtCore/QObject>
#include <QtCore/QStringList>
#include <QtCore/QVector>

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
/// (the bus ends a running scan in the same call). Its report is a banner entry that stays
/// until dismissed: who acknowledged and, in red, the known or commanded IDs that did not;
/// while disconnected, that nothing could be sent and which drives were last commanded.
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

signals:
    /// Emitted before anything is sent: whatever sends motion by itself must stop now, so
    /// that no setpoint can follow the Motor Off frames.
    void halting(const QString &reason);
    /// The report is shown (the bus has an answer, or silence, from every ID).
    void reported();

private:
    using Pending = EmergencyStopReport::Context;
    using Outcome = EmergencyStopReport::Outcome;
    void onFinished(quint64 ticket, const QVector<int> &acknowledged, const QVector<int> &silent,
                    const QVector<int> &unsent);
    void report(const Pending &p, const Outcome &outcome);

    BusController *m_controller;
    CommandedMotion *m_motion;
    MessageBanner *m_banner;
    EmergencyKeyFilter *m_keys;
    QHash<quint64, Pending> m_pending;
};

} // namespace lk::ui
