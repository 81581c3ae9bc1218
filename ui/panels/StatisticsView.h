#pragma once

#include <QtWidgets/QGroupBox>

class QLabel;
class QGridLayout;

namespace lk::ui {

class BusModel;
class ListenStatisticsPane;

/// Bus statistics for the whole bus and the selected drive: poll rate achieved against the
/// rate asked for and the bus limit, latency, timeouts, retries and frame faults. While the
/// link listens only, what the other master does instead (ListenStatisticsPane).
class StatisticsView : public QGroupBox {
    Q_OBJECT
public:
    explicit StatisticsView(BusModel *model, QWidget *parent = nullptr);

    /// The text of one figure (tests): row key such as "timeouts", column 0 bus, 1 drive.
    QString figure(const QString &row, int column) const;
    ListenStatisticsPane *listenPane() const { return m_listen; }

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
    QHash<QString, QPair<QLabel *, QLabel *>> m_rows;
};

} // namespace lk::ui
