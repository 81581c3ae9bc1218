#include "StepOverlayChart.h"

#include <plot/MinMax.h>
#include <plot/StripChart.h>
#include <plot/TimeChartView.h>

#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
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
    m_response->setMinimumHeight(160);
    m_effort->setMinimumHeight(110);
    setRuns({});
}

void StepOverlayChart::rebuild(TimeChartView *view, const QString &valueTitle)
{
    QChart *chart = view->chart();
    chart->removeAllSeries();
    for (QAbstractAxis *axis : chart->axes())
        chart->removeAxis(axis);
    auto *time = new QValueAxis(chart);
    time->setTitleText(tr("Time from the step (s)"));
    auto *value = new QValueAxis(chart);
    value->setTitleText(valueTitle);
    chart->addAxis(time, Qt::AlignBottom);
    chart->addAxis(value, Qt::AlignLeft);
    chart->setMargins(QMargins(4, 4, 4, 4));
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
    static_cast<QValueAxis *>(axes.at(0))->setRange(x.min, x.max > x.min ? x.max : x.min + 1);
    const auto [lo, hi] = scaledRange(y);
    static_cast<QValueAxis *>(axes.at(1))->setRange(lo, hi);
    view->applyPalette();
}

void StepOverlayChart::setRuns(const QVector<OverlayRun> &runs)
{
    const bool speed = runs.isEmpty() || runs.first().trace.loop == StepLoop::Speed;
    const bool power = !runs.isEmpty() && runs.first().trace.effortIsPower;
    rebuild(m_response, speed ? tr("Speed (dps, rotor)") : tr("Angle (\u00b0, rotor)"));
    rebuild(m_effort, power ? tr("Power (rel.)") : tr("iq (A)"));
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
    m_effort->chart()->legend()->setVisible(false);
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
