#include "BusWorker.h"

#include "BusLog.h"
#include "EmergencyStop.h"
#include "Scanner.h"
#include "WireEncoding.h"

#include <protocol/Checksum.h>

#include <QtCore/QMetaObject>

#include <algorithm>
#include <cmath>

namespace lk::bus {

using protocol::Command;
using protocol::CommandTable;
using transport::Transport;

namespace {
bool movesMotor(Command c)
{
    return CommandTable::info(c).movesMotor;
}
} // namespace

BusWorker::BusWorker(TransportFactory factory, int baud, const BusConfig &config,
                     BusTimeSource time, QObject *parent)
    : QObject(parent), m_config(config), m_link(std::move(factory), baud, this),
      m_clock(std::move(time.clock)), m_timers(std::move(time.timers)),
      m_diagnostics(m_motors, m_clock, m_timers, this),
      m_wire(m_link, m_motors, m_diagnostics, m_clock, m_timers, config, this),
      m_telemetry(this, m_timers)
{
    m_wire.setOutcomes({[this](Pending p, protocol::Reply reply, double latencyS) {
                            onReplied(std::move(p), std::move(reply), latencyS);
                        },
                        [this](Pending p, RequestStatus status, const QString &reason) {
                            onAttemptFailed(std::move(p), status, reason);
                        },
                        [this] { pumpNow(); },
                        [this](int id, protocol::Generation generation) {
                            if (m_motors.learnCanGeneration(id, generation))
                                emit knownMotorsChanged(m_motors.all());
                        }});
    connect(&m_diagnostics, &BusDiagnostics::statisticsDue, this, [this] {
        emit statisticsUpdated(statisticsSnapshot());
        if (linkMode() == LinkMode::ListenOnly)
            emit listenStatisticsUpdated(m_listen.snapshot(this->baud()));
    });
    connect(&m_listen, &ListenMonitor::motorsChanged, this,
            [this] { emit knownMotorsChanged(m_motors.all()); });
    connect(&m_diagnostics, &BusDiagnostics::trafficCaptured, this, &BusWorker::trafficCaptured);
    m_telemetry.setRateHz(config.telemetryHz);
    connect(&m_telemetry, &TelemetryBatcher::batchReady, this, &BusWorker::telemetryReceived);
    connect(&m_setpoints, &SetpointStream::started, this, &BusWorker::setpointStreamStarted);
    connect(&m_setpoints, &SetpointStream::stopped, this, &BusWorker::setpointStreamStopped);
    connect(&m_setpoints, &SetpointStream::setpointCompleted, this, &BusWorker::requestCompleted);
    connect(&m_setpoints, &SetpointStream::setpointFailed, this, &BusWorker::setpointFailed);
    m_polls.scheduler().setSeriesLookup([this](int id) { return seriesOf(id); });
    connect(&m_polls, &PollRunner::pollingChanged, this, &BusWorker::pollingChanged);
    connect(&m_speedWatch, &SpeedWatch::watchedChanged, this, [this](const QVector<int> &ids) {
        m_polls.setWatched(ids);
        schedulePump();
    });
    connect(&m_speedWatch, &SpeedWatch::tripped, this, &BusWorker::speedWatchTripped);
    wireLink();
}

BusWorker::~BusWorker()
{
    shutdown(tr("bus closed"));
}

void BusWorker::wireLink()
{
    connect(&m_link, &TransportLink::bytesReceived, this, &BusWorker::onBytes);
    connect(&m_link, &TransportLink::stateChanged, this, &BusWorker::onLinkState);
    connect(&m_link, &TransportLink::errorOccurred, this,
            [this](const transport::TransportError &error) {
                m_diagnostics.recordNote(error.message);
                emit errorOccurred(error);
            });
    connect(&m_link, &TransportLink::connectionChanged, this, [this](const ConnectionStatus &s) {
        if (!m_shutDown) // the last word of shutdown(): no capture is delivered after it
            m_diagnostics.recordNote(
                QStringLiteral("%1: %2").arg(s.description, s.isOpen() ? tr("open") : s.reason));
        emit connectionChanged(s);
    });
}

void BusWorker::start(LinkMode mode)
{
    m_link.setMode(mode);
    m_diagnostics.startStatistics(m_config.statisticsHz);
    m_link.start();
}

bool BusWorker::takeOver()
{
    if (m_shutDown || linkMode() == LinkMode::Active)
        return isOpen();
    qCInfo(lcBus) << "taking over the bus: the port reopens read-write";
    m_link.setMode(LinkMode::Active);
    m_wire.restartStream();
    return m_link.reopenAt(baud()); // a new transport, read-write; its open reports the mode
}

bool BusWorker::refuseListenOnly()
{
    if (linkMode() != LinkMode::ListenOnly)
        return false;
    ++m_refusedCalls;
    return true;
}

void BusWorker::reconnect()
{
    if (m_shutDown)
        return;
    m_link.reopen();
}

bool BusWorker::reopenAt(int baud)
{
    if (m_shutDown)
        return false;
    haltSetpoints(SetpointStopReason::BusChanged);
    abortInflight(RequestStatus::Cancelled, tr("the port was reopened at another baud"));
    m_wire.restartStream();
    m_wire.forgetLatencies(); // another baud, other latencies
    return m_link.reopenAt(baud);
}

void BusWorker::shutdown(const QString &reason)
{
    if (m_shutDown)
        return;
    m_shutDown = true;
    if (m_scanner)
        m_scanner->cancel();
    m_polls.clear();
    failAll(RequestStatus::Cancelled, reason);
    m_wire.stop();
    m_diagnostics.stop();
    m_telemetry.flush();
    m_link.close(reason);
}

Transport::State BusWorker::state() const
{
    return m_link.state();
}

int BusWorker::baud() const
{
    return m_link.baud();
}

double BusWorker::now() const
{
    return static_cast<double>(m_clock->nowNs()) * 1e-9;
}

void BusWorker::onLinkState(Transport::State state, const QString &reason)
{
    if (m_shutDown)
        return;
    if (state == Transport::State::Open) {
        m_motors.setLink(m_link.link());
        m_wire.restartStream();
        m_listen.restart(m_link.link());
        m_link.report();
        if (m_polls.isSuspended() && (m_config.resumePollingOnReconnect || !m_polls.isActive()))
            m_polls.setSuspended(false);
        schedulePump();
        return;
    }
    if (m_scanner && m_scanner->isRunning() && !m_scanner->isReopening())
        m_scanner->abort(reason);
    failAll(RequestStatus::Disconnected, reason);
    m_polls.setSuspended(true);
    m_link.report(reason);
}

void BusWorker::setConfig(const BusConfig &config)
{
    m_config = config;
    m_wire.setConfig(config);
    m_telemetry.setRateHz(config.telemetryHz);
    m_diagnostics.setStatisticsHz(config.statisticsHz);
}

bool BusWorker::isRetrySafe(Command command)
{
    // A timeout does not mean the drive did not act: a repeated incremental move moves twice,
    // a repeated flash write (0x32, 0x91, 0x19) wears the chip twice. The caller hears of the
    // timeout and reads back instead. Everything else is idempotent (a target, a state, a read).
    if (CommandTable::info(command).writesFlash)
        return false;
    return command != Command::IncrementPosition && command != Command::IncrementPositionLimited;
}

int BusWorker::retriesFor(const BusRequest &r) const
{
    if (!isRetrySafe(r.request.command))
        return 0;
    return r.retries >= 0 ? r.retries : m_config.retries;
}

void BusWorker::submit(BusRequest request, Completion done)
{
    if (request.priority == Priority::Emergency && request.request.command != Command::MotorOff &&
        request.request.command != Command::MotorStop)
        request.priority = Priority::Operator; // nothing moves a motor from the emergency lane
    Pending p;
    p.req = request;
    p.done = std::move(done);
    if (refuseListenOnly()) {
        complete(std::move(p), RequestStatus::Error, std::nullopt, listenOnlyReason(), 0,
                 SendRefusal::ListenOnly);
        return;
    }
    if (m_shutDown || !isOpen()) {
        const QString why =
            m_link.lastError().isEmpty() ? tr("the bus is not open") : m_link.lastError();
        complete(std::move(p), RequestStatus::Disconnected, std::nullopt, why, 0);
        return;
    }
    if (const std::optional<QString> why = m_motors.unavailableReason(request.request)) {
        complete(std::move(p), RequestStatus::Error, std::nullopt, *why, 0);
        return;
    }
    m_queue.push(std::move(p)); // encoded when it goes out, with the drive's context then

    schedulePump();
}

void BusWorker::schedulePump()
{
    if (m_shutDown)
        return;
    // Completions run inside the parser's callback: the next write must not happen
    // re-entrantly from there. onBytes() sends it once the parser is done with the chunk,
    // without waiting for another turn of the event loop (that turn costs throughput).
    if (m_inBytes && m_directPumps < kMaxDirectPumps) {
        m_pumpWanted = true;
        return;
    }
    if (m_pumpPosted)
        return;
    m_pumpPosted = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_pumpPosted = false;
            m_directPumps = 0; // the event loop had its turn
            pumpNow();
        },
        Qt::QueuedConnection);
}

