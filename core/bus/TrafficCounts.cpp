#include "TrafficCounts.h"

namespace lk::bus {

void TrafficCounts::add(const TrafficEvent &event)
{
    ++events;
    switch (event.kind) {
    case TrafficEvent::Kind::Sent:
        ++sent;
        break;
    case TrafficEvent::Kind::Frame:
        ++frames;
        break;
    case TrafficEvent::Kind::Fault: {
        const auto i = static_cast<size_t>(event.error);
        if (i < faults.size())
            ++faults[i];
        break;
    }
    case TrafficEvent::Kind::Timeout:
        ++timeouts;
        break;
    case TrafficEvent::Kind::Note:
        break;
    }
}

void TrafficCounts::add(const TrafficBatch &batch)
{
    for (const TrafficEvent &e : batch)
        add(e);
}

TrafficCounts &TrafficCounts::operator+=(const TrafficCounts &other)
{
    for (size_t i = 0; i < faults.size(); ++i)
        faults[i] += other.faults[i];
    timeouts += other.timeouts;
    sent += other.sent;
    frames += other.frames;
    events += other.events;
    return *this;
}

quint64 TrafficCounts::faultTotal() const
{
    quint64 n = 0;
    for (quint64 f : faults)
        n += f;
    return n;
}

} // namespace lk::bus
