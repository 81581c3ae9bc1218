#pragma once

#include "RequestResult.h"
#include "SetpointStop.h"
#include "SetpointStreamPlan.h"
#include "SingleShotTimer.h"

#include <protocol/Request.h>

#include <QtCore/QObject>

#include <functional>
#include <memory>

namespace lk::bus {

class BusWorker;

/// The setpoint generator as a command source on the bus thread, beside the poll scheduler:
/// paced by its own timer there, so a busy GUI neither delays nor bunches setpoints.
///
/// Each tick takes the waveform's value at the session clock's time since the start, builds
/// the request (speed, multi-turn position or torque) and plans it with the same
/// MotionPlanner/MotionGuard check as the GUI's motion gate, from the plan's series, soft
/// limits and start angle. A refused value stops the stream with the typed verdict and sends
/// nothing. At most one setpoint is queued or on the wire: a tick meanwhile is skipped
/// (counted), so a slow bus gets fewer setpoints, never a backlog. Setpoints go through the
/// worker's queue at Operator priority, and their ends reach BusWorker::requestCompleted.
///
/// Owned by BusWorker, which stops it first on an emergency stop and on a disconnect,
/// close or reopen. Call it only on the worker's thread.
class SetpointStream : public QObject {
    Q_OBJECT
public:
    /// Ticks on a timer from `timers` (the worker's) and reads the worker's session clock.
    SetpointStream(BusWorker &worker, const SingleShotTimerFactory &timers);
    ~SetpointStream() override;

    /// Tests: timers fired by hand and a clock (seconds) of the stream's own, apart from the
    /// worker's (whose reply and poll timers then keep running on their own).
    void setTiming(const SingleShotTimerFactory &timers, std::function<double()> clock);

    /// Starts `plan` (rate and period bounded), replacing a running stream; the first
    /// setpoint is sent at once. A closed bus stops it at once (Disconnected).
    void start(const SetpointStreamPlan &plan);
    /// Stops the stream, if running; stopped() says why. Sends nothing.
    void stop(SetpointStopReason reason);
    bool isRunning() const { return m_running; }
    qint64 emitted() const { return m_emitted; }
    qint64 skipped() const { return m_skipped; }

    /// The request for setpoint `value` of `plan` to a drive of `generation` (a torque is in
    /// the drive's own units), as built (before the limits are applied).
    static protocol::BuildResult build(const SetpointStreamPlan &plan, double value,
                                       protocol::Generation generation);
    /// Whether `ticket` belongs to a setpoint (its own range: never one BusSession gives out).
    static bool isSetpointTicket(quint64 ticket);

signals:
    void started(quint64 stream);
    void stopped(const lk::bus::SetpointStop &stop);
    /// The end of one setpoint request (every one, also after the stream stopped).
    void setpointCompleted(const lk::bus::RequestResult &result);
    /// One setpoint of stream `stream` did not complete (timeout, corrupt reply, cancelled,
    /// link lost).
    void setpointFailed(quint64 stream, const lk::bus::RequestResult &result);

private:
    void tick();
    void scheduleNext(double t);
    void onCompleted(quint64 stream, const RequestResult &result);
    void stopRefused(const safety::Verdict &verdict,
                     const std::optional<protocol::FieldError> &fieldError);
    void finish(SetpointStop stop);

    BusWorker &m_worker;
    std::unique_ptr<SingleShotTimer> m_timer;
    std::function<double()> m_clock;
    SetpointStreamPlan m_plan;
    protocol::Generation m_generation = protocol::Generation::V2_3; ///< the plan's drive's
    bool m_running = false;
    double m_startS = 0; ///< clock time of the start
    double m_nextS = 0;  ///< when the next tick is due, seconds after the start
    qint64 m_emitted = 0;
    qint64 m_skipped = 0;
    quint64 m_ticket = 0; ///< the setpoint queued or on the wire; 0: none
    quint64 m_lastTicket = 0;
};

} // namespace lk::bus
