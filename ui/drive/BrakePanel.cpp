#include "BrakePanel.h"

#include "ConfirmDialog.h"
#include "DriveSettingsStore.h"
#include "DriveText.h"
#include "GenerationNote.h"

#include <panels/StatusColors.h>
#include <protocol/RequestBuilder.h>

#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
using protocol::BrakeAction;
using protocol::Command;
namespace build = protocol::build;
} // namespace

BrakePanel::BrakePanel(QWidget *parent) : QGroupBox(tr("Brake (0x8C)"), parent)
{
    setObjectName(QStringLiteral("brake"));
    m_stateLabel = new QLabel(this);
    m_stateLabel->setObjectName(QStringLiteral("brakeState"));
    m_stateLabel->setWordWrap(true);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("brakeStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_read = new QPushButton(tr("Read"), this);
    m_read->setObjectName(QStringLiteral("brakeRead"));
    m_read->setToolTip(tr("0x8C with 0x10: reads the brake state, changes nothing"));
    m_engage = new QPushButton(tr("Engage"), this);
    m_engage->setObjectName(QStringLiteral("brakeEngage"));
    m_engage->setToolTip(tr("0x8C 0x00: the brake is unpowered and holds the shaft"));
    m_release = new QPushButton(tr("Release\u2026"), this);
    m_release->setObjectName(QStringLiteral("brakeRelease"));
    m_release->setToolTip(tr("0x8C 0x01: the brake is powered and lets the shaft turn"));
    connect(m_read, &QPushButton::clicked, this, &BrakePanel::readState);
    connect(m_engage, &QPushButton::clicked, this, &BrakePanel::engage);
    connect(m_release, &QPushButton::clicked, this, &BrakePanel::release);
    auto *row = new QHBoxLayout;
    row->addWidget(m_read);
    row->addWidget(m_engage);
    row->addWidget(m_release);
    row->addStretch();
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_stateLabel);
    layout->addLayout(row);
    layout->addWidget(m_status);
    setDrive(0, {}, false);
}

void BrakePanel::setDrive(int id, const bus::KnownMotor &motor, bool canSend, protocol::Link link)
{
    const bool other =
        id != m_id ||
        DriveSettingsStore::driveKey(id, motor) != DriveSettingsStore::driveKey(m_id, m_motor) ||
        motor.generation != m_motor.generation;
    m_id = id;
    m_motor = motor;
    m_canSend = canSend;
    m_absence = id > 0 ? GenerationNote::absence(motor, Command::Brake, tr("brake control"), link)
                       : QString();
    if (!canSend)
        m_busy = false; // the view forgets pending requests when the link goes: none is awaited
    if (other) {
        // What was read or in flight for another drive says nothing about this one.
        m_state.reset();
        m_busy = false;
        setStatus(QString());
    }
    if (id <= 0)
        m_stateLabel->setText(tr("No drive selected."));
    else if (!m_absence.isEmpty())
        m_stateLabel->setText(m_absence);
    else if (!m_state)
        m_stateLabel->setText(tr("Brake state: not read yet."));
    refreshEnabled();
}

bool BrakePanel::usable() const
{
    return m_id > 0 && m_canSend && m_absence.isEmpty() && m_send && !m_busy;
}

bool BrakePanel::stillSame(int id) const
{
    return id == m_id && m_canSend && m_absence.isEmpty();
}

QString BrakePanel::statusText() const
{
    return m_status->text();
}

void BrakePanel::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(
        error ? StatusColors::textStyle(StatusColors::Role::Error, palette(), true) : QString());
}

void BrakePanel::setBusy(bool busy)
{
    m_busy = busy;
    refreshEnabled();
}

void BrakePanel::refreshEnabled()
{
    const bool can = usable();
    m_read->setEnabled(can);
    m_engage->setEnabled(can);
    m_release->setEnabled(can);
}

QString BrakePanel::stateText(const protocol::BrakeState &state)
{
    if (state.raw == 0x00)
        return tr("engaged (unpowered, holding)");
    if (state.raw == 0x01)
        return tr("released (powered, the shaft is free)");
    return tr("unknown code 0x%1").arg(state.raw, 2, 16, QLatin1Char('0'));
}

void BrakePanel::showState(const protocol::BrakeState &state)
{
    m_state = state;
    m_stateLabel->setText(tr("Brake state: %1.").arg(stateText(state)));
    emit stateRead(state);
}

void BrakePanel::readState()
{
    if (!usable())
        return;
    const int id = m_id;
    setBusy(true);
    m_send(
        *build::brake(id, BrakeAction::Read).request,
        [this, id](const bus::RequestResult &r) {
            if (id != m_id)
                return;
            setBusy(false);
            if (const auto *s = replyPayload<protocol::BrakeState>(r)) {
                showState(*s);
                setStatus(tr("Read the brake of drive %1: %2.").arg(id).arg(stateText(*s)));
            } else {
                setStatus(DriveText::failure(r), true);
            }
        },
        -1);
}