std::optional<BusWorker::Pending> BusWorker::takeNext()
{
    if (std::optional<Pending> p = m_queue.takeNext())
        return p;
    if (isScanning())
        return std::nullopt;
    return m_polls.next(now());
}

void BusWorker::pumpNow()
{
    if (m_wire.isBusy() || m_shutDown || !isOpen() || linkMode() == LinkMode::ListenOnly ||
        m_wire.holdForQuiet())
        return;
    while (std::optional<Pending> p = takeNext()) {
        if (p->bytes.isEmpty() && !encode(*p))
            continue; // refused and completed: the next one may go
        m_wire.send(std::move(*p));
        return;
    }
}

bool BusWorker::encode(Pending &p)
{
    if (!p.req.group.isEmpty())
        return encodeMultiTorque(p);
    const protocol::Request &r = p.req.request;
    const auto limits = m_softLimits.constFind(r.id);
    const protocol::WireEncodeResult e = encodeForWire(
        p.req.request, m_motors.decodeContext(r.id),
        limits == m_softLimits.cend() ? nullptr : &*limits, m_motors.series(r.id).has_value());
    p.bytes = e.bytes;
    if (e.ok())
        return true;
    // A value this link and generation cannot carry: nothing is sent, the caller hears why.
    const QString why = tr("%1 to drive %2 was not sent: %3")
                            .arg(CommandTable::name(r.command))
                            .arg(r.id)
                            .arg(e.error.message());
    complete(std::move(p), RequestStatus::Error, std::nullopt, why, 0);
    return false;
}

