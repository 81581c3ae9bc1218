#include "DecimatedSeries.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace lk::ui {

ColumnMap::ColumnMap(double t0, double t1, int columns)
    : m_t0(t0), m_scale(t1 > t0 && columns > 1 ? columns / (t1 - t0) : 0.0),
      m_last(std::max(0, columns - 1))
{
}

int decimationColumn(double time, double t0, double t1, int columns)
{
    return ColumnMap(t0, t1, columns)(time);
}

DecimatedSeries::DecimatedSeries(double t0, double t1, int columns)
    : m_t0(t0), m_t1(t1), m_columns(std::max(1, columns)), m_map(t0, t1, m_columns)
{
    m_points.reserve(2 * m_columns + 4);
}

void DecimatedSeries::add(double time, double value)
{
    if (time < m_t0) {
        m_before = {time, value};
        m_hasBefore = true;
        return;
    }
    if (time > m_t1) {
        if (!m_hasAfter) {
            m_after = {time, value};
            m_hasAfter = true;
        }
        return;
    }
    if (m_hasBefore && !m_beforeTaken) {
        // Inputs ascend: no point before the window comes after this one. Appended now, it
        // spares finish() a prepend, which moved the whole reduced series at every frame.
        m_points.append(m_before);
        m_beforeTaken = true;
    }
    const int index = m_map(time);
    if (index != m_column.index) {
        flush(false);
        m_column = Column{index, 0, {}, {}, {}, {}, 0, 0};
    }
    Column &c = m_column;
    const QPointF p(time, value);
    if (c.count == 0) {
        c.first = c.min = c.max = p;
    } else if (value < c.min.y()) { // strict: the first of equal extremes is kept
        c.min = p;
        c.minOrder = c.count;
    } else if (value > c.max.y()) {
        c.max = p;
        c.maxOrder = c.count;
    }
    c.last = p;
    ++c.count;
}

void DecimatedSeries::add(const double *times, const double *values, qsizetype count)
{
    for (qsizetype i = 0; i < count; ++i) {
        add(times[i], values[i]);
    }
}

void DecimatedSeries::flush(bool isLastColumn)
{
    const Column &c = m_column;
    if (c.count == 0) {
        return;
    }
    // Up to four candidates keyed by their position in the column, emitted in time order.
    std::array<std::pair<qsizetype, QPointF>, 4> picks;
    int n = 0;
    picks[n++] = {c.minOrder, c.min};
    picks[n++] = {c.maxOrder, c.max};
    if (m_firstColumn) {
        picks[n++] = {0, c.first};
    }
    if (isLastColumn) {
        picks[n++] = {c.count - 1, c.last};
    }
    for (int i = 1; i < n; ++i) { // insertion sort of at most four
        for (int j = i; j > 0 && picks[size_t(j)].first < picks[size_t(j - 1)].first; --j) {
            std::swap(picks[size_t(j)], picks[size_t(j - 1)]);
        }
    }
    for (int i = 0; i < n; ++i) {
        if (i == 0 || picks[size_t(i)].first != picks[size_t(i - 1)].first) {
            m_points.append(picks[size_t(i)].second);
        }
    }
    m_firstColumn = false;
}

QList<QPointF> DecimatedSeries::finish()
{
    flush(true);
    m_column = Column{};
    if (m_hasBefore && !m_beforeTaken) {
        m_points.prepend(m_before); // nothing inside the window: a list of at most one point
    }
    if (m_hasAfter) {
        m_points.append(m_after);
    }
    return std::move(m_points);
}

QList<QPointF> DecimatedSeries::decimate(const QList<QPointF> &points, double t0, double t1,
                                         int columns)
{
    DecimatedSeries d(t0, t1, columns);
    for (const QPointF &p : points) {
        d.add(p.x(), p.y());
    }
    return d.finish();
}

} // namespace lk::ui
