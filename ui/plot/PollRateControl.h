#pragma once

#include <QtWidgets/QWidget>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;

namespace lk::ui {

/// Poll rate request (Hz, or "max" = as fast as the bus allows) beside the bus limit for the
/// current baud and motor count, so the user sees what is physically possible.
class PollRateControl : public QWidget {
    Q_OBJECT
public:
    explicit PollRateControl(QWidget *parent = nullptr);

    /// Shows a rate without emitting pollRateRequested; 0 means max.
    void setPollRate(double hz);
    double pollRate() const; ///< 0 when max is ticked
    /// Transactions per second the bus carries and the full-cycle rate over every polled
    /// motor; values <= 0 clear the display.
    void setBusLimit(double transactionsPerSecond, double cycleLimitHz);
    QString busLimitText() const;

signals:
    /// The user asked for a rate; 0 = as fast as the bus allows.
    void pollRateRequested(double hz);

private:
    void emitRequest();
    void updateLimitText();

    QDoubleSpinBox *m_rate;
    QCheckBox *m_max;
    QLabel *m_limit;
    double m_transactions = 0;
    double m_cycleHz = 0;
};

} // namespace lk::ui