void BusWorker::onAttemptFailed(Pending p, RequestStatus status, const QString &reason)
{
    if (!p.noRetry && p.attempts <= retriesFor(p.req)) {
        // Back to the head of its own lane: an emergency stop still overtakes a retry. An
        // emergency motor_off retries behind the other drives' first "off" instead, but ahead
        // of the one-attempt probes of IDs nobody has seen: a known drive whose "off" or reply
        // was lost is asked again within milliseconds, not after 28 silent IDs.
        if (p.req.priority == Priority::Emergency)
            m_queue.pushBefore(std::move(p), [](const Pending &q) {
                return q.req.origin == RequestOrigin::Emergency && q.req.retries == 0 &&
                       q.attempts == 0;
            });
        else
            m_queue.pushFront(std::move(p));
    } else {
        complete(std::move(p), status, std::nullopt, reason, 0);
    }
    schedulePump();
}

void BusWorker::complete(Pending p, RequestStatus status, std::optional<protocol::Reply> reply,
                         const QString &reason, double latencyS, SendRefusal refusal)
{
    if (!p.req.group.isEmpty())
        return completeMultiTorque(std::move(p), status, reason, refusal);
    m_speedWatch.noteRequestEnded(p.req.request, status, p.attempts);
    RequestResult r;
    r.ticket = p.req.ticket;
    r.request = p.req.request;
    r.priority = p.req.priority;
    r.status = status;
    r.reply = std::move(reply);
    r.reason = reason;
    r.latencyMs = latencyS * 1e3;
    r.attempts = p.attempts;
    r.refusal = refusal;
    if (p.done)
        p.done(r);
    else
        emit requestCompleted(r);
}

void BusWorker::cancelQueued(const std::function<bool(const Pending &)> &which,
                             RequestStatus status, const QString &reason)
{
    std::vector<Pending> out = m_queue.takeIf(which);
    // Completions run after the queues are consistent: they may submit again.
    for (Pending &p : out)
        complete(std::move(p), status, std::nullopt, reason, 0);
}

void BusWorker::abortInflight(RequestStatus status, const QString &reason)
{
    if (std::optional<Pending> p = m_wire.abort())
        complete(std::move(*p), status, std::nullopt, reason, 0);
}

