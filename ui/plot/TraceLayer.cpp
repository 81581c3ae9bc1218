#include "TraceLayer.h"

#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>
#include <QtGui/QPainter>

namespace lk::ui {

namespace {
// QtCharts stacks its items by these z values (ChartPresenter, Qt 6): plot area 0, shades 1,
// grid 2, axes 3, series 4, legend 5. The layer takes the series' place.
constexpr double kSeriesZ = 4;
} // namespace

TraceLayer::TraceLayer(QChart *chart, QValueAxis *timeAxis)
    : QGraphicsItem(chart), m_chart(chart), m_time(timeAxis)
{
    setZValue(kSeriesZ);
    setFlag(ItemClipsToShape, false);
    setAcceptedMouseButtons(Qt::NoButton); // the view handles the mouse: pan, zoom, cursor
    m_area = chart->plotArea();
}

void TraceLayer::setTraces(const QVector<std::pair<QPen, QValueAxis *>> &traces)
{
    m_traces.clear();
    for (const auto &[pen, axis] : traces)
        m_traces.append(Trace{pen, axis, {}});
    update();
}

void TraceLayer::setPieces(int index, const LineSegments &pieces)
{
    m_traces[index].pieces = pieces;
    update();
}

void TraceLayer::plotAreaChanged()
{
    if (m_chart->plotArea() == m_area)
        return;
    prepareGeometryChange();
    m_area = m_chart->plotArea();
}

QRectF TraceLayer::boundingRect() const
{
    return m_area;
}

void TraceLayer::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const double t0 = m_time->min();
    const double tSpan = m_time->max() - t0;
    if (!(tSpan > 0) || m_area.isEmpty())
        return;
    const double xScale = m_area.width() / tSpan;
    painter->save();
    painter->setClipRect(m_area);
    for (const Trace &trace : std::as_const(m_traces)) {
        const double v0 = trace.axis->min();
        const double vSpan = trace.axis->max() - v0;
        if (!(vSpan > 0))
            continue;
        const double yScale = m_area.height() / vSpan;
        painter->setPen(trace.pen);
        for (const QList<QPointF> &piece : trace.pieces) {
            m_mapped.resize(piece.size());
            QPointF *out = m_mapped.data();
            for (const QPointF &p : piece) {
                *out++ = QPointF(m_area.left() + (p.x() - t0) * xScale,
                                 m_area.bottom() - (p.y() - v0) * yScale);
            }
            if (m_mapped.size() == 1)
                painter->drawPoint(m_mapped.first());
            else
                painter->drawPolyline(m_mapped);
        }
    }
    painter->restore();
}

} // namespace lk::ui
