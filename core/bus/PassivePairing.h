#pragma once

#include <protocol/Frame.h>
#include <protocol/StreamParser.h>

#include <QtCore/QVector>
#include <QtCore/QtGlobal>

#include <optional>

namespace lk::bus {

/// Pairs the requests another master sends with its drives' replies, from the one byte stream
/// a listener on the bus sees both directions on. Pure logic, no I/O; times are nanoseconds
/// of the session clock (when the chunk holding the frame arrived).
///
/// Half duplex: a reply follows its request before the next request. So pairing is by order:
/// a frame whose layout is a request's starts a transaction (the one still open got no
/// answer: the other master's timeout); a reply's layout with the open request's command and
/// ID ends it. Echo commands (motor_off, write_pid_ram, ...) and 0x8C look the same both ways:
/// such a frame is the reply when it repeats the open request byte for byte (or answers a
/// request-only layout, 0x8C's read), else a new request. An echo frame taken as a request that
/// then gets no answer may as well have been a reply whose request was lost: it is counted
/// ambiguous, never guessed to be either.
///
/// Frames are stamped when the host reads their chunk, and a host that was not scheduled for a
/// while reads a reply late: so a reply with the open request's command and ID answers it
/// however late (no other request came between), and only the next request, or kSilenceNs
/// without any frame (expire()), shows a request unanswered. The clock matters for echo
/// frames alone: one that comes after the open echo request's reply window (what a reply
/// takes at the baud plus `slackS` for the adapter's latency timer) is a retry, not the reply.
/// After a fault (garbage, a bad checksum) a reply that matches the open request still pairs;
/// if none comes, the request is counted a broken pair, not a timeout, since the lost bytes may
/// have been its reply. A reply whose request was not seen is still the drive's word about
/// itself (its header names drive and command): it is reported, unpaired.
///
/// On CAN (setLink) frames have no length to tell requests from replies; the caller says
/// which way a frame may go (takeCan, CanTapDirection): a frame on 0x180+ID, or on 0x140+ID
/// with a reply's layout, is a reply; a frame on the old generation's shared 0x140+ID with a
/// request's layout is told by order, as an echo frame on RS485 is.
class PassivePairing {
public:
    /// What one frame was, as far as the pairing tells.
    struct Outcome {
        enum class Role { None, Request, Reply };
        Role role = Role::None;
        /// Reply: the request it answers (nullopt: its request was not seen).
        std::optional<protocol::Frame> request;
        qint64 latencyNs = 0; ///< Reply with a request: from the request's arrival
        /// The request that was open before this frame and is now known to be unanswered
        /// (not for an ambiguous echo frame nor after a fault: those are only counted).
        std::optional<protocol::Frame> unanswered;
        /// The torques of a multi-motor frame (openGroup) whose drives stayed silent past
        /// their reply window.
        QVector<protocol::Frame> unansweredInGroup;
    };
    struct Counts {
        quint64 requests = 0;
        quint64 replies = 0;        ///< reply frames, paired or not
        quint64 paired = 0;         ///< replies matched with their request
        quint64 unanswered = 0;     ///< requests the next request or silence showed unanswered
        quint64 orphanReplies = 0;  ///< replies whose request was not seen
        quint64 ambiguous = 0;      ///< echo frames that were a request or a reply, unknowable
        quint64 corruptReplies = 0; ///< the open request's reply, with a bad data checksum
        quint64 brokenPairs = 0;    ///< open requests left unpaired after a fault or an orphan
    };
    static constexpr double kDefaultSlackS = 0.020; ///< an FTDI latency timer is 16 ms
    /// No frame for this long (or the reply window, if longer): the open request is unanswered.
    static constexpr qint64 kSilenceNs = 250'000'000;

    void setBaud(int baud) { m_baud = baud; }
    /// The link the frames come on: its timing sets the reply window (RS485 by default).
    void setLink(protocol::Link link) { m_link = link; }
    void setSlackS(double slackS) { m_slackS = slackS; }
    /// Takes the next parse event, which arrived at `nowNs`.
    Outcome take(const protocol::ParseEvent &event, qint64 nowNs);
    /// Takes the next CAN frame or fault. `direction`: Reply for a frame only a drive sends;
    /// Echo for a frame that is a request or, following one with its command and ID, the
    /// reply; Request for a frame that can only be a request. `openAs`: how the frame, taken
    /// as a request, waits for its reply (Echo: only a frame repeating it answers it).
    Outcome takeCan(const protocol::ParseEvent &event, protocol::FrameDirection direction,
                    protocol::FrameDirection openAs, qint64 nowNs);
    /// Which way a CAN frame a listener hears may go, for takeCan.
    struct CanDirections {
        protocol::FrameDirection direction = protocol::FrameDirection::Request;
        protocol::FrameDirection openAs = protocol::FrameDirection::Request;
    };
    /// A frame on 0x180+ID, or with no request's layout on either generation, is a reply.
    /// One with a request's layout on 0x140+ID is a request, unless it follows the open
    /// request of its command and ID (an echo command's reply, 0x8C's state after a read).
    static CanDirections canDirections(const protocol::ParseEvent &event,
                                       const protocol::DecodeContext &context);
    /// Time passed without a frame: an open request silent for kSilenceNs (or its reply
    /// window, if longer) is unanswered (returned).
    std::optional<protocol::Frame> expire(qint64 nowNs);
    /// Another master's multi-motor torque frame (CAN 0x280): each drive it names answers on
    /// its own ID with the 0xA1 reply. `torques`: the 0xA1 request each drive expected to
    /// answer takes it as, all counted as requests; a 0xA1 reply of one of them pairs with it
    /// (another request may come between). Returns the torques of an earlier frame whose
    /// drives have not answered: unanswered.
    QVector<protocol::Frame> openGroup(const QVector<protocol::Frame> &torques, qint64 nowNs);
    /// The open group's silent drives once its reply window has passed (counted unanswered).
    QVector<protocol::Frame> expireGroup(qint64 nowNs);
    /// A new stream (the port reopened): nothing is open.
    void reset()
    {
        m_open.reset();
        m_group.clear();
    }
    const Counts &counts() const { return m_counts; }
    bool hasOpenRequest() const { return m_open.has_value(); }

private:
    struct Open {
        protocol::Frame frame;
        protocol::FrameDirection direction = protocol::FrameDirection::Request;
        qint64 timeNs = 0;
        bool faultSince = false; ///< a fault came after it: its reply may have been lost
    };
    /// Whether `frame` (layout `direction`) is the reply to the open request.
    bool answersOpen(const protocol::Frame &frame, protocol::FrameDirection direction) const;
    /// The open request got no answer: counted (ambiguous for an echo frame), returned.
    std::optional<protocol::Frame> closeUnanswered();
    Outcome takeFrame(const protocol::ParseEvent &event, protocol::FrameDirection direction,
                      protocol::FrameDirection openAs, qint64 nowNs);
    void takeFault(const protocol::ParseEvent &event);
    qint64 windowNs(quint8 command) const;
    bool pastWindow(qint64 nowNs) const;

    /// The open multi-motor frame's torques, one per drive still to answer, and its time.
    QVector<protocol::Frame> m_group;
    qint64 m_groupTimeNs = 0;

    std::optional<Open> m_open;
    Counts m_counts;
    int m_baud = 115200;
    protocol::Link m_link = protocol::Link::Rs485;
    double m_slackS = kDefaultSlackS;
};

} // namespace lk::bus
