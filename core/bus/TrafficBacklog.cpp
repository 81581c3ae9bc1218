#include "TrafficBacklog.h"

#include <utility>

namespace lk::bus {

void TrafficBacklog::append(const TrafficBatch &batch, std::optional<TrafficCounts> counts)
{
    if (batch.isEmpty())
        return;
    m_batches.append(batch);
    m_counts.append(std::move(counts));
    m_rows += batch.size();
    // Whole batches go: the newest always stays, however large it is.
    while (m_limit > 0 && m_batches.size() > 1 && m_rows - m_batches.first().size() >= m_limit) {
        if (m_counts.first())
            m_dropped += *m_counts.first();
        else
            m_dropped.add(m_batches.first());
        m_rows -= m_batches.first().size();
        TrafficBatch dropped = m_batches.takeFirst();
        m_counts.removeFirst();
        if (m_dispose)
            m_dispose(std::move(dropped));
    }
}

TrafficBatch TrafficBacklog::takeRows()
{
    TrafficBatch all;
    if (m_batches.size() == 1) {
        all = std::move(m_batches.first());
    } else if (!m_batches.isEmpty()) {
        all.reserve(m_rows); // one list, however many batches came
        for (const TrafficBatch &batch : std::as_const(m_batches))
            all += batch;
    }
    m_batches.clear();
    m_counts.clear();
    m_rows = 0;
    return all;
}

TrafficCounts TrafficBacklog::takeDropped()
{
    return std::exchange(m_dropped, TrafficCounts{});
}

void TrafficBacklog::clear()
{
    m_batches.clear();
    m_counts.clear();
    m_rows = 0;
    m_dropped = {};
}

} // namespace lk::bus
