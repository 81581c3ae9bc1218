#pragma once

#include "BusConfig.h"
#include "BusDiagnostics.h"
#include "BusRequest.h"
#include "BusStatistics.h"
#include "BusTimeSource.h"
#include "ConnectionStatus.h"
#include "KnownMotor.h"
#include "LinkMode.h"
#include "ListenMonitor.h"
#include "ListenStatistics.h"
#include "MotorRegistry.h"
#include "PollPlan.h"
#include "PollRunner.h"
#include "PollScheduler.h"
#include "Priority.h"
#include "ReplyIntake.h"
#include "RequestQueue.h"
#include "RequestResult.h"
#include "ScanTypes.h"
#include "SetpointStop.h"
#include "SetpointStream.h"
#include "SetpointStreamPlan.h"
#include "SingleShotTimer.h"
#include "SpeedWatch.h"
#include "TelemetryBatcher.h"
#include "TelemetrySample.h"
#include "TrafficEvent.h"
#include "TransportFactory.h"
#include "TransportLink.h"
#include "WireExchange.h"

#include <transport/Transport.h>

#include <QtCore/QObject>

#include <functional>
#include <memory>
#include <optional>

namespace lk::bus {

class Scanner;

/// The bus engine. Lives on the bus thread. Half duplex: exactly one request on the wire;
/// queues run Emergency > Operator > Background, then the poll scheduler fills idle time.
/// Every request completes exactly once: through its callback when it has one, else through
/// requestCompleted (the callbacks of setpoints and emergency offs pass their ends on to
/// requestCompleted too). Its parts, each its own object on the same thread:
/// - TransportLink: the transport's lifecycle (made by the factory on this thread, opened,
///   reopened, closed) and the connection status it reports;
/// - WireExchange: the request on the wire: sent, its reply matched by command and ID, timed
///   out (BusTiming plus an adaptive margin), the quiet period after a timeout;
/// - BusDiagnostics: the statistics and the traffic capture;
/// - MotorRegistry: the drives known, how their replies decode, what their generation lacks;
/// - ListenMonitor: in a listen-only session, what another master and its drives say.
///
/// Listen-only (LinkMode::ListenOnly, start()): the transport is read-only and nothing is sent.
/// submit, emergencyStop, scan, startPolling and startSetpointStream complete refused
/// (SendRefusal::ListenOnly) and are counted (refusedCalls()); pumpNow never sends, and the
/// link drops what still reaches it. Bytes go to the ListenMonitor instead of the exchange.
/// The worker decides what is sent next, retries, completes, and reacts to the link.
///
/// Quiet period: after a timeout nothing is transmitted until a late reply to the request
/// could no longer be on its way (AdaptiveTimeout::quietS: the drive's longest turnaround,
/// the longest reply's wire time and the link's latency). After a scan probe's short
/// timeout, where silence is the usual answer, it lasts only until a reply could have come
/// from a drive that keeps its turnaround (AdaptiveTimeout::replyDeadlineS, from the send),
/// so that silent IDs stay cheap. After an emergency stop's Motor Off it lasts only as long as
/// the wire itself needs (request, turnaround, longest reply): the link's latency delays only
/// our reading of a reply, and one drive's late reply lifts only that drive's timeout. Bytes
/// arriving meanwhile are a reply in progress and restart it (full length); a complete late
/// reply to that request ends it. Late replies are counted (BusStatistics) and never taken
/// for a later request's answer. Probes of IDs that never answered on this connection that
/// stay silent are counted apart from timeouts (BusStatistics silentProbes).
///
/// Retries (BusConfig::retries, BusRequest::retries) never apply to incremental moves or ROM
/// writes: a drive that acted but whose reply was lost would move twice or write flash twice.
///
/// Local echo: a frame byte-identical to the request just sent is skipped when its layout is
/// a request's (it cannot be the reply). For commands whose reply is an echo of the request
/// (motor_off, ...) the first identical frame is taken as the reply, unless
/// BusConfig::localEcho says the adapter echoes, in which case the first one is skipped.
///
/// Setpoints for tuning come from a SetpointStream, a command source beside the poll
/// scheduler that queues at Operator priority. emergencyStop() stops it before its first
/// motor_off is queued; a disconnect, shutdown and a reopen stop it too.
///
/// A SpeedWatch bounds the speed of drives under torque or open-loop commands: it sees every
/// request's end and every reply's telemetry, has the watched drives polled often, and stops
/// one past its limit (stopForSpeedWatch) before anything else queued for it goes out.
///
/// All public functions must be called on the worker's thread (BusSession posts them).
class BusWorker : public QObject {
    Q_OBJECT
public:
    using Completion = PendingRequest::Completion;

