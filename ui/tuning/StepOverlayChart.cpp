#include "StepOverlayChart.h"

#include <panels/Format.h>
#include <plot/CursorReadout.h>
#include <plot/MinMax.h>
#include <plot/StripChart.h>
#include <plot/TelemetryChannel.h>
#include <plot/TimeChartView.h>

#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <QtWidgets/QGraphicsLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QToolButton>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lk::ui {

using tuning::StepLoop;
using tuning::StepTrace;

namespace {

constexpr int kTimeTicks = 6;

/// Time of a run's samples relative to its first edge; the trace's own start without edges.
double alignTime(const StepTrace &trace)
{
    if (!trace.edges.isEmpty())
        return trace.edges.first().time;
    return trace.time.isEmpty() ? 0.0 : trace.time.first();
}

QList<QPointF> responsePoints(const StepTrace &trace)
{
    const double t0 = alignTime(trace);
    QList<QPointF> points;
    points.reserve(trace.size());
    for (int i = 0; i < trace.size(); ++i)
        points.append({trace.time.at(i) - t0, trace.value.at(i)});
    return points;
}

/// Effort samples only where a sample carried it: a gap in the data is not drawn as 0.
QList<QPointF> effortPoints(const StepTrace &trace)
{
    const double t0 = alignTime(trace);
    QList<QPointF> points;
    for (int i = 0; i < trace.size(); ++i) {
        if (!StepTrace::isMissing(trace.effort.at(i)))
            points.append({trace.time.at(i) - t0, trace.effort.at(i)});
    }
    return points;
}

/// The target as steps: `from` before the first edge, then each edge's `to` from its time on.
QList<QPointF> targetPoints(const StepTrace &trace)
{
    QList<QPointF> points;
    if (trace.edges.isEmpty() || trace.time.isEmpty())
        return points;
    const double t0 = alignTime(trace);
    points.append({trace.time.first() - t0, trace.edges.first().from});
    for (const tuning::StepEdge &e : trace.edges) {
        points.append({e.time - t0, e.from});
        points.append({e.time - t0, e.to});
    }
    points.append({trace.time.last() - t0, trace.edges.last().to});
    return points;
}

/// The newest sample at or before `time` (aligned) that carries the value, as the live plots
/// readout holds a value until the next sample; none before the first or past the last.
std::optional<double> heldAt(const StepTrace &trace, double time, bool effort)
{
    const double t = time + alignTime(trace);
    if (trace.time.isEmpty() || t < trace.time.first() || t > trace.time.last())
        return std::nullopt;
    const auto after = std::upper_bound(trace.time.begin(), trace.time.end(), t);
    for (qsizetype i = (after - trace.time.begin()) - 1; i >= 0; --i) {
        const double v = effort ? trace.effort.at(i) : trace.value.at(i);
        if (!StepTrace::isMissing(v))
            return v;
    }
    return std::nullopt;
}

QLineSeries *addLine(QChart *chart, const QList<QPointF> &points, const QColor &color,
                     const QString &name, Qt::PenStyle style, QValueAxis *valueAxis)
{
    auto *line = new QLineSeries(chart);
    line->setName(name);
    QPen pen(color);
    pen.setWidthF(style == Qt::SolidLine ? 1.6 : 1.0);
    pen.setStyle(style);
    line->setPen(pen);
    line->replace(points);
    chart->addSeries(line);
    line->attachAxis(chart->axes(Qt::Horizontal).value(0));
    line->attachAxis(valueAxis);
    return line;
}

/// Empties `view`'s chart and gives it a time axis (titled only under the lower chart:
/// QtCharts elides labels rather than dropping them when a short chart has no room for both).
void clearChart(TimeChartView *view, bool timeTitle)
{
    QChart *chart = view->chart();
    chart->removeAllSeries(); // deletes them
    for (QAbstractAxis *axis : chart->axes()) {
        chart->removeAxis(axis); // hands the axis back to us: it would leak
        delete axis;
    }
    auto *time = new QValueAxis(chart);
    time->setTitleText(timeTitle ? StepOverlayChart::tr("Time from the step (s)") : QString());
    chart->addAxis(time, Qt::AlignBottom);
    chart->setMargins(QMargins(2, 2, 2, 2));
    chart->layout()->setContentsMargins(0, 0, 0, 0);
    chart->setBackgroundRoundness(0);
    chart->legend()->setAlignment(Qt::AlignRight);
}

QValueAxis *addValueAxis(TimeChartView *view, const QString &title, Qt::Alignment side)
{
    auto *axis = new QValueAxis(view->chart());
    axis->setTitleText(title);
    view->chart()->addAxis(axis, side);
    return axis;
}

/// A short chart gets fewer value labels: QtCharts would shorten crowded ones to "...".
int valueTicks(const TimeChartView *view)
{
    return view->height() < 200 ? 2 : 4;
}

/// Every value axis of `view` to the data of the series attached to it.
void fitValueAxes(TimeChartView *view)
{
    for (QAbstractAxis *a : view->chart()->axes(Qt::Vertical)) {
        auto *axis = static_cast<QValueAxis *>(a);
        MinMax y;
        for (QAbstractSeries *s : view->chart()->series()) {
            if (!s->attachedAxes().contains(axis))
                continue;
            for (const QPointF &p : static_cast<QLineSeries *>(s)->points())
                y.add(p.y());
        }
        const auto [lo, hi] = y.isValid() ? scaledRange(y) : std::pair<double, double>{0, 1};
        setAxisRange(axis, lo, hi, valueTicks(view));
    }
}

QString responseValue(const StepTrace &trace, double time)
{
    const bool speed = trace.loop == StepLoop::Speed;
    return CursorReadout::value(
        channelLabel(speed ? TelemetryChannel::Speed : TelemetryChannel::MultiTurn, false),
        heldAt(trace, time, false), speed ? 1 : 2,
        speed ? QStringLiteral("dps") : QStringLiteral("\u00b0"));
}

QString effortValue(const StepTrace &trace, double time)
{
    const bool power = trace.effortIsPower;
    return CursorReadout::value(channelLabel(TelemetryChannel::Torque, power),
                                heldAt(trace, time, true), power ? 0 : 3,
                                power ? Format::powerUnit() : QStringLiteral("A"));
}

} // namespace

