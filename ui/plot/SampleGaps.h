#pragma once

#include <QtCore/QVector>

#include <deque>

namespace lk::ui {

/// A time without samples: from the last sample before it to the first one after it.
struct SampleGap {
    double from = 0;
    double to = 0;
    bool operator==(const SampleGap &o) const { return from == o.from && to == o.to; }
};

/// The gaps of one sample stream (times ascending). A new sample starts a new line segment
/// when it follows a break (breakNext(): the link dropped) or when its interval is more than
/// kGapFactor times the stream's usual one (and at least kMinGapS): the drive went silent.
/// The usual interval is an envelope of recent intervals that decays with time, so that
/// replies to operator commands between polls do not make the next poll look late, and a
/// lower poll rate costs at most one cut before the envelope has learnt it.
class SampleGaps {
public:
    static constexpr double kGapFactor = 5;
    static constexpr double kMinGapS = 0.25;
    static constexpr double kHalfLifeS = 10; ///< how fast the usual interval forgets

    /// The sample at `time` follows one at `previous` (previous <= time); true when the
    /// interval is a gap, which is then recorded.
    bool noteSample(double previous, double time);
    /// The next sample starts a new segment whatever its interval.
    void breakNext() { m_breakPending = true; }
    void clear();
    /// Forget gaps that end before `oldest` (the ring overwrote the samples around them).
    void dropBefore(double oldest);

    bool isEmpty() const { return m_gaps.empty(); }
    /// Gaps that overlap (t0, t1) by more than a point, oldest first.
    QVector<SampleGap> within(double t0, double t1) const;
    /// Whether `time` lies strictly inside a gap (no sample describes it).
    bool contains(double time) const;

private:
    std::deque<SampleGap> m_gaps;
    double m_usual = 0; ///< envelope of recent intervals, seconds (0: none seen yet)
    bool m_haveInterval = false;
    bool m_breakPending = false;
};

} // namespace lk::ui
