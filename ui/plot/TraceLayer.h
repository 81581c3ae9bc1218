#pragma once

#include "SampleRing.h"

#include <QtCore/QVector>
#include <QtGui/QPen>
#include <QtWidgets/QGraphicsItem>

class QChart;
class QValueAxis;

namespace lk::ui {

/// The lines of a StripChart, drawn by one graphics item over the chart's plot area: each
/// trace a polyline per gap-free piece, mapped through its axes' ranges when painted.
/// QtCharts' own line items rebuild a painter path and a hover outline of every point at
/// every frame (a fifth of the GUI thread with every signal plotted); this only maps the
/// points and draws them. The chart's (empty) line series still carry the legend.
class TraceLayer : public QGraphicsItem {
public:
    /// A child of `chart`, above its grid and below its legend.
    explicit TraceLayer(QChart *chart, QValueAxis *timeAxis);

    /// One line per trace, drawn with `pen` against `valueAxis` (and the time axis).
    void setTraces(const QVector<std::pair<QPen, QValueAxis *>> &traces);
    /// The points of trace `index`, piece by piece (a gap in the data between two pieces).
    void setPieces(int index, const LineSegments &pieces);
    const LineSegments &pieces(int index) const { return m_traces.at(index).pieces; }
    int traceCount() const { return int(m_traces.size()); }
    /// The plot area moved or resized: the item's bounds follow.
    void plotAreaChanged();

    QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

private:
    struct Trace {
        QPen pen;
        QValueAxis *axis = nullptr;
        LineSegments pieces;
    };
    QChart *m_chart;
    QValueAxis *m_time;
    QVector<Trace> m_traces;
    QRectF m_area;
    QPolygonF m_mapped; ///< reused at every paint: no allocation per piece
};

} // namespace lk::ui
