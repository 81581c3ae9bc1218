#include "RingTrafficTap.h"

#include <recording/RecordTraffic.h>

namespace lk::ui {

using recording::RecordEvent;

namespace {

// The same row RecordTraffic's trafficEventsOf makes of a frame; that one parses a whole
// recording at once, this converter goes on from one take() to the next.
bus::TrafficEvent trafficEventOf(const recording::RecordedFrame &f)
{
    bus::TrafficEvent e;
    e.time = double(f.timeNs) * 1e-9;
    e.bytes = f.event.bytes;
    e.id = f.event.frame.id;
    e.command = f.event.frame.command;
    if (f.event.isFrame) {
        e.kind = f.transmitted ? bus::TrafficEvent::Kind::Sent : bus::TrafficEvent::Kind::Frame;
        e.frame = f.event.frame;
        e.context = f.context;
    } else {
        e.kind = bus::TrafficEvent::Kind::Fault;
        e.error = f.event.error;
    }
    return e;
}

} // namespace

void RingTrafficTap::append(RecordEvent event)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_enabled)
        return;
    if (m_pending.size() >= m_maxPending) {
        m_overflowed = true;
        return;
    }
    m_pending.append(std::move(event));
}

void RingTrafficTap::setEnabled(bool on)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_enabled = on;
    m_pending.clear();
    m_overflowed = false;
}

bool RingTrafficTap::isEnabled() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_enabled;
}

QVector<RecordEvent> RingTrafficTap::take(bool *overflowed)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (overflowed)
        *overflowed = m_overflowed;
    m_overflowed = false;
    return std::exchange(m_pending, {});
}

bus::TrafficBatch RecordTrafficConverter::convert(const QVector<RecordEvent> &records)
{
    bus::TrafficBatch out;
    const auto sink = [&out](const recording::RecordedFrame &f) { out.append(trafficEventOf(f)); };
    for (const RecordEvent &r : records) {
        m_parser.feed(r, sink);
        if (r.kind == RecordEvent::Kind::Link || r.kind == RecordEvent::Kind::Dropped)
            out += recording::trafficEventsOf({r}, {}); // a link event or drop: one Note
    }
    return out;
}

} // namespace lk::ui
