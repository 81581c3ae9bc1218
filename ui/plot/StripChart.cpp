#include "StripChart.h"

#include "SeriesColors.h"
#include "TimeGridLayer.h"
#include "TraceLayer.h"

#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <QtGui/QPainter>

#include <algorithm>
#include <array>
#include <cmath>

namespace lk::ui {

namespace {

constexpr int kBaseMargin = 6;
constexpr double kScalePadding = 0.05; // share of the range left free above and below
constexpr int kValueTicks = 5;

// Each setter is called only for a change: QValueAxis (Qt 6.4) emits its change signal on
// every call, and QtCharts answers labelFormatChanged with a relayout of the whole chart (every
// axis builds its labels again as rich text). Called at every autoscale, that relayout cost a
// fifth of the GUI thread's time with every signal plotted.
void setNiceTicks(QValueAxis *axis, double span, int ticks)
{
    const double step = niceStep(span / ticks);
    if (axis->tickType() != QValueAxis::TicksDynamic)
        axis->setTickType(QValueAxis::TicksDynamic);
    if (axis->tickAnchor() != 0)
        axis->setTickAnchor(0);
    if (axis->tickInterval() != step)
        axis->setTickInterval(step);
    const QString format = QStringLiteral("%.%1f").arg(tickDecimals(step));
    if (axis->labelFormat() != format)
        axis->setLabelFormat(format);
}

} // namespace

// QtCharts lays the ticks out on every setter. Going from a flat signal (range ~0.001) to a
// real one with the old interval would lay out millions of ticks and freeze the GUI, and the
// reverse order has the same problem when the range shrinks; so a growing interval is set
// before the range and a shrinking one after it.
void setAxisRange(QValueAxis *axis, double min, double max, int ticks)
{
    const double step = niceStep((max - min) / ticks);
    // A fixed-count axis lays out only its few ticks whatever the range: range first, then.
    const bool grows = axis->tickType() == QValueAxis::TicksDynamic && step >= axis->tickInterval();
    if (grows)
        setNiceTicks(axis, max - min, ticks);
    axis->setRange(min, max);
    if (!grows)
        setNiceTicks(axis, max - min, ticks);
}

namespace {

// Autoscale keeps the value axis while the data stays inside it and fills at least this share
// of it: the axis then changes a few times a second at most instead of every frame, which
// spares QtCharts a relayout per frame and the user a jittering scale.
constexpr double kMinFill = 0.5;

bool keepsRange(std::pair<double, double> range, const MinMax &data)
{
    return data.min >= range.first && data.max <= range.second &&
           (data.max - data.min) >= kMinFill * (range.second - range.first);
}

} // namespace

std::pair<double, double> scaledRange(const MinMax &data)
{
    const double span = data.max - data.min;
    const double pad = std::max(span * kScalePadding, std::max(std::abs(data.max), 1.0) * 1e-3);
    // Rounded out to whole ticks so that the labels stay put while the range does.
    const double step = niceStep((span + 2 * pad) / kValueTicks);
    return {std::floor((data.min - pad) / step) * step, std::ceil((data.max + pad) / step) * step};
}

int tickDecimals(double step)
{
    return std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
}

double niceStep(double raw)
{
    if (!(raw > 0) || !std::isfinite(raw)) {
        return 1;
    }
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * decade >= raw * (1 - 1e-9)) {
            return m * decade;
        }
    }
    return 10 * decade;
}

StripChart::StripChart(QWidget *parent) : TimeChartView(parent)
{
    // The view's own chart: setChart() would release (and so leak) the one it made.
    QChart *c = chart();
    c->setAnimationOptions(QChart::NoAnimation);
    c->setBackgroundRoundness(0);
    c->setMargins(QMargins(kBaseMargin, kBaseMargin, kBaseMargin, kBaseMargin));
    c->legend()->setAlignment(Qt::AlignTop);
    c->legend()->hide();
    // The time axis maps and holds the range; hidden, it costs QtCharts no layout when the range
    // moves at every frame. TimeGridLayer draws its grid and labels.
    m_time = new QValueAxis(c);
    m_time->setRange(0, 10);
    c->addAxis(m_time, Qt::AlignBottom);
    m_time->setVisible(false);
    m_grid = new TimeGridLayer(c, m_time);
    m_lines = new TraceLayer(c, m_time);
    connect(c, &QChart::plotAreaChanged, this, [this] {
        m_grid->plotAreaChanged();
        m_lines->plotAreaChanged();
    });
    applyPalette();
}

