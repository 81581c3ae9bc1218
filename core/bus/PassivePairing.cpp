#include "PassivePairing.h"

#include <type_traits>
#include <variant>

#include "BusTiming.h"
#include "LinkTiming.h"

#include <protocol/CanLayout.h>
#include <protocol/Command.h>
#include <protocol/Values.h>

#include <algorithm>
#include <utility>

namespace lk::bus {

using protocol::Command;
using protocol::FrameDirection;

qint64 PassivePairing::windowNs(quint8 command) const
{
    const auto c = static_cast<protocol::Command>(command);
    const double s = m_link == protocol::Link::Can
                         ? LinkTiming::can(m_baud).replyTimeoutS(c, m_slackS)
                         : BusTiming::replyTimeoutS(c, m_baud, m_slackS);
    return static_cast<qint64>(s * 1e9);
}

std::optional<protocol::Frame> PassivePairing::closeUnanswered()
{
    if (!m_open)
        return std::nullopt;
    const Open open = std::move(*m_open);
    m_open.reset();
    // Bytes lost meanwhile may have been its reply; an echo frame nobody answered was a
    // request that timed out or the reply to a request that was lost: neither is told.
    if (open.faultSince) {
        ++m_counts.brokenPairs;
        return std::nullopt;
    }
    if (open.direction == FrameDirection::Echo) {
        ++m_counts.ambiguous;
        return std::nullopt;
    }
    ++m_counts.unanswered;
    return open.frame;
}

bool PassivePairing::pastWindow(qint64 nowNs) const
{
    return m_open && nowNs - m_open->timeNs > windowNs(m_open->frame.command);
}

std::optional<protocol::Frame> PassivePairing::expire(qint64 nowNs)
{
    if (!m_open || nowNs - m_open->timeNs <= std::max(windowNs(m_open->frame.command), kSilenceNs))
        return std::nullopt;
    return closeUnanswered();
}

bool PassivePairing::answersOpen(const protocol::Frame &frame, FrameDirection direction) const
{
    if (!m_open || m_open->frame.id != frame.id || m_open->frame.command != frame.command)
        return false;
    switch (direction) {
    case FrameDirection::Reply:
        return true;
    case FrameDirection::Echo:
        // An echo answers a request-only layout (0x8C's read), or repeats an echo request.
        return m_open->direction == FrameDirection::Request || m_open->frame == frame;
    case FrameDirection::Request:
        return false;
    }
    return false;
}

QVector<protocol::Frame> PassivePairing::expireGroup(qint64 nowNs)
{
    if (m_group.isEmpty() || nowNs - m_groupTimeNs <= windowNs(quint8(Command::Torque)))
        return {};
    m_counts.unanswered += quint64(m_group.size());
    return std::exchange(m_group, {});
}

QVector<protocol::Frame> PassivePairing::openGroup(const QVector<protocol::Frame> &torques,
                                                   qint64 nowNs)
{
    // The drives of the frame before answer within their window: any still silent at the next
    // frame (a master repeats it every cycle) did not answer it.
    m_counts.unanswered += quint64(m_group.size());
    QVector<protocol::Frame> silent = std::exchange(m_group, torques);
    m_groupTimeNs = nowNs;
    m_counts.requests += quint64(torques.size());
    return silent;
}

PassivePairing::Outcome PassivePairing::take(const protocol::ParseEvent &event, qint64 nowNs)
{
    if (!event.isFrame) {
        takeFault(event);
        return {};
    }
    return takeFrame(event, event.direction, event.direction, nowNs);
}

PassivePairing::Outcome PassivePairing::takeCan(const protocol::ParseEvent &event,
                                                FrameDirection direction, FrameDirection openAs,
                                                qint64 nowNs)
{
    if (!event.isFrame)
        return take(event, nowNs);
    return takeFrame(event, direction, openAs, nowNs);
}

namespace {

/// Whether B1..B7 could be a request of `command` on either CAN generation: it decodes as one
/// and encodes back to the same bytes. A generation whose codec refuses the frame either way
/// (no such request, or a value it will not send: V2.36's 0xA2 torque limit read from an MS
/// drive's negative power) tells nothing; where no generation can tell, it could be.
bool hasRequestLayout(const protocol::Frame &frame, const protocol::DecodeContext &context)
{
    bool told = false;
    for (const protocol::Generation g : {protocol::Generation::V2_3, protocol::Generation::V2_35}) {
        protocol::DecodeContext c = context;
        c.link = protocol::Link::Can;
        c.generation = g;
        protocol::RequestDecodeResult dec = protocol::can::decodeRequest(frame, c);
        if (!dec.request)
            continue;
        // A max speed of 0 is no request's (the encoder refuses it), but the bytes compare as
        // well without it: a motion reply with no current in B2-B3 still has its temperature
        // in B1, where a request has 0.
        std::visit(
            [](auto &p) {
                using P = std::decay_t<decltype(p)>;
                if constexpr (std::is_same_v<P, protocol::MultiPositionCommand> ||
                              std::is_same_v<P, protocol::SinglePositionCommand> ||
                              std::is_same_v<P, protocol::IncrementPositionCommand>) {
                    if (p.maxSpeedRaw == 0u)
                        p.maxSpeedRaw.reset();
                }
            },
            dec.request->payload);
        const protocol::can::CanEncodeResult enc = protocol::can::encodeRequest(*dec.request, c);
        if (!enc.data)
            continue;
        told = true;
        if (enc.data->bytes == protocol::can::bytesOf(frame))
            return true;
    }
    return !told;
}

} // namespace

PassivePairing::CanDirections PassivePairing::canDirections(const protocol::ParseEvent &event,
                                                            const protocol::DecodeContext &context)
{
    const protocol::Frame &f = event.frame;
    const bool brakeRead = f.command == quint8(protocol::Command::Brake) && !f.data.isEmpty() &&
                           static_cast<quint8>(f.data.at(0)) == protocol::kBrakeReadCode;
    const protocol::CommandInfo *info = protocol::CommandTable::find(f.command);
    // 0x8C's reply repeats the state the request set (or says it, to a read).
    const bool echoLike = info && (info->replyEchoesRequest || info->command == Command::Brake);
    CanDirections d;
    d.openAs = echoLike && !brakeRead ? FrameDirection::Echo : FrameDirection::Request;
    const std::optional<protocol::can::DriveAddress> address =
        event.canId ? protocol::can::driveAddressOf(*event.canId) : std::nullopt;
    if ((address && address->base == protocol::can::IdBase::Base180) ||
        !hasRequestLayout(f, context))
        d.direction = FrameDirection::Reply; // only a drive sends there, or sends that
    else
        d.direction = echoLike && !brakeRead ? FrameDirection::Echo : FrameDirection::Request;
    return d;
}

void PassivePairing::takeFault(const protocol::ParseEvent &event)
{
    if (!m_open)
        return;
    // A bad data checksum keeps a trusted header: when it names the open request and its
    // length is a reply's, the reply came, spoilt. Other faults are noise or a frame nobody
    // can name: a reply that still follows matches by command and ID as ever, but if none
    // does, the lost bytes may have been it, and the request is not counted unanswered.
    const bool spoiltReply = event.error == protocol::ParseError::BadDataChecksum &&
                             event.frame.id == m_open->frame.id &&
                             event.frame.command == m_open->frame.command &&
                             event.frame.direction() != FrameDirection::Request;
    if (spoiltReply) {
        ++m_counts.corruptReplies;
        m_open.reset();
        return;
    }
    m_open->faultSince = true;
}

PassivePairing::Outcome PassivePairing::takeFrame(const protocol::ParseEvent &event,
                                                  FrameDirection direction, FrameDirection openAs,
                                                  qint64 nowNs)
{
    Outcome out;
    const protocol::Frame &f = event.frame;
    // A long silence closed the open request. Short of that, a reply with its command and ID
    // answers it however late it was read (no other request came between); but an echo frame
    // after the open echo request's reply window is its retry, not its reply.
    out.unanswered = expire(nowNs);
    if (direction == FrameDirection::Echo && pastWindow(nowNs))
        out.unanswered = closeUnanswered();
    if (answersOpen(f, direction)) {
        out.role = Outcome::Role::Reply;
        out.request = std::move(m_open->frame);
        out.latencyNs = nowNs - m_open->timeNs;
        m_open.reset();
        ++m_counts.replies;
        ++m_counts.paired;
        return out;
    }
    out.unansweredInGroup = expireGroup(nowNs);
    // Const iterators: begin() on a list that holds nothing allocates one (Qt detaches a
    // null list), and this runs for every frame heard.
    const auto inGroup = std::find_if(m_group.cbegin(), m_group.cend(), [&f](const auto &t) {
        return t.id == f.id && t.command == f.command;
    });
    if (direction == FrameDirection::Reply && inGroup != m_group.cend()) {
        out.role = Outcome::Role::Reply;
        out.request = *inGroup;
        out.latencyNs = nowNs - m_groupTimeNs;
        m_group.erase(inGroup);
        ++m_counts.replies;
        ++m_counts.paired;
        return out;
    }
    if (direction == FrameDirection::Reply) {
        // Its request was lost (or never on this bus): the open one, if any, is no longer
        // sure to be unanswered - its reply may be what was lost.
        if (m_open) {
            ++m_counts.brokenPairs;
            m_open.reset();
        }
        out.role = Outcome::Role::Reply;
        ++m_counts.replies;
        ++m_counts.orphanReplies;
        return out;
    }
    if (m_open)
        out.unanswered = closeUnanswered();
    m_open = Open{f, openAs, nowNs};
    out.role = Outcome::Role::Request;
    ++m_counts.requests;
    return out;
}

} // namespace lk::bus
