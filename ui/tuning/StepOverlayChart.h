#pragma once

#include <tuning/StepTrace.h>

#include <QtCore/QVector>
#include <QtGui/QColor>
#include <QtWidgets/QWidget>

class QLineSeries;
class QValueAxis;

namespace lk::ui {

class TimeChartView;

/// One run as the overlay draws it.
struct OverlayRun {
    QString label;
    QColor color;
    tuning::StepTrace trace;
};

/// Step-test runs overlaid time-aligned on their first step (t = 0 at the edge): the response
/// (speed or angle, rotor values) above with each run's target as a dashed line in its colour,
/// the torque current (power on MS) below. Runs of one loop only; the caller chooses which.
class StepOverlayChart : public QWidget {
    Q_OBJECT
public:
    explicit StepOverlayChart(QWidget *parent = nullptr);

    void setRuns(const QVector<OverlayRun> &runs);
    int runCount() const { return m_runCount; }
    TimeChartView *responseView() const { return m_response; }
    TimeChartView *effortView() const { return m_effort; }
    /// The response line of run `index` (tests).
    QLineSeries *responseSeries(int index) const;

private:
    static void rebuild(TimeChartView *view, const QString &valueTitle, bool timeTitle);
    static void fitAxes(TimeChartView *view);

    TimeChartView *m_response;
    TimeChartView *m_effort;
    QVector<QLineSeries *> m_responseLines;
    int m_runCount = 0;
};

} // namespace lk::ui
