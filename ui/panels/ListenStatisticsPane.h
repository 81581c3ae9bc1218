#pragma once

#include <QtWidgets/QWidget>

class QLabel;
class QTableWidget;

namespace lk::ui {

class BusModel;

/// What another master does on a bus the link only listens to (bus::ListenStatistics): its
/// request rate, bus load, unanswered requests (its timeouts), checksum errors (on CAN: error
/// frames and frames of IDs that are no drive's); per drive its
/// requests/s, unanswered requests and reply latency; per command its requests/s.
class ListenStatisticsPane : public QWidget {
    Q_OBJECT
public:
    explicit ListenStatisticsPane(BusModel *model, QWidget *parent = nullptr);

    /// The summary line and the two tables (tests).
    QString summary() const;
    QTableWidget *drivesTable() const { return m_drives; }
    QTableWidget *commandsTable() const { return m_commands; }
    /// The figures are a recording's (StatisticsView::setReplaying): worded as such.
    void setReplaying(bool replaying);

public slots:
    void refresh();

private:
    void fillDrives();
    void fillCommands();

    BusModel *m_model;
    bool m_replaying = false;
    QLabel *m_summary;
    QTableWidget *m_drives;
    QTableWidget *m_commands;
};

} // namespace lk::ui
