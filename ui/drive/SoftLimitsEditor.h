#pragma once

#include <protocol/Series.h>
#include <safety/SoftLimits.h>

#include <QtWidgets/QGroupBox>

#include <optional>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace lk::ui {

/// Edits one drive's soft limits (torque, open-loop power, speed, angle range, step size).
/// Edits take effect on Apply; "Defaults" restores SoftLimits::defaults for the series. The
/// speed limit always has a value (the series top speed by default, shown as a number).
class SoftLimitsEditor : public QGroupBox {
    Q_OBJECT
public:
    explicit SoftLimitsEditor(QWidget *parent = nullptr);

    /// Shows `limits` as the ones in force; the series decides which fields apply.
    void setLimits(const safety::SoftLimits &limits, std::optional<protocol::Series> series);
    /// The limits in force (last set or applied).
    safety::SoftLimits limits() const { return m_limits; }
    /// A problem with the limits (damaged stored entry), shown until cleared with an empty text.
    void setProblem(const QString &text);
    /// What the fields say now (not yet applied).
    safety::SoftLimits edited() const;

public slots:
    void apply();
    void restoreDefaults();

signals:
    /// The user applied new limits (or restored the defaults).
    void limitsApplied(const lk::safety::SoftLimits &limits);

private:
    QDoubleSpinBox *number(const QString &name, double lo, double hi, int decimals,
                           const QString &suffix);
    QCheckBox *optionalBox(const QString &name, const QString &text, QDoubleSpinBox *value);
    void showLimits(const safety::SoftLimits &limits);
    void refreshDirty();

    safety::SoftLimits m_limits;
    std::optional<protocol::Series> m_series;
    QDoubleSpinBox *m_torque;
    QSpinBox *m_power;
    QDoubleSpinBox *m_speed;
    QCheckBox *m_minOn;
    QDoubleSpinBox *m_min;
    QCheckBox *m_maxOn;
    QDoubleSpinBox *m_max;
    QCheckBox *m_stepOn;
    QDoubleSpinBox *m_step;
    QLabel *m_note;
    QString m_problem;
    QPushButton *m_apply;
};

} // namespace lk::ui