void StripChart::clearChart()
{
    chart()->removeAllSeries(); // deletes them
    m_series.clear();
    m_lines->setTraces({});
    m_outages.clear();
    for (auto &[quantity, axis] : m_valueAxes) {
        chart()->removeAxis(axis);
        delete axis;
    }
    m_valueAxes.clear();
    m_axisColors.clear();
}

void StripChart::applyPalette()
{
    TimeChartView::applyPalette();
    // The hidden time axis took the palette's colours with the others: its grid draws in them.
    m_grid->setColors(m_time->gridLineColor(), m_time->linePenColor(), m_time->labelsColor());
    m_grid->setFonts(m_time->labelsFont(), m_time->titleFont());
    applyMargins(); // the labels' height follows the font
    for (const auto &[quantity, color] : m_axisColors) {
        if (QValueAxis *axis = valueAxis(quantity)) {
            axis->setLabelsColor(color);
            axis->setTitleBrush(color);
        }
    }
}

QColor StripChart::traceColor(int index) const
{
    const PlotTrace &trace = m_traces.at(index);
    if (m_coloring == Coloring::ByChannel) {
        return SeriesColors::at(int(trace.channel));
    }
    return SeriesColors::at(int(driveOrder().indexOf(trace.driveId)));
}

QVector<int> StripChart::driveOrder() const
{
    QVector<int> drives;
    for (const PlotTrace &t : m_traces) {
        if (!drives.contains(t.driveId)) {
            drives.append(t.driveId);
        }
    }
    return drives;
}

void StripChart::setTraces(const QVector<PlotTrace> &traces, Coloring coloring)
{
    if (traces == m_traces && coloring == m_coloring && m_series.size() == traces.size()) {
        return;
    }
    clearChart();
    m_traces = traces;
    m_coloring = coloring;
    QVector<std::pair<QPen, QValueAxis *>> lines;
    for (int i = 0; i < m_traces.size(); ++i) {
        const PlotTrace &trace = m_traces.at(i);
        QValueAxis *&axis = m_valueAxes[trace.quantity()];
        if (!axis) {
            axis = new QValueAxis(chart());
            axis->setTitleText(quantityTitle(trace.quantity()));
            const bool left = m_valueAxes.size() % 2 == 1;
            chart()->addAxis(axis, left ? Qt::AlignLeft : Qt::AlignRight);
            if (m_coloring == Coloring::ByChannel)
                m_axisColors[trace.quantity()] = traceColor(i);
        }
        const QPen pen = tracePen(i);
        m_series.append(addLegendSeries(i, pen));
        lines.append({pen, axis});
    }
    m_lines->setTraces(lines);
    chart()->legend()->setVisible(driveOrder().size() > 1 || m_valueAxes.size() > 1);
    applyPalette(); // the new axes
    m_needsScale = true;
}

QPen StripChart::tracePen(int index) const
{
    const PlotTrace &trace = m_traces.at(index);
    QPen pen(traceColor(index), 1);
    // Cosmetic: the raster engine draws it directly, dashes included; a non-cosmetic pen goes
    // through QPainterPathStroker on every frame (a tenth of the GUI thread with every signal
    // plotted). At a width of one pixel both look the same.
    pen.setCosmetic(true);
    if (m_coloring == Coloring::ByChannel) {
        // Several drives in one overlaid chart: the drive shows as the dash pattern.
        static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine,
                                              Qt::DashDotLine, Qt::DashDotDotLine};
        pen.setStyle(styles[driveOrder().indexOf(trace.driveId) % 5]);
    }
    return pen;
}

QLineSeries *StripChart::addLegendSeries(int index, const QPen &pen)
{
    const PlotTrace &trace = m_traces.at(index);
    auto *series = new QLineSeries(chart());
    series->setUseOpenGL(false); // raster: works offscreen and on any remote display
    series->setName(
        tr("ID %1 %2").arg(trace.driveId).arg(channelLabel(trace.channel, trace.power)));
    series->setPen(pen);
    chart()->addSeries(series);
    // Not on the time axis: the legend needs no time, and a series on it had QtCharts
    // recompute its domain and geometry at every frame's new range (a sixteenth of the GUI
    // thread with every signal plotted, for series holding no point).
    series->attachAxis(valueAxis(trace.quantity()));
    return series;
}

