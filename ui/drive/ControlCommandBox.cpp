#include "ControlCommandBox.h"

#include "DriveStateCheck.h"

#include <panels/StatusColors.h>

#include <QtCore/QEvent>
#include <QtCore/QStringList>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

ControlCommandBox::ControlCommandBox(QWidget *parent) : QGroupBox(tr("Command"), parent)
{
    m_selection = new QLabel(this);
    m_selection->setObjectName(QStringLiteral("selectionNote"));
    m_selection->setWordWrap(true);
    m_selection->hide();
    m_modes = new ControlModePanel(this);
    m_send = new QPushButton(tr("Send"), this);
    m_send->setObjectName(QStringLiteral("send"));
    m_send->setToolTip(tr("Checked against the series and your soft limits before sending"));
    auto *row = new QHBoxLayout;
    row->addStretch();
    row->addWidget(m_send);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_selection);
    layout->addWidget(m_modes);
    layout->addLayout(row);
    m_driveState = new QLabel(this);
    m_driveState->setObjectName(QStringLiteral("driveState"));
    m_driveState->setWordWrap(true);
    m_driveState->hide();
    layout->addWidget(m_driveState);
    layout->addWidget(buildRunButtons());
    applyPaletteStyles();

    connect(m_send, &QPushButton::clicked, this, &ControlCommandBox::sendRequested);
    connect(m_modes, &ControlModePanel::sendRequested, this, &ControlCommandBox::sendRequested);
    connect(m_motorOff, &QPushButton::clicked, this, &ControlCommandBox::motorOffRequested);
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
    m_motorOff = make(QStringLiteral("motorOff"), tr("Motor Off"),
                      tr("0x80: output off, the stored command is cleared"));
    m_stop = make(QStringLiteral("motorStop"), tr("Stop"),
                  tr("0x81: output off, the stored command is kept for Run"));
    m_run = make(QStringLiteral("motorRun"), tr("Run"), tr("0x88: resume after Stop"));
    auto *row = new QHBoxLayout(w);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(m_motorOff);
    row->addWidget(m_stop);
    row->addWidget(m_run);
    return w;
}

void ControlCommandBox::setSendEnabled(bool enabled)
{
    for (QPushButton *b : {m_send, m_motorOff, m_stop, m_run})
        b->setEnabled(enabled);
}

void ControlCommandBox::setSelection(int selected, const QString &driveTitle)
{
    m_selection->setVisible(selected > 1);
    if (selected > 1)
        m_selection->setText(
            tr("%n drives are selected: every command here acts on %1 only.", nullptr, selected)
                .arg(driveTitle));
}

void ControlCommandBox::setGeneration(protocol::Generation generation)
{
    const bool v235 = generation == protocol::Generation::V2_35;
    m_run->setText(v235 ? tr("Motor On") : tr("Run"));
    m_run->setToolTip(v235 ? tr("0x88: turns the motor on after Motor Off or a protection "
                                "trip (V2.35: a control command does not); it holds no command")
                           : tr("0x88: resume after Stop"));
}

void ControlCommandBox::showDriveState(const DriveStateCheck &state, const QString &limits)
{
    m_off = !state.refusal().isEmpty();
    m_held = !state.warning().isEmpty();
    QStringList lines{state.stateText(), limits};
    lines.removeAll(QString());
    const QString text = lines.join(QLatin1Char('\n'));
    m_driveState->setText(text);
    m_driveState->setVisible(!text.isEmpty());
    applyPaletteStyles();
}

QString ControlCommandBox::driveStateText() const
{
    return m_driveState->text();
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
    const QPalette palette = StatusColors::current();
    m_motorOff->setStyleSheet(StatusColors::textStyle(StatusColors::Role::Error, palette, true));
    // Off: Motor On is what the drive needs next, and the state says so in red.
    m_run->setStyleSheet(m_off ? QStringLiteral("font-weight: bold;") : QString());
    m_driveState->setStyleSheet(
        m_off    ? StatusColors::textStyle(StatusColors::Role::Error, palette, true)
        : m_held ? StatusColors::textStyle(StatusColors::Role::Warning, palette, true)
                 : QString());
}

} // namespace lk::ui
