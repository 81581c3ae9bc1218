#pragma once

#include <QtCore/QList>
#include <QtCore/QPointF>
#include <QtCore/QtGlobal>

namespace lk::ui {

/// Splits [t0, t1] into `columns` equal pixel columns (t1 falls in the last one); times
/// outside are clamped to the first or last column. Every decimation path uses this one
/// mapping, so they agree on which column a point belongs to.
class ColumnMap {
public:
    ColumnMap(double t0, double t1, int columns);
    int operator()(double time) const
    {
        // Truncation is floor for the positive columns left after clamping, and one
        // conversion instead of floor's emulation (the x86-64 baseline has no rounding
        // instruction): this runs for every point of every trace at every frame.
        const double column = (time - m_t0) * m_scale;
        if (!(column > 0))
            return 0;
        return column >= m_last ? m_last : int(column);
    }

private:
    double m_t0;
    double m_scale; // columns per second
    int m_last;
};

/// ColumnMap(t0, t1, columns)(time).
int decimationColumn(double time, double t0, double t1, int columns);

/// Reduces a time series to what `columns` pixel columns can show, reading each point once:
/// per column its minimum and maximum points in time order (real points, so a one-sample
/// spike survives), plus the window's real first and last points and the nearest point
/// outside each edge (so the line reaches the edges). Output: at most 2 * columns + 4 points,
/// ascending in time. Feed points in ascending time order.
class DecimatedSeries {
public:
    DecimatedSeries(double t0, double t1, int columns);

    void add(double time, double value);
    void add(const double *times, const double *values, qsizetype count);
    /// The reduced series; the object is spent afterwards.
    QList<QPointF> finish();

    /// One-call form over a whole point list.
    static QList<QPointF> decimate(const QList<QPointF> &points, double t0, double t1, int columns);

private:
    struct Column {
        int index = -1;
        qsizetype count = 0;
        QPointF first, last, min, max;
        qsizetype minOrder = 0, maxOrder = 0; // position inside the column
    };
    void flush(bool isLastColumn);

    double m_t0, m_t1;
    int m_columns;
    ColumnMap m_map;
    Column m_column;
    bool m_firstColumn = true;
    bool m_hasBefore = false, m_hasAfter = false;
    bool m_beforeTaken = false; ///< m_before is in m_points already
    QPointF m_before, m_after;
    QList<QPointF> m_points;
};

} // namespace lk::ui
