#include "RecordedFrameParser.h"

namespace lk::recording {

protocol::DecodeContext decodeContextOf(const ContextSnapshot &snapshot, int id)
{
    protocol::DecodeContext c;
    for (const DriveContext &d : snapshot) {
        if (d.id != id)
            continue;
        c.series = d.series.value_or(protocol::Series::MF);
        c.generation = d.generation;
    }
    return c;
}

void RecordedFrameParser::parse(bool transmitted, const QByteArray &bytes, const Sink &sink)
{
    (transmitted ? m_tx : m_rx).feed(bytes, [&](const protocol::ParseEvent &e) {
        sink(RecordedFrame{m_timeNs, transmitted, e, decodeContextOf(m_context, e.frame.id)});
    });
}

void RecordedFrameParser::finishStream(bool transmitted, const Sink &sink)
{
    (transmitted ? m_tx : m_rx).finish([&](const protocol::ParseEvent &e) {
        sink(RecordedFrame{m_timeNs, transmitted, e, decodeContextOf(m_context, e.frame.id)});
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
