#pragma once

#include <QtWidgets/QGroupBox>

class QLabel;
class QGridLayout;

namespace lk::ui {

class BusModel;

/// Bus statistics for the whole bus and the selected drive: poll rate achieved against the
/// rate asked for and the bus limit, latency, timeouts, retries and frame faults.
class StatisticsView : public QGroupBox {
    Q_OBJECT
public:
    explicit StatisticsView(BusModel *model, QWidget *parent = nullptr);

    /// The text of one figure (tests): row key such as "timeouts", column 0 bus, 1 drive.
    QString figure(const QString &row, int column) const;

public slots:
    void refresh();

private:
    QLabel *addRow(const QString &key, const QString &caption);

    BusModel *m_model;
    QGridLayout *m_grid;
    QLabel *m_driveHeader = nullptr;
    QLabel *m_rate = nullptr;
    QHash<QString, QPair<QLabel *, QLabel *>> m_rows;
};

} // namespace lk::ui