void BrakePanel::engage()
{
    if (!usable())
        return;
    sendAction(m_id, BrakeAction::Engage);
}

void BrakePanel::release()
{
    if (!usable())
        return;
    const int id = m_id;
    const bool yes = ConfirmDialog::ask(
        this, ConfirmRequest{QStringLiteral("brake_release"), tr("Release the brake"),
                             tr("Release the brake of drive %1?").arg(id),
                             tr("The shaft is then held only by the motor. A vertical axis (or "
                                "any load that gravity or a spring pulls) drops or turns as soon "
                                "as the brake lets go unless the motor holds it."),
                             tr("Release brake")});
    if (!yes) {
        setStatus(tr("Cancelled: the brake was not released, nothing was sent."));
        return;
    }
    if (!stillSame(id) || m_busy) {
        setStatus(tr("The drive or the connection changed: nothing was sent."), true);
        return;
    }
    // Whether the motor could hold the load is read now, not assumed.
    setBusy(true);
    setStatus(tr("Reading whether the motor of drive %1 is on\u2026").arg(id));
    m_send(
        *build::plain(Command::ReadState1, id).request,
        [this, id](const bus::RequestResult &r) {
            if (id != m_id)
                return;
            setBusy(false);
            releaseAfterMotorState(id, r);
        },
        -1);
}

void BrakePanel::releaseAfterMotorState(int id, const bus::RequestResult &state)
{
    const auto *s = replyPayload<protocol::State1>(state);
    if (!s) {
        setStatus(tr("Refused: could not read whether the motor is on, so the brake was not "
                     "released. Nothing sent. %1")
                      .arg(DriveText::failure(state)),
                  true);
        return;
    }
    const std::optional<bool> on = s->as(protocol::Generation::V2_35).motorOn();
    if (on != true) {
        const QString question =
            on ? tr("The motor of drive %1 is OFF. Release the brake anyway?").arg(id)
               : tr("Whether the motor of drive %1 is on cannot be told (state code 0x%2). "
                    "Release the brake anyway?")
                     .arg(id)
                     .arg(s->motorStateRaw, 2, 16, QLatin1Char('0'));
        const bool yes = ConfirmDialog::ask(
            this, ConfirmRequest{QStringLiteral("brake_release_motor_off"),
                                 tr("Release the brake with the motor off"), question,
                                 tr("Nothing holds the shaft once the brake lets go: a vertical "
                                    "axis falls, a loaded axis turns freely. Support the load "
                                    "or turn the motor on first."),
                                 tr("Release with the motor off")});
        if (!yes) {
            setStatus(tr("Refused: the motor is off, so the brake was not released. Nothing "
                         "sent."),
                      true);
            return;
        }
        if (!stillSame(id) || m_busy) {
            setStatus(tr("The drive or the connection changed: nothing was sent."), true);
            return;
        }
    }
    sendAction(id, BrakeAction::Release);
}

void BrakePanel::sendAction(int id, BrakeAction action)
{
    const bool releasing = action == BrakeAction::Release;
    const QString what = releasing ? tr("release (0x8C 0x01)") : tr("engage (0x8C 0x00)");
    setBusy(true);
    setStatus(tr("Sent %1 to drive %2\u2026").arg(what).arg(id));
    // Sent once: a lost reply leaves the state unknown, and the read-back tells it.
    m_send(
        *build::brake(id, action).request,
        [this, id, what](const bus::RequestResult &r) {
            if (id != m_id)
                return;
            const auto *s = replyPayload<protocol::BrakeState>(r);
            const QString answered =
                s ? tr("Sent %1 to drive %2; it answered: %3.").arg(what).arg(id).arg(stateText(*s))
                  : tr("Sent %1 to drive %2; %3").arg(what).arg(id).arg(DriveText::failure(r));
            if (s)
                showState(*s);
            setStatus(answered, !s);
            emit changeFinished(s != nullptr);
            // Read back what the drive holds now, whatever the answer was.
            m_send(
                *build::brake(id, BrakeAction::Read).request,
                [this, id, answered, ok = s != nullptr](const bus::RequestResult &back) {
                    if (id != m_id)
                        return;
                    setBusy(false);
                    const auto *b = replyPayload<protocol::BrakeState>(back);
                    if (b)
                        showState(*b);
                    setStatus(
                        answered + QLatin1Char(' ') +
                            (b ? tr("Read back: %1.").arg(stateText(*b))
                               : tr("Reading it back failed: %1").arg(DriveText::failure(back))),
                        !b || m_status->styleSheet().size() > 0);
                },
                -1);
        },
        0);
}

} // namespace lk::ui
