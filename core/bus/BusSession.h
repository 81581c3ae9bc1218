#pragma once

#include "BusConfig.h"
#include "BusMetaTypes.h"
#include "BusStatistics.h"
#include "ConnectionStatus.h"
#include "KnownMotor.h"
#include "LinkMode.h"
#include "ListenStatistics.h"
#include "MultiTorque.h"
#include "PollPlan.h"
#include "Priority.h"
#include "RequestResult.h"
#include "ScanTypes.h"
#include "SetpointStop.h"
#include "SetpointStreamPlan.h"
#include "SpeedWatchTrip.h"
#include "TelemetrySample.h"
#include "TicketCallbacks.h"
#include "TrafficEvent.h"
#include "TransportFactory.h"

#include <transport/Transport.h>

#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QVector>

#include <functional>
#include <optional>

class QThread;

namespace lk::bus {

class BusWorker;

/// The thread-safe face of one bus (RS485, or CAN through CanTransport) for the GUI and the
/// CLI. The link is the transport's (Transport::link()); ConnectionStatus says which, and on
/// CAN the bus condition (bus-off, error-passive, no-ACK) with its fix.
///
/// Lives in the caller's thread; owns a QThread on which a BusWorker and its transport run.
/// Every call returns at once and is forwarded as a queued invocation; every result comes
/// back as a signal carrying plain values, and to the callback given with the call, if any.
/// Call it only from the thread it lives in.
/// Several sessions (several adapters) may be open at once.
///
/// Safety: the session does not apply soft limits. Every motion request (torque, speed,
/// position, open loop, motor_run) must pass lk::safety::MotionGuard::check() (with
/// series(id) and the user's soft limits) before send(); knownMotors()/series() say what
/// each ID supports. emergencyStop() is the one motion-related call that needs no check.
/// The one bound the bus thread keeps itself is the speed of a drive under a torque or
/// open-loop command (setSoftLimits, speedWatchTripped): the drives do not bound it.
class BusSession : public QObject {
    Q_OBJECT
public:
    explicit BusSession(QObject *parent = nullptr);
    ~BusSession() override; ///< close(): pending requests end Cancelled, thread joined

    /// Start the bus thread, create the transport there with `factory(baud)` and open it.
    /// An open session is closed first. Progress arrives as connectionChanged/errorOccurred.
    /// `mode` ListenOnly: the transport opens read-only and nothing is ever sent; every call
    /// below that would transmit completes refused (SendRefusal::ListenOnly, 0 bytes written)
    /// and connection().canTransmit stays false, until takeOver().
    void open(TransportFactory factory, int baud = 115200, const BusConfig &config = {},
              LinkMode mode = LinkMode::Active);
    /// "Take over the bus": a listen-only session reopens its port read-write and becomes
    /// Active; the poll plan given meanwhile (startPolling, poll extras) starts then. Only on
    /// the user's explicit, confirmed request (another master may still be driving the bus):
    /// nothing calls it on its own. connectionChanged reports the new mode and canTransmit.
    void takeOver();
    /// The mode asked for at open() or by takeOver() (connection().mode: as reported).
    LinkMode linkMode() const { return m_mode; }
    /// Reopen the existing transport after a disconnect (or a failed open).
    void reconnect();
    /// Close the transport, end pending requests as Cancelled, join the thread (bounded).
    /// The final completions and the Closed state are delivered before it returns.
    void close();
    bool isRunning() const; ///< the bus thread exists (open() called, close() not yet)
    ConnectionStatus connection() const { return m_connection; } ///< last reported state

    void setConfig(const BusConfig &config);

    using Completion = std::function<void(const RequestResult &)>;
    /// An emergency stop's end: who acknowledged, who stayed silent, and which of the silent
    /// never got the halt onto the wire (the link was gone).
    using StopCompletion = std::function<void(
        const QVector<int> &acknowledged, const QVector<int> &silent, const QVector<int> &unsent)>;

