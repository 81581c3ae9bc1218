#pragma once

#include <tuning/GainSearchRunner.h>

#include <QtWidgets/QWidget>

class QTableWidget;
class QTabWidget;

namespace lk::ui {

class BodeChart;
class StepOverlayChart;

/// The gain search's best beside the gains read (GainSearchView): their gains and figures as a
/// table, their steps overlaid (each candidate's own step, from its score) and, when the search
/// measured them, their Bode plots with bandwidth and peak.
class GainSearchViewComparison : public QWidget {
    Q_OBJECT
public:
    explicit GainSearchViewComparison(QWidget *parent = nullptr);

    /// Shows `result` (nothing: empty).
    void show(const std::optional<tuning::GainSearchResult> &result);
    QTableWidget *table() const { return m_table; }
    StepOverlayChart *overlay() const { return m_overlay; }
    BodeChart *bode() const { return m_bode; }
    /// "41.3 Hz" or "not reached" for a response's -3 dB bandwidth.
    static QString bandwidthText(const tuning::FrequencyResponse &response);
    /// "0.9 dB at 12.4 Hz".
    static QString peakText(const tuning::FrequencyResponse &response);

private:
    void addRow(const QString &name, const QString &read, const QString &best);

    QTableWidget *m_table;
    QTabWidget *m_tabs;
    StepOverlayChart *m_overlay;
    BodeChart *m_bode;
};

} // namespace lk::ui