void StripChart::showSegments(int index, const LineSegments &segments)
{
    m_lines->setPieces(index, segments);
}

QList<QPointF> StripChart::points(int index) const
{
    const LineSegments pieces = segments(index);
    return pieces.isEmpty() ? QList<QPointF>() : pieces.first();
}

LineSegments StripChart::segments(int index) const
{
    LineSegments out;
    if (index < 0 || index >= m_lines->traceCount()) {
        return out;
    }
    for (const QList<QPointF> &piece : m_lines->pieces(index)) {
        if (!piece.isEmpty()) {
            out.append(piece);
        }
    }
    return out;
}

void StripChart::collectOutages(const TelemetryStore &store, TimeSpan span)
{
    // The union of every trace's outages in view: overlapping ones merge into one band.
    QVector<TimeSpan> all;
    for (const PlotTrace &trace : std::as_const(m_traces)) {
        all += store.outages(trace.driveId, trace.channel, span.begin, span.end);
    }
    std::sort(all.begin(), all.end(),
              [](const TimeSpan &a, const TimeSpan &b) { return a.begin < b.begin; });
    QVector<TimeSpan> merged;
    for (const TimeSpan &o : std::as_const(all)) {
        if (!merged.isEmpty() && o.begin <= merged.last().end) {
            merged.last().end = std::max(merged.last().end, o.end);
        } else {
            merged.append(o);
        }
    }
    if (merged.size() != m_outages.size() ||
        !std::equal(merged.cbegin(), merged.cend(), m_outages.cbegin(),
                    [](const TimeSpan &a, const TimeSpan &b) {
                        return a.begin == b.begin && a.end == b.end;
                    })) {
        m_outages = merged;
        viewport()->update();
    }
}

void StripChart::drawForeground(QPainter *painter, const QRectF &rect)
{
    // Outages first, under the cursor line: a hatched band where nothing was measured.
    if (!m_outages.isEmpty() && m_time->max() > m_time->min()) {
        const QRectF area = chart()->plotArea();
        const double scale = area.width() / (m_time->max() - m_time->min());
        QColor shade = palette().color(QPalette::WindowText);
        shade.setAlpha(40);
        painter->save();
        painter->setPen(Qt::NoPen);
        for (const TimeSpan &o : std::as_const(m_outages)) {
            const double x0 =
                std::max(area.left(), area.left() + (o.begin - m_time->min()) * scale);
            const double x1 = std::min(area.right(), area.left() + (o.end - m_time->min()) * scale);
            if (x1 <= x0) {
                continue;
            }
            const QRectF band(chart()->mapToScene(QPointF(x0, area.top())),
                              chart()->mapToScene(QPointF(x1, area.bottom())));
            painter->fillRect(band, shade);
            painter->fillRect(band, QBrush(shade, Qt::BDiagPattern));
        }
        painter->restore();
    }
    drawMarkers(painter);
    TimeChartView::drawForeground(painter, rect);
}

void StripChart::setMarkers(const QVector<TimeMarker> &markers)
{
    if (markers.size() == m_markers.size() &&
        std::equal(markers.cbegin(), markers.cend(), m_markers.cbegin(),
                   [](const TimeMarker &a, const TimeMarker &b) {
                       return a.time == b.time && a.label == b.label;
                   }))
        return;
    m_markers = markers;
    viewport()->update();
}

void StripChart::drawMarkers(QPainter *painter)
{
    if (m_markers.isEmpty() || !(m_time->max() > m_time->min()))
        return;
    const QRectF area = chart()->plotArea();
    const double scale = area.width() / (m_time->max() - m_time->min());
    painter->save();
    QPen pen(palette().color(QPalette::Highlight));
    pen.setStyle(Qt::DashLine);
    painter->setPen(pen);
    for (const TimeMarker &m : std::as_const(m_markers)) {
        const double x = area.left() + (m.time - m_time->min()) * scale;
        if (x < area.left() || x > area.right())
            continue;
        const QPointF top = chart()->mapToScene(QPointF(x, area.top()));
        const QPointF bottom = chart()->mapToScene(QPointF(x, area.bottom()));
        painter->drawLine(top, bottom);
        painter->drawText(top + QPointF(3, painter->fontMetrics().ascent()), m.label);
    }
    painter->restore();
}