void BusWorker::failAll(RequestStatus status, const QString &reason)
{
    haltSetpoints(status == RequestStatus::Disconnected ? SetpointStopReason::Disconnected
                                                        : SetpointStopReason::Closed);
    abortInflight(status, reason);
    cancelQueued([](const Pending &) { return true; }, status, reason);
}

void BusWorker::onBytes(const QByteArray &bytes)
{
    if (linkMode() == LinkMode::ListenOnly) {
        m_listen.feed(bytes, baud()); // another master's traffic: nothing of ours is on the wire
        return;
    }
    // Completions inside the parser's callback only ask for the next send (schedulePump).
    m_inBytes = true;
    if (m_wire.feed(bytes))
        m_pumpWanted = true; // the late reply is all here and nothing follows: the wire is free
    m_inBytes = false;
    if (m_pumpWanted) {
        // A transport that delivers at once (SimTransport without delays) would otherwise
        // keep us inside its signal forever: every kMaxDirectPumps the event loop gets a turn.
        m_pumpWanted = false;
        ++m_directPumps;
        pumpNow();
    }
}

void BusWorker::onReplied(Pending p, protocol::Reply reply, double latencyS)
{
    if (p.req.group.isEmpty()) // a multi-motor frame publishes each drive's reply at its end
        noteReply(reply, now(), p);
    complete(std::move(p), RequestStatus::Ok, std::move(reply), {}, latencyS);
    schedulePump();
}

void BusWorker::noteReply(const protocol::Reply &reply, double time, const Pending &request)
{
    bool motorsChanged = false;
    const ReplyIntake::Asked asked{request.req.request.command,
                                   request.req.origin == RequestOrigin::Scan, request.pollCycle,
                                   request.pollCycleStart};
    const std::optional<TelemetrySample> s = m_intake.take(reply, time, asked, motorsChanged);
    if (motorsChanged)
        emit knownMotorsChanged(m_motors.all());
    if (s)
        m_speedWatch.noteSample(*s);
}

void BusWorker::emergencyStop(quint64 ticket, const QVector<int> &ids, Command halt)
{
    // The setpoint stream first: no setpoint may follow the stop, whatever the GUI does.
    haltSetpoints(SetpointStopReason::EmergencyStop);
    // The stop ends every multi-motor frame's group: a later trip names only its own drive.
    m_multiTorqueIds.clear();
    if (refuseListenOnly()) {
        // Nothing may go on a bus another master owns: the stop says so rather than claim one.
        const QVector<int> targets = m_motors.emergencyTargets(ids).all();
        qCWarning(lcBus) << "emergency stop in listen-only mode: nothing was sent";
        emit emergencyStopRefused(ticket, SendRefusal::ListenOnly);
        emit emergencyStopFinished(ticket, {}, targets, targets);
        return;
    }
    if (halt != Command::MotorStop)
        halt = Command::MotorOff; // nothing else may ride in this lane
    // A running scan would go on probing (and a baud sweep reopening the port) behind the
    // stop: it ends here, in this same call, before the offs are queued.
    if (isScanning())
        cancelScan();
    auto stop = std::make_shared<EmergencyStop>(ticket, m_motors.emergencyTargets(ids),
                                                m_config.emergencyRetries, halt);
    QVector<BusRequest> offs = stop->requests();
    // The first "off" to each ID waits only as long as a drive on a fast link needs: every
    // drive hears it quickly; known drives that stay silent are asked again before the IDs
    // nobody has seen (onAttemptFailed).
    for (BusRequest &r : offs)
        r.firstTimeoutS = probeTimeoutS(halt);
    qCInfo(lcBus) << "emergency" << CommandTable::name(halt) << "to" << offs.size() << "ID(s)";
    cancelQueued([](const Pending &p) { return movesMotor(p.req.request.command); },
                 RequestStatus::Cancelled, tr("cancelled by emergency stop"));
    if (Pending *p = m_wire.inflight(); p && movesMotor(p->req.request.command))
        p->noRetry = true; // it may finish, but it is not sent again
    m_wire.hurry();        // a poll on the wire is waited for only as long as the wire needs
    for (const BusRequest &r : offs) {
        submit(r, [this, stop](const RequestResult &res) {
            emit requestCompleted(res);
            if (stop->record(res))
                emit emergencyStopFinished(stop->ticket(), stop->acknowledged(), stop->silent(),
                                           stop->unsent());
            else
                emit emergencyStopProgress(stop->ticket(), stop->acknowledged(), stop->silent(),
                                           stop->remaining());
        });
    }
}

