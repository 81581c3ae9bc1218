#pragma once

#include <bus/RequestResult.h>
#include <protocol/Request.h>

#include <QtCore/QDateTime>
#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QVector>

#include <optional>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

/// Remembers, per drive, the last motion command that went out on a session and when (wall
/// clock). It watches the session's completions, so whoever sent the command (Control view,
/// jog, setpoint generator, demo) is seen in this one place. A Motor Off or Stop the drive
/// acknowledged, or a zero speed/torque/power command, ends a drive's record. The emergency
/// stop reads it to know whom to stop first and what to say while disconnected; the link-loss
/// warnings read it to say which drive may still be moving.
class CommandedMotion : public QObject {
    Q_OBJECT
public:
    struct Entry {
        protocol::Request request;
        QDateTime sentAt; ///< when its completion arrived: it left the host before that
    };

    explicit CommandedMotion(QObject *parent = nullptr);

    void setSession(bus::BusSession *session);
    /// Drives whose last motion command was not followed by an acknowledged off or stop.
    QVector<int> movingIds() const { return m_entries.keys().toVector(); }
    std::optional<Entry> last(int id) const;
    /// One completion seen on the session (called for every requestCompleted).
    void observe(const bus::RequestResult &result);

    /// "speed 360 dps", "position 90°", ... (translated).
    static QString describe(const protocol::Request &request);
    /// "Drive 2 (speed 360 dps at 12:03:04)" for drive `id`; just "Drive 2" without a record.
    QString driveText(int id) const;

signals:
    void changed();

private:
    QPointer<bus::BusSession> m_session;
    QMetaObject::Connection m_connection;
    QMetaObject::Connection m_multiTorqueConnection;
    QMap<int, Entry> m_entries;
};

} // namespace lk::ui
