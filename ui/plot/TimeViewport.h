#pragma once

#include "TelemetryStore.h"

namespace lk::ui {

/// Which stretch of session time the plots show: either following the newest sample with a
/// fixed window length, or a fixed range the user zoomed or panned to.
class TimeViewport {
public:
    static constexpr double kMinSpan = 0.001;       ///< 1 ms: below, samples are far apart
    static constexpr double kMaxSpan = 24 * 3600.0; ///< one day

    /// Window length used while following; when not following, the right edge stays.
    void setWindow(double seconds);
    double window() const { return m_window; }
    bool isFollowing() const { return m_following; }
    void follow() { m_following = true; }

    /// The visible range; `latest` is the newest time to follow (ignored when not following).
    /// While following, the range starts at 0 until a whole window has been recorded.
    TimeSpan range(double latest) const;

    /// Scales the span around `anchor` (factor < 1 zooms in) and stops following.
    void zoom(double factor, double anchor, double latest);
    /// Moves the range by `seconds` (positive = later) and stops following.
    void pan(double seconds, double latest);
    /// Shows exactly [t0, t1] (in either order) and stops following.
    void select(double t0, double t1);

private:
    double m_window = 10.0;
    bool m_following = true;
    TimeSpan m_fixed{0, 10.0};
};

} // namespace lk::ui
