#pragma once

#include "DecimatedSeries.h"
#include "MinMax.h"
#include "SampleGaps.h"

#include <QtCore/QList>
#include <QtCore/QPointF>
#include <QtCore/QtGlobal>

#include <limits>
#include <vector>

namespace lk::ui {

/// The pieces of a line, each drawn on its own: no segment joins two of them.
using LineSegments = QList<QList<QPointF>>;

/// How a time window is reduced to pixel columns.
enum class DecimationMethod {
    Auto,    ///< Pyramid when the window holds many points per column, else Scan
    Scan,    ///< read every point in the window: O(points in window)
    Pyramid, ///< min/max blocks of 2^k points: O(columns x log(points per column))
};

/// A fixed-capacity ring of (time, value) points, times non-decreasing, with a min/max
/// pyramid over aligned blocks of 2^k slots (k = 3..16) so that a long window decimates
/// without reading every point. Storage is reserved once: appending never allocates (on
/// Linux the reservation costs address space; pages become resident when first written).
/// It knows its gaps (SampleGaps: a silent drive, a dropped link): decimation returns one
/// line segment per stretch between gaps and never joins across one.
class SampleRing {
public:
    /// Holds at most `capacity` points. With a finite `retainSeconds` the ring closes as soon
    /// as it spans that long: its capacity becomes the points held then, so memory stays at
    /// what the retention needs at the rate the points come (pages of the reservation past
    /// that are never written), instead of growing to `capacity` at a slow rate.
    explicit SampleRing(qsizetype capacity,
                        double retainSeconds = std::numeric_limits<double>::infinity());

    /// Appends a point; refuses (returns false) one older than the newest point or not finite.
    bool append(double time, double value);
    /// The next point starts a new line segment (the link dropped: what follows is not
    /// joined to what came before).
    void breakLine() { m_gaps.breakNext(); }
    void clear();
    /// Gaps overlapping [t0, t1], oldest first.
    QVector<SampleGap> gaps(double t0, double t1) const { return m_gaps.within(t0, t1); }
    /// Whether `time` falls inside a gap (nothing was measured then).
    bool inGap(double time) const { return m_gaps.contains(time); }

    qsizetype size() const { return m_size; }
    qsizetype capacity() const { return m_capacity; }
    bool isEmpty() const { return m_size == 0; }
    quint64 totalAppended() const { return m_total; }

    /// Point `index`, 0 being the oldest point held.
    double timeAt(qsizetype index) const { return m_times[size_t(physical(index))]; }
    double valueAt(qsizetype index) const { return m_values[size_t(physical(index))]; }
    QPointF pointAt(qsizetype index) const { return {timeAt(index), valueAt(index)}; }

    qsizetype lowerBound(double time) const; ///< first index with time >= `time`, or size()
    qsizetype upperBound(double time) const; ///< first index with time > `time`, or size()
    /// Min/max of values [begin, end) from whole pyramid blocks plus at most 14 single points
    /// at each end: O(log(end - begin)).
    MinMax minMax(qsizetype begin, qsizetype end) const;

    /// Calls f(const double *times, const double *values, qsizetype n) for the at most two
    /// contiguous stretches that hold [begin, end).
    template <typename F> void forEachSpan(qsizetype begin, qsizetype end, F f) const;

    /// The window [t0, t1] reduced to at most 2 points per column (see DecimatedSeries),
    /// plus the nearest point outside each edge so that the line reaches the edges: one
    /// segment per stretch between gaps, oldest first (a single one when there is no gap).
    LineSegments decimate(double t0, double t1, int columns,
                          DecimationMethod method = DecimationMethod::Auto) const;

private:
    struct Level {
        int shift = 0; // blocks of 2^shift slots at physical positions: no modulo anywhere
        std::vector<double> min, max;
    };

    qsizetype physical(qsizetype index) const
    {
        const qsizetype p = m_oldest + index;
        return p >= m_capacity ? p - m_capacity : p;
    }
    void minMaxSlots(qsizetype begin, qsizetype end, MinMax &result) const;
    qsizetype columnEnd(qsizetype begin, qsizetype end, qsizetype guess,
                        const ColumnMap &columnOf) const;
    /// One gap-free stretch [begin, end) of points, reduced over [t0, t1].
    QList<QPointF> decimateStretch(qsizetype begin, qsizetype end, double t0, double t1,
                                   int columns, DecimationMethod method) const;
    QList<QPointF> decimatePyramid(qsizetype i0, qsizetype i1, qsizetype begin, qsizetype end,
                                   double t0, double t1, int columns) const;

    /// The ring closes at the point count it holds now (see the constructor).
    void closeAt(qsizetype points);
    void buildLevels(); ///< empty pyramid levels for m_capacity

    qsizetype m_capacity;
    qsizetype m_maxCapacity; ///< as constructed; m_capacity is smaller once closed early
    double m_retainSeconds;
    qsizetype m_size = 0;
    qsizetype m_oldest = 0; // physical slot of index 0
    qsizetype m_head = 0;   // physical slot the next point goes to
    quint64 m_total = 0;    // points ever appended
    std::vector<double> m_times, m_values;
    std::vector<Level> m_levels;
    SampleGaps m_gaps;
};

template <typename F> void SampleRing::forEachSpan(qsizetype begin, qsizetype end, F f) const
{
    if (begin >= end) {
        return;
    }
    const qsizetype start = physical(begin);
    const qsizetype first = std::min(end - begin, m_capacity - start);
    f(m_times.data() + start, m_values.data() + start, first);
    if (first < end - begin) {
        f(m_times.data(), m_values.data(), end - begin - first);
    }
}

} // namespace lk::ui
