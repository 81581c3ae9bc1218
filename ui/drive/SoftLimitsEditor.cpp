#include "SoftLimitsEditor.h"

#include <motor/SeriesLimits.h>
#include <panels/StatusColors.h>

#include <QtWidgets/QCheckBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>

namespace lk::ui {

namespace {
constexpr double kMaxAngle = 1e9;
constexpr double kMaxSpeedField = 1e6;
constexpr double kMinSpeedField = 0.1;
constexpr double kMaxTorqueField = 100;
} // namespace

SoftLimitsEditor::SoftLimitsEditor(QWidget *parent) : QGroupBox(tr("Soft limits"), parent)
{
    setObjectName(QStringLiteral("softLimits"));
    m_torque = number(QStringLiteral("limitTorque"), 0, kMaxTorqueField, 2, tr(" A"));
    m_power = new QSpinBox(this);
    m_power->setObjectName(QStringLiteral("limitPower"));
    m_power->setRange(0, 1000);
    // Never 0 and never "no limit": every move is bounded by this value.
    m_speed = number(QStringLiteral("limitSpeed"), kMinSpeedField, kMaxSpeedField, 1, tr(" dps"));
    m_speed->setToolTip(tr("Bounds speed commands, jog and the max speed of every position "
                           "move"));
    m_min = number(QStringLiteral("limitMinAngle"), -kMaxAngle, kMaxAngle, 2, tr(" \u00b0"));
    m_max = number(QStringLiteral("limitMaxAngle"), -kMaxAngle, kMaxAngle, 2, tr(" \u00b0"));
    m_step = number(QStringLiteral("limitStep"), 0, kMaxAngle, 2, tr(" \u00b0"));
    m_minOn = optionalBox(QStringLiteral("limitMinAngleOn"), tr("Angle at least"), m_min);
    m_maxOn = optionalBox(QStringLiteral("limitMaxAngleOn"), tr("Angle at most"), m_max);
    m_stepOn = optionalBox(QStringLiteral("limitStepOn"), tr("Step at most"), m_step);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);

    m_apply = new QPushButton(tr("Apply"), this);
    m_apply->setObjectName(QStringLiteral("applyLimits"));
    auto *defaults = new QPushButton(tr("Defaults"), this);
    defaults->setObjectName(QStringLiteral("defaultLimits"));
    connect(m_apply, &QPushButton::clicked, this, &SoftLimitsEditor::apply);
    connect(defaults, &QPushButton::clicked, this, &SoftLimitsEditor::restoreDefaults);

    auto *form = new QFormLayout(this);
    form->addRow(tr("Torque current at most:"), m_torque);
    form->addRow(tr("Open-loop power at most:"), m_power);
    form->addRow(tr("Speed at most:"), m_speed);
    form->addRow(m_minOn, m_min);
    form->addRow(m_maxOn, m_max);
    form->addRow(m_stepOn, m_step);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch();
    buttons->addWidget(defaults);
    buttons->addWidget(m_apply);
    form->addRow(m_note);
    form->addRow(buttons);
    showLimits(m_limits);
}

QDoubleSpinBox *SoftLimitsEditor::number(const QString &name, double lo, double hi, int decimals,
                                         const QString &suffix)
{
    auto *box = new QDoubleSpinBox(this);
    box->setObjectName(name);
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    connect(box, &QDoubleSpinBox::valueChanged, this, &SoftLimitsEditor::refreshDirty);
    return box;
}

QCheckBox *SoftLimitsEditor::optionalBox(const QString &name, const QString &text,
                                         QDoubleSpinBox *value)
{
    auto *box = new QCheckBox(text, this);
    box->setObjectName(name);
    connect(box, &QCheckBox::toggled, value, &QWidget::setEnabled);
    connect(box, &QCheckBox::toggled, this, &SoftLimitsEditor::refreshDirty);
    value->setEnabled(false);
    return box;
}

