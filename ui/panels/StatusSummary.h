#pragma once

#include <QtWidgets/QWidget>

class QLabel;

namespace lk::ui {

class BusModel;

/// The status bar's permanent part: link state, a "Simulated" badge on the built-in bus,
/// and a one-line bus statistics summary.
class StatusSummary : public QWidget {
    Q_OBJECT
public:
    explicit StatusSummary(BusModel *model, QWidget *parent = nullptr);

    bool isSimulatedBadgeShown() const;
    QString linkText() const;
    QString statisticsText() const;

private:
    void updateLink();
    void updateStatistics();

    BusModel *m_model;
    QLabel *m_badge;
    QLabel *m_link;
    QLabel *m_stats;
};

} // namespace lk::ui