StepOverlayChart::StepOverlayChart(QWidget *parent)
    : QWidget(parent), m_response(new TimeChartView(this)), m_effort(new TimeChartView(this)),
      m_readout(new CursorReadout(this)), m_reset(new QToolButton(this))
{
    m_response->setObjectName(QStringLiteral("stepResponseChart"));
    m_effort->setObjectName(QStringLiteral("stepEffortChart"));
    m_readout->setObjectName(QStringLiteral("stepReadout"));
    m_reset->setObjectName(QStringLiteral("stepResetZoom"));
    m_reset->setText(tr("Reset zoom"));
    m_reset->setToolTip(tr("Show every sample again after zooming or panning"));
    auto *bar = new QHBoxLayout;
    bar->addWidget(m_readout, 1);
    bar->addWidget(m_reset);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(bar);
    layout->addWidget(m_response, 3);
    layout->addWidget(m_effort, 2);
    m_response->setMinimumHeight(170);
    m_effort->setMinimumHeight(140);
    connect(m_reset, &QToolButton::clicked, this, &StepOverlayChart::resetZoom);
    connectGestures(m_response);
    connectGestures(m_effort);
    setRuns({});
}

void StepOverlayChart::connectGestures(TimeChartView *view)
{
    connect(view, &TimeChartView::panRequested, this, [this](double seconds) {
        m_viewport.pan(seconds, m_data.end);
        showRange();
    });
    connect(view, &TimeChartView::zoomRequested, this, [this](double factor, double anchor) {
        m_viewport.zoom(factor, anchor, m_data.end);
        showRange();
    });
    connect(view, &TimeChartView::rangeSelected, this, [this](double t0, double t1) {
        m_viewport.select(t0, t1);
        showRange();
    });
    connect(view, &TimeChartView::valueZoomRequested, this,
            [view](double factor) { scaleValueAxes(view, factor); });
    connect(view, &TimeChartView::cursorMoved, this, [this](double t) { setCursorTime(t); });
    connect(view, &TimeChartView::cursorLeft, this, [this] { setCursorTime(std::nullopt); });
}

void StepOverlayChart::rebuildCharts()
{
    const bool speed = m_runs.isEmpty() || m_runs.first().trace.loop == StepLoop::Speed;
    const bool anyPower = std::any_of(m_runs.begin(), m_runs.end(),
                                      [](const OverlayRun &r) { return r.trace.effortIsPower; });
    const bool anyCurrent =
        m_runs.isEmpty() || std::any_of(m_runs.begin(), m_runs.end(),
                                        [](const OverlayRun &r) { return !r.trace.effortIsPower; });
    clearChart(m_response, false);
    clearChart(m_effort, true);
    addValueAxis(m_response, speed ? tr("Speed (dps)") : tr("Angle (\u00b0)"), Qt::AlignLeft);
    // Power and current have no common scale: each its own axis, named for what it holds.
    m_currentAxis = anyCurrent ? addValueAxis(m_effort, tr("iq (A)"), Qt::AlignLeft) : nullptr;
    m_powerAxis = anyPower ? addValueAxis(m_effort, tr("Power (rel.)"),
                                          anyCurrent ? Qt::AlignRight : Qt::AlignLeft)
                           : nullptr;
}

