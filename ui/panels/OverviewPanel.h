#pragma once

#include <QtWidgets/QWidget>

class QLabel;
class QTableView;
class QTimer;

namespace lk::ui {

class BusModel;
class OverviewModel;

/// Every drive on the bus at once, one row each, for field diagnostics.
class OverviewPanel : public QWidget {
    Q_OBJECT
public:
    explicit OverviewPanel(BusModel *model, QWidget *parent = nullptr);
    QTableView *view() const { return m_view; }

private:
    void selectCurrent();
    void updateSummary();
    void fitColumns();

    BusModel *m_model;
    OverviewModel *m_table;
    QTableView *m_view;
    QLabel *m_summary;
    QTimer *m_refresh;
    bool m_syncing = false;
    int m_ticks = 0;
};

} // namespace lk::ui
