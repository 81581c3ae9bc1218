#pragma once

#include <plot/TimeViewport.h>
#include <tuning/StepTrace.h>

#include <QtCore/QVector>
#include <QtGui/QColor>
#include <QtWidgets/QWidget>

#include <optional>

class QLineSeries;
class QToolButton;
class QValueAxis;

namespace lk::ui {

class CursorReadout;
class TimeChartView;

/// One run as the overlay draws it.
struct OverlayRun {
    QString label;
    QColor color;
    tuning::StepTrace trace;
};

/// Step-test runs overlaid time-aligned on their first step (t = 0 at the edge): the response
/// (speed or angle, rotor values) above with each run's target as a dashed line in its colour,
/// the effort below: torque current (A) on a left axis, an MS drive's power on a right axis of
/// its own. Runs of one loop only; the caller chooses which.
///
/// Both charts share one time range, moved as the live plots move theirs (TimeChartView's
/// gestures, TimeViewport's arithmetic): the wheel zooms around the mouse, a drag pans,
/// Shift+drag or right-drag selects a range, Ctrl+wheel scales the value axes, "Reset zoom"
/// shows every sample again. Hovering draws the cursor line on both charts and reads out
/// each run's values at that time (CursorReadout).
class StepOverlayChart : public QWidget {
    Q_OBJECT
public:
    explicit StepOverlayChart(QWidget *parent = nullptr);

    void setRuns(const QVector<OverlayRun> &runs);
    int runCount() const { return int(m_runs.size()); }
    TimeChartView *responseView() const { return m_response; }
    TimeChartView *effortView() const { return m_effort; }
    /// The response line of run `index` (tests).
    QLineSeries *responseSeries(int index) const;
    /// The time range both charts show.
    TimeSpan shownRange() const;
    /// Every sample's time range: what "Reset zoom" shows.
    TimeSpan dataRange() const { return m_data; }
    /// Shows every sample again.
    void resetZoom();
    std::optional<double> cursorTime() const { return m_cursor; }
    QString readoutText() const;

private:
    void rebuildCharts();
    void addRun(const OverlayRun &run);
    void showRange();
    void setCursorTime(std::optional<double> time);
    void connectGestures(TimeChartView *view);
    QString readoutAt(double time) const;
    static void scaleValueAxes(TimeChartView *view, double factor);

    TimeChartView *m_response;
    TimeChartView *m_effort;
    CursorReadout *m_readout;
    QToolButton *m_reset;
    QValueAxis *m_currentAxis = nullptr; ///< effort in A; null when no run carries current
    QValueAxis *m_powerAxis = nullptr;   ///< effort as power; null when no run carries power
    QVector<QLineSeries *> m_responseLines;
    QVector<OverlayRun> m_runs;
    TimeViewport m_viewport;
    TimeSpan m_data{0, 1};
    std::optional<double> m_cursor;
};

} // namespace lk::ui
