#include "LatencyWindow.h"

#include <algorithm>
#include <cmath>

namespace lk::bus {

LatencyWindow::LatencyWindow(int capacity) : m_capacity(std::max(1, capacity))
{
    m_samples.reserve(m_capacity);
}

void LatencyWindow::add(double seconds)
{
    if (m_samples.size() < m_capacity) {
        m_samples.append(seconds);
    } else {
        m_samples[m_next] = seconds;
        m_next = (m_next + 1) % m_capacity;
    }
    m_dirty = true;
}

void LatencyWindow::clear()
{
    m_samples.clear();
    m_sorted.clear();
    m_next = 0;
    m_dirty = false;
}

void LatencyWindow::sort() const
{
    if (!m_dirty)
        return;
    m_sorted = m_samples;
    std::sort(m_sorted.begin(), m_sorted.end());
    m_dirty = false;
}

double LatencyWindow::quantile(double q) const
{
    if (m_samples.isEmpty())
        return 0;
    sort();
    const double clamped = std::clamp(q, 0.0, 1.0);
    // Nearest rank: the smallest sample with at least q of the window at or below it.
    const int n = m_sorted.size();
    const int rank = std::max(1, static_cast<int>(std::ceil(clamped * n)));
    return m_sorted[std::min(rank, n) - 1];
}

LatencySummary LatencyWindow::summaryMs() const
{
    LatencySummary s;
    s.samples = size();
    if (s.samples == 0)
        return s;
    s.minMs = min() * 1e3;
    s.medianMs = median() * 1e3;
    s.p95Ms = p95() * 1e3;
    s.maxMs = max() * 1e3;
    return s;
}

} // namespace lk::bus
