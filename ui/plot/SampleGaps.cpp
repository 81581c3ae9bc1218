#include "SampleGaps.h"

#include <algorithm>
#include <cmath>

namespace lk::ui {

bool SampleGaps::noteSample(double previous, double time)
{
    const double dt = time - previous;
    const bool forced = m_breakPending;
    m_breakPending = false;
    // The first interval has nothing to compare with: it teaches the cadence.
    const bool late = m_haveInterval && dt > std::max(kMinGapS, kGapFactor * m_usual);
    const double decayed = m_usual * std::exp2(-dt / kHalfLifeS);
    if (forced) {
        m_usual = decayed; // an outage says nothing about the cadence
    } else if (late) {
        // Either the drive was silent or the poll rate went down: in the second case the
        // next intervals are this long too, and must not all be cut (hence the headroom).
        m_usual = std::max(decayed, 2 * dt / kGapFactor);
    } else {
        m_usual = std::max(decayed, dt);
        m_haveInterval = true;
    }
    if (!forced && !late)
        return false;
    m_gaps.push_back(SampleGap{previous, time});
    return true;
}

void SampleGaps::clear()
{
    m_gaps.clear();
    m_usual = 0;
    m_haveInterval = false;
    m_breakPending = false;
}

void SampleGaps::dropBefore(double oldest)
{
    while (!m_gaps.empty() && m_gaps.front().to < oldest)
        m_gaps.pop_front();
}

QVector<SampleGap> SampleGaps::within(double t0, double t1) const
{
    QVector<SampleGap> out;
    // Gaps are ordered and disjoint: the first that ends after t0 starts the answer.
    auto it = std::lower_bound(m_gaps.cbegin(), m_gaps.cend(), t0,
                               [](const SampleGap &g, double t) { return g.to <= t; });
    for (; it != m_gaps.cend() && it->from < t1; ++it)
        out.append(*it);
    return out;
}

bool SampleGaps::contains(double time) const
{
    auto it = std::lower_bound(m_gaps.cbegin(), m_gaps.cend(), time,
                               [](const SampleGap &g, double t) { return g.to <= t; });
    return it != m_gaps.cend() && it->from < time && time < it->to;
}

} // namespace lk::ui