QValueAxis *StripChart::valueAxis(Quantity quantity) const
{
    const auto it = m_valueAxes.find(quantity);
    return it == m_valueAxes.end() ? nullptr : it->second;
}

void StripChart::setTimeLabelsVisible(bool visible)
{
    m_grid->setLabels(visible, visible ? tr("Time (s)") : QString());
    applyMargins();
}

bool StripChart::timeLabelsVisible() const
{
    return m_grid->labelsVisible();
}

int StripChart::plotColumns() const
{
    const double width = chart()->plotArea().width();
    return std::max(1, int(width > 0 ? width : this->width()));
}

void StripChart::refresh(const TelemetryStore &store, TimeSpan span, bool autoscale,
                         DecimationMethod method)
{
    if (!(span.end > span.begin)) {
        span.end = span.begin + TimeViewport::kMinSpan;
    }
    const int columns = plotColumns();
    QVector<LineSegments> points(m_traces.size());
    std::map<Quantity, MinMax> inWindow, anywhere;
    for (int i = 0; i < m_traces.size(); ++i) {
        const PlotTrace &trace = m_traces.at(i);
        points[i] =
            store.decimated(trace.driveId, trace.channel, span.begin, span.end, columns, method);
        MinMax &inside = inWindow[trace.quantity()];
        MinMax &all = anywhere[trace.quantity()];
        for (const QList<QPointF> &segment : std::as_const(points[i])) {
            for (const QPointF &p : segment) {
                all.add(p.y());
                if (p.x() >= span.begin && p.x() <= span.end) {
                    inside.add(p.y());
                }
            }
        }
    }
    std::map<Quantity, std::pair<double, double>> ranges;
    if (autoscale || m_needsScale) {
        bool scaled = false;
        for (const auto &[quantity, axis] : m_valueAxes) {
            // Only neighbours outside the window: scale on them rather than on nothing.
            const MinMax mm =
                inWindow[quantity].isValid() ? inWindow[quantity] : anywhere[quantity];
            if (!mm.isValid()) {
                continue;
            }
            const std::pair<double, double> target = scaledRange(mm);
            const std::pair<double, double> current{axis->min(), axis->max()};
            if (m_needsScale || (target != current && !keepsRange(current, mm))) {
                ranges[quantity] = target;
            }
            scaled = true;
        }
        m_needsScale = m_needsScale && !scaled;
    }
    if (m_time->min() != span.begin || m_time->max() != span.end) {
        m_time->setRange(span.begin, span.end);
        m_grid->update();
    }
    for (const auto &[quantity, range] : ranges) {
        QValueAxis *axis = m_valueAxes.at(quantity);
        setAxisRange(axis, range.first, range.second, kValueTicks);
    }
    for (int i = 0; i < m_traces.size(); ++i) {
        showSegments(i, points.at(i));
    }
    collectOutages(store, span);
}

void StripChart::scaleValueAxes(double factor)
{
    for (auto &[quantity, axis] : m_valueAxes) {
        const double mid = (axis->min() + axis->max()) / 2;
        const double half = (axis->max() - axis->min()) / 2 * factor;
        setAxisRange(axis, mid - half, mid + half, kValueTicks);
    }
    m_lines->update();
}

double StripChart::axisInsetLeft() const
{
    return chart()->plotArea().left() - chart()->margins().left();
}

double StripChart::axisInsetRight() const
{
    return chart()->size().width() - chart()->plotArea().right() - chart()->margins().right();
}

void StripChart::setAlignmentPadding(double left, double right)
{
    if (qFuzzyCompare(left + 1, m_padLeft + 1) && qFuzzyCompare(right + 1, m_padRight + 1)) {
        return;
    }
    m_padLeft = left;
    m_padRight = right;
    applyMargins();
}

void StripChart::applyMargins()
{
    // QtCharts lays the chart out again on every margin change: set them only when they change.
    const QMargins margins(kBaseMargin + int(m_padLeft), kBaseMargin, kBaseMargin + int(m_padRight),
                           kBaseMargin + m_grid->labelAreaHeight());
    if (chart()->margins() != margins)
        chart()->setMargins(margins);
}

} // namespace lk::ui
