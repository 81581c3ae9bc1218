#include "TrafficRecorder.h"

#include <protocol/CanRecord.h>

#include <QtCore/QCoreApplication>

#include <utility>

namespace lk::bus {

namespace {

/// The frame in bytes the host encoded itself (3E CMD ID LEN HCS [DATA..., DCS]): a slice,
/// since they are well formed by construction and a parser would cost more than the event.
/// On CAN the bytes are one CanRecord: its frame is {B0, drive ID, B1..B7}.
protocol::Frame frameOfOwnBytes(const QByteArray &bytes, protocol::Link link)
{
    if (link == protocol::Link::Can) {
        const std::optional<protocol::CanRecord> record = protocol::CanRecord::decode(bytes);
        std::optional<protocol::Frame> f;
        if (record)
            f = protocol::can::frameOf(record->canData());
        return f.value_or(protocol::Frame{});
    }
    constexpr qsizetype kHeaderSize = 5;
    protocol::Frame f;
    if (bytes.size() < kHeaderSize)
        return f;
    f.command = static_cast<quint8>(bytes.at(1));
    f.id = static_cast<quint8>(bytes.at(2));
    const auto len = static_cast<quint8>(bytes.at(3));
    if (len > 0)
        f.data = bytes.mid(kHeaderSize, len);
    return f;
}

} // namespace

void TrafficRecorder::setEnabled(bool enabled)
{
    m_enabled = enabled;
    if (!enabled) {
        m_pending.clear();
        m_dropped = 0;
    }
}

bool TrafficRecorder::admit()
{
    if (!m_enabled)
        return false;
    if (m_pending.size() >= kMaxPending) {
        ++m_dropped;
        return false;
    }
    return true;
}

void TrafficRecorder::record(TrafficEvent event)
{
    if (admit())
        m_pending.append(std::move(event));
}

void TrafficRecorder::record(TrafficEvent::Kind kind, double time, const QByteArray &bytes, int id,
                             quint8 command, const QString &text)
{
    if (!m_enabled)
        return;
    TrafficEvent e;
    e.kind = kind;
    e.time = time;
    e.bytes = bytes;
    e.id = id;
    e.command = command;
    e.text = text;
    record(std::move(e));
}

void TrafficRecorder::recordSent(double time, const QByteArray &bytes,
                                 const protocol::DecodeContext &context)
{
    // Checked before the frame is built: a full buffer drops the event at no cost.
    if (!admit())
        return;
    TrafficEvent e;
    e.kind = TrafficEvent::Kind::Sent;
    e.time = time;
    e.bytes = bytes;
    e.frame = frameOfOwnBytes(bytes, context.link);
    e.id = e.frame.id;
    e.command = e.frame.command;
    e.context = context;
    m_pending.append(std::move(e));
}

void TrafficRecorder::recordParseEvent(const protocol::ParseEvent &event, double time,
                                       const protocol::DecodeContext &context)
{
    if (!admit())
        return;
    TrafficEvent e;
    e.kind = event.isFrame ? TrafficEvent::Kind::Frame : TrafficEvent::Kind::Fault;
    e.time = time;
    e.bytes = event.bytes;
    e.error = event.error;
    e.id = event.frame.id;
    e.command = event.frame.command;
    if (event.isFrame) {
        e.frame = event.frame; // shares the parser's data bytes
        e.context = context;
    }
    m_pending.append(std::move(e));
}

TrafficBatch TrafficRecorder::take(double now)
{
    TrafficBatch out;
    out.swap(m_pending);
    if (m_dropped > 0) {
        TrafficEvent note;
        note.kind = TrafficEvent::Kind::Note;
        note.time = now;
        note.text = QCoreApplication::translate("lk::bus::TrafficRecorder",
                                                "%1 traffic events dropped (view too slow)")
                        .arg(m_dropped);
        out.append(note);
        m_dropped = 0;
    }
    return out;
}

} // namespace lk::bus
