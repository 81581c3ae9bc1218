#include "TimeViewport.h"

#include <algorithm>

namespace lk::ui {

void TimeViewport::setWindow(double seconds)
{
    m_window = std::clamp(seconds, kMinSpan, kMaxSpan);
    if (!m_following) {
        m_fixed.begin = m_fixed.end - m_window;
    }
}

TimeSpan TimeViewport::range(double latest) const
{
    if (!m_following) {
        return m_fixed;
    }
    const double end = std::max(latest, m_window);
    return {end - m_window, end};
}

void TimeViewport::zoom(double factor, double anchor, double latest)
{
    const TimeSpan now = range(latest);
    const double span = std::clamp(now.length() * factor, kMinSpan, kMaxSpan);
    const double share = now.length() > 0 ? (anchor - now.begin) / now.length() : 1.0;
    const double begin = anchor - std::clamp(share, 0.0, 1.0) * span;
    m_fixed = {begin, begin + span};
    m_following = false;
}

void TimeViewport::pan(double seconds, double latest)
{
    const TimeSpan now = range(latest);
    m_fixed = {now.begin + seconds, now.end + seconds};
    m_following = false;
}

void TimeViewport::select(double t0, double t1)
{
    if (t1 < t0) {
        std::swap(t0, t1);
    }
    const double span = std::clamp(t1 - t0, kMinSpan, kMaxSpan);
    const double mid = (t0 + t1) / 2;
    m_fixed = {mid - span / 2, mid + span / 2};
    m_following = false;
}

} // namespace lk::ui