    /// `time`: the clock and timers it runs on (default the product's; tests run it on a
    /// clock they advance by hand).
    BusWorker(TransportFactory factory, int baud, const BusConfig &config, BusTimeSource time = {},
              QObject *parent = nullptr);
    ~BusWorker() override;

    /// Create the transport at the initial baud and open it, read-only in ListenOnly.
    void start(LinkMode mode = LinkMode::Active);
    /// Listen-only to Active: the read-only transport is replaced by a read-write one at the
    /// same baud, and from then on everything transmits as in a session opened Active. Only on
    /// the user's explicit, confirmed request; never automatic. True when the link is open.
    bool takeOver();
    LinkMode linkMode() const { return m_link.mode(); }
    /// Calls refused because the session listens only (sends, stops, scans, polls, streams).
    quint64 refusedCalls() const { return m_refusedCalls; }
    /// Bytes that reached the link's write in ListenOnly and were dropped there (0 unless a
    /// sender bypassed the refusals above).
    quint64 refusedBytes() const { return m_link.refusedBytes(); }
    /// Reopen the current transport (after a disconnect or a failed open).
    void reconnect();
    /// Replace the transport by a new one from the factory at `baud` and open it.
    bool reopenAt(int baud);
    /// Cancel everything, close and delete the transport, stop timers. Idempotent.
    void shutdown(const QString &reason);

    void setConfig(const BusConfig &config);
    void submit(BusRequest request, Completion done = {});
    using MultiTorqueCompletion = std::function<void(const MultiTorqueResult &)>;
    /// The old CAN generation's multi-motor torque frame (0x280) at Operator priority, queued
    /// and sent like any request, and on the wire until every drive named answered (or each
    /// silent one timed out, counted per drive); never sent twice. Refused, nothing sent for
    /// any drive, when MultiTorqueGuard refuses it: not CAN, a drive of V2.36 or unknown
    /// generation, a series unknown, an iq over a drive's series current or torque limit (its
    /// soft limits, setSoftLimits, else SoftLimits::defaults of its series), or listen-only.
    /// Its drives are then watched as under a torque command; a trip of one stops them all.
    /// Ends once, through `done`, else multiTorqueCompleted; its replies are telemetry.
    void submitMultiTorque(quint64 ticket, const MultiTorqueRequest &request,
                           MultiTorqueCompletion done = {});
    /// `halt`: MotorOff, or MotorStop for a "stop all" that keeps the drives' commands.
    void emergencyStop(quint64 ticket, const QVector<int> &ids,
                       protocol::Command halt = protocol::Command::MotorOff);
    void scan(const ScanOptions &options);
    void cancelScan();
    bool isScanning() const;
    void startPolling(const PollPlan &plan);
    void stopPolling();
    /// Runs a setpoint stream (SetpointStream), replacing a running one.
    void startSetpointStream(const SetpointStreamPlan &plan);
    /// Stops the stream and drops its setpoint still queued (one on the wire may finish).
    void stopSetpointStream();
    SetpointStream &setpointStream() { return m_setpoints; }
    /// The soft limits of drive `id`: the speed watch bounds torque and open loop by them.
    void setSoftLimits(int id, const safety::SoftLimits &limits);
    const SpeedWatch &speedWatch() const { return m_speedWatch; }
    void setSeries(int id, protocol::Series series)
    {
        if (m_motors.setSeries(id, series))
            emit knownMotorsChanged(m_motors.all());
    }
    /// The user's word on a drive no model read can tell (BusSession::setDriveIdentity).
    void setDriveIdentity(int id, protocol::Series series, protocol::Generation generation,
                          std::optional<double> gearRatio)
    {
        if (m_motors.setIdentity(id, series, generation, gearRatio))
            emit knownMotorsChanged(m_motors.all());
    }
    void learnModel(int id, const protocol::ModelInfo &model,
                    std::optional<protocol::Series> series);
    /// Make `id` known without a model (a drive answered but its model could not be read).
    void noteMotor(int id)
    {
        if (m_motors.noteSeen(id))
            emit knownMotorsChanged(m_motors.all());
    }
    void forgetMotors();
    void forgetMotors(int firstId, int lastId);
    void setTrafficCapture(bool enabled) { m_diagnostics.setTrafficCapture(enabled); }
    void resetStatistics() { m_diagnostics.counters().reset(); }

