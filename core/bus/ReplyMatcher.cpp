#include "ReplyMatcher.h"

#include <algorithm>
#include <iterator>

namespace lk::bus {

using protocol::FrameDirection;

void ReplyMatcher::expect(const protocol::Request &request, const QByteArray &bytes, qint64 sentNs,
                          qint64 earliestReplyNs)
{
    m_expected = Expected{
        static_cast<quint8>(request.command), request.id, bytes, sentNs, false, earliestReplyNs};
}

void ReplyMatcher::timedOut()
{
    // A retry of a request already remembered keeps the older entry: a late reply then
    // measures the longer latency, and the margin errs on the safe side.
    const bool known =
        m_expected &&
        std::any_of(m_timedOut.cbegin(), m_timedOut.cend(), [this](const Expected &e) {
            return e.id == m_expected->id && e.command == m_expected->command;
        });
    if (m_expected && !known) {
        m_timedOut.push_back(*m_expected);
        if (m_timedOut.size() > size_t(kMaxTimedOut))
            m_timedOut.pop_front();
    }
    m_expected.reset();
}

void ReplyMatcher::reset()
{
    m_expected.reset();
    m_timedOut.clear();
}

std::optional<ReplyMatcher::Expected> ReplyMatcher::takeTimedOut(const protocol::Frame &f,
                                                                 qint64 nowNs)
{
    while (!m_timedOut.empty() && nowNs - m_timedOut.front().sentNs >= kLateWindowNs)
        m_timedOut.pop_front();
    for (auto it = m_timedOut.rbegin(); it != m_timedOut.rend(); ++it) {
        if (it->id == f.id && it->command == f.command) {
            Expected e = *it;
            m_timedOut.erase(std::next(it).base());
            return e;
        }
    }
    return std::nullopt;
}

bool ReplyMatcher::isLocalEcho(const protocol::ParseEvent &event)
{
    // CAN: the transport flags our own frame looped back; a drive's identical echo (the old
    // generation answers on the request's own ID) carries no flag and is the reply.
    if (event.canId)
        return event.echoed;
    if (event.bytes != m_expected->bytes)
        return false;
    if (event.direction == FrameDirection::Request)
        return true; // a request's layout can never be the reply
    if (m_localEcho && !m_expected->echoSkipped) {
        m_expected->echoSkipped = true; // the adapter's copy; the drive's identical echo follows
        return true;
    }
    return false;
}

ReplyMatcher::Outcome ReplyMatcher::classify(const protocol::ParseEvent &event,
                                             const protocol::DecodeContext &context, qint64 nowNs)
{
    Outcome out;
    if (!event.isFrame) {
        // The header of a bad-data-checksum frame is trusted: it names the reply it spoils.
        const bool spoilsReply = event.error == protocol::ParseError::BadDataChecksum &&
                                 matches(m_expected, event.frame);
        out.verdict = spoilsReply ? Verdict::CorruptReply : Verdict::Fault;
        return out;
    }
    const protocol::Frame &f = event.frame;
    if (matches(m_expected, f) && event.direction != FrameDirection::Request &&
        nowNs < m_expected->earliestReplyNs) {
        // Too soon to be the answer to what was just sent: the late answer to the same
        // request sent before (which timed out), if there was one.
        if (const std::optional<Expected> late = takeTimedOut(f, nowNs)) {
            out.verdict = Verdict::LateReply;
            out.lateLatencyS = static_cast<double>(nowNs - late->sentNs) * 1e-9;
            return out;
        }
    }
    if (matches(m_expected, f)) {
        if (isLocalEcho(event)) {
            out.verdict = Verdict::LocalEcho;
            return out;
        }
        if (event.direction != FrameDirection::Request) {
            protocol::ReplyDecodeResult dec = protocol::decodeReply(f, context);
            out.verdict = dec.reply ? Verdict::Reply : Verdict::Undecodable;
            out.reply = std::move(dec.reply);
            return out;
        }
    }
    if (event.direction != FrameDirection::Request) {
        if (const std::optional<Expected> late = takeTimedOut(f, nowNs)) {
            out.verdict = Verdict::LateReply;
            out.lateLatencyS = static_cast<double>(nowNs - late->sentNs) * 1e-9;
            return out;
        }
    }
    out.verdict = Verdict::Unexpected;
    return out;
}

} // namespace lk::bus
