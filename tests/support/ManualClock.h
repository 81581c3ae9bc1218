#pragma once

#include <bus/BusClock.h>

namespace lk::testsupport {

/// A BusClock a test advances by hand: time stands still between the test's steps, so a
/// loaded machine cannot make a reply late or a timeout early.
class ManualClock final : public bus::BusClock {
public:
    qint64 nowNs() const override { return m_nowNs; }
    double nowMs() const { return double(m_nowNs) * 1e-6; }
    /// Move to `ns` (never back: a steady clock does not go back).
    void setNs(qint64 ns)
    {
        if (ns > m_nowNs)
            m_nowNs = ns;
    }
    void advanceMs(double ms) { setNs(m_nowNs + qint64(ms * 1e6)); }

private:
    qint64 m_nowNs = 0;
};

} // namespace lk::testsupport
