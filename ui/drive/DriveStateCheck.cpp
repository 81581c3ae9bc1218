#include "DriveStateCheck.h"

#include <bus/NewestSample.h>
#include <protocol/RequestBuilder.h>

namespace lk::ui {

namespace {
using protocol::Command;
namespace build = protocol::build;
} // namespace

DriveStateCheck::DriveStateCheck(Sender sender, QObject *parent)
    : QObject(parent), m_send(std::move(sender))
{
}

void DriveStateCheck::setDrive(int id, const bus::KnownMotor &motor)
{
    const bool v235 = motor.generation == protocol::Generation::V2_35;
    if (id == m_id && v235 == m_v235)
        return;
    m_id = id;
    m_v235 = v235;
    m_motorOn.reset();
    m_brakeReleased.reset();
    emit changed();
}

bool DriveStateCheck::applies() const
{
    return m_id > 0 && m_v235;
}

bool DriveStateCheck::gates(const protocol::Request &request) const
{
    if (!applies() || request.id != m_id || request.command == Command::MotorRun ||
        !protocol::CommandTable::info(request.command).movesMotor)
        return false;
    const auto &p = request.payload;
    if (const auto *s = std::get_if<protocol::SpeedCommand>(&p))
        return s->speedRaw != 0;
    if (const auto *t = std::get_if<protocol::TorqueCommand>(&p))
        return t->iqRaw != 0;
    if (const auto *o = std::get_if<protocol::OpenLoopCommand>(&p))
        return o->power != 0;
    return true;
}

void DriveStateCheck::setMotorOn(std::optional<bool> on)
{
    if (on == m_motorOn)
        return;
    m_motorOn = on;
    emit changed();
}

void DriveStateCheck::refresh(std::function<void(bool ok)> then, bool motorOnly)
{
    if (!applies()) {
        if (then)
            then(false);
        return;
    }
    const int id = m_id;
    const quint64 sent =
        m_send(*build::plain(Command::ReadState1, id).request,
               [this, id, then](const bus::RequestResult &r) {
                   if (id != m_id)
                       return;
                   const auto *s = replyPayload<protocol::State1>(r);
                   // Unknown is not off: a failed read leaves the state unknown, and says so.
                   setMotorOn(s ? s->as(protocol::Generation::V2_35).motorOn() : std::nullopt);
                   if (then)
                       then(s != nullptr);
               });
    if (!sent && then)
        then(false);
    if (motorOnly || !sent)
        return;
    m_send(*build::brake(id, protocol::BrakeAction::Read).request,
           [this, id](const bus::RequestResult &r) {
               const auto *b = replyPayload<protocol::BrakeState>(r);
               if (id == m_id && b)
                   noteBrake(*b);
           });
}

void DriveStateCheck::whenKnown(std::function<void()> known,
                                std::function<void(const QString &)> unknown)
{
    const int id = m_id;
    refresh(
        [this, id, known, unknown](bool) {
            if (id != m_id)
                return;
            if (m_motorOn)
                known();
            else
                unknown(tr("Refused: whether the motor of drive %1 is on could not be told "
                           "(read_state1). Nothing sent.")
                            .arg(id));
        },
        true);
}

void DriveStateCheck::noteTelemetry(const bus::TelemetryBatch &batch)
{
    if (!applies())
        return;
    if (const bus::TelemetrySample *s =
            bus::newestSample(batch, m_id, bus::TelemetryField::MotorOn))
        setMotorOn(s->motorOn);
}

void DriveStateCheck::noteBrake(const protocol::BrakeState &state)
{
    const std::optional<bool> released =
        state.raw <= 0x01 ? std::optional<bool>(state.released()) : std::nullopt;
    if (released == m_brakeReleased)
        return;
    m_brakeReleased = released;
    emit changed();
}

QString DriveStateCheck::refusal() const
{
    if (!applies() || m_motorOn != false)
        return QString();
    return tr("Refused: drive %1 is off: Motor On first (a V2.35 drive stays off after Motor Off "
              "or a protection trip, and a control command does not turn it on). Nothing sent.")
        .arg(m_id);
}

QString DriveStateCheck::warning() const
{
    if (!applies() || m_brakeReleased != false)
        return QString();
    return tr("The brake of drive %1 reads engaged: the shaft is held and does not move until "
              "the brake is released.")
        .arg(m_id);
}

QString DriveStateCheck::stateText() const
{
    if (!applies())
        return QString();
    const QString motor = !m_motorOn   ? tr("motor state not read yet")
                          : *m_motorOn ? tr("motor on")
                                       : tr("motor OFF: Motor On first");
    const QString brake = !m_brakeReleased   ? tr("brake not read")
                          : *m_brakeReleased ? tr("brake released")
                                             : tr("brake ENGAGED: the shaft is held");
    return tr("Drive %1: %2; %3.").arg(m_id).arg(motor, brake);
}

} // namespace lk::ui
