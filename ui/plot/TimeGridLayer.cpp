#include "TimeGridLayer.h"

#include "StripChart.h"

#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>
#include <QtGui/QFontMetricsF>
#include <QtGui/QPainter>

#include <algorithm>
#include <cmath>

namespace lk::ui {

namespace {
// QtCharts stacks its items by these z values (ChartPresenter, Qt 6): plot area 0, shades 1,
// grid 2, axes 3, series 4, legend 5. The layer takes the grid's place, under the lines.
constexpr double kGridZ = 2;
constexpr double kLabelGap = 3; ///< pixels between the plot area and the labels, and below them
// Labels are centred on their ticks: the outermost may reach this far beside the plot area.
constexpr double kLabelOverhang = 60;
} // namespace

TimeGridLayer::TimeGridLayer(QChart *chart, QValueAxis *timeAxis)
    : QGraphicsItem(chart), m_chart(chart), m_time(timeAxis)
{
    setZValue(kGridZ);
    setAcceptedMouseButtons(Qt::NoButton); // the view handles the mouse
    m_area = chart->plotArea();
    m_font = chart->font();
    m_titleFont = chart->font();
}

double TimeGridLayer::tickStep(double span, int columns)
{
    const int count = std::clamp(columns / kPixelsPerTick, 2, kMaxTicks);
    return niceStep(span / count);
}

QVector<double> TimeGridLayer::ticks(double t0, double t1, int columns)
{
    QVector<double> out;
    if (!(t1 > t0) || !std::isfinite(t0) || !std::isfinite(t1))
        return out;
    const double step = tickStep(t1 - t0, columns);
    // Multiples of the step, computed from their index so that they do not drift.
    for (double k = std::ceil(t0 / step - 1e-9); k * step <= t1 + step * 1e-9; k += 1)
        out.append(k * step == 0 ? 0.0 : k * step); // no "-0.0"
    return out;
}

void TimeGridLayer::setLabels(bool visible, const QString &title)
{
    if (visible == m_labels && title == m_title)
        return;
    prepareGeometryChange();
    m_labels = visible;
    m_title = title;
}

int TimeGridLayer::labelAreaHeight() const
{
    if (!m_labels)
        return 0;
    const double title = m_title.isEmpty() ? 0 : QFontMetricsF(m_titleFont).height();
    return int(std::ceil(QFontMetricsF(m_font).height() + title + 2 * kLabelGap));
}

void TimeGridLayer::setColors(const QColor &grid, const QColor &line, const QColor &text)
{
    m_grid = grid;
    m_line = line;
    m_text = text;
    update();
}

void TimeGridLayer::setFonts(const QFont &labels, const QFont &title)
{
    if (labels == m_font && title == m_titleFont)
        return;
    prepareGeometryChange();
    m_font = labels;
    m_titleFont = title;
}

void TimeGridLayer::plotAreaChanged()
{
    if (m_chart->plotArea() != m_area) {
        prepareGeometryChange();
        m_area = m_chart->plotArea();
    }
    update();
}

QRectF TimeGridLayer::boundingRect() const
{
    // A pixel around the area: its lines are drawn on its edges.
    if (!m_labels)
        return m_area.adjusted(-1, -1, 1, 1);
    return m_area.adjusted(-kLabelOverhang, -1, kLabelOverhang, labelAreaHeight());
}

void TimeGridLayer::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const double t0 = m_time->min();
    const double t1 = m_time->max();
    if (!(t1 > t0) || m_area.isEmpty())
        return;
    const int columns = std::max(1, int(m_area.width()));
    const QVector<double> at = ticks(t0, t1, columns);
    const double xScale = m_area.width() / (t1 - t0);
    painter->save();
    painter->setPen(QPen(m_grid, 0)); // cosmetic: drawn directly, no stroker
    QVector<QLineF> lines;
    lines.reserve(at.size());
    for (double t : at) {
        const double x = m_area.left() + (t - t0) * xScale;
        lines.append(QLineF(x, m_area.top(), x, m_area.bottom()));
    }
    painter->drawLines(lines);
    painter->setPen(QPen(m_line, 0));
    painter->drawLine(m_area.bottomLeft(), m_area.bottomRight());
    if (m_labels) {
        painter->setFont(m_font);
        painter->setPen(m_text);
        const QFontMetricsF fm(m_font);
        const int decimals = tickDecimals(tickStep(t1 - t0, columns));
        const double top = m_area.bottom() + kLabelGap;
        // Centred on its tick, but never past the chart's edge (the outermost of a plot with no
        // axis beside it) nor over the label before it.
        const QRectF chart = m_chart->rect();
        double freeFrom = chart.left();
        for (double t : at) {
            const QString text = QString::number(t, 'f', decimals);
            const double x = m_area.left() + (t - t0) * xScale;
            const double w = fm.horizontalAdvance(text);
            const double left = std::min(x - w / 2, chart.right() - w);
            if (left < freeFrom)
                continue;
            painter->drawText(QRectF(left, top, w, fm.height()), Qt::AlignCenter, text);
            freeFrom = left + w + fm.averageCharWidth();
        }
        if (!m_title.isEmpty()) {
            painter->setFont(m_titleFont);
            const QRectF titleBox(m_area.left(), top + fm.height(), m_area.width(),
                                  QFontMetricsF(m_titleFont).height());
            painter->drawText(titleBox, Qt::AlignCenter, m_title);
        }
    }
    painter->restore();
}

} // namespace lk::ui