    /// Queue a request; returns its ticket, repeated in the requestCompleted it ends with.
    /// `retries` < 0 uses BusConfig::retries; incremental moves and ROM writes are never
    /// retried (the drive may have acted on the first one: read back instead). A closed
    /// session completes it as Disconnected.
    quint64 send(const protocol::Request &request, Priority priority = Priority::Operator,
                 int retries = -1);
    /// send(), and `done` runs with the result right after the requestCompleted that carries
    /// the ticket: once, never inside this call, on `context`'s thread, and not at all once
    /// `context` is destroyed or the session is (a context on another thread must not be
    /// deleted while the result is posted to it: Qt's rule for queued calls).
    quint64 send(const protocol::Request &request, QObject *context, Completion done,
                 Priority priority = Priority::Operator, int retries = -1);
    using MultiTorqueCompletion = std::function<void(const MultiTorqueResult &)>;
    /// The old CAN generation's multi-motor torque frame (0x280): up to four drives' torque in
    /// one frame, queued and sent on the bus thread like send(), its drives' replies matched
    /// to them and published as telemetry. Unlike send(), the bus thread applies the soft
    /// limits itself (BusWorker::submitMultiTorque; those given with setSoftLimits, else the
    /// series' defaults) and refuses it, nothing sent to any drive, naming the drive and the
    /// limit; callers check first with safety::MultiTorqueGuard and the user's limits, as for
    /// any motion. Ends with multiTorqueCompleted, then `done` (send()'s rules for `context`).
    quint64 sendMultiTorque(const MultiTorqueRequest &request, QObject *context = nullptr,
                            MultiTorqueCompletion done = {});
    /// Motor off to every ID in `ids` and every known ID first, then to every other ID of
    /// 1..32, ahead of everything queued; a running scan and queued motion commands are
    /// cancelled first. Each motor_off ends with a requestCompleted carrying the returned
    /// ticket (status Disconnected when it could not be sent), then emergencyStopFinished.
    /// A closed session sends nothing and reports every ID silent.
    /// `halt` MotorStop sends motor_stop the same way (the drives keep their commands).
    quint64 emergencyStop(const QVector<int> &ids = {},
                          protocol::Command halt = protocol::Command::MotorOff);
    /// emergencyStop(), and `done` runs right after its emergencyStopFinished, with send()'s
    /// rules for `context`. What is sent, and when, is the same.
    quint64 emergencyStop(const QVector<int> &ids, protocol::Command halt, QObject *context,
                          StopCompletion done);

    void scan(const ScanOptions &options = {});
    void cancelScan();

    void startPolling(const PollPlan &plan);
    void stopPolling();
    /// The plan last given to startPolling() (as given); nullopt after stopPolling(), close()
    /// or before any. A step test focuses it on its drive and gives it back afterwards.
    std::optional<PollPlan> pollPlan() const { return m_pollPlan; }
    /// Read `commands` of drive `id` in its poll round besides the plan's (extra commands,
    /// see PollPlan) until removePollExtras() with the returned handle (never 0). They outlive
    /// startPolling() and stopPolling() (so a step test's focus and its end keep them, and
    /// without a plan the bus polls them alone); close() drops them.
    quint64 addPollExtras(int id, const QVector<protocol::Command> &commands);
    void removePollExtras(quint64 handle); ///< a handle close() dropped is ignored
    bool hasPollExtras(quint64 handle) const { return m_pollExtras.contains(handle); }
    /// What the bus polls: pollPlan() (or nothing) with every extra command added; nullopt
    /// when neither is there.
    std::optional<PollPlan> effectivePollPlan() const;

    /// Run the setpoint stream of `plan` on the bus thread (SetpointStream: paced there, each
    /// setpoint checked with the plan's limits before it is queued), replacing a running one.
    /// Returns its handle (plan.stream is set to it), repeated in setpointStreamStarted and
    /// setpointStreamStopped. A closed session never starts it: setpointStreamStopped alone
    /// follows (SetpointStopReason::Closed).
    /// An emergency stop, a disconnect, close() and a reopen at another baud stop it on the
    /// bus thread before anything else happens.
    quint64 startSetpointStream(SetpointStreamPlan plan);
    /// Stop the running stream; its setpoint still queued is dropped, one on the wire may
    /// finish but is not sent again. Sends nothing: the caller decides whether the drive is
    /// stopped too.
    void stopSetpointStream();

    /// The user's soft limits of drive `id`, for the bus thread's speed watch (SpeedWatch):
    /// a drive under a torque or open-loop command is stopped (Motor Stop) once its speed
    /// passes SpeedWatch::thresholdDps(limits.maxSpeedDps); without them, the series'
    /// default. Kept over close() and open(); speedWatchTripped() reports each stop.
    void setSoftLimits(int id, const safety::SoftLimits &limits);

    /// Tell the bus how to decode replies from `id` (iq vs power); also makes `id` known.
    void setSeries(int id, protocol::Series series);
    /// The user's word on drive `identity.id`: its series, generation and gear ratio. A drive
    /// whose model cannot be read (every drive on CAN, and listen-only RS485) decodes by it,
    /// and torque, power and open loop follow its series (unknown until then: refused, as for
    /// any drive of unknown series). Remembered over close() and open() and given to each new
    /// link; no reply overrides it. On CAN, Generation::V2_3 is the old CAN generation,
    /// V2_35 CAN V2.36.
    void setDriveIdentity(const DriveIdentity &identity);
    /// What setDriveIdentity() said of `id`; nullopt when nothing.
    std::optional<DriveIdentity> driveIdentity(int id) const;
    /// Forget every known ID (e.g. before telling the bus a new set by hand).
    void forgetMotors();
    KnownMotors knownMotors() const { return m_motors; } ///< last reported by the worker
    std::optional<protocol::Series> series(int id) const;

