#include "BusWorker.h"

#include "BusLog.h"
#include "BusTiming.h"
#include "EmergencyStop.h"
#include "Scanner.h"

#include <protocol/Checksum.h>

#include <QtCore/QMetaObject>

#include <algorithm>
#include <cmath>

namespace lk::bus {

using protocol::Command;
using protocol::CommandTable;
using transport::Transport;

namespace {
constexpr int kTrafficIntervalMs = 50;

bool movesMotor(Command c)
{
    return CommandTable::info(c).movesMotor;
}

QString commandText(const protocol::Request &r)
{
    return QStringLiteral("%1 (ID %2)").arg(CommandTable::name(r.command)).arg(r.id);
}
} // namespace

BusWorker::BusWorker(TransportFactory factory, int baud, const BusConfig &config,
                     BusTimeSource time, QObject *parent)
    : QObject(parent), m_factory(std::move(factory)), m_baud(baud), m_config(config),
      m_clock(std::move(time.clock)), m_timers(std::move(time.timers)), m_timeout(config),
      m_telemetry(this, m_timers)
{
    m_matcher.setLocalEcho(config.localEcho);
    // The reply, quiet and poll timers pace the wire: precise. Statistics and traffic only
    // feed the screen: coarse, each restarted on its timeout (a periodic timer).
    m_replyTimer = m_timers(
        this, [this] { onTimeout(); }, Qt::PreciseTimer);
    m_pollTimer = m_timers(
        this, [this] { pumpNow(); }, Qt::PreciseTimer);
    m_quietTimer = m_timers(
        this, [this] { pumpNow(); }, Qt::PreciseTimer);
    m_statsTimer = m_timers(
        this,
        [this] {
            m_statsTimer->start(statisticsIntervalMs());
            emitStatistics();
        },
        Qt::CoarseTimer);
    m_trafficTimer = m_timers(
        this,
        [this] {
            m_trafficTimer->start(kTrafficIntervalMs);
            flushTraffic();
        },
        Qt::CoarseTimer);
    m_telemetry.setRateHz(config.telemetryHz);
    connect(&m_telemetry, &TelemetryBatcher::batchReady, this, &BusWorker::telemetryReceived);
    connect(&m_setpoints, &SetpointStream::started, this, &BusWorker::setpointStreamStarted);
    connect(&m_setpoints, &SetpointStream::stopped, this, &BusWorker::setpointStreamStopped);
    connect(&m_setpoints, &SetpointStream::setpointCompleted, this, &BusWorker::requestCompleted);
    connect(&m_setpoints, &SetpointStream::setpointFailed, this, &BusWorker::setpointFailed);
    m_poller.setSeriesLookup([this](int id) { return seriesOf(id); });
    m_reported.baud = baud;
}

BusWorker::~BusWorker()
{
    shutdown(tr("bus closed"));
}

void BusWorker::start()
{
    m_statsTimer->start(statisticsIntervalMs());
    attachTransport(m_factory ? m_factory(m_baud) : nullptr);
    openTransport();
}

void BusWorker::attachTransport(std::unique_ptr<Transport> t)
{
    dropTransport();
    m_transport = std::move(t);
    if (!m_transport)
        return;
    connect(m_transport.get(), &Transport::bytesReceived, this, &BusWorker::onBytes);
    connect(m_transport.get(), &Transport::stateChanged, this, &BusWorker::onTransportState);
    connect(m_transport.get(), &Transport::errorOccurred, this, &BusWorker::onTransportError);
}

void BusWorker::dropTransport()
{
    if (!m_transport)
        return;
    // Silence it first: closing on purpose is not a disconnect to report or to fail on.
    disconnect(m_transport.get(), nullptr, this, nullptr);
    m_transport->close();
    m_transport.reset();
}

bool BusWorker::openTransport()
{
    if (!m_transport) {
        m_lastError = tr("No transport: the transport factory returned nothing.");
        reportConnection(m_lastError);
        return false;
    }
    m_lastError.clear();
    m_parser.reset();
    const bool ok = m_transport->state() == Transport::State::Open || m_transport->open();
    if (ok)
        onTransportState(Transport::State::Open);
    else
        reportConnection(m_lastError);
    return ok;
}

void BusWorker::reconnect()
{
    if (m_shutDown)
        return;
    if (!m_transport)
        attachTransport(m_factory ? m_factory(m_baud) : nullptr);
    openTransport();
}

bool BusWorker::reopenAt(int baud)
{
    if (m_shutDown)
        return false;
    haltSetpoints(SetpointStopReason::BusChanged);
    abortInflight(RequestStatus::Cancelled, tr("the port was reopened at another baud"));
    m_matcher.reset();
    m_recentLatency.clear(); // another baud, other latencies
    m_baud = baud;
    attachTransport(m_factory ? m_factory(baud) : nullptr);
    return openTransport();
}

void BusWorker::shutdown(const QString &reason)
{
    if (m_shutDown)
        return;
    m_shutDown = true;
    if (m_scanner)
        m_scanner->cancel();
    m_poller.clear();
    failAll(RequestStatus::Cancelled, reason);
    dropTransport();
    for (SingleShotTimer *t : {m_replyTimer.get(), m_quietTimer.get(), m_pollTimer.get(),
                               m_statsTimer.get(), m_trafficTimer.get()})
        t->stop();
    m_telemetry.flush();
    m_reported.state = Transport::State::Closed;
    m_reported.reason = reason;
    emit connectionChanged(m_reported);
}

Transport::State BusWorker::state() const
{
    return m_transport ? m_transport->state() : Transport::State::Closed;
}

int BusWorker::baud() const
{
    return m_transport ? m_transport->baud() : m_baud;
}

double BusWorker::now() const
{
    return static_cast<double>(m_clock->nowNs()) * 1e-9;
}

void BusWorker::onTransportError(const transport::TransportError &error)
{
    m_lastError = error.message;
    recordTraffic(TrafficEvent::Kind::Note, {}, 0, 0, error.message);
    emit errorOccurred(error);
}

void BusWorker::onTransportState(Transport::State state)
{
    if (m_shutDown)
        return;
    if (state == Transport::State::Open) {
        m_parser.reset();
        m_matcher.reset();
        reportConnection();
        if (m_pollSuspended && (m_config.resumePollingOnReconnect || !m_poller.isActive()))
            setPollingSuspended(false);
        schedulePump();
        return;
    }
    const QString reason =
        m_lastError.isEmpty()
            ? (state == Transport::State::Closed ? tr("closed") : tr("disconnected"))
            : m_lastError;
    if (m_scanner && m_scanner->isRunning() && !m_scanner->isReopening())
        m_scanner->abort(reason);
    failAll(RequestStatus::Disconnected, reason);
    setPollingSuspended(true);
    reportConnection(reason);
}

void BusWorker::reportConnection(const QString &reason)
{
    ConnectionStatus s;
    s.state = state();
    s.description = m_transport ? m_transport->description() : QString();
    s.baud = baud();
    s.reason = s.state == Transport::State::Open ? QString() : reason;
    if (s.state == m_reported.state && s.description == m_reported.description &&
        s.baud == m_reported.baud && s.reason == m_reported.reason)
        return;
    m_reported = s;
    recordTraffic(TrafficEvent::Kind::Note, {}, 0, 0,
                  QStringLiteral("%1: %2").arg(s.description, s.isOpen() ? tr("open") : s.reason));
    emit connectionChanged(s);
}

void BusWorker::setConfig(const BusConfig &config)
{
    m_config = config;
    m_timeout.setConfig(config);
    m_telemetry.setRateHz(config.telemetryHz);
    m_matcher.setLocalEcho(config.localEcho);
    if (m_statsTimer->isActive())
        m_statsTimer->start(statisticsIntervalMs()); // as QTimer::setInterval: from now
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
    if (m_shutDown || !isOpen()) {
        const QString why = m_lastError.isEmpty() ? tr("the bus is not open") : m_lastError;
        complete(std::move(p), RequestStatus::Disconnected, std::nullopt, why, 0);
        return;
    }
    if (const std::optional<QString> why = unavailableReason(request.request)) {
        complete(std::move(p), RequestStatus::Error, std::nullopt, *why, 0);
        return;
    }
    p.bytes = request.request.encode();
    m_queue.push(std::move(p));
    schedulePump();
}

std::optional<QString> BusWorker::unavailableReason(const protocol::Request &request) const
{
    // Nothing a drive's generation lacks is sent to it (docs/V2.35.md section 3): it would stay
    // silent and the timeout would blame the wiring. Known only once its model was read.
    const auto it = m_motors.all().constFind(request.id);
    if (it == m_motors.all().cend() || !it->model ||
        protocol::CommandTable::availableOn(request.command, it->generation))
        return std::nullopt;
    return it->generation == protocol::Generation::V2_35
               ? tr("drive %1 runs firmware 2.35 or later (protocol V2.35), which has no %2; "
                    "nothing was sent")
                     .arg(request.id)
                     .arg(protocol::CommandTable::name(request.command))
               : tr("drive %1 speaks protocol V2.3, which has no %2 (firmware 2.35 added it); "
                    "nothing was sent")
                     .arg(request.id)
                     .arg(protocol::CommandTable::name(request.command));
}

int BusWorker::queuedCount() const
{
    return m_queue.size();
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
    if (!m_poller.isActive() || m_pollSuspended || isScanning())
        return std::nullopt;
    const double t = now();
    if (std::optional<protocol::Request> r = m_poller.next(t)) {
        Pending p;
        p.req.request = *r;
        p.req.priority = Priority::Background;
        p.req.retries = 0; // a missed sample is read again next cycle
        p.req.origin = RequestOrigin::Poll;
        p.bytes = r->encode();
        p.done = [this](const RequestResult &res) { onPollDone(res); };
        p.pollCycle = m_poller.cycle();
        p.pollCycleStart = m_poller.cycleStart();
        return p;
    }
    const double due = m_poller.nextDueTime(t);
    if (std::isfinite(due))
        m_pollTimer->start(std::max(0, static_cast<int>(std::ceil((due - t) * 1e3))));
    return std::nullopt;
}

void BusWorker::pumpNow()
{
    if (m_inflight || m_shutDown || !isOpen() || holdForQuiet())
        return;
    if (std::optional<Pending> p = takeNext())
        sendAttempt(std::move(*p));
}

void BusWorker::sendAttempt(Pending p)
{
    ++p.attempts;
    const protocol::Request &r = p.req.request;
    m_stats.requestSent(r.id, p.attempts > 1);
    recordTraffic(TrafficEvent::Kind::Sent, p.bytes, r.id, static_cast<quint8>(r.command));
    const double timeoutS = p.attempts == 1 && p.req.firstTimeoutS > 0
                                ? p.req.firstTimeoutS
                                : m_timeout.timeoutS(r.command, baud());
    const protocol::Request request = r;
    const QByteArray bytes = p.bytes;
    m_inflight = std::move(p);
    m_transport->write(bytes);
    if (!m_inflight)
        return; // the write lost the link, which failed the request
    // The reply clock starts once the bytes are handed to the port, not before: a thread
    // preempted between the two would otherwise have spent part of the timeout (and of a
    // probe's quiet period) before the request even left, and could talk over a drive that
    // answers in time. Replies are only read from the event loop, so expecting one now is
    // early enough.
    m_sentNs = m_clock->nowNs();
    m_matcher.expect(request, bytes, m_sentNs, m_sentNs + earliestReplyNs(request.command));
    m_replyTimer->start(std::max(1, static_cast<int>(std::ceil(timeoutS * 1e3))));
}

qint64 BusWorker::earliestReplyNs(Command command) const
{
    const double wireS = BusTiming::wireTimeS(BusTiming::requestBytes(command),
                                              BusTiming::replyBytes(command), baud());
    return static_cast<qint64>(m_recentLatency.earliestReplyS(wireS) * 1e9);
}

void BusWorker::onTimeout()
{
    if (!m_inflight)
        return;
    const protocol::Request &r = m_inflight->req.request;
    m_stats.timedOut(r.id);
    m_matcher.timedOut();
    beginQuiet(r, m_inflight->attempts == 1 && m_inflight->req.firstTimeoutS > 0);
    recordTraffic(TrafficEvent::Kind::Timeout, {}, r.id, static_cast<quint8>(r.command));
    failAttempt(RequestStatus::Timeout,
                tr("no reply to %1 after %n attempt(s)", nullptr, m_inflight->attempts)
                    .arg(commandText(r)));
}

void BusWorker::beginQuiet(const protocol::Request &request, bool probe)
{
    const qint64 lengthNs = static_cast<qint64>(m_timeout.quietS(request.command, baud()) * 1e9);
    // Silence is the common answer to a probe (scan, emergency stop), so it is not made to
    // wait twice: only until a reply from a drive that keeps its turnaround could have come
    // through this link, counted from the send. Often that is over already.
    const qint64 untilNs =
        probe ? m_sentNs +
                    static_cast<qint64>(m_timeout.replyDeadlineS(request.command, baud()) * 1e9)
              : m_clock->nowNs() + lengthNs;
    m_quiet.begin(untilNs, lengthNs, request.id, static_cast<quint8>(request.command));
}

bool BusWorker::holdForQuiet()
{
    const qint64 nowNs = m_clock->nowNs();
    const qint64 leftNs = m_quiet.leftNs(nowNs);
    if (leftNs <= 0)
        return false;
    if (!m_quietTimer->isActive() || m_quietTimerDueNs < nowNs + leftNs) {
        const int ms = static_cast<int>((leftNs + 999'999) / 1'000'000);
        m_quietTimer->start(ms);
        m_quietTimerDueNs = nowNs + qint64(ms) * 1'000'000;
    }
    return true;
}

void BusWorker::failAttempt(RequestStatus status, const QString &reason)
{
    Pending p = std::move(*m_inflight);
    m_inflight.reset();
    m_matcher.clear();
    m_replyTimer->stop();
    if (!p.noRetry && p.attempts <= retriesFor(p.req)) {
        // Back to the head of its own lane: an emergency stop still overtakes a retry. An
        // emergency motor_off retries at the back instead, so that every drive hears its
        // first "off" before any silent one is asked again.
        if (p.req.priority == Priority::Emergency)
            m_queue.push(std::move(p));
        else
            m_queue.pushFront(std::move(p));
    } else {
        complete(std::move(p), status, std::nullopt, reason, 0);
    }
    schedulePump();
}

void BusWorker::complete(Pending p, RequestStatus status, std::optional<protocol::Reply> reply,
                         const QString &reason, double latencyS)
{
    RequestResult r;
    r.ticket = p.req.ticket;
    r.request = p.req.request;
    r.priority = p.req.priority;
    r.status = status;
    r.reply = std::move(reply);
    r.reason = reason;
    r.latencyMs = latencyS * 1e3;
    r.attempts = p.attempts;
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
    if (!m_inflight)
        return;
    Pending p = std::move(*m_inflight);
    m_inflight.reset();
    m_matcher.clear();
    m_replyTimer->stop();
    complete(std::move(p), status, std::nullopt, reason, 0);
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
    if (!m_inflight) // with a request in flight these are its reply, not an old one's tail
        m_quiet.bytesArrived(m_clock->nowNs());
    m_quiet.chunkStarted();
    m_inBytes = true;
    m_parser.feed(bytes, [this](const protocol::ParseEvent &ev) { onParseEvent(ev); });
    m_inBytes = false;
    if (m_quiet.endIfAnswered(m_parser.pendingBytes() == 0, m_clock->nowNs())) {
        // The late reply is all here and nothing follows it: the wire is free again.
        m_quietTimer->stop();
        m_pumpWanted = true;
    }
    if (m_pumpWanted) {
        // A transport that delivers at once (SimTransport without delays) would otherwise
        // keep us inside its signal forever: every kMaxDirectPumps the event loop gets a turn.
        m_pumpWanted = false;
        ++m_directPumps;
        pumpNow();
    }
}

void BusWorker::onParseEvent(const protocol::ParseEvent &ev)
{
    recordParseEvent(ev);
    using V = ReplyMatcher::Verdict;
    const protocol::Frame &f = ev.frame;
    ReplyMatcher::Outcome out =
        m_matcher.classify(ev, m_motors.decodeContext(f.id), m_clock->nowNs());
    switch (out.verdict) {
    case V::Fault:
        m_stats.parseFault(ev);
        return;
    case V::CorruptReply:
        // Retry now rather than wait for the timeout.
        m_stats.parseFault(ev);
        failAttempt(RequestStatus::Error, tr("corrupt reply to %1 (bad data checksum)")
                                              .arg(commandText(m_inflight->req.request)));
        return;
    case V::LocalEcho:
        m_stats.localEcho();
        return;
    case V::Undecodable:
        m_stats.undecodable(f.id);
        failAttempt(RequestStatus::Error,
                    tr("undecodable reply to %1").arg(commandText(m_inflight->req.request)));
        return;
    case V::LateReply:
        // The link is slower than the margin assumed: let the margin learn from it.
        m_stats.lateReply(f.id);
        m_timeout.addLateReply(static_cast<Command>(f.command), baud(), out.lateLatencyS);
        m_lateRequestSentS = std::max(m_lateRequestSentS, now() - out.lateLatencyS);
        m_quiet.lateFrameParsed(f.id, f.command);
        return;
    case V::Unexpected:
        m_stats.unexpectedFrame(f.id);
        return;
    case V::Reply:
        completeWithReply(std::move(*out.reply));
        return;
    }
}

void BusWorker::completeWithReply(protocol::Reply reply)
{
    const double latency = static_cast<double>(m_clock->nowNs() - m_sentNs) * 1e-9;
    m_recentLatency.add(latency);
    m_stats.replyReceived(reply.id, latency);
    m_timeout.addReply(reply.command, baud(), latency);
    Pending p = std::move(*m_inflight);
    m_inflight.reset();
    m_matcher.clear();
    m_replyTimer->stop();
    noteReply(reply, now(), p);
    complete(std::move(p), RequestStatus::Ok, std::move(reply), {}, latency);
    schedulePump();
}

void BusWorker::noteReply(const protocol::Reply &reply, double time, const Pending &request)
{
    bool changed = m_motors.noteSeen(reply.id);
    // A model reply tells the drive's generation, whoever asked for it (a scan, lkctl info,
    // the drive-info view): later replies from it are decoded with its layouts.
    if (const auto *model = std::get_if<protocol::ModelInfo>(&reply.payload))
        changed = m_motors.learnModel(reply.id, *model, std::nullopt) || changed;
    if (changed)
        emit knownMotorsChanged(m_motors.all());
    if (std::optional<TelemetrySample> s = TelemetrySample::fromReply(reply, time)) {
        s->cycle = request.pollCycle; // which poll round it answers: rows are built per round
        s->cycleTime = request.pollCycleStart;
        m_telemetry.add(*s);
    }
}

void BusWorker::emergencyStop(quint64 ticket, const QVector<int> &ids, Command halt)
{
    // The setpoint stream first: no setpoint may follow the stop, whatever the GUI does.
    haltSetpoints(SetpointStopReason::EmergencyStop);
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
    // drive hears it quickly, and silent IDs are asked again at the back of the lane.
    for (BusRequest &r : offs)
        r.firstTimeoutS = probeTimeoutS(halt);
    qCInfo(lcBus) << "emergency" << CommandTable::name(halt) << "to" << offs.size() << "ID(s)";
    cancelQueued([](const Pending &p) { return movesMotor(p.req.request.command); },
                 RequestStatus::Cancelled, tr("cancelled by emergency stop"));
    if (m_inflight && movesMotor(m_inflight->req.request.command))
        m_inflight->noRetry = true; // it may finish, but it is not sent again
    for (const BusRequest &r : offs) {
        submit(r, [this, stop](const RequestResult &res) {
            emit requestCompleted(res);
            if (stop->record(res))
                emit emergencyStopFinished(stop->ticket(), stop->acknowledged(), stop->silent(),
                                           stop->unsent());
        });
    }
}

void BusWorker::scan(const ScanOptions &options)
{
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
    m_poller.setPlan(plan, now());
    m_pollSuspended = !isOpen();
    emit pollingChanged(m_poller.isActive() && !m_pollSuspended);
    schedulePump();
}

void BusWorker::stopPolling()
{
    const bool was = m_poller.isActive() && !m_pollSuspended;
    m_poller.clear();
    m_pollTimer->stop();
    m_pollSuspended = false;
    if (was)
        emit pollingChanged(false);
}

void BusWorker::startSetpointStream(const SetpointStreamPlan &plan)
{
    m_setpoints.start(plan);
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
    if (m_inflight && m_inflight->req.origin == RequestOrigin::Setpoint)
        m_inflight->noRetry = true;
}

void BusWorker::setPollingSuspended(bool suspended)
{
    if (!m_poller.isActive() || m_pollSuspended == suspended)
        return;
    m_pollSuspended = suspended;
    if (suspended)
        m_pollTimer->stop();
    emit pollingChanged(!suspended);
}

void BusWorker::onPollDone(const RequestResult &r)
{
    m_poller.completed(r.request.id, r.request.command);
    schedulePump();
}

std::optional<protocol::Series> BusWorker::seriesOf(int id) const
{
    return m_motors.series(id);
}

void BusWorker::setSeries(int id, protocol::Series series)
{
    if (m_motors.setSeries(id, series))
        emit knownMotorsChanged(m_motors.all());
}

void BusWorker::learnModel(int id, const protocol::ModelInfo &model,
                           std::optional<protocol::Series> series)
{
    if (m_motors.learnModel(id, model, series))
        emit knownMotorsChanged(m_motors.all());
}

void BusWorker::noteMotor(int id)
{
    if (m_motors.noteSeen(id))
        emit knownMotorsChanged(m_motors.all());
}

double BusWorker::probeTimeoutS(Command command) const
{
    return BusTiming::replyTimeoutS(command, baud(), m_config.minMarginMs * 1e-3);
}

quint64 BusWorker::lateReplyCount() const
{
    return m_stats.busCounters().lateReplies;
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

void BusWorker::resetStatistics()
{
    m_stats.reset();
}

BusStatistics BusWorker::statisticsSnapshot()
{
    BusStatistics s = m_stats.snapshot(now());
    s.baud = baud();
    s.timeoutMarginMs = currentMarginMs();
    const std::optional<double> turnaround = m_timeout.measuredTurnaroundS();
    const double turnaroundS = turnaround.value_or(BusTiming::kTurnaroundS);
    s.turnaroundMs = turnaroundS * 1e3;
    s.turnaroundMeasured = turnaround.has_value();
    s.pollLimitPerSecond =
        m_poller.isActive() ? m_poller.busLimitPerSecond(baud(), turnaroundS) : 0;
    s.pollCycleLimitHz = m_poller.isActive() ? m_poller.cycleLimitHz(baud(), turnaroundS) : 0;
    return s;
}

void BusWorker::emitStatistics()
{
    emit statisticsUpdated(statisticsSnapshot());
}

int BusWorker::statisticsIntervalMs() const
{
    return static_cast<int>(1000.0 / std::max(0.1, m_config.statisticsHz));
}

void BusWorker::setTrafficCapture(bool enabled)
{
    m_traffic.setEnabled(enabled);
    if (enabled)
        m_trafficTimer->start(kTrafficIntervalMs);
    else
        m_trafficTimer->stop();
}

void BusWorker::flushTraffic()
{
    if (m_traffic.hasPending())
        emit trafficCaptured(m_traffic.take(now()));
}

void BusWorker::recordParseEvent(const protocol::ParseEvent &ev)
{
    if (!m_traffic.isEnabled())
        return;
    // The context of this moment goes with the frame: a series learnt later must not change
    // how an earlier row reads.
    m_traffic.recordParseEvent(
        ev, now(), ev.isFrame ? m_motors.decodeContext(ev.frame.id) : protocol::DecodeContext{});
}

void BusWorker::recordTraffic(TrafficEvent::Kind kind, const QByteArray &bytes, int id,
                              quint8 command, const QString &text)
{
    if (!m_traffic.isEnabled())
        return;
    if (kind == TrafficEvent::Kind::Sent)
        m_traffic.recordSent(now(), bytes, m_motors.decodeContext(id));
    else
        m_traffic.record(kind, now(), bytes, id, command, text);
}

} // namespace lk::bus
