#include "RecordedFrameParser.h"

#include <bus/PassivePairing.h>
#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>
#include <protocol/CanRecordParser.h>

namespace lk::recording {

protocol::DecodeContext decodeContextOf(const ContextSnapshot &snapshot, int id,
                                        protocol::Link link)
{
    protocol::DecodeContext c;
    c.link = link;
    for (const DriveContext &d : snapshot) {
        if (d.id != id)
            continue;
        c.series = d.series.value_or(protocol::Series::MF);
        c.generation = d.generation;
    }
    return c;
}

bool learnCanGeneration(ContextSnapshot &context, const protocol::ParseEvent &reply)
{
    if (!reply.canId || !reply.isFrame || reply.echoed)
        return false;
    const protocol::can::CanData data{*reply.canId, protocol::can::bytesOf(reply.frame)};
    const std::optional<protocol::Generation> g = protocol::can::generationHint(data);
    if (!g)
        return false;
    for (DriveContext &d : context) {
        if (d.id != reply.frame.id)
            continue;
        // The user's choice stands, as it does live (bus::MotorRegistry::learnCanGeneration).
        if (d.chosen || d.generation == *g)
            return false;
        d.generation = *g;
        return true;
    }
    context.append(DriveContext{reply.frame.id, std::nullopt, *g});
    return true;
}

RecordedFrameParser::RecordedFrameParser(ContextSnapshot context, protocol::Link link)
    : m_context(std::move(context)), m_link(link),
      m_rx(protocol::makeFrameParser(link, protocol::LinkEnd::Host)),
      // What the tool sent, seen from the drives' end: on CAN, its frames are requests.
      m_tx(protocol::makeFrameParser(link, protocol::LinkEnd::Drive))
{
}

void RecordedFrameParser::emitEvent(bool transmitted, protocol::ParseEvent event, const Sink &sink)
{
    protocol::DecodeContext context = decodeContextOf(m_context, event.frame.id, m_link);
    const bool multiTorque = event.canId == protocol::can::kMultiMotorId;
    if (m_link == protocol::Link::Can && !transmitted && event.isFrame && !event.echoed &&
        !multiTorque) {
        event.direction = bus::PassivePairing::canDirections(event, context).direction;
        if (event.direction != protocol::FrameDirection::Request &&
            learnCanGeneration(m_context, event))
            context = decodeContextOf(m_context, event.frame.id, m_link);
    }
    sink(RecordedFrame{m_timeNs, transmitted, std::move(event), context});
}

void RecordedFrameParser::parse(bool transmitted, const QByteArray &bytes, const Sink &sink)
{
    // The multi-motor torque frame (0x280, docs/CAN.md section 4.2), the tool's own or another
    // master's, is on no drive's ID, so the CAN parser hands it aside: it is a request all the
    // same, reported as one (no drive, no command of the table; its bytes hold the slots).
    auto *can = m_link == protocol::Link::Can
                    ? dynamic_cast<protocol::CanRecordParser *>((transmitted ? m_tx : m_rx).get())
                    : nullptr;
    if (can)
        can->setOtherFrameSink([&](const protocol::CanRecord &r) {
            if (r.isEcho() || r.isError() || r.isExtended() ||
                r.canId != protocol::can::kMultiMotorId)
                return;
            protocol::ParseEvent e;
            e.isFrame = true;
            e.direction = protocol::FrameDirection::Request;
            e.bytes = r.encode();
            e.canId = r.canId;
            emitEvent(transmitted, e, sink);
        });
    (transmitted ? m_tx : m_rx)->feed(bytes, [&](const protocol::ParseEvent &e) {
        emitEvent(transmitted, e, sink);
    });
    if (can)
        can->setOtherFrameSink({}); // it refers to this call's sink
}

void RecordedFrameParser::finishStream(bool transmitted, const Sink &sink)
{
    (transmitted ? m_tx : m_rx)->finish([&](const protocol::ParseEvent &e) {
        emitEvent(transmitted, e, sink);
    });
}

void RecordedFrameParser::feed(const RecordEvent &record, const Sink &sink)
{
    m_timeNs = record.timeNs;
    switch (record.kind) {
    case RecordEvent::Kind::Rx:
    case RecordEvent::Kind::Tx:
        parse(record.kind == RecordEvent::Kind::Tx, record.bytes, sink);
        return;
    case RecordEvent::Kind::Context:
        m_context = record.context;
        return;
    case RecordEvent::Kind::Link:
        if (record.link != LinkEventKind::Error)
            finish(sink);
        return;
    case RecordEvent::Kind::Dropped:
        return;
    }
}

void RecordedFrameParser::finish(const Sink &sink)
{
    finishStream(true, sink);
    finishStream(false, sink);
}

} // namespace lk::recording
