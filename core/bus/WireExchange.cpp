#include "WireExchange.h"

#include "BusDiagnostics.h"
#include "MotorRegistry.h"
#include "TransportLink.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecordParser.h>

#include <QtCore/QStringList>

#include <algorithm>
#include <cmath>

namespace lk::bus {

using protocol::Command;

namespace {
QString commandText(const protocol::Request &r)
{
    return QStringLiteral("%1 (ID %2)").arg(protocol::CommandTable::name(r.command)).arg(r.id);
}

/// A frame's length on the wire: header, data and, with data, its checksum (on CAN the
/// timing counts 8 data bytes, whatever this says).
int wireBytes(const protocol::Frame &f)
{
    const int data = static_cast<int>(f.data.size());
    return protocol::kHeaderSize + data + (data > 0 ? 1 : 0);
}
} // namespace

WireExchange::WireExchange(TransportLink &link, const MotorRegistry &motors,
                           BusDiagnostics &diagnostics, std::shared_ptr<BusClock> clock,
                           const SingleShotTimerFactory &timers, const BusConfig &config,
                           QObject *parent)
    : QObject(parent), m_link(link), m_motors(motors), m_diagnostics(diagnostics),
      m_clock(std::move(clock)), m_parser(protocol::makeFrameParser(protocol::Link::Rs485)),
      m_timeout(config)
{
    m_matcher.setLocalEcho(config.localEcho);
    // Both pace the wire: precise.
    m_replyTimer = timers(
        this, [this] { onTimeout(); }, Qt::PreciseTimer);
    m_quietTimer = timers(
        this,
        [this] {
            if (m_outcomes.quietOver)
                m_outcomes.quietOver();
        },
        Qt::PreciseTimer);
}

WireExchange::~WireExchange() = default;

void WireExchange::setConfig(const BusConfig &config)
{
    m_timeout.setConfig(config);
    m_matcher.setLocalEcho(config.localEcho);
}

void WireExchange::restartStream()
{
    m_parser = protocol::makeFrameParser(m_link.link(), protocol::LinkEnd::Host);
    if (auto *can = dynamic_cast<protocol::CanRecordParser *>(m_parser.get())) {
        // Error frames and other devices' frames are no fault of the LK protocol: counted
        // apart (the transport reads the bus condition from the error frames).
        can->setErrorFrameSink(
            [this](const protocol::CanRecord &) { m_diagnostics.counters().canErrorFrame(); });
        can->setOtherFrameSink(
            [this](const protocol::CanRecord &) { m_diagnostics.counters().otherFrame(); });
    }
    m_matcher.reset();
}

int WireExchange::baud() const
{
    return m_link.baud();
}

LinkTiming WireExchange::timing() const
{
    return m_link.timing();
}

void WireExchange::send(Pending p)
{
    ++p.attempts;
    const protocol::Request &r = p.req.request;
    // A multi-motor frame is a request to each drive it names: each counts one, as each
    // counts its reply or its timeout.
    if (p.req.group.isEmpty())
        m_diagnostics.counters().requestSent(r.id, p.attempts > 1);
    for (const protocol::Request &member : std::as_const(p.req.group))
        m_diagnostics.counters().requestSent(member.id, p.attempts > 1);
    m_diagnostics.recordSent(p.bytes, r.id);
    double timeoutS = p.attempts == 1 && p.req.firstTimeoutS > 0
                          ? p.req.firstTimeoutS
                          : m_timeout.timeoutS(r.command, timing(), r.id);
    const protocol::Request request = r;
    const QByteArray bytes = p.bytes;
    m_inflight = std::move(p);
    // A reply cannot arrive sooner than its bytes and ours take on the wire after the write
    // began. That bar is counted from here, not from m_sentNs below: a write that is slow to
    // return (a preempted thread; the in-process simulator computing the reply within it) would
    // otherwise make the drive's prompt answer look too soon, and it would be taken for the late
    // reply to an earlier, timed-out identical request. Then this request timed out too, and so
    // would every retry of the same command to that drive after it.
    const qint64 writeStartNs = m_clock->nowNs();
    m_link.write(bytes);
    if (!m_inflight)
        return; // the write lost the link, which failed the request
    // The reply clock starts once the bytes are handed to the port, not before: a thread
    // preempted between the two would otherwise have spent part of the timeout (and of a
    // probe's quiet period) before the request even left, and could talk over a drive that
    // answers in time. Replies are only read from the event loop, so expecting one now is
    // early enough.
    m_sentNs = m_clock->nowNs();
    const int group = static_cast<int>(m_inflight->req.group.size());
    if (group == 0) {
        m_matcher.expect(request, bytes, m_sentNs, writeStartNs + earliestReplyNs(request.command));
    } else {
        // A multi-motor frame: its drives' replies are taken by takeGroupReply(), one after
        // the other on the bus, so the last may come the other replies' wire time later.
        m_matcher.clear();
        timeoutS += (group - 1) * timing().maxReplyWireS(request.command);
    }
    const int timeoutMs = std::max(1, static_cast<int>(std::ceil(timeoutS * 1e3)));
    m_deadlineNs = m_sentNs + qint64(timeoutMs) * 1'000'000;
    m_hurried = false;
    m_replyTimer->start(timeoutMs);
}

qint64 WireExchange::wireFreeNs(Command command) const
{
    return m_sentNs + static_cast<qint64>(timing().replyTimeoutS(command, 0) * 1e9);
}

void WireExchange::hurry()
{
    const qint64 nowNs = m_clock->nowNs();
    if (!m_inflight) {
        if (m_quiet.isQuiet(nowNs))
            m_quiet.shortenTo(wireFreeNs(static_cast<Command>(m_quiet.command())));
        return;
    }
    if (m_inflight->req.priority == Priority::Emergency)
        return; // the stop's own requests wait the physical limit already
    qint64 freeNs = wireFreeNs(m_inflight->req.request.command);
    // A multi-motor frame's replies follow one another: the wire is free after all of them,
    // and a drive cut short of its turn would be reported silent when it was not.
    const auto group = static_cast<qint64>(m_inflight->req.group.size());
    if (group > 1)
        freeNs += static_cast<qint64>(
            (group - 1) * timing().maxReplyWireS(m_inflight->req.request.command) * 1e9);
    if (freeNs >= m_deadlineNs)
        return;
    m_hurried = true;
    m_deadlineNs = freeNs;
    m_replyTimer->start(
        static_cast<int>(std::max<qint64>(0, freeNs - nowNs + 999'999) / 1'000'000));
}

qint64 WireExchange::earliestReplyNs(Command command) const
{
    const double wireS = timing().wireTimeS(command);
    return static_cast<qint64>(m_recentLatency.earliestReplyS(wireS) * 1e9);
}

std::optional<PendingRequest> WireExchange::abort()
{
    if (!m_inflight)
        return std::nullopt;
    std::optional<Pending> p = std::move(m_inflight);
    m_inflight.reset();
    m_matcher.clear();
    m_replyTimer->stop();
    return p;
}

void WireExchange::fail(RequestStatus status, const QString &reason)
{
    std::optional<Pending> p = abort();
    if (p && m_outcomes.failed)
        m_outcomes.failed(std::move(*p), status, reason);
}

void WireExchange::onTimeout()
{
    if (!m_inflight)
        return;
    const protocol::Request &r = m_inflight->req.request;
    // An ID with no drive answers no probe: a scan or a stop would otherwise add some 28
    // "timeouts" each, hiding the ones that mean something.
    const RequestOrigin origin = m_inflight->req.origin;
    const QVector<int> silent = silentInGroup();
    if ((origin == RequestOrigin::Scan || origin == RequestOrigin::Emergency) &&
        !m_motors.answered().contains(r.id))
        m_diagnostics.counters().silentProbe();
    else if (silent.isEmpty())
        m_diagnostics.counters().timedOut(r.id);
    for (int id : silent) // a multi-motor frame: one timeout for each drive that stayed silent
        m_diagnostics.counters().timedOut(id);
    m_matcher.timedOut();
    beginQuiet(r, m_inflight->attempts == 1 && m_inflight->req.firstTimeoutS > 0,
               m_inflight->req.priority == Priority::Emergency || m_hurried);
    if (silent.isEmpty())
        m_diagnostics.recordTimeout(r.id, static_cast<quint8>(r.command));
    for (int id : silent)
        m_diagnostics.recordTimeout(id, static_cast<quint8>(r.command));
    if (!silent.isEmpty()) {
        QStringList ids;
        for (int id : silent)
            ids << QString::number(id);
        fail(RequestStatus::Timeout, tr("no reply from drive(s) %1 to the multi-motor torque "
                                        "frame (0x280): not in its Broadcast Mode, or absent")
                                         .arg(ids.join(QStringLiteral(", "))));
        return;
    }
    fail(RequestStatus::Timeout,
         tr("no reply to %1 after %n attempt(s)", nullptr, m_inflight->attempts)
             .arg(commandText(r)));
}

QVector<int> WireExchange::silentInGroup() const
{
    QVector<int> silent;
    if (!m_inflight)
        return silent;
    for (const protocol::Request &r : m_inflight->req.group) {
        const auto answered =
            std::any_of(m_inflight->groupReplies.cbegin(), m_inflight->groupReplies.cend(),
                        [&r](const PendingRequest::GroupReply &g) { return g.reply.id == r.id; });
        if (!answered)
            silent.append(r.id);
    }
    return silent;
}

bool WireExchange::takeGroupReply(const protocol::ParseEvent &ev)
{
    if (!m_inflight || m_inflight->req.group.isEmpty() || !ev.isFrame || ev.echoed ||
        ev.frame.command != static_cast<quint8>(Command::Torque) ||
        !silentInGroup().contains(ev.frame.id))
        return false;
    const protocol::ReplyDecodeResult dec =
        protocol::decodeReply(ev.frame, m_motors.decodeContext(ev.frame.id));
    if (!dec.reply) {
        // That drive's reply is lost; the others may still come (its timeout is counted).
        m_diagnostics.counters().undecodable(ev.frame.id);
        return true;
    }
    const double latency = static_cast<double>(m_clock->nowNs() - m_sentNs) * 1e-9;
    m_diagnostics.counters().replyReceived(ev.frame.id, latency);
    m_inflight->groupReplies.append({*dec.reply, latency});
    if (!silentInGroup().isEmpty())
        return true;
    std::optional<Pending> p = abort();
    if (p && m_outcomes.replied)
        m_outcomes.replied(std::move(*p), *dec.reply, latency);
    return true;
}

void WireExchange::beginQuiet(const protocol::Request &request, bool probe, bool emergency)
{
    const qint64 lengthNs =
        static_cast<qint64>(m_timeout.quietS(request.command, timing(), request.id) * 1e9);
    qint64 untilNs = m_clock->nowNs() + lengthNs;
    if (emergency) {
        // The stop's next Motor Off waits only for what the wire itself needs: a drive that
        // heard this one answers within its turnaround, and its reply's last byte has left by
        // then. An adapter's or host's latency delays only our reading of it, and a drive's
        // late reply earlier on lifts only that drive's timeout: neither holds the stop.
        untilNs = wireFreeNs(request.command);
    } else if (probe) {
        // Silence is the common answer to a probe (scan), so it is not made to wait twice:
        // only until a reply from a drive that keeps its turnaround could have come through
        // this link, counted from the send. Often that is over already.
        untilNs =
            m_sentNs + static_cast<qint64>(
                           m_timeout.replyDeadlineS(request.command, timing(), request.id) * 1e9);
    }
    m_quiet.begin(untilNs, lengthNs, request.id, static_cast<quint8>(request.command));
}

bool WireExchange::holdForQuiet()
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

void WireExchange::stop()
{
    m_replyTimer->stop();
    m_quietTimer->stop();
}

bool WireExchange::feed(const QByteArray &bytes)
{
    if (!m_inflight) // with a request in flight these are its reply, not an old one's tail
        m_quiet.bytesArrived(m_clock->nowNs());
    m_quiet.chunkStarted();
    m_parser->feed(bytes, [this](const protocol::ParseEvent &ev) { onParseEvent(ev); });
    if (!m_quiet.endIfAnswered(m_parser->pendingBytes() == 0, m_clock->nowNs()))
        return false;
    m_quietTimer->stop();
    return true;
}

void WireExchange::noteCanGeneration(const protocol::ParseEvent &ev)
{
    if (!ev.canId || !ev.isFrame || ev.echoed || !m_outcomes.generationSeen)
        return;
    const protocol::can::CanData data{*ev.canId, protocol::can::bytesOf(ev.frame)};
    if (const std::optional<protocol::Generation> g = protocol::can::generationHint(data))
        m_outcomes.generationSeen(ev.frame.id, *g);
}

void WireExchange::onParseEvent(const protocol::ParseEvent &ev)
{
    noteCanGeneration(ev); // first: the frame is recorded and decoded with what it tells
    m_diagnostics.recordParseEvent(ev);
    if (takeGroupReply(ev))
        return;
    StatisticsCollector &stats = m_diagnostics.counters();
    using V = ReplyMatcher::Verdict;
    const protocol::Frame &f = ev.frame;
    ReplyMatcher::Outcome out =
        m_matcher.classify(ev, m_motors.decodeContext(f.id), m_clock->nowNs());
    switch (out.verdict) {
    case V::Fault:
        stats.parseFault(ev);
        return;
    case V::CorruptReply:
        // Retry now rather than wait for the timeout.
        stats.parseFault(ev);
        fail(RequestStatus::Error, tr("corrupt reply to %1 (bad data checksum)")
                                       .arg(commandText(m_inflight->req.request)));
        return;
    case V::LocalEcho:
        stats.localEcho();
        return;
    case V::Undecodable:
        stats.undecodable(f.id);
        fail(RequestStatus::Error,
             tr("undecodable reply to %1").arg(commandText(m_inflight->req.request)));
        return;
    case V::LateReply:
        // The link is slower than the margin assumed: let the margin learn from it.
        stats.lateReply(f.id);
        m_timeout.addLateReply(static_cast<Command>(f.command), timing(), out.lateLatencyS, f.id,
                               wireBytes(f));
        m_lateRequestSentS = std::max(m_lateRequestSentS, now() - out.lateLatencyS);
        m_quiet.lateFrameParsed(f.id, f.command);
        return;
    case V::Unexpected:
        stats.unexpectedFrame(f.id);
        return;
    case V::Reply:
        takeReply(std::move(*out.reply), wireBytes(f));
        return;
    }
}

void WireExchange::takeReply(protocol::Reply reply, int frameBytes)
{
    const double latency = static_cast<double>(m_clock->nowNs() - m_sentNs) * 1e-9;
    m_recentLatency.add(latency);
    m_diagnostics.counters().replyReceived(reply.id, latency);
    m_timeout.addReply(reply.command, timing(), latency, reply.id, frameBytes);
    std::optional<Pending> p = abort();
    if (p && m_outcomes.replied)
        m_outcomes.replied(std::move(*p), std::move(reply), latency);
}

} // namespace lk::bus
