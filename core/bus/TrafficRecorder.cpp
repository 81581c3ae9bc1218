#include "TrafficRecorder.h"

#include <QtCore/QCoreApplication>

#include <utility>

namespace lk::bus {

void TrafficRecorder::setEnabled(bool enabled)
{
    m_enabled = enabled;
    if (!enabled) {
        m_pending.clear();
        m_dropped = 0;
    }
}

void TrafficRecorder::record(TrafficEvent event)
{
    if (!m_enabled)
        return;
    if (m_pending.size() >= kMaxPending) {
        ++m_dropped;
        return;
    }
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

void TrafficRecorder::recordParseEvent(const protocol::ParseEvent &event, double time)
{
    if (!m_enabled)
        return;
    TrafficEvent e;
    e.kind = event.isFrame ? TrafficEvent::Kind::Frame : TrafficEvent::Kind::Fault;
    e.time = time;
    e.bytes = event.bytes;
    e.error = event.error;
    e.id = event.frame.id;
    e.command = event.frame.command;
    record(std::move(e));
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
