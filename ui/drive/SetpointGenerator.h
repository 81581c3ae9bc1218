#pragma once

#include "MotionGate.h"

#include <bus/RequestResult.h>
#include <bus/SetpointStop.h>
#include <bus/SetpointStreamPlan.h>

#include <QtCore/QObject>
#include <QtCore/QPointer>
#include <QtCore/QString>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

/// The GUI's side of a session's setpoint stream: the waveform runs on the bus thread
/// (bus::SetpointStream, which also checks every setpoint against the limits), so a busy GUI
/// neither delays nor bunches setpoints. This starts and stops it, knows at once whether it
/// runs (before the bus thread has heard), and words why the stream stopped itself.
class SetpointGenerator : public QObject {
    Q_OBJECT
public:
    explicit SetpointGenerator(QObject *parent = nullptr);
    /// A running stream stops with its view: nothing on the bus thread drives a drive that no
    /// view shows.
    ~SetpointGenerator() override;

    /// The session the stream runs on (not owned); a stream running on the previous one is
    /// stopped there.
    void setSession(bus::BusSession *session);
    /// Starts `plan` on the session, replacing a running stream; running from now on, and the
    /// first setpoint goes out as soon as the bus thread has it.
    void start(const bus::SetpointStreamPlan &plan);
    /// Stops the stream (a setpoint still queued is dropped, nothing else is sent); emits
    /// stopped(reason) when it was running.
    void stop(const QString &reason);
    bool isRunning() const { return m_stream != 0; }
    const bus::SetpointStreamPlan &plan() const { return m_plan; }

signals:
    void started();
    void stopped(const QString &reason);
    /// The stream stopped at a value the builder or the limits refused; nothing of it was
    /// sent (emitted before stopped()).
    void refused(const lk::ui::MotionOutcome &outcome);
    /// A setpoint of the running stream did not complete (timeout, lost link, ...).
    void setpointFailed(const lk::bus::RequestResult &result);

private:
    void onStopped(const bus::SetpointStop &stop);
    void onFailed(quint64 stream, const bus::RequestResult &result);

    QPointer<bus::BusSession> m_session;
    QMetaObject::Connection m_stoppedConnection;
    QMetaObject::Connection m_failedConnection;
    bus::SetpointStreamPlan m_plan;
    quint64 m_stream = 0; ///< the running stream's handle; 0: none
};

} // namespace lk::ui
