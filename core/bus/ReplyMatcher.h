#pragma once

#include <protocol/Reply.h>
#include <protocol/Request.h>
#include <protocol/StreamParser.h>

#include <QtCore/QByteArray>

#include <deque>
#include <optional>

namespace lk::bus {

/// Decides what a parsed frame or fault means for the one request on the wire: its reply,
/// our own bytes read back (local echo), a corrupt or undecodable reply, a late reply to the
/// request that timed out before, or an unexpected frame. Pure logic, no I/O; times are
/// nanoseconds of the worker's clock.
///
/// Local echo: a frame byte-identical to the request is skipped when its layout is a request's
/// (it cannot be the reply). For commands whose reply is an echo (motor_off, write_pid_ram...)
/// the first identical frame is the reply, unless localEcho is set (the adapter echoes), in
/// which case the first is skipped and the second taken. On CAN the transport's echo flag
/// (ParseEvent::echoed) alone says what is our own frame.
class ReplyMatcher {
public:
    enum class Verdict {
        Reply,
        LocalEcho,
        CorruptReply,
        Undecodable,
        LateReply,
        Unexpected,
        Fault
    };
    struct Outcome {
        Verdict verdict = Verdict::Fault;
        std::optional<protocol::Reply> reply; ///< Reply only
        double lateLatencyS = 0;              ///< LateReply only: since the timed-out send
    };
    static constexpr qint64 kLateWindowNs = 1'000'000'000; ///< later than 1 s is noise
    /// Timed-out requests remembered for late replies. A scan's first pass times out every
    /// ID quickly, so behind a slow adapter a reply can arrive several probes later.
    static constexpr int kMaxTimedOut = 32;

    void setLocalEcho(bool on) { m_localEcho = on; }
    /// A request went on the wire at `sentNs`. A matching frame before `earliestReplyNs`
    /// came too soon to answer it (the bytes cannot have crossed the wire yet): when the same
    /// request timed out before, that frame is the late reply to the earlier one.
    void expect(const protocol::Request &request, const QByteArray &bytes, qint64 sentNs,
                qint64 earliestReplyNs = 0);
    /// The request ended (reply, failure or cancellation): nothing is expected any more.
    void clear() { m_expected.reset(); }
    /// The request on the wire timed out: a reply to it may still arrive late (within
    /// kLateWindowNs; the last kMaxTimedOut such requests are remembered).
    void timedOut();
    /// The link was reopened: nothing old can arrive any more.
    void reset();

    Outcome classify(const protocol::ParseEvent &event, const protocol::DecodeContext &context,
                     qint64 nowNs);

private:
    struct Expected {
        quint8 command = 0;
        quint8 id = 0;
        QByteArray bytes;
        qint64 sentNs = 0;
        bool echoSkipped = false;
        qint64 earliestReplyNs = 0;
    };
    bool matches(const std::optional<Expected> &e, const protocol::Frame &f) const
    {
        return e && e->id == f.id && e->command == f.command;
    }
    bool isLocalEcho(const protocol::ParseEvent &event);
    /// Take the timed-out request `f` answers, newest first; drops entries past the window.
    std::optional<Expected> takeTimedOut(const protocol::Frame &f, qint64 nowNs);

    std::optional<Expected> m_expected;
    std::deque<Expected> m_timedOut; ///< oldest first
    bool m_localEcho = false;
};

} // namespace lk::bus
