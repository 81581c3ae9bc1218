#include "BodeChart.h"

#include <panels/Format.h>

#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>
#include <QtGui/QCursor>
#include <QtWidgets/QLabel>
#include <QtWidgets/QToolTip>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lk::ui {

using tuning::FrequencyPoint;
using tuning::FrequencyResponse;

namespace {

struct Range {
    double min = 0;
    double max = 0;
    bool empty = true;
    void take(double v)
    {
        min = empty ? v : std::min(min, v);
        max = empty ? v : std::max(max, v);
        empty = false;
    }
};

QChartView *makeView(const QString &name, QWidget *parent)
{
    auto *chart = new QChart;
    chart->legend()->setVisible(false);
    chart->setMargins(QMargins(4, 4, 4, 4));
    auto *view = new QChartView(chart, parent);
    view->setObjectName(name);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(140);
    return view;
}

void clearChart(QChart *chart)
{
    chart->removeAllSeries(); // deletes them
    for (QAbstractAxis *axis : chart->axes()) {
        chart->removeAxis(axis); // hands the axis back: it would leak
        delete axis;
    }
}

/// A figure with one decimal, never "-0.0" for a value that rounds to zero.
QString tenth(double v)
{
    double r = std::round(v * 10) / 10;
    if (r == 0)
        r = 0; // -0 prints as "-0.0"
    return Format::number(r, 1);
}

/// Whether the run left a frequency out for want of samples: the limit line is drawn only
/// when the rate really cost one.
bool droppedAboveResolution(const FrequencyResponse &r)
{
    return std::any_of(r.dropped.begin(), r.dropped.end(), [](const tuning::DroppedFrequency &d) {
        return d.reason == tuning::DroppedReason::AboveResolution;
    });
}

} // namespace

BodeChart::BodeChart(QWidget *parent)
    : QWidget(parent), m_magnitudeView(makeView(QStringLiteral("bodeMagnitude"), this)),
      m_phaseView(makeView(QStringLiteral("bodePhase"), this)), m_figures(new QLabel(this)),
      m_resolution(new QLabel(this))
{
    setObjectName(QStringLiteral("bodeChart"));
    m_figures->setObjectName(QStringLiteral("bodeFigures"));
    m_figures->setWordWrap(true);
    m_figures->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_resolution->setObjectName(QStringLiteral("bodeResolution"));
    m_resolution->setWordWrap(true);
    QLegend *legend = m_magnitudeView->chart()->legend();
    legend->setVisible(true);
    legend->setAlignment(Qt::AlignBottom);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_magnitudeView, 1);
    layout->addWidget(m_phaseView, 1);
    layout->addWidget(m_figures);
    layout->addWidget(m_resolution);
    rebuild();
}

void BodeChart::setRuns(const QVector<BodeRun> &runs)
{
    m_runs = runs;
    rebuild();
}

QScatterSeries *BodeChart::magnitudePoints(int index) const
{
    return m_magnitudePoints.value(index);
}

QScatterSeries *BodeChart::phasePoints(int index) const
{
    return m_phasePoints.value(index);
}

void BodeChart::rebuild()
{
    clearChart(m_magnitudeView->chart());
    clearChart(m_phaseView->chart());
    m_magnitudePoints.clear();
    m_phasePoints.clear();
    m_runLines.clear();
    m_resolutionLine = nullptr;
    fitAxes();
    for (int i = 0; i < m_runs.size(); ++i)
        addRun(i);
    addMarkers();
    m_figures->setText(figuresText());
    m_resolution->setText(resolutionText());
    m_resolution->setVisible(!m_resolution->text().isEmpty());
}

