#pragma once

#include <bus/TrafficBacklog.h>
#include <bus/TrafficEvent.h>

#include <QtWidgets/QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QTableView;
class QTimer;
class QToolButton;

namespace lk::ui {

class BusModel;
class TrafficFilter;
class TrafficModel;

/// The decoded bus log: every frame sent and received with its fields and raw bytes,
/// filterable by ID and command, pausable, with fault counts by kind, bounded in memory and
/// exportable to a text file that `lkctl decode -` reads back; on CAN the frames show in
/// candump notation and export also as a `candump -L` log. Capture runs only while the
/// view is shown or "Keep recording" is on (captureWanted).
class TrafficPanel : public QWidget {
    Q_OBJECT
public:
    explicit TrafficPanel(BusModel *model, QWidget *parent = nullptr, int capacity = 50000);

    TrafficModel *trafficModel() const { return m_model; }
    TrafficFilter *filter() const { return m_filter; }
    QTableView *view() const { return m_view; }
    bool isPaused() const;
    bool wantsCapture() const { return m_wantCapture; }
    /// Write the rows shown (after filters) for `lkctl decode -`; false with a message.
    bool exportTo(const QString &fileName, QString *error = nullptr) const;
    /// On a CAN link: write the frames of the rows shown as a `candump -L` log (can-utils,
    /// python-can and SavvyCAN read it); false with a message.
    bool exportCandumpTo(const QString &fileName, QString *error = nullptr) const;
    /// The bus's counters (the same as the Dashboard's and the status bar's, cleared with
    /// them when the link closes), then this log's frame faults by kind and dropped rows.
    QString countsText() const;

public slots:
    void appendTraffic(const lk::bus::TrafficBatch &batch);
    /// Count rows dropped before they reached this view (a replay's Load all keeps only the
    /// newest rows the table can hold).
    void countDroppedTraffic(const lk::bus::TrafficCounts &counts);
    /// Replace the log with `batch` (the black box's ring, read again when the view opens).
    void showTraffic(const lk::bus::TrafficBatch &batch);
    void flush(); ///< move buffered events into the table now (the timer does it at 10 Hz)
    void exportWithDialog();

signals:
    void captureWanted(bool wanted);

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    QWidget *buildToolbar();
    void updateCapture();
    void updateCounts();
    void fillCommandFilter();

    BusModel *m_bus;
    TrafficModel *m_model;
    TrafficFilter *m_filter;
    QTableView *m_view = nullptr;
    QComboBox *m_idFilter = nullptr;
    QComboBox *m_commandFilter = nullptr;
    QCheckBox *m_faultsOnly = nullptr;
    QCheckBox *m_hidePolling = nullptr;
    QToolButton *m_pause = nullptr;
    QToolButton *m_record = nullptr;
    QLabel *m_counts = nullptr;
    QTimer *m_flush = nullptr;
    bus::TrafficBacklog m_backlog; ///< not yet in the table
    bool m_shown = false;
    bool m_wantCapture = false;
};

} // namespace lk::ui
