#include "StepOverlayChart.h"

#include <plot/MinMax.h>
#include <plot/StripChart.h>
#include <plot/TimeChartView.h>

#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <QtWidgets/QGraphicsLayout>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lk::ui {

using tuning::StepLoop;
using tuning::StepTrace;

namespace {

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

QLineSeries *addLine(QChart *chart, const QList<QPointF> &points, const QColor &color,
                     const QString &name, Qt::PenStyle style)
{
    auto *line = new QLineSeries(chart);
    line->setName(name);
    QPen pen(color);
    pen.setWidthF(style == Qt::SolidLine ? 1.6 : 1.0);
    pen.setStyle(style);
    line->setPen(pen);
    line->replace(points);
    chart->addSeries(line);
    for (QAbstractAxis *axis : chart->axes())
        line->attachAxis(axis);
    return line;
}

} // namespace

StepOverlayChart::StepOverlayChart(QWidget *parent)
    : QWidget(parent), m_response(new TimeChartView(this)), m_effort(new TimeChartView(this))
{
    m_response->setObjectName(QStringLiteral("stepResponseChart"));
    m_effort->setObjectName(QStringLiteral("stepEffortChart"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_response, 3);
    layout->addWidget(m_effort, 2);
    m_response->setMinimumHeight(170);
    m_effort->setMinimumHeight(140);
    setRuns({});
}

void StepOverlayChart::rebuild(TimeChartView *view, const QString &valueTitle, bool timeTitle)
{
    QChart *chart = view->chart();
    chart->removeAllSeries(); // deletes them
    for (QAbstractAxis *axis : chart->axes()) {
        chart->removeAxis(axis); // hands the axis back to us: it would leak
        delete axis;
    }
    auto *time = new QValueAxis(chart);
    // One time title under the lower chart: QtCharts elides labels ("...") rather than
    // dropping them when a short chart has no room for a title as well.
    time->setTitleText(timeTitle ? tr("Time from the step (s)") : QString());
    auto *value = new QValueAxis(chart);
    value->setTitleText(valueTitle);
    chart->addAxis(time, Qt::AlignBottom);
    chart->addAxis(value, Qt::AlignLeft);
    chart->setMargins(QMargins(2, 2, 2, 2));
    chart->layout()->setContentsMargins(0, 0, 0, 0);
    chart->setBackgroundRoundness(0);
    chart->legend()->setAlignment(Qt::AlignRight);
}

void StepOverlayChart::fitAxes(TimeChartView *view)
{
    QChart *chart = view->chart();
    MinMax x, y;
    for (QAbstractSeries *s : chart->series()) {
        for (const QPointF &p : static_cast<QLineSeries *>(s)->points()) {
            x.add(p.x());
            y.add(p.y());
        }
    }
    const auto axes = chart->axes();
    if (axes.size() != 2 || !x.isValid())
        return;
    auto ticks = [](QValueAxis *axis, double lo, double hi, int count) {
        // Fixed round steps, as the strip charts have: labels that fit, never "...".
        const double step = niceStep((hi - lo) / count);
        axis->setTickType(QValueAxis::TicksFixed); // no layout at the old interval
        axis->setRange(lo, hi);
        axis->setTickAnchor(0);
        axis->setTickInterval(step);
        axis->setTickType(QValueAxis::TicksDynamic);
        const int decimals = std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
        axis->setLabelFormat(QStringLiteral("%.%1f").arg(decimals));
    };
    ticks(static_cast<QValueAxis *>(axes.at(0)), x.min, x.max > x.min ? x.max : x.min + 1, 6);
    const auto [lo, hi] = scaledRange(y);
    // A short chart gets fewer value labels: QtCharts would shorten crowded ones to "...".
    ticks(static_cast<QValueAxis *>(axes.at(1)), lo, hi, view->height() < 200 ? 2 : 4);
    view->applyPalette();
}

void StepOverlayChart::setRuns(const QVector<OverlayRun> &runs)
{
    const bool speed = runs.isEmpty() || runs.first().trace.loop == StepLoop::Speed;
    const bool power = !runs.isEmpty() && runs.first().trace.effortIsPower;
    rebuild(m_response, speed ? tr("Speed (dps)") : tr("Angle (\u00b0)"), false);
    rebuild(m_effort, power ? tr("Power (rel.)") : tr("iq (A)"), true);
    m_responseLines.clear();
    for (const OverlayRun &run : runs) {
        m_responseLines.append(addLine(m_response->chart(), responsePoints(run.trace), run.color,
                                       run.label, Qt::SolidLine));
        QColor faint = run.color;
        faint.setAlpha(150);
        QLineSeries *target =
            addLine(m_response->chart(), targetPoints(run.trace), faint, QString(), Qt::DashLine);
        m_response->chart()->legend()->markers(target).value(0)->setVisible(false);
        addLine(m_effort->chart(), effortPoints(run.trace), run.color, run.label, Qt::SolidLine);
    }
    // Both legends (on the right) keep the two plot areas the same width, so times line up.
    m_effort->chart()->legend()->setVisible(!runs.isEmpty());
    m_response->chart()->legend()->setVisible(!runs.isEmpty());
    fitAxes(m_response);
    fitAxes(m_effort);
    m_runCount = int(runs.size());
}

QLineSeries *StepOverlayChart::responseSeries(int index) const
{
    return m_responseLines.value(index);
}

} // namespace lk::ui