void BusWorker::scan(const ScanOptions &options)
{
    if (refuseListenOnly()) {
        emit scanFinished(ScanSummary::refusedListenOnly(baud()));
        return;
    }
    if (!m_scanner) {
        m_scanner = new Scanner(*this, m_timers, this);
        connect(m_scanner, &Scanner::progress, this, &BusWorker::scanProgress);
        connect(m_scanner, &Scanner::found, this, &BusWorker::motorFound);
        connect(m_scanner, &Scanner::finished, this, [this](const ScanSummary &s) {
            emit scanFinished(s);
            schedulePump(); // polling paused for the scan resumes
        });
    }
    m_scanner->start(options);
}

void BusWorker::cancelScan()
{
    if (m_scanner)
        m_scanner->cancel();
    cancelQueued([](const Pending &p) { return p.req.origin == RequestOrigin::Scan; },
                 RequestStatus::Cancelled, tr("scan cancelled"));
}

bool BusWorker::isScanning() const
{
    return m_scanner && m_scanner->isRunning();
}

void BusWorker::startPolling(const PollPlan &plan)
{
    if (refuseListenOnly())
        return; // BusSession posts its plan again after takeOver()
    m_polls.start(plan, now(), isOpen());
    schedulePump();
}

void BusWorker::stopPolling()
{
    m_polls.stop();
}

void BusWorker::startSetpointStream(const SetpointStreamPlan &plan)
{
    if (refuseListenOnly()) {
        emit setpointStreamStopped(SetpointStop::refusedListenOnly(plan.stream));
        return;
    }
    m_setpointDrive = plan.id;
    m_setpoints.start(plan);
}

void BusWorker::setSoftLimits(int id, const safety::SoftLimits &limits)
{
    m_softLimits.insert(id, limits);
    m_speedWatch.setSoftLimits(id, limits);
}

void BusWorker::stopSetpointStream()
{
    haltSetpoints(SetpointStopReason::Requested);
}

void BusWorker::haltSetpoints(SetpointStopReason reason)
{
    m_setpoints.stop(reason);
    // A setpoint still queued would go out after the stop the caller sends next (or at the
    // next baud); one on the wire may finish, but a timeout must not send it again ahead of
    // that stop.
    cancelQueued([](const Pending &p) { return p.req.origin == RequestOrigin::Setpoint; },
                 RequestStatus::Cancelled, tr("setpoint stream stopped"));
    if (Pending *p = m_wire.inflight(); p && p->req.origin == RequestOrigin::Setpoint)
        p->noRetry = true;
}

std::optional<protocol::Series> BusWorker::seriesOf(int id) const
{
    return m_motors.series(id);
}

void BusWorker::learnModel(int id, const protocol::ModelInfo &model,
                           std::optional<protocol::Series> series)
{
    if (m_motors.learnModel(id, model, series))
        emit knownMotorsChanged(m_motors.all());
}

void BusWorker::forgetMotors()
{
    forgetMotors(protocol::kMinId, protocol::kMaxId);
}

void BusWorker::forgetMotors(int firstId, int lastId)
{
    if (m_motors.forget(firstId, lastId))
        emit knownMotorsChanged(m_motors.all());
}

BusStatistics BusWorker::statisticsSnapshot()
{
    BusStatistics s = m_diagnostics.counters().snapshot(now());
    s.baud = baud();
    s.link = link();
    s.mode = linkMode();
    s.listenOnlyRefusals = m_refusedCalls;
    s.timeoutMarginMs = currentMarginMs();
    const std::optional<double> turnaround = m_wire.timeouts().measuredTurnaroundS();
    const LinkTiming t = timing();
    const double turnaroundS = turnaround.value_or(t.turnaroundS());
    s.turnaroundMs = turnaroundS * 1e3;
    s.turnaroundMeasured = turnaround.has_value();
    const PollScheduler &polls = m_polls.scheduler();
    s.pollLimitPerSecond = polls.isActive() ? polls.busLimitPerSecond(t, turnaroundS) : 0;
    s.pollCycleLimitHz = polls.isActive() ? polls.cycleLimitHz(t, turnaroundS) : 0;
    return s;
}

} // namespace lk::bus
