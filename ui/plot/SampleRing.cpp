#include "SampleRing.h"

#include "DecimatedSeries.h"

#include <cmath>

namespace lk::ui {

namespace {

// Blocks smaller than 8 points cost more bookkeeping than they save; blocks above 65536
// points would only help windows far wider than any plot.
constexpr int kFirstShift = 3;
constexpr int kLastShift = 16;
// Below this many points per column a plain scan is as fast as the pyramid and keeps the
// real time of every extreme.
constexpr qsizetype kPyramidPointsPerColumn = 8;

} // namespace

SampleRing::SampleRing(qsizetype capacity, double retainSeconds)
    : m_capacity(std::max<qsizetype>(1, capacity)), m_maxCapacity(m_capacity),
      m_retainSeconds(retainSeconds)
{
    m_times.reserve(size_t(m_capacity));
    m_values.reserve(size_t(m_capacity));
    buildLevels();
}

void SampleRing::buildLevels()
{
    m_levels.clear();
    for (int shift = kFirstShift; shift <= kLastShift && (qsizetype(1) << shift) <= m_capacity;
         ++shift) {
        Level level;
        level.shift = shift;
        const size_t blocks = size_t((m_capacity + (qsizetype(1) << shift) - 1) >> shift);
        level.min.reserve(blocks);
        level.max.reserve(blocks);
        m_levels.push_back(std::move(level));
    }
}

bool SampleRing::append(double time, double value)
{
    if (!std::isfinite(time) || !std::isfinite(value) ||
        (m_size > 0 && time < timeAt(m_size - 1))) {
        return false; // binary searches need ascending times; NaN would poison min/max
    }
    if (m_size > 0) {
        m_gaps.noteSample(timeAt(m_size - 1), time);
    }
    // Still filling for the first time (index 0 is slot 0) and already spanning the
    // retention: wrap here rather than at the full capacity.
    if (m_size > 0 && m_size < m_capacity && m_head == m_size &&
        time - m_times.front() > m_retainSeconds) {
        closeAt(m_size);
    }
    const qsizetype slot = m_head;
    if (size_t(slot) == m_times.size()) {
        m_times.push_back(time); // within the reservation: never reallocates
        m_values.push_back(value);
    } else {
        m_times[size_t(slot)] = time;
        m_values[size_t(slot)] = value;
    }
    // A block's min/max is set when its last slot is written, from its points (the smallest
    // blocks) or its two halves (the level below). minMaxSlots uses only blocks that lie
    // wholly inside the held points, which never contain the write head, so a block being
    // rewritten is not read before it is whole again. Most points end no block: the append
    // then touches no level (every level at every point was a third of the GUI thread).
    const qsizetype next = slot + 1;
    for (size_t i = 0; i < m_levels.size(); ++i) {
        Level &level = m_levels[i];
        const qsizetype blockSize = qsizetype(1) << level.shift;
        if ((next & (blockSize - 1)) != 0)
            break; // not the end of a block here, nor of the larger blocks above
        const size_t block = size_t(slot) >> level.shift;
        double lo = 0;
        double hi = 0;
        if (i == 0) {
            const double *v = m_values.data() + (next - blockSize);
            lo = hi = v[0];
            for (qsizetype k = 1; k < blockSize; ++k) {
                lo = std::min(lo, v[k]);
                hi = std::max(hi, v[k]);
            }
        } else {
            const Level &half = m_levels[i - 1];
            lo = std::min(half.min[2 * block], half.min[2 * block + 1]);
            hi = std::max(half.max[2 * block], half.max[2 * block + 1]);
        }
        if (block == level.min.size()) {
            level.min.push_back(lo);
            level.max.push_back(hi);
        } else {
            level.min[block] = lo;
            level.max[block] = hi;
        }
    }
    m_head = slot + 1 == m_capacity ? 0 : slot + 1;
    if (m_size < m_capacity) {
        ++m_size;
    } else {
        m_oldest = m_head; // the oldest point was just overwritten
        m_gaps.dropBefore(timeAt(0));
    }
    ++m_total;
    return true;
}

void SampleRing::closeAt(qsizetype points)
{
    m_capacity = points;
    m_head = 0;
    // A level whose block is larger than the ring could never be used (a block is used only
    // when it lies wholly inside the held points).
    while (!m_levels.empty() && (qsizetype(1) << m_levels.back().shift) > m_capacity) {
        m_levels.pop_back();
    }
}

void SampleRing::clear()
{
    m_times.clear();
    m_values.clear();
    m_capacity = m_maxCapacity; // the next recording may come at another rate
    buildLevels();
    m_size = m_oldest = m_head = 0;
    m_total = 0;
    m_gaps.clear();
}

qsizetype SampleRing::lowerBound(double time) const
{
    qsizetype lo = 0, hi = m_size;
    while (lo < hi) {
        const qsizetype mid = lo + (hi - lo) / 2;
        if (timeAt(mid) < time) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return lo;
}

qsizetype SampleRing::upperBound(double time) const
{
    qsizetype lo = 0, hi = m_size;
    while (lo < hi) {
        const qsizetype mid = lo + (hi - lo) / 2;
        if (timeAt(mid) <= time) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return lo;
}

MinMax SampleRing::minMax(qsizetype begin, qsizetype end) const
{
    MinMax result;
    begin = std::max<qsizetype>(begin, 0);
    end = std::min(end, m_size);
    if (begin >= end) {
        return result;
    }
    const qsizetype start = physical(begin);
    const qsizetype first = std::min(end - begin, m_capacity - start);
    minMaxSlots(start, start + first, result);
    if (first < end - begin) {
        minMaxSlots(0, end - begin - first, result);
    }
    return result;
}

void SampleRing::minMaxSlots(qsizetype begin, qsizetype end, MinMax &result) const
{
    // [begin, end) is one contiguous stretch of held points. A block wholly inside it cannot
    // contain the write head (the head is at an edge of the held data: the stretch ends at
    // or before it, or starts at or after it), so its min/max describes exactly its slots.
    const int top = kFirstShift + int(m_levels.size()) - 1;
    qsizetype a = begin;
    while (a < end) {
        const int aligned = a == 0 ? 62 : __builtin_ctzll(quint64(a));
        const int fits = 63 - __builtin_clzll(quint64(end - a));
        const int shift = std::min({aligned, fits, top});
        if (shift < kFirstShift) {
            result.add(m_values[size_t(a)]);
            ++a;
            continue;
        }
        const Level &level = m_levels[size_t(shift - kFirstShift)];
        const size_t block = size_t(a) >> shift;
        result.min = std::min(result.min, level.min[block]);
        result.max = std::max(result.max, level.max[block]);
        a += qsizetype(1) << shift;
    }
}

LineSegments SampleRing::decimate(double t0, double t1, int columns, DecimationMethod method) const
{
    columns = std::max(1, columns);
    // The window's points and their nearest neighbours outside it, cut at every gap.
    const qsizetype begin = std::max<qsizetype>(0, lowerBound(t0) - 1);
    const qsizetype end = std::min(m_size, upperBound(t1) + 1);
    LineSegments out;
    if (begin >= end) {
        return out;
    }
    qsizetype from = begin;
    for (const SampleGap &gap : m_gaps.within(timeAt(begin), timeAt(end - 1))) {
        const qsizetype after = std::clamp(lowerBound(gap.to), from, end);
        if (after > from) {
            out.append(decimateStretch(from, after, t0, t1, columns, method));
        }
        from = after;
    }
    if (from < end) {
        out.append(decimateStretch(from, end, t0, t1, columns, method));
    }
    if (out.size() > 1) {
        // A lone neighbour outside the window, on the far side of a gap, belongs to no line
        // here: leave it out. A lone sample inside the window is data (the first reply after
        // an outage) and stays, for the scale and the cursor.
        out.removeIf([t0, t1](const QList<QPointF> &segment) {
            return segment.isEmpty() ||
                   (segment.size() == 1 && (segment.front().x() < t0 || segment.front().x() > t1));
        });
    }
    return out;
}

QList<QPointF> SampleRing::decimateStretch(qsizetype begin, qsizetype end, double t0, double t1,
                                           int columns, DecimationMethod method) const
{
    const qsizetype i0 = std::clamp(lowerBound(t0), begin, end);
    const qsizetype i1 = std::clamp(upperBound(t1), begin, end);
    const qsizetype inWindow = i1 - i0;
    const bool pyramid =
        !m_levels.empty() &&
        (method == DecimationMethod::Pyramid ||
         (method == DecimationMethod::Auto && inWindow > kPyramidPointsPerColumn * columns));
    if (pyramid && inWindow > 0) {
        return decimatePyramid(i0, i1, begin, end, t0, t1, columns);
    }
    DecimatedSeries reducer(t0, t1, columns);
    forEachSpan(std::max(begin, i0 - 1), std::min(end, i1 + 1),
                [&](const double *t, const double *v, qsizetype n) { reducer.add(t, v, n); });
    return reducer.finish();
}

qsizetype SampleRing::columnEnd(qsizetype begin, qsizetype end, qsizetype guess,
                                const ColumnMap &columnOf) const
{
    // First index after `begin` in a later column than begin's. A plain binary search reads
    // ~log2(n) scattered cache lines per column; sampling is nearly regular, so probing at
    // the expected width and galloping from there touches two or three nearby ones.
    const int column = columnOf(timeAt(begin));
    auto later = [&](qsizetype i) { return columnOf(timeAt(i)) > column; };
    qsizetype lo = begin + 1, hi = end; // the answer lies in [lo, hi]
    const qsizetype probe = std::min(begin + guess, end - 1);
    if (probe >= lo) {
        if (later(probe)) {
            hi = probe;
            for (qsizetype step = 1; probe - step >= lo; step *= 2) {
                if (!later(probe - step)) {
                    lo = probe - step + 1;
                    break;
                }
                hi = probe - step;
            }
        } else {
            lo = probe + 1;
            for (qsizetype step = 1; probe + step < end; step *= 2) {
                if (later(probe + step)) {
                    hi = probe + step;
                    break;
                }
                lo = probe + step + 1;
            }
        }
    }
    while (lo < hi) {
        const qsizetype mid = lo + (hi - lo) / 2;
        if (later(mid)) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    return lo;
}

QList<QPointF> SampleRing::decimatePyramid(qsizetype i0, qsizetype i1, qsizetype begin,
                                           qsizetype end, double t0, double t1, int columns) const
{
    QList<QPointF> out;
    out.reserve(2 * columns + 4);
    if (i0 > begin) {
        out.append(pointAt(i0 - 1));
    }
    qsizetype lastEmitted = -1;
    auto emitIndex = [&](qsizetype i) {
        if (i != lastEmitted) {
            out.append(pointAt(i));
            lastEmitted = i;
        }
    };
    emitIndex(i0); // the window's real first point
    double previous = valueAt(i0);
    const ColumnMap columnOf(t0, t1, columns);
    qsizetype width = std::max<qsizetype>(1, (i1 - i0) / columns); // expected points/column
    for (qsizetype cs = i0; cs < i1;) {
        const qsizetype ce = columnEnd(cs, i1, width, columnOf);
        width = ce - cs;
        if (ce - cs <= 2) {
            for (qsizetype i = cs; i < ce; ++i) {
                emitIndex(i);
            }
            previous = valueAt(ce - 1);
        } else {
            // The pyramid knows the extremes but not where they are: draw them at the
            // column's first and last times, ordered to continue the line from the previous
            // column (what the eye follows), which at one column per pixel looks the same.
            const MinMax mm = minMax(cs, ce);
            const bool minFirst = std::abs(previous - mm.min) <= std::abs(previous - mm.max);
            const double a = minFirst ? mm.min : mm.max;
            const double b = minFirst ? mm.max : mm.min;
            out.append(QPointF(timeAt(cs), a));
            out.append(QPointF(timeAt(ce - 1), b));
            lastEmitted = -1;
            previous = b;
        }
        cs = ce;
    }
    emitIndex(i1 - 1); // the window's real last point
    if (i1 < end) {
        out.append(pointAt(i1));
    }
    return out;
}

} // namespace lk::ui
