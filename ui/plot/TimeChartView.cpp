#include "TimeChartView.h"

#include <QtCharts/QLegend>
#include <QtCharts/QValueAxis>
#include <QtGui/QMouseEvent>
#include <QtGui/QPainter>
#include <QtGui/QPen>
#include <QtGui/QRegion>
#include <QtGui/QWheelEvent>
#include <QtWidgets/QGraphicsLayout>
#include <QtWidgets/QGraphicsScene>
#include <QtWidgets/QRubberBand>

#include <cmath>

namespace lk::ui {

namespace {

constexpr double kWheelZoomPerNotch = 0.8; // one wheel notch shows 80 % of the span
constexpr int kMinSelectPixels = 4;        // a shorter drag is a click, not a selection
constexpr double kGridShare = 0.18;        // grid lines: this much text colour in the base
constexpr double kAxisShare = 0.5;

QColor mix(const QColor &base, const QColor &over, double share)
{
    return QColor::fromRgbF(float(base.redF() + (over.redF() - base.redF()) * share),
                            float(base.greenF() + (over.greenF() - base.greenF()) * share),
                            float(base.blueF() + (over.blueF() - base.blueF()) * share));
}

QPen hairline(QPen pen)
{
    if (pen.widthF() <= 1.0)
        pen.setWidthF(0);
    return pen;
}

} // namespace

TimeChartView::TimeChartView(QWidget *parent) : QChartView(parent)
{
    setMouseTracking(true);
    setRubberBand(QChartView::NoRubberBand); // zoom is ours: every chart must zoom alike
    setDragMode(QGraphicsView::NoDrag);
    // Items move or change at every frame (the lines, an autoscaled axis): a BSP index of the
    // scene would be rebuilt for each of them (a stroke of every line's shape), for lookups a
    // chart of a few dozen items does not need.
    scene()->setItemIndexMethod(QGraphicsScene::NoIndex);
    // The view paints every pixel of its viewport (its background brush, then the chart):
    // without this, each frame also filled the viewport's own background and the window's
    // behind it first (a seventh of the GUI thread with every signal plotted).
    viewport()->setAttribute(Qt::WA_OpaquePaintEvent);
    // Every item paints inside its bounds, lines aliased: the 2 pixels QGraphicsView adds around
    // each changed area for antialiasing only brought the value axis's labels beside the plot
    // area into every frame's repaint (8 % of the GUI thread with every signal plotted).
    setOptimizationFlag(QGraphicsView::DontAdjustForAntialiasing);
    applyPalette();
}

void TimeChartView::applyPalette()
{
    QChart *c = chart();
    if (!c)
        return;
    const QPalette pal = palette();
    const QColor base = pal.color(QPalette::Base);
    const QColor text = pal.color(QPalette::Text);
    c->setBackgroundBrush(base);
    c->setBackgroundPen(Qt::NoPen);
    c->setTitleBrush(text);
    c->legend()->setLabelColor(text);
    setBackgroundBrush(pal.color(QPalette::Window)); // the view around the chart
    for (QAbstractAxis *axis : c->axes()) {
        axis->setLabelsColor(text);
        axis->setTitleBrush(text);
        axis->setLinePenColor(mix(base, text, kAxisShare));
        axis->setGridLineColor(mix(base, text, kGridShare));
        axis->setMinorGridLineColor(mix(base, text, kGridShare / 2));
        // Hairlines (width 0) paint the same pixels as the theme's 1-pixel pens, aliased and
        // unscaled; but a line item with a pen of width 1 strokes a path for its bounds each
        // time the view asks, and it asks for every grid line at every frame (3 % of the GUI
        // thread with every signal plotted).
        axis->setLinePen(hairline(axis->linePen()));
        axis->setGridLinePen(hairline(axis->gridLinePen()));
        axis->setMinorGridLinePen(hairline(axis->minorGridLinePen()));
    }
}

QRectF TimeChartView::chartBackgroundInScene() const
{
    const QChart *c = chart();
    // Only a square, opaque, shadowless background covers all of its rectangle.
    if (!c || !c->layout() || c->backgroundRoundness() > 0 || c->isDropShadowEnabled() ||
        !c->isBackgroundVisible() || c->backgroundBrush().style() != Qt::SolidPattern ||
        !c->backgroundBrush().isOpaque())
        return {};
    qreal left = 0, top = 0, right = 0, bottom = 0;
    c->layout()->getContentsMargins(&left, &top, &right, &bottom);
    return c->mapRectToScene(c->rect().adjusted(left, top, -right, -bottom));
}

void TimeChartView::drawBackground(QPainter *painter, const QRectF &rect)
{
    // The chart's opaque background (square corners) paints what lies within it: the view's
    // own fill underneath was a second fill of the plot area at every frame. Only the band
    // around it is the view's.
    const QRectF covered = chartBackgroundInScene();
    if (covered.contains(rect))
        return;
    QRegion band(rect.toAlignedRect());
    band -= covered.toAlignedRect().adjusted(1, 1, -1, -1); // its edge pixels may be partial
    for (const QRect &r : band)
        painter->fillRect(r, backgroundBrush());
}

void TimeChartView::changeEvent(QEvent *event)
{
    QChartView::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        applyPalette();
}

void TimeChartView::setCursorTime(std::optional<double> time)
{
    if (time == m_cursorTime) {
        return;
    }
    // Repaint only the strips under the old and the new line, not the whole chart: the
    // mouse moves far more often than the data changes.
    viewport()->update(cursorStrip(m_cursorTime));
    m_cursorTime = time;
    viewport()->update(cursorStrip(m_cursorTime));
}

std::optional<double> TimeChartView::cursorX(double time) const
{
    const QValueAxis *axis = timeAxis();
    if (!chart() || !axis || axis->max() <= axis->min()) {
        return std::nullopt;
    }
    const double share = (time - axis->min()) / (axis->max() - axis->min());
    if (share < 0 || share > 1) {
        return std::nullopt;
    }
    const QRectF area = chart()->plotArea();
    return area.left() + share * area.width(); // chart coordinates
}

QRect TimeChartView::cursorStrip(std::optional<double> time) const
{
    const std::optional<double> x = time ? cursorX(*time) : std::nullopt;
    if (!x) {
        return {};
    }
    const QRectF area = chart()->plotArea();
    const QRectF strip(*x - 2, area.top(), 4, area.height());
    return mapFromScene(chart()->mapToScene(strip)).boundingRect().adjusted(-1, -1, 1, 1);
}

QRectF TimeChartView::plotAreaInView() const
{
    return mapFromScene(chart()->mapToScene(chart()->plotArea())).boundingRect();
}

QValueAxis *TimeChartView::timeAxis() const
{
    const QList<QAbstractAxis *> axes = chart()->axes(Qt::Horizontal);
    return axes.isEmpty() ? nullptr : qobject_cast<QValueAxis *>(axes.first());
}

double TimeChartView::timeAtX(double viewX) const
{
    const QRectF area = plotAreaInView();
    const QValueAxis *axis = timeAxis();
    if (!axis || area.width() <= 0) {
        return 0;
    }
    return axis->min() + (viewX - area.left()) / area.width() * (axis->max() - axis->min());
}

double TimeChartView::secondsPerPixel() const
{
    const QRectF area = chart()->plotArea();
    const QValueAxis *axis = timeAxis();
    if (!axis || area.width() <= 0) {
        return 0;
    }
    return (axis->max() - axis->min()) / area.width();
}

void TimeChartView::mousePressEvent(QMouseEvent *event)
{
    const bool select =
        event->button() == Qt::RightButton ||
        (event->button() == Qt::LeftButton && event->modifiers().testFlag(Qt::ShiftModifier));
    if (select) {
        m_drag = Drag::Select;
        m_selectStartX = event->position().x();
        if (!m_band) {
            m_band = new QRubberBand(QRubberBand::Rectangle, viewport());
        }
        const QRectF area = plotAreaInView();
        m_band->setGeometry(QRect(int(m_selectStartX), int(area.top()), 0, int(area.height())));
        m_band->show();
    } else if (event->button() == Qt::LeftButton) {
        m_drag = Drag::Pan;
        m_lastX = event->position().x();
        setCursor(Qt::ClosedHandCursor);
    }
    event->accept();
}

void TimeChartView::mouseMoveEvent(QMouseEvent *event)
{
    const double x = event->position().x();
    if (m_drag == Drag::Pan) {
        const double dx = x - m_lastX;
        m_lastX = x;
        if (dx != 0) {
            emit panRequested(-dx * secondsPerPixel()); // dragging right shows earlier times
        }
    } else if (m_drag == Drag::Select && m_band) {
        const QRectF area = plotAreaInView();
        const double left = std::min(x, m_selectStartX);
        m_band->setGeometry(QRect(int(left), int(area.top()), int(std::abs(x - m_selectStartX)),
                                  int(area.height())));
    }
    if (plotAreaInView().contains(event->position())) {
        emit cursorMoved(timeAtX(x));
    } else {
        emit cursorLeft();
    }
    event->accept();
}

void TimeChartView::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_drag == Drag::Select && m_band) {
        m_band->hide();
        const double x = event->position().x();
        if (std::abs(x - m_selectStartX) >= kMinSelectPixels) {
            emit rangeSelected(timeAtX(m_selectStartX), timeAtX(x));
        }
    }
    if (m_drag == Drag::Pan) {
        unsetCursor();
    }
    m_drag = Drag::None;
    event->accept();
}

void TimeChartView::wheelEvent(QWheelEvent *event)
{
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0) {
        event->ignore();
        return;
    }
    const double factor = std::pow(kWheelZoomPerNotch, notches);
    if (event->modifiers().testFlag(Qt::ControlModifier)) {
        emit valueZoomRequested(factor);
    } else {
        emit zoomRequested(factor, timeAtX(event->position().x()));
    }
    event->accept();
}

void TimeChartView::leaveEvent(QEvent *event)
{
    emit cursorLeft();
    QChartView::leaveEvent(event);
}

void TimeChartView::drawForeground(QPainter *painter, const QRectF &rect)
{
    QChartView::drawForeground(painter, rect);
    if (!m_cursorTime || !chart()) {
        return;
    }
    const std::optional<double> x = cursorX(*m_cursorTime);
    if (!x) {
        return;
    }
    const QRectF area = chart()->plotArea();
    const QPointF top = chart()->mapToScene(QPointF(*x, area.top()));
    const QPointF bottom = chart()->mapToScene(QPointF(*x, area.bottom()));
    painter->save();
    painter->setPen(QPen(palette().color(QPalette::WindowText), 0, Qt::DashLine));
    painter->drawLine(top, bottom);
    painter->restore();
}

} // namespace lk::ui
