#pragma once

#include <tuning/FrequencyResponse.h>

#include <QtCore/QVector>
#include <QtGui/QColor>
#include <QtWidgets/QWidget>

class QAbstractSeries;
class QChart;
class QChartView;
class QLabel;
class QLineSeries;
class QScatterSeries;

namespace lk::ui {

/// One measured response as the Bode chart draws it.
struct BodeRun {
    QString label;
    QColor color;
    tuning::FrequencyResponse response;
};

/// Frequency responses overlaid as a Bode plot: magnitude (dB) above, phase (degrees) below,
/// against a logarithmic frequency axis. Only measured points are drawn: the frequencies a
/// run's sample rate could not resolve are left out, and a dashed line at the newest run's
/// limit says so (its note gives the rate and the frequencies dropped). The newest run's -3 dB
/// bandwidth is marked on both plots. Hovering a point shows its values and fit quality. The
/// magnitude plot's legend names each run by its label.
class BodeChart : public QWidget {
    Q_OBJECT
public:
    explicit BodeChart(QWidget *parent = nullptr);

    void setRuns(const QVector<BodeRun> &runs);
    int runCount() const { return int(m_runs.size()); }
    /// The magnitude points of run `index` (tests).
    QScatterSeries *magnitudePoints(int index) const;
    QScatterSeries *phasePoints(int index) const;
    /// The dashed line at the newest run's resolution limit; null when every planned frequency
    /// was resolved.
    QLineSeries *resolutionLine() const { return m_resolutionLine; }
    /// What the line means, and what was left out (empty without a line).
    QString resolutionText() const;
    /// The figures of every run drawn, one line each.
    QString figuresText() const;
    /// The tooltip of point `point` of run `run`: frequency, magnitude, phase, fit quality.
    QString pointText(int run, int point) const;
    /// The legend's entries (the magnitude plot's): one per run, its label.
    QStringList legendLabels() const;
    /// One line of a run's figures: bandwidth, phase there, peak.
    static QString figuresLine(const QString &label, const tuning::FrequencyResponse &response);

private:
    void rebuild();
    void addRun(int index);
    void addMarkers();
    void fitAxes();
    QLineSeries *verticalLine(QChart *chart, double hz, const QColor &color, Qt::PenStyle style,
                              const QString &name);

    QChartView *m_magnitudeView;
    QChartView *m_phaseView;
    QLabel *m_figures;
    QLabel *m_resolution;
    QVector<BodeRun> m_runs;
    QVector<QScatterSeries *> m_magnitudePoints;
    QVector<QScatterSeries *> m_phasePoints;
    QVector<QAbstractSeries *> m_runLines; ///< each run's magnitude line: its legend entry
    QLineSeries *m_resolutionLine = nullptr;
};

} // namespace lk::ui