void BodeChart::fitAxes()
{
    Range hz, db, deg;
    for (const BodeRun &run : std::as_const(m_runs)) {
        for (const FrequencyPoint &p : run.response.points) {
            hz.take(p.hz);
            db.take(p.magnitudeDb);
            deg.take(p.phaseDeg);
        }
    }
    if (!m_runs.isEmpty() && droppedAboveResolution(m_runs.last().response))
        hz.take(m_runs.last().response.resolvedHz());
    if (hz.empty) {
        hz = {1, 100, false};
        db = {-10, 2, false};
        deg = {-180, 0, false};
    }
    const auto axes = [](QChart *chart, const Range &x, const Range &y, double pad,
                         const QString &title) {
        auto *f = new QLogValueAxis(chart);
        f->setBase(10);
        f->setLabelFormat(QStringLiteral("%g"));
        f->setRange(x.min / 1.3, x.max * 1.3);
        f->setMinorTickCount(8);
        auto *v = new QValueAxis(chart);
        v->setRange(y.min - pad, y.max + pad);
        v->setTitleText(title);
        v->applyNiceNumbers();
        chart->addAxis(f, Qt::AlignBottom);
        chart->addAxis(v, Qt::AlignLeft);
        return f;
    };
    axes(m_magnitudeView->chart(), hz, db, 3, tr("Magnitude (dB)"));
    QLogValueAxis *f = axes(m_phaseView->chart(), hz, deg, 15, tr("Phase (\u00b0)"));
    f->setTitleText(tr("Frequency (Hz)"));
}

void BodeChart::addRun(int index)
{
    const BodeRun &run = m_runs.at(index);
    const auto add = [&](QChartView *view, bool magnitude) {
        QChart *chart = view->chart();
        auto *line = new QLineSeries(chart);
        auto *dots = new QScatterSeries(chart);
        line->setName(run.label);
        dots->setName(run.label);
        QPen pen(run.color);
        pen.setWidthF(1.6);
        line->setPen(pen);
        dots->setColor(run.color);
        dots->setBorderColor(run.color);
        dots->setMarkerSize(7);
        for (const FrequencyPoint &p : run.response.points) {
            const QPointF at(p.hz, magnitude ? p.magnitudeDb : p.phaseDeg);
            line->append(at);
            dots->append(at);
        }
        for (QAbstractSeries *s :
             {static_cast<QAbstractSeries *>(line), static_cast<QAbstractSeries *>(dots)}) {
            chart->addSeries(s);
            s->attachAxis(chart->axes(Qt::Horizontal).value(0));
            s->attachAxis(chart->axes(Qt::Vertical).value(0));
        }
        // The legend names each run once, by its line.
        for (QLegendMarker *m : chart->legend()->markers(dots))
            m->setVisible(false);
        if (magnitude)
            m_runLines.append(line);
        // The fit quality of each point is one hover away.
        connect(dots, &QScatterSeries::hovered, this,
                [this, index, dots](const QPointF &at, bool state) {
                    if (!state) {
                        QToolTip::hideText();
                        return;
                    }
                    const QList<QPointF> pts = dots->points();
                    const auto it = std::find(pts.begin(), pts.end(), at);
                    if (it != pts.end())
                        QToolTip::showText(QCursor::pos(), pointText(index, int(it - pts.begin())));
                });
        return dots;
    };
    m_magnitudePoints.append(add(m_magnitudeView, true));
    m_phasePoints.append(add(m_phaseView, false));
}

QLineSeries *BodeChart::verticalLine(QChart *chart, double hz, const QColor &color,
                                     Qt::PenStyle style, const QString &name)
{
    auto *axis = qobject_cast<QValueAxis *>(chart->axes(Qt::Vertical).value(0));
    auto *line = new QLineSeries(chart);
    line->setName(name);
    QPen pen(color);
    pen.setStyle(style);
    pen.setWidthF(1.2);
    line->setPen(pen);
    line->append(hz, axis->min());
    line->append(hz, axis->max());
    chart->addSeries(line);
    for (QLegendMarker *m : chart->legend()->markers(line))
        m->setVisible(false); // a marker, not a run
    line->attachAxis(chart->axes(Qt::Horizontal).value(0));
    line->attachAxis(axis);
    return line;
}

