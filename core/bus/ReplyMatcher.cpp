#include "ReplyMatcher.h"

namespace lk::bus {

using protocol::FrameDirection;

void ReplyMatcher::expect(const protocol::Request &request, const QByteArray &bytes, qint64 sentNs)
{
    m_expected = Expected{static_cast<quint8>(request.command), request.id, bytes, sentNs, false};
}

void ReplyMatcher::timedOut()
{
    m_timedOut = m_expected;
    m_expected.reset();
}

void ReplyMatcher::reset()
{
    m_expected.reset();
    m_timedOut.reset();
}

bool ReplyMatcher::isLocalEcho(const protocol::ParseEvent &event)
{
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
    if (matches(m_timedOut, f) && event.direction != FrameDirection::Request &&
        nowNs - m_timedOut->sentNs < kLateWindowNs) {
        out.verdict = Verdict::LateReply;
        out.lateLatencyS = static_cast<double>(nowNs - m_timedOut->sentNs) * 1e-9;
        m_timedOut.reset();
        return out;
    }
    out.verdict = Verdict::Unexpected;
    return out;
}

} // namespace lk::bus
