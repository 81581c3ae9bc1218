#pragma once

#include <QtWidgets/QGroupBox>

class QLabel;
class QGridLayout;

namespace lk::ui {

class BusModel;
class ListenStatisticsPane;

/// Bus statistics for the whole bus and the selected drive: poll rate achieved against the
/// rate asked for and the bus limit, latency, timeouts, retries and frame faults. While the
/// link listens only, what the other master does instead (ListenStatisticsPane); while a
/// recording plays, the recorded traffic counted the same way.
class StatisticsView : public QGroupBox {
    Q_OBJECT
public:
    explicit StatisticsView(BusModel *model, QWidget *parent = nullptr);

    /// The text of one figure (tests): row key such as "timeouts", column 0 bus, 1 drive.
    QString figure(const QString &row, int column) const;
    ListenStatisticsPane *listenPane() const { return m_listen; }
    /// A recording plays into the views (no link is open): show its traffic's figures
    /// (BusModel::listenStatistics, fed by the replay) instead of this tool's own.
    void setReplaying(bool replaying);
    bool isReplaying() const { return m_replaying; }

public slots:
    void refresh();

private:
    QLabel *addRow(const QString &key, const QString &caption);

    void showMode();

    BusModel *m_model;
    QWidget *m_own;
    QGridLayout *m_grid;
    ListenStatisticsPane *m_listen;
    QLabel *m_driveHeader = nullptr;
    QLabel *m_rate = nullptr;
    bool m_replaying = false;
    QHash<QString, QPair<QLabel *, QLabel *>> m_rows;
};

} // namespace lk::ui
