#include "RingTrafficTap.h"

#include <recording/RecordTraffic.h>

namespace lk::ui {

using recording::RecordEvent;

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
    const auto sink = [&out](const recording::RecordedFrame &f) {
        out.append(recording::trafficEventOf(f));
    };
    for (const RecordEvent &r : records) {
        m_parser.feed(r, sink);
        if (std::optional<bus::TrafficEvent> note = recording::noteEventOf(r))
            out.append(std::move(*note));
    }
    return out;
}

} // namespace lk::ui