    const KnownMotors &knownMotors() const { return m_motors.all(); }
    std::optional<protocol::Series> seriesOf(int id) const;
    transport::Transport::State state() const;
    bool isOpen() const { return state() == transport::Transport::State::Open; }
    int baud() const;
    /// What the link carries (RS485 or CAN) and its timing at its bit rate.
    protocol::Link link() const { return m_link.link(); }
    LinkTiming timing() const { return m_link.timing(); }
    double now() const; ///< seconds since the worker was made (the session clock)
    bool isBusy() const { return m_wire.isBusy(); }
    /// Whether transmissions are held back now: the quiet period after a timeout.
    bool isQuiet() const { return m_wire.isQuiet(); }
    double currentMarginMs() const { return m_wire.timeouts().marginS() * 1e3; }
    /// The reply timeout a request of `command` to drive `id` gets now (a late reply of that
    /// drive lifts it for a while; AdaptiveTimeout).
    double replyTimeoutS(protocol::Command command, int id) const
    {
        return m_wire.timeouts().timeoutS(command, timing(), id);
    }
    /// The shortest sensible reply timeout: wire time + turnaround + BusConfig::minMarginMs,
    /// for probes where silence is the common answer (scan pass 1, emergency stop).
    double probeTimeoutS(protocol::Command command) const
    {
        return timing().replyTimeoutS(command, m_config.minMarginMs * 1e-3);
    }
    /// Replies that came after their request had timed out, since the last reset.
    quint64 lateReplyCount() const { return m_diagnostics.counters().busCounters().lateReplies; }
    /// When the latest-sent request that got a late reply went out (session clock, seconds;
    /// -1: none yet). A scan pass asks whether one of its own probes was answered late.
    double lateRequestSentTime() const { return m_wire.lateRequestSentTime(); }
    const BusConfig &config() const { return m_config; }
    /// The statistics now (also emitted by statisticsUpdated at BusConfig::statisticsHz).
    BusStatistics statisticsSnapshot();

signals:
    void connectionChanged(const lk::bus::ConnectionStatus &status);
    void errorOccurred(const lk::transport::TransportError &error);
    void requestCompleted(const lk::bus::RequestResult &result);
    /// One more halt of a stop has its result; `remaining` are still to come.
    void emergencyStopProgress(quint64 ticket, const QVector<int> &acknowledged,
                               const QVector<int> &silent, int remaining);
    /// `unsent`: the silent IDs whose halt never reached the wire.
    void emergencyStopFinished(quint64 ticket, const QVector<int> &acknowledged,
                               const QVector<int> &silent, const QVector<int> &unsent);
    /// An emergency stop sent nothing because the session listens only; emergencyStopFinished
    /// follows with every target silent and unsent. The machine must be stopped by its own
    /// emergency stop.
    void emergencyStopRefused(quint64 ticket, lk::bus::SendRefusal refusal);
    void scanProgress(const lk::bus::ScanProgress &progress);
    void motorFound(const lk::bus::FoundMotor &motor);
    void scanFinished(const lk::bus::ScanSummary &summary);
    void knownMotorsChanged(const lk::bus::KnownMotors &motors);
    void pollingChanged(bool active);
    void setpointStreamStarted(quint64 stream);
    void setpointStreamStopped(const lk::bus::SetpointStop &stop);
    void setpointFailed(quint64 stream, const lk::bus::RequestResult &result);
    void telemetryReceived(const lk::bus::TelemetryBatch &batch);
    void statisticsUpdated(const lk::bus::BusStatistics &statistics);
    /// What another master did (listen-only sessions only), beside statisticsUpdated.
    void listenStatisticsUpdated(const lk::bus::ListenStatistics &statistics);
    void trafficCaptured(const lk::bus::TrafficBatch &batch);
    /// The speed watch stopped a drive past its limit (after the stop's end).
    void speedWatchTripped(const lk::bus::SpeedWatchTrip &trip);
    /// The end of a multi-motor torque frame submitted without a completion.
    void multiTorqueCompleted(const lk::bus::MultiTorqueResult &result);

private:
    using Pending = PendingRequest;