void SoftLimitsEditor::setLimits(const safety::SoftLimits &limits,
                                 std::optional<protocol::Series> series)
{
    m_limits = limits;
    m_series = series;
    const bool ms = series == protocol::Series::MS;
    m_torque->setEnabled(series && !ms);
    m_power->setEnabled(ms);
    showLimits(limits);
}

void SoftLimitsEditor::showLimits(const safety::SoftLimits &l)
{
    const QSignalBlocker b1(m_torque), b2(m_power), b3(m_speed), b4(m_min), b5(m_max), b6(m_step),
        b7(m_minOn), b8(m_maxOn), b9(m_stepOn);
    m_torque->setValue(l.maxTorqueA);
    m_power->setValue(l.maxPower);
    m_speed->setValue(l.maxSpeedDps);
    m_minOn->setChecked(l.minAngleDeg.has_value());
    m_min->setEnabled(l.minAngleDeg.has_value());
    m_min->setValue(l.minAngleDeg.value_or(0));
    m_maxOn->setChecked(l.maxAngleDeg.has_value());
    m_max->setEnabled(l.maxAngleDeg.has_value());
    m_max->setValue(l.maxAngleDeg.value_or(0));
    m_stepOn->setChecked(l.maxIncrementDeg.has_value());
    m_step->setEnabled(l.maxIncrementDeg.has_value());
    m_step->setValue(l.maxIncrementDeg.value_or(0));
    refreshDirty();
}

safety::SoftLimits SoftLimitsEditor::edited() const
{
    safety::SoftLimits l = m_limits;
    l.maxTorqueA = m_torque->value();
    l.maxPower = m_power->value();
    l.maxSpeedDps = m_speed->value();
    l.minAngleDeg = m_minOn->isChecked() ? std::optional<double>(m_min->value()) : std::nullopt;
    l.maxAngleDeg = m_maxOn->isChecked() ? std::optional<double>(m_max->value()) : std::nullopt;
    l.maxIncrementDeg =
        m_stepOn->isChecked() ? std::optional<double>(m_step->value()) : std::nullopt;
    return l;
}

void SoftLimitsEditor::refreshDirty()
{
    const safety::SoftLimits e = edited();
    const bool badRange = e.minAngleDeg && e.maxAngleDeg && *e.minAngleDeg > *e.maxAngleDeg;
    // With a problem shown, applying the limits as they are is how the user answers it.
    m_apply->setEnabled(!badRange && (!(e == m_limits) || !m_problem.isEmpty()));
    QString note;
    if (!m_problem.isEmpty())
        note = m_problem;
    else if (badRange)
        note = tr("The lowest angle must not be above the highest.");
    else if (m_series)
        note = tr("Checked before every command, after the %1 series limits (%2 A, %3 dps; "
                  "the default speed limit is that top speed). Angles and speeds are rotor "
                  "values; a position move goes at most one output turn.")
                   .arg(protocol::seriesName(*m_series))
                   .arg(motor::seriesLimits(*m_series).maxCurrentA)
                   .arg(motor::seriesLimits(*m_series).maxSpeedDps());
    else
        note = tr("The series is unknown: torque and open loop stay refused until a scan; the "
                  "default speed limit is %1 dps, the slowest series' top speed.")
                   .arg(safety::SoftLimits::kUnknownSeriesSpeedDps);
    m_note->setText(note);
    m_note->setStyleSheet(
        m_problem.isEmpty() || badRange
            ? QString()
            : StatusColors::textStyle(StatusColors::Role::Error, palette(), true));
}

void SoftLimitsEditor::setProblem(const QString &text)
{
    m_problem = text;
    refreshDirty();
}

void SoftLimitsEditor::apply()
{
    const safety::SoftLimits e = edited();
    if (e.minAngleDeg && e.maxAngleDeg && *e.minAngleDeg > *e.maxAngleDeg)
        return;
    m_limits = e;
    refreshDirty();
    emit limitsApplied(m_limits);
}

void SoftLimitsEditor::restoreDefaults()
{
    m_limits = safety::SoftLimits::defaults(m_series);
    showLimits(m_limits);
    emit limitsApplied(m_limits);
}

} // namespace lk::ui
