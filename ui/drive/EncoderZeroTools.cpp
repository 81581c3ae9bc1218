#include "EncoderZeroTools.h"

#include "ConfirmDialog.h"
#include "DriveText.h"
#include "GenerationNote.h"

#include <protocol/RequestBuilder.h>

#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

#include <cmath>

namespace lk::ui {

namespace {
using protocol::Command;
namespace build = protocol::build;

} // namespace

EncoderZeroTools::EncoderZeroTools(QWidget *parent) : QGroupBox(tr("Zero"), parent)
{
    setObjectName(QStringLiteral("zeroTools"));
    m_clearAngle = new QPushButton(tr("Clear motor angle (0x95)\u2026"), this);
    m_clearAngle->setObjectName(QStringLiteral("clearAngle"));
    m_zeroRom = new QPushButton(tr("Write current position to ROM as zero (0x19)\u2026"), this);
    m_zeroRom->setObjectName(QStringLiteral("zeroRom"));
    connect(m_clearAngle, &QPushButton::clicked, this, &EncoderZeroTools::clearAngle);
    connect(m_zeroRom, &QPushButton::clicked, this, &EncoderZeroTools::writeZeroToRom);
    auto *clearText = new QLabel(tr("Multi-turn and single-turn angle become 0 here until "
                                    "power-off; the result is checked with read_multi_turn "
                                    "(0x92)."),
                                 this);
    auto *zeroText = new QLabel(tr("Stores the present encoder position as the zero in flash. "
                                   "Takes effect only after a power cycle; each write wears the "
                                   "flash."),
                                this);
    m_clearTurns = new QPushButton(tr("Clear turn count (0x93)\u2026"), this);
    m_clearTurns->setObjectName(QStringLiteral("clearTurns"));
    connect(m_clearTurns, &QPushButton::clicked, this, &EncoderZeroTools::clearTurnCount);
    m_clearTurnsNote = new QLabel(this);
    m_clearTurnsNote->setObjectName(QStringLiteral("clearTurnsNote"));
    for (QLabel *l : {clearText, zeroText, m_clearTurnsNote})
        l->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_clearAngle);
    layout->addWidget(clearText);
    layout->addWidget(m_clearTurns);
    layout->addWidget(m_clearTurnsNote);
    layout->addWidget(m_zeroRom);
    layout->addWidget(zeroText);
    refreshEnabled();
}

void EncoderZeroTools::setDrive(int id, const bus::KnownMotor &motor, bool canSend,
                                protocol::Link link)
{
    m_id = id;
    m_motor = motor;
    m_link = link;
    m_canSend = canSend;
    refreshEnabled();
}

void EncoderZeroTools::abandon(bool forgetCheck)
{
    if (forgetCheck)
        m_angleCheck.reset();
    m_busy = false;
    refreshEnabled();
}

void EncoderZeroTools::setBlocked(bool blocked)
{
    m_blocked = blocked;
    refreshEnabled();
}

void EncoderZeroTools::setBusy(bool busy)
{
    m_busy = busy;
    refreshEnabled();
    emit busyChanged(busy);
}

void EncoderZeroTools::fail(const bus::RequestResult &result)
{
    setBusy(false);
    emit statusChanged(DriveText::failure(result), true);
}

QString EncoderZeroTools::turnCountAbsence() const
{
    if (m_id <= 0)
        return QString();
    return GenerationNote::absence(m_motor, Command::ClearTurnCount, tr("clear turn count"),
                                   m_link);
}

void EncoderZeroTools::refreshEnabled()
{
    const bool can = canStart();
    m_clearAngle->setEnabled(can);
    m_zeroRom->setEnabled(can);
    const QString absent = turnCountAbsence();
    m_clearTurns->setEnabled(can && absent.isEmpty());
    m_clearTurnsNote->setText(
        absent.isEmpty() ? tr("Whole turns of the multi-turn angle are dropped; the angle within "
                              "the present turn stays. Checked with read_multi_turn (0x92).")
                         : absent);
}

bool EncoderZeroTools::confirm(const ConfirmRequest &request)
{
    const int id = m_id;
    QString why;
    bool changed = false;
    // The dialog ran an event loop: the drive or the link may have changed meanwhile.
    if (ConfirmDialog::askUnchanged(
            this, request, [this, id] { return canStart() && m_id == id; }, &why, &changed))
        return true;
    emit statusChanged(why, changed);
    return false;
}

void EncoderZeroTools::readMultiTurn(std::function<void(double)> then)
{
    m_send(
        *build::plain(Command::ReadMultiTurn, m_id).request,
        [this, then](const bus::RequestResult &r) {
            const auto *a = replyPayload<protocol::MultiTurnAngle>(r);
            if (!a) {
                fail(r);
                return;
            }
            emit multiTurnRead(a->degrees());
            then(a->degrees());
        },
        -1);
}

void EncoderZeroTools::clearAngle()
{
    if (!canStart())
        return;
    if (!confirm({QStringLiteral("clear_angle"), tr("Clear motor angle"),
                  tr("Make the present position of drive %1 angle 0?").arg(m_id),
                  tr("Multi-turn and single-turn angles restart from 0 here until power-off, so "
                     "absolute position commands go elsewhere afterwards."),
                  tr("Clear angle")}))
        return;
    setBusy(true);
    const int id = m_id;
    emit statusChanged(tr("Clearing the angle of drive %1\u2026").arg(id), false);
    readMultiTurn([this, id](double before) {
        m_send(
            *build::plain(Command::ClearAngle, id).request,
            [this, id, before](const bus::RequestResult &r) {
                if (!r.ok())
                    fail(r);
                else
                    onClearAcknowledged(id, before);
            },
            -1);
    });
}