    /// Deliver raw traffic (trafficCaptured) while enabled. Off by default.
    void setTrafficCapture(bool enabled);
    void resetStatistics();

signals:
    void connectionChanged(const lk::bus::ConnectionStatus &status);
    /// Once per failed open, and for an I/O failure of an open link. Never for an unplug:
    /// that is connectionChanged to Disconnected, whose reason says what happened.
    void errorOccurred(const lk::transport::TransportError &error);
    /// The end of a send() or of one emergency motor_off. Polls and scan probes do not
    /// report here: their replies arrive as telemetry and scan signals.
    void requestCompleted(const lk::bus::RequestResult &result);
    /// A send() was accepted for the bus, emitted on the caller's thread before send()
    /// returns: whoever moves drives on its own (the demo) hears of a command before one of
    /// its own can be queued behind it.
    void requestSubmitted(quint64 ticket, const lk::protocol::Request &request,
                          lk::bus::Priority priority);
    /// One more ID of an emergency stop answered or stayed silent (in the order the results
    /// came); `remaining` halts are still to come. emergencyStopFinished follows the last.
    void emergencyStopProgress(quint64 ticket, const QVector<int> &acknowledged,
                               const QVector<int> &silent, int remaining);
    /// Every ID has answered or stayed silent. `unsent`: the silent IDs whose motor_off never
    /// reached the wire (the link dropped, or the session was closed: then all of them).
    void emergencyStopFinished(quint64 ticket, const QVector<int> &acknowledged,
                               const QVector<int> &silent, const QVector<int> &unsent);
    /// The stop `ticket` sent nothing: the session listens only (`refusal`). Comes right
    /// before its emergencyStopFinished (every target silent and unsent). The words for the
    /// user: "Listen-only: NOTHING was sent. Stop the machine with its own emergency stop."
    void emergencyStopRefused(quint64 ticket, lk::bus::SendRefusal refusal);
    void scanProgress(const lk::bus::ScanProgress &progress);
    void motorFound(const lk::bus::FoundMotor &motor);
    void scanFinished(const lk::bus::ScanSummary &summary);
    void knownMotorsChanged(const lk::bus::KnownMotors &motors);
    void pollingChanged(bool active); ///< polling started, stopped, suspended or resumed
    void setpointStreamStarted(quint64 stream);
    /// Why the stream ended and what it sent (also after stopSetpointStream()).
    void setpointStreamStopped(const lk::bus::SetpointStop &stop);
    /// A setpoint of the stream did not complete; its end also comes as requestCompleted.
    void setpointFailed(quint64 stream, const lk::bus::RequestResult &result);
    /// Samples from every reply that carries telemetry (polls and operator commands alike).
    void telemetryReceived(const lk::bus::TelemetryBatch &batch);
    void statisticsUpdated(const lk::bus::BusStatistics &statistics);
    /// Listen-only sessions: what the other master did (requests/s per drive and command,
    /// unanswered requests, reply latency, checksum errors, bus load), at statisticsHz.
    /// Samples from its drives' replies arrive as telemetryReceived, as polled ones do; its
    /// commanded values too (TelemetryField::CommandedSpeed, ...).
    void listenStatisticsUpdated(const lk::bus::ListenStatistics &statistics);
    void trafficCaptured(const lk::bus::TrafficBatch &batch);
    /// The speed watch stopped a drive under torque or open loop past its speed limit; sent
    /// once the Motor Stop has ended (which also comes as requestCompleted, ticket 0).
    void speedWatchTripped(const lk::bus::SpeedWatchTrip &trip);
    /// The end of a sendMultiTorque(): each drive's reply or why there was none.
    void multiTorqueCompleted(const lk::bus::MultiTorqueResult &result);

private:
    void connectWorker();
    void join();
    void finishRequest(const RequestResult &result);
    void finishMultiTorque(const MultiTorqueResult &result);
    void postPollPlan(); ///< the worker polls effectivePollPlan()
    void postIdentity(const DriveIdentity &identity);
    void finishStop(quint64 ticket, const QVector<int> &acknowledged, const QVector<int> &silent,
                    const QVector<int> &unsent);
    template <typename F> void post(F &&f);
    template <typename... Args>
    void relay(void (BusWorker::*from)(Args...), void (BusSession::*to)(Args...));

    QThread *m_thread = nullptr;
    BusWorker *m_worker = nullptr; ///< lives on m_thread; touched only through post()
    quint64 m_nextTicket = 1;
    quint64 m_generation = 0; ///< signals of a worker from an earlier open() are ignored
    ConnectionStatus m_connection;
    LinkMode m_mode = LinkMode::Active;
    KnownMotors m_motors;
    BusConfig m_config;
    std::optional<PollPlan> m_pollPlan;
    struct PollExtras {
        int id = 0;
        QVector<protocol::Command> commands;
    };
    QMap<quint64, PollExtras> m_pollExtras; ///< by handle
    quint64 m_nextExtrasHandle = 1;
    quint64 m_nextStream = 1;
    QMap<int, safety::SoftLimits> m_softLimits; ///< by drive, given again to each new worker
    QMap<int, DriveIdentity> m_identities;      ///< by drive, given again to each new worker
    TicketCallbacks<RequestResult> m_requestCallbacks;
    TicketCallbacks<MultiTorqueResult> m_multiTorqueCallbacks;
    TicketCallbacks<QVector<int>, QVector<int>, QVector<int>> m_stopCallbacks;
};

} // namespace lk::bus
