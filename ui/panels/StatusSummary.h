#pragma once

#include <QtWidgets/QWidget>

class QLabel;

namespace lk::ui {

class ElidedLabel;

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
    ElidedLabel *m_link; ///< the whole link state; cut short rather than widen the window
    QLabel *m_stats;
};

} // namespace lk::ui
