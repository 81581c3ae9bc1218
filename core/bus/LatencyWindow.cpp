#include "LatencyWindow.h"

#include <algorithm>
#include <cmath>

namespace lk::bus {

LatencyWindow::LatencyWindow(int capacity) : m_capacity(std::max(1, capacity))
{
    m_samples.reserve(m_capacity);
    m_sorted.reserve(m_capacity);
}

void LatencyWindow::add(double seconds)
{
    // The sorted copy is kept up to date here instead of sorting the window again for every
    // timeout computed, which the bus thread does once per transaction.
    if (m_samples.size() < m_capacity) {
        m_samples.append(seconds);
        m_sorted.insert(std::upper_bound(m_sorted.cbegin(), m_sorted.cend(), seconds), seconds);
        return;
    }
    const double evicted = m_samples[m_next];
    m_samples[m_next] = seconds;
    m_next = (m_next + 1) % m_capacity;
    if (evicted == seconds)
        return; // the sorted copy holds the same values
    // Full: the evicted sample's slot and the new one's are usually close (latencies vary
    // little), so only what lies between them moves, by one, instead of the whole tail twice.
    const auto first = m_sorted.begin();
    const auto out = std::lower_bound(first, m_sorted.end(), evicted);
    const auto in = std::upper_bound(first, m_sorted.end(), seconds);
    if (in > out) {
        std::move(out + 1, in, out);
        *(in - 1) = seconds;
    } else {
        std::move_backward(in, out, out + 1);
        *in = seconds;
    }
}

void LatencyWindow::clear()
{
    m_samples.clear();
    m_sorted.clear();
    m_next = 0;
}

double LatencyWindow::quantile(double q) const
{
    if (m_samples.isEmpty())
        return 0;
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
