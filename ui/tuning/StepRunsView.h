#pragma once

#include <QtWidgets/QWidget>

class QLabel;
class QPushButton;
class QTableView;

namespace lk::ui {

class StepOverlayChart;
class StepRunList;
class StepRunsModel;

/// The runs of this session compared: the overlaid runs time-aligned on their step (one loop
/// at a time, the newest shown run's), their metrics and gains side by side with the best
/// value of each metric marked, the metric definitions one click away, and saving / loading
/// runs (JSON + a CSV per trace) to compare with another day's.
class StepRunsView : public QWidget {
    Q_OBJECT
public:
    explicit StepRunsView(StepRunList *runs, QWidget *parent = nullptr);

    /// Saves every run; returns an error text, empty on success.
    QString saveRuns(const QString &path);
    /// Adds the runs of a file as they were saved (numbers and names kept); a bad file adds
    /// nothing. Returns an error text, empty on success.
    QString loadRuns(const QString &path);

    StepOverlayChart *overlay() const { return m_overlay; }
    QTableView *table() const { return m_table; }
    StepRunsModel *model() const { return m_model; }
    QString statusText() const;

private:
    void refreshOverlay();
    void removeSelected();
    void showDefinitions();
    void setStatus(const QString &text, bool error = false);

    StepRunList *m_runs;
    StepOverlayChart *m_overlay;
    StepRunsModel *m_model;
    QTableView *m_table;
    QLabel *m_note;
    QLabel *m_status;
    QPushButton *m_save;
    QPushButton *m_remove;
    QPushButton *m_clear;
};

} // namespace lk::ui