    void wireLink();
    /// The link opened or dropped: start the stream afresh, or fail what is pending and hold
    /// polling; then the link reports its new state.
    void onLinkState(transport::Transport::State state, const QString &reason);
    void onBytes(const QByteArray &bytes);
    void onReplied(Pending p, protocol::Reply reply, double latencyS);
    /// An attempt failed: sent again when its command allows it, else completed.
    void onAttemptFailed(Pending p, RequestStatus status, const QString &reason);
    void schedulePump();
    void pumpNow();
    std::optional<Pending> takeNext();
    /// The bytes of `p` for its drive's context now; false (and `p` completed with the
    /// codec's reason) when the link and generation cannot carry its values.
    bool encode(Pending &p);
    void complete(Pending p, RequestStatus status, std::optional<protocol::Reply> reply,
                  const QString &reason, double latencyS, SendRefusal refusal = SendRefusal::None);
    /// True (and counted) when the session listens only: the caller then sends nothing.
    bool refuseListenOnly();
    void cancelQueued(const std::function<bool(const Pending &)> &which, RequestStatus status,
                      const QString &reason);
    void abortInflight(RequestStatus status, const QString &reason);
    void failAll(RequestStatus status, const QString &reason);
    /// Every way of stopping the setpoint stream: stops it, drops its queued setpoint and
    /// keeps the one on the wire from being sent again.
    void haltSetpoints(SetpointStopReason reason);
    void noteReply(const protocol::Reply &reply, double time, const Pending &request);
    /// Motor Stop to `id` from the emergency lane, for the speed watch: its setpoint stream
    /// and queued motion commands go first, so that nothing restarts it behind the stop.
    void stopForSpeedWatch(int id, Completion done);
    /// Defined in BusWorkerMotion.cpp (this file's twin is at its size limit):
    /// The refusal of a multi-motor frame by MultiTorqueGuard with the drives known now.
    std::optional<QString> multiTorqueRefusal(const QVector<protocol::Request> &torques) const;
    /// The multi-motor frame's bytes, checked again for the link and drives of now.
    bool encodeMultiTorque(Pending &p);
    /// Its end: each drive's result, the speed watch told of each, the replies published.
    void completeMultiTorque(Pending p, RequestStatus status, const QString &reason,
                             SendRefusal refusal);
    /// Whether `p` commands drive `id` (its own request, or a slot of its multi-motor frame).
    static bool commands(const Pending &p, int id);
    int retriesFor(const BusRequest &r) const;
    /// Whether sending `command` again after a timeout or a corrupt reply is harmless.
    static bool isRetrySafe(protocol::Command command);

    BusConfig m_config;
    TransportLink m_link; ///< a child, as the other QObjects here: they move threads with it
    std::shared_ptr<BusClock> m_clock; ///< the session clock: now() and every ns figure
    SingleShotTimerFactory m_timers;   ///< also the Scanner's
    MotorRegistry m_motors;
    BusDiagnostics m_diagnostics;
    WireExchange m_wire;

    RequestQueue m_queue;
    static constexpr int kMaxDirectPumps = 64;
    bool m_pumpPosted = false;
    bool m_inBytes = false;    ///< inside onBytes(): the parser is delivering events
    bool m_pumpWanted = false; ///< a completion inside onBytes() asked for the next send
    int m_directPumps = 0;     ///< sends started from onBytes() since the event loop's turn
    bool m_shutDown = false;

    PollRunner m_polls{m_timers, [this] { pumpNow(); }, [this] { schedulePump(); }, this};
    Scanner *m_scanner = nullptr;
    TelemetryBatcher m_telemetry;
    SetpointStream m_setpoints{*this, m_timers};
    int m_setpointDrive = 0; ///< the drive of the setpoint stream last started
    SpeedWatch m_speedWatch{
        [this](int id, Completion done) { stopForSpeedWatch(id, std::move(done)); },
        [this](int id) { return seriesOf(id); }, [this] { return now(); }, this};
    ReplyIntake m_intake{m_motors, m_telemetry};
    ListenMonitor m_listen{m_motors, m_telemetry, m_diagnostics, m_clock, this};
    quint64 m_refusedCalls = 0;
    QMap<int, safety::SoftLimits> m_softLimits; ///< by drive: the V2.36 speed's torque limit
    /// The drives the last multi-motor frame set turning: a speed-watch trip of one stops all.
    QVector<int> m_multiTorqueIds;
};

} // namespace lk::bus