void EncoderZeroTools::onClearAcknowledged(int id, double before)
{
    readMultiTurn([this, id, before](double after) {
        setBusy(false);
        if (id == m_id)
            showAngleCheck(AngleCheck::classify(before, after));
    });
}

void EncoderZeroTools::showAngleCheck(const AngleCheck &check)
{
    m_angleCheck = check;
    switch (check.outcome) {
    case AngleCheck::Outcome::Cleared:
        emit statusChanged(tr("Angle cleared: the drive reads %1\u00b0 (was %2\u00b0).")
                               .arg(check.afterDeg, 0, 'f', 2)
                               .arg(check.beforeDeg, 0, 'f', 2),
                           false);
        break;
    case AngleCheck::Outcome::AlreadyZero:
        emit statusChanged(tr("The angle read %1\u00b0 before already: whether the drive "
                              "applied 0x95 cannot be told.")
                               .arg(check.beforeDeg, 0, 'f', 2),
                           false);
        break;
    case AngleCheck::Outcome::Unchanged:
        emit statusChanged(tr("The drive acknowledged 0x95 but its angle did not change "
                              "(%1\u00b0): this firmware ignores clear-angle. Use the encoder "
                              "offset or 0x19 instead.")
                               .arg(check.afterDeg, 0, 'f', 2),
                           true);
        break;
    case AngleCheck::Outcome::ChangedNotZero:
        emit statusChanged(tr("The angle changed from %1\u00b0 to %2\u00b0 but is not 0: was "
                              "the motor turning? Stop it and clear again.")
                               .arg(check.beforeDeg, 0, 'f', 2)
                               .arg(check.afterDeg, 0, 'f', 2),
                           true);
        break;
    }
    emit angleCheckFinished(check);
}

void EncoderZeroTools::writeZeroToRom()
{
    if (!canStart())
        return;
    if (!confirm({QStringLiteral("write_zero_rom"), tr("Write zero to ROM"),
                  tr("Store the present position of drive %1 as its zero in ROM?").arg(m_id),
                  tr("It takes effect only after the drive is powered off and on again. It "
                     "writes the drive's flash, which wears with every write: do it once, "
                     "not as a routine."),
                  tr("Write zero to ROM")}))
        return;
    setBusy(true);
    const int id = m_id;
    // Sent exactly once: a lost reply is reported, never retried.
    m_send(
        *build::plain(Command::WriteZeroRom, id).request,
        [this, id](const bus::RequestResult &r) {
            const auto *z = replyPayload<protocol::ZeroWritten>(r);
            if (!z) {
                fail(r);
                emit zeroWriteFinished(false);
                return;
            }
            setBusy(false);
            QString text = tr("Zero written to the ROM of drive %1. Power the drive off and on "
                              "for it to take effect.")
                               .arg(id);
            if (z->encoderOffset)
                text += QLatin1Char(' ') +
                        tr("The drive reports the new zero as encoder %1.").arg(*z->encoderOffset);
            emit statusChanged(text, false);
            emit zeroWriteFinished(true);
        },
        0);
}

void EncoderZeroTools::clearTurnCount()
{
    if (!canStart())
        return;
    if (const QString absent = turnCountAbsence(); !absent.isEmpty()) {
        emit statusChanged(absent, true);
        return;
    }
    // docs/V2.35.md names 0x93 only: neither RAM nor ROM, nor whether the motor must be off, is
    // documented, so the confirmation says so rather than guess.
    if (!confirm({QStringLiteral("clear_turn_count"), tr("Clear turn count"),
                  tr("Set the turn count of drive %1 to 0?").arg(m_id),
                  tr("The multi-turn angle keeps only the angle within the present turn, so "
                     "multi-turn position commands go elsewhere afterwards. The V2.35 document "
                     "does not say whether this survives a power cycle (RAM or ROM) or whether "
                     "the motor must be off: stop the motor first."),
                  tr("Clear turn count")}))
        return;
    setBusy(true);
    const int id = m_id;
    emit statusChanged(tr("Clearing the turn count of drive %1\u2026").arg(id), false);
    readMultiTurn([this, id](double before) {
        // Sent once: whether it writes flash is not documented.
        m_send(
            *build::plain(Command::ClearTurnCount, id).request,
            [this, id, before](const bus::RequestResult &r) {
                if (!r.ok()) {
                    fail(r);
                    emit turnCountCleared(false);
                    return;
                }
                onTurnsCleared(id, before);
            },
            0);
    });
}

void EncoderZeroTools::onTurnsCleared(int id, double before)
{
    readMultiTurn([this, id, before](double after) {
        setBusy(false);
        if (id != m_id)
            return;
        // One output turn is 360 degrees times the gear ratio of rotor angle.
        const bool ok = std::abs(after) < 360.0 * m_ratio;
        emit statusChanged(ok ? tr("Turn count of drive %1 cleared: the multi-turn angle reads "
                                   "%2\u00b0 (was %3\u00b0).")
                                    .arg(id)
                                    .arg(after, 0, 'f', 2)
                                    .arg(before, 0, 'f', 2)
                              : tr("Drive %1 acknowledged 0x93, but its multi-turn angle reads "
                                   "%2\u00b0 (was %3\u00b0): more than one turn, so the turn "
                                   "count was not cleared.")
                                    .arg(id)
                                    .arg(after, 0, 'f', 2)
                                    .arg(before, 0, 'f', 2),
                           !ok);
        emit turnCountCleared(ok);
    });
}

} // namespace lk::ui
