#include "SetpointPanel.h"

#include "SetpointGenerator.h"

#include <motor/SeriesLimits.h>
#include <panels/StatusColors.h>

#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

namespace lk::ui {

namespace {
constexpr double kWide = 1e7;
using Gen = bus::SetpointWaveform;
} // namespace

SetpointPanel::SetpointPanel(QWidget *parent) : QGroupBox(tr("Setpoint generator"), parent)
{
    setObjectName(QStringLiteral("setpoint"));
    m_waveform = new QComboBox(this);
    m_waveform->setObjectName(QStringLiteral("waveform"));
    m_waveform->addItem(tr("Step"), int(Gen::Waveform::Step));
    m_waveform->addItem(tr("Square"), int(Gen::Waveform::Square));
    m_waveform->addItem(tr("Sine"), int(Gen::Waveform::Sine));
    m_waveform->addItem(tr("Ramp (triangle)"), int(Gen::Waveform::Ramp));
    m_target = new QComboBox(this);
    m_target->setObjectName(QStringLiteral("target"));
    auto number = [this](const QString &name, double lo, double hi, int decimals) {
        auto *b = new QDoubleSpinBox(this);
        b->setObjectName(name);
        b->setRange(lo, hi);
        b->setDecimals(decimals);
        return b;
    };
    m_amplitude = number(QStringLiteral("amplitude"), -kWide, kWide, 2);
    m_offset = number(QStringLiteral("offset"), -kWide, kWide, 2);
    m_period = number(QStringLiteral("period"), Gen::kMinPeriodS, 3600, 2);
    m_period->setSuffix(tr(" s"));
    m_rate = number(QStringLiteral("rate"), Gen::kMinRateHz, Gen::kMaxRateHz, 0);
    m_rate->setSuffix(tr(" Hz"));
    m_rate->setToolTip(tr("Commands per second (at most %1; skipped while the bus is behind)")
                           .arg(Gen::kMaxRateHz));
    m_start = new QPushButton(tr("Start"), this);
    m_start->setObjectName(QStringLiteral("startGenerator"));
    m_stop = new QPushButton(tr("Stop generator"), this);
    m_stop->setObjectName(QStringLiteral("stopGenerator"));
    m_state = new QLabel(this);
    m_state->setObjectName(QStringLiteral("generatorState"));
    m_state->setWordWrap(true);

    auto *form = new QFormLayout(this);
    form->addRow(tr("Waveform:"), m_waveform);
    form->addRow(tr("Drives:"), m_target);
    form->addRow(tr("Amplitude:"), m_amplitude);
    form->addRow(tr("Offset:"), m_offset);
    form->addRow(tr("Period:"), m_period);
    form->addRow(tr("Rate:"), m_rate);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    form->addRow(buttons);
    form->addRow(m_state);

    connect(m_target, &QComboBox::currentIndexChanged, this, &SetpointPanel::refreshUnits);
    connect(m_target, &QComboBox::currentIndexChanged, this, [this] {
        m_offsetEdited = false; // the old offset was in another unit
        fillOffsetFromDrive();
    });
    connect(m_offset, &QDoubleSpinBox::valueChanged, this, [this] { m_offsetEdited = true; });
    connect(m_start, &QPushButton::clicked, this, [this] { emit startRequested(settings()); });
    connect(m_stop, &QPushButton::clicked, this, &SetpointPanel::stopRequested);
    setSeries(std::nullopt);
    setSettings(Gen::Settings{});
    m_offsetEdited = false;
    setRunning(false);
}

void SetpointPanel::setSeries(std::optional<protocol::Series> series)
{
    const QVariant previous = m_target->currentData();
    const QSignalBlocker block(m_target);
    m_target->clear();
    m_target->addItem(tr("Speed"), int(Gen::Target::Speed));
    m_target->addItem(tr("Position (multi-turn)"), int(Gen::Target::Position));
    if (series && motor::supports(*series, protocol::Command::Torque))
        m_target->addItem(tr("Torque current"), int(Gen::Target::Torque));
    const int keep = m_target->findData(previous);
    m_target->setCurrentIndex(keep >= 0 ? keep : 0);
    refreshUnits();
}

void SetpointPanel::refreshUnits()
{
    const auto target = Gen::Target(m_target->currentData().toInt());
    const QString unit = target == Gen::Target::Speed      ? tr(" dps")
                         : target == Gen::Target::Position ? tr(" \u00b0")
                                                           : tr(" A");
    m_amplitude->setSuffix(unit);
    m_offset->setSuffix(unit);
}

bus::SetpointWaveform::Settings SetpointPanel::settings() const
{
    Gen::Settings s;
    s.waveform = Gen::Waveform(m_waveform->currentData().toInt());
    s.target = Gen::Target(m_target->currentData().toInt());
    s.amplitude = m_amplitude->value();
    s.offset = m_offset->value();
    s.periodS = m_period->value();
    s.rateHz = m_rate->value();
    return s;
}

void SetpointPanel::setSettings(const bus::SetpointWaveform::Settings &s)
{
    m_waveform->setCurrentIndex(m_waveform->findData(int(s.waveform)));
    const int target = m_target->findData(int(s.target));
    if (target >= 0)
        m_target->setCurrentIndex(target);
    m_amplitude->setValue(s.amplitude);
    m_offset->setValue(s.offset);
    m_period->setValue(s.periodS);
    m_rate->setValue(s.rateHz);
}

void SetpointPanel::setDriveAngle(std::optional<double> deg)
{
    if (!deg)
        m_offsetEdited = false; // another drive: nothing typed for the last one carries over
    m_driveAngle = deg;
    fillOffsetFromDrive();
}

void SetpointPanel::fillOffsetFromDrive()
{
    if (m_offsetEdited || Gen::Target(m_target->currentData().toInt()) != Gen::Target::Position)
        return;
    const QSignalBlocker block(m_offset);
    // Unknown angle: 0 until it is read; the control view refuses setpoints a turn away.
    m_offset->setValue(m_driveAngle.value_or(0));
}

void SetpointPanel::setRunning(bool running, const QString &message)
{
    m_stop->setEnabled(running);
    m_state->setText(!message.isEmpty() ? message
                     : running          ? tr("Running: Stop, Motor Off or Esc ends it.")
                                        : tr("Stopped."));
    m_state->setStyleSheet(
        running ? StatusColors::textStyle(StatusColors::Role::Busy, palette(), true) : QString());
}

void SetpointPanel::setStartEnabled(bool enabled)
{
    m_start->setEnabled(enabled);
}

void SetpointPanel::follow(SetpointGenerator *generator)
{
    connect(generator, &SetpointGenerator::started, this, [this] { setRunning(true); });
    connect(generator, &SetpointGenerator::stopped, this,
            [this](const QString &reason) { setRunning(false, reason); });
}

} // namespace lk::ui