void BodeChart::addMarkers()
{
    if (m_runs.isEmpty())
        return;
    const BodeRun &newest = m_runs.last();
    const tuning::BodeFigures f = newest.response.figures();
    if (f.bandwidthHz) {
        for (QChartView *view : {m_magnitudeView, m_phaseView})
            verticalLine(view->chart(), *f.bandwidthHz, newest.color, Qt::DotLine,
                         tr("-3 dB bandwidth"));
    }
    if (droppedAboveResolution(newest.response)) {
        const double limit = newest.response.resolvedHz();
        m_resolutionLine = verticalLine(m_magnitudeView->chart(), limit, palette().text().color(),
                                        Qt::DashLine, tr("Resolution limit"));
        verticalLine(m_phaseView->chart(), limit, palette().text().color(), Qt::DashLine,
                     tr("Resolution limit"));
    }
}

QString BodeChart::resolutionText() const
{
    if (m_runs.isEmpty() || !droppedAboveResolution(m_runs.last().response))
        return {};
    const FrequencyResponse &r = m_runs.last().response;
    QStringList dropped;
    for (const tuning::DroppedFrequency &d : r.dropped) {
        if (d.reason == tuning::DroppedReason::AboveResolution)
            dropped << Format::number(d.hz, d.hz < 10 ? 2 : 1);
    }
    return tr("Dashed line: %1 Hz, the highest frequency %2 samples/s resolve (%3 samples a "
              "period at least). Not shown above it: %4 Hz.")
        .arg(Format::number(r.resolvedHz(), 1), Format::number(r.sampleRateHz, 0),
             Format::number(r.samplesPerPeriod, 0), dropped.join(QStringLiteral(", ")));
}

QStringList BodeChart::legendLabels() const
{
    QStringList out;
    // The runs' lines' markers (a marker's own visibility follows the legend's layout, which
    // has not run yet right after a change).
    for (QLegendMarker *m : m_magnitudeView->chart()->legend()->markers())
        if (m_runLines.contains(m->series()))
            out << m->label();
    return out;
}

QString BodeChart::figuresLine(const QString &label, const FrequencyResponse &response)
{
    const tuning::BodeFigures f = response.figures();
    const QString bandwidth =
        f.bandwidthHz
            ? tr("-3 dB bandwidth %1 Hz (phase there %2\u00b0)")
                  .arg(tenth(*f.bandwidthHz),
                       f.phaseAtBandwidth ? Format::number(*f.phaseAtBandwidth, 0) : tr("unknown"))
            : tr("no -3 dB bandwidth within the frequencies measured");
    const QString peak =
        f.peakDb ? tr("peak %1 dB at %2 Hz").arg(tenth(*f.peakDb), tenth(f.peakHz.value_or(0)))
                 : tr("no peak (too few points)");
    return tr("%1: %2; %3.").arg(label, bandwidth, peak);
}

QString BodeChart::figuresText() const
{
    if (m_runs.isEmpty())
        return tr("No frequency response yet.");
    QStringList lines;
    for (const BodeRun &run : m_runs)
        lines << figuresLine(run.label, run.response);
    return lines.join(QLatin1Char('\n'));
}

QString BodeChart::pointText(int run, int point) const
{
    if (run < 0 || run >= m_runs.size() || point < 0 ||
        point >= m_runs.at(run).response.points.size())
        return {};
    const FrequencyPoint &p = m_runs.at(run).response.points.at(point);
    return tr("%1\n%2 Hz: %3 dB, %4\u00b0\nFit quality %5 (%6 samples)")
        .arg(m_runs.at(run).label, Format::number(p.hz, p.hz < 10 ? 2 : 1),
             Format::number(p.magnitudeDb, 2), Format::number(p.phaseDeg, 1),
             Format::number(p.quality, 3))
        .arg(p.samples);
}

} // namespace lk::ui
