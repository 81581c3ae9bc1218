#include "ControlCommandBox.h"

#include <panels/StatusColors.h>

#include <QtCore/QEvent>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

ControlCommandBox::ControlCommandBox(QWidget *parent) : QGroupBox(tr("Command"), parent)
{
    m_modes = new ControlModePanel(this);
    m_send = new QPushButton(tr("Send"), this);
    m_send->setObjectName(QStringLiteral("send"));
    m_send->setToolTip(tr("Checked against the series and your soft limits before sending"));
    auto *row = new QHBoxLayout;
    row->addStretch();
    row->addWidget(m_send);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_modes);
    layout->addLayout(row);
    layout->addWidget(buildRunButtons());
    applyPaletteStyles();

    connect(m_send, &QPushButton::clicked, this, &ControlCommandBox::sendRequested);
    connect(m_modes, &ControlModePanel::sendRequested, this, &ControlCommandBox::sendRequested);
    connect(m_off, &QPushButton::clicked, this, &ControlCommandBox::motorOffRequested);
    connect(m_stop, &QPushButton::clicked, this, &ControlCommandBox::motorStopRequested);
    connect(m_run, &QPushButton::clicked, this, &ControlCommandBox::motorRunRequested);
    connect(m_modes, &ControlModePanel::modeChanged, this,
            [this](ControlMode mode) { emit loopChanged(loopOf(mode)); });
}

QWidget *ControlCommandBox::buildRunButtons()
{
    auto *w = new QWidget(this);
    auto make = [w](const QString &name, const QString &text, const QString &tip) {
        auto *b = new QPushButton(text, w);
        b->setObjectName(name);
        b->setToolTip(tip);
        return b;
    };
    m_off = make(QStringLiteral("motorOff"), tr("Motor Off"),
                 tr("0x80: output off, the stored command is cleared"));
    m_stop = make(QStringLiteral("motorStop"), tr("Stop"),
                  tr("0x81: output off, the stored command is kept for Run"));
    m_run = make(QStringLiteral("motorRun"), tr("Run"), tr("0x88: resume after Stop"));
    auto *row = new QHBoxLayout(w);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(m_off);
    row->addWidget(m_stop);
    row->addWidget(m_run);
    return w;
}

void ControlCommandBox::setSendEnabled(bool enabled)
{
    for (QPushButton *b : {m_send, m_off, m_stop, m_run})
        b->setEnabled(enabled);
}

TunedLoop ControlCommandBox::loopOf(ControlMode mode)
{
    switch (mode) {
    case ControlMode::OpenLoop:
    case ControlMode::Torque:
        return TunedLoop::Current;
    case ControlMode::Speed:
        return TunedLoop::Speed;
    default:
        return TunedLoop::Angle;
    }
}

void ControlCommandBox::changeEvent(QEvent *event)
{
    QGroupBox::changeEvent(event);
    // The palette (light/dark) changed while running: the styles derived from it follow. The
    // sheets are set on children, so this does not loop.
    if (event->type() == QEvent::PaletteChange)
        applyPaletteStyles();
}

void ControlCommandBox::applyPaletteStyles()
{
    m_off->setStyleSheet(
        StatusColors::textStyle(StatusColors::Role::Error, StatusColors::current(), true));
}

} // namespace lk::ui
