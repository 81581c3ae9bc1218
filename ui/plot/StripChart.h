#pragma once

#include "PlotTrace.h"
#include "SampleRing.h"
#include "TelemetryStore.h"
#include "TimeChartView.h"
#include "TimeViewport.h"

#include <QtCore/QList>
#include <QtCore/QVector>

#include <map>

class QLineSeries;
class QValueAxis;

namespace lk::ui {

class TimeGridLayer;
class TraceLayer;

/// A labelled instant on a chart's time axis (e.g. "gains written").
struct TimeMarker {
    double time = 0; ///< same clock as the samples
    QString label;
};

/// One chart of the plot panel: a time axis, one value axis per quantity (alternating left
/// and right) and one line per trace, refreshed from the store decimated to its pixel width.
/// A trace with gaps in its data (a silent drive, a dropped link) is drawn as separate line
/// pieces, never joined across a gap, and each outage in view is shaded. QtCharts draws the
/// axes and the legend (from one empty line series per trace); a TraceLayer draws the lines.
class StripChart : public TimeChartView {
    Q_OBJECT
public:
    enum class Coloring { ByDrive, ByChannel };

    explicit StripChart(QWidget *parent = nullptr);

    /// Rebuilds series and axes when the traces or the colouring changed; else does nothing.
    void setTraces(const QVector<PlotTrace> &traces, Coloring coloring);
    const QVector<PlotTrace> &traces() const { return m_traces; }
    /// Each trace's legend entry (a line series without points: the lines are drawn apart).
    QList<QLineSeries *> lineSeries() const { return m_series; }
    /// The points drawn for trace `index`: its first line piece (oldest), empty when none.
    QList<QPointF> points(int index) const;
    /// Every line piece of trace `index` that holds points, oldest first.
    LineSegments segments(int index) const;
    /// The outages shaded now (union over the traces, within the shown time span).
    const QVector<TimeSpan> &outageBands() const { return m_outages; }
    /// Instants drawn as labelled vertical lines while they are in view.
    void setMarkers(const QVector<TimeMarker> &markers);
    const QVector<TimeMarker> &markers() const { return m_markers; }
    QValueAxis *valueAxis(Quantity quantity) const;

    /// Time labels and title under the plot (the bottom strip of a stack), or the grid alone.
    void setTimeLabelsVisible(bool visible);
    bool timeLabelsVisible() const;
    /// Decimates every trace over `span` to the plot's pixel width and hands the points to
    /// the series; rescales value axes when `autoscale` (or on the first data after a
    /// rebuild), else keeps their ranges.
    void refresh(const TelemetryStore &store, TimeSpan span, bool autoscale,
                 DecimationMethod method = DecimationMethod::Auto);
    /// Pixel columns of the plot area: the decimation width.
    int plotColumns() const;
    /// Scales every value axis around its centre (factor < 1 zooms in).
    void scaleValueAxes(double factor);

    /// Room the axes take left and right of the plot area, margins excluded: stacked charts
    /// pad to the widest so that their time axes line up.
    double axisInsetLeft() const;
    double axisInsetRight() const;
    void setAlignmentPadding(double left, double right);
    /// The palette colours of the base class, then each overlaid axis in its trace's colour.
    void applyPalette() override;

protected:
    void drawForeground(QPainter *painter, const QRectF &rect) override;

private:
    void clearChart();
    QColor traceColor(int index) const;
    QVector<int> driveOrder() const; ///< drives in the order their traces come
    QLineSeries *addLegendSeries(int index, const QPen &pen);
    QPen tracePen(int index) const;
    void showSegments(int index, const LineSegments &segments);
    void collectOutages(const TelemetryStore &store, TimeSpan span);
    void drawMarkers(QPainter *painter);
    /// Base margins, the alignment padding and room for the time labels.
    void applyMargins();

    QVector<PlotTrace> m_traces;
    Coloring m_coloring = Coloring::ByDrive;
    QList<QLineSeries *> m_series;   ///< per trace: its legend entry
    TraceLayer *m_lines = nullptr;   ///< a child of the chart
    TimeGridLayer *m_grid = nullptr; ///< a child of the chart: time grid and labels
    QVector<TimeSpan> m_outages;
    QVector<TimeMarker> m_markers;
    std::map<Quantity, QValueAxis *> m_valueAxes;
    std::map<Quantity, QColor> m_axisColors; ///< overlay: an axis takes its trace's colour
    QValueAxis *m_time = nullptr;
    bool m_needsScale = true;
    double m_padLeft = 0, m_padRight = 0;
};

/// A step of 1, 2 or 5 x 10^k at least `raw`, for tick intervals.
double niceStep(double raw);
/// The decimals a label needs to tell ticks `step` apart (0..6).
int tickDecimals(double step);
/// The autoscaled value range for data spanning `data`: padded and rounded out to ticks.
std::pair<double, double> scaledRange(const MinMax &data);
/// Shows [min, max] on `axis` with about `ticks` round steps (1, 2 or 5 x 10^k) and labels
/// with the decimals the step needs; never lays out a tick spacing that does not fit.
void setAxisRange(QValueAxis *axis, double min, double max, int ticks);

} // namespace lk::ui