void StepOverlayChart::addRun(const OverlayRun &run)
{
    QValueAxis *response = static_cast<QValueAxis *>(m_response->chart()->axes(Qt::Vertical)[0]);
    m_responseLines.append(addLine(m_response->chart(), responsePoints(run.trace), run.color,
                                   run.label, Qt::SolidLine, response));
    QColor faint = run.color;
    faint.setAlpha(150);
    QLineSeries *target = addLine(m_response->chart(), targetPoints(run.trace), faint, QString(),
                                  Qt::DashLine, response);
    m_response->chart()->legend()->markers(target).value(0)->setVisible(false);
    addLine(m_effort->chart(), effortPoints(run.trace), run.color, run.label, Qt::SolidLine,
            run.trace.effortIsPower ? m_powerAxis : m_currentAxis);
}

void StepOverlayChart::setRuns(const QVector<OverlayRun> &runs)
{
    m_runs = runs;
    m_responseLines.clear();
    rebuildCharts();
    MinMax x;
    for (const OverlayRun &run : runs) {
        addRun(run);
        for (const QPointF &p : responsePoints(run.trace))
            x.add(p.x());
    }
    // Both legends (on the right) keep the two plot areas the same width, so times line up.
    m_effort->chart()->legend()->setVisible(!runs.isEmpty());
    m_response->chart()->legend()->setVisible(!runs.isEmpty());
    m_data = x.isValid() ? TimeSpan{x.min, x.max > x.min ? x.max : x.min + 1} : TimeSpan{0, 1};
    m_cursor.reset();
    resetZoom();
}

void StepOverlayChart::resetZoom()
{
    m_viewport.select(m_data.begin, m_data.end);
    fitValueAxes(m_response);
    fitValueAxes(m_effort);
    showRange();
}

TimeSpan StepOverlayChart::shownRange() const
{
    return m_viewport.range(m_data.end);
}

void StepOverlayChart::showRange()
{
    const TimeSpan r = shownRange();
    for (TimeChartView *view : {m_response, m_effort}) {
        if (QValueAxis *time = view->timeAxis())
            setAxisRange(time, r.begin, r.end, kTimeTicks);
        view->applyPalette();
    }
    const double same = 1e-9 * m_data.length(); // select() centres: rounding is not a zoom
    m_reset->setEnabled(std::abs(r.begin - m_data.begin) > same ||
                        std::abs(r.end - m_data.end) > same);
    setCursorTime(m_cursor);
}

void StepOverlayChart::scaleValueAxes(TimeChartView *view, double factor)
{
    for (QAbstractAxis *a : view->chart()->axes(Qt::Vertical)) {
        auto *axis = static_cast<QValueAxis *>(a);
        const double mid = (axis->min() + axis->max()) / 2;
        const double half = (axis->max() - axis->min()) / 2 * factor;
        setAxisRange(axis, mid - half, mid + half, valueTicks(view));
    }
}

void StepOverlayChart::setCursorTime(std::optional<double> time)
{
    m_cursor = time;
    m_response->setCursorTime(time);
    m_effort->setCursorTime(time);
    if (time)
        m_readout->showText(readoutAt(*time));
    else if (m_runs.isEmpty())
        m_readout->showText(QString());
    else
        m_readout->showText(tr("Hover for values \u00b7 wheel: zoom \u00b7 drag: pan \u00b7 "
                               "Shift+drag: select a range"));
}

QString StepOverlayChart::readoutAt(double time) const
{
    QStringList groups;
    for (const OverlayRun &run : m_runs)
        groups << tr("%1: %2").arg(run.label, responseValue(run.trace, time) +
                                                  QStringLiteral(", ") +
                                                  effortValue(run.trace, time));
    return CursorReadout::line(time, groups);
}

QString StepOverlayChart::readoutText() const
{
    return m_readout->text();
}

QLineSeries *StepOverlayChart::responseSeries(int index) const
{
    return m_responseLines.value(index);
}

} // namespace lk::ui
