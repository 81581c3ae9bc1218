#include "CommandedMotion.h"

#include <bus/BusSession.h>
#include <panels/Format.h>
#include <protocol/Command.h>
#include <text/CommandTitle.h>

#include <QtCore/QRegularExpression>

#include <variant>

namespace lk::ui {

using protocol::Command;

namespace {
QString number(double v)
{
    return QString::number(v, 'f', 2).remove(QRegularExpression(QStringLiteral("\\.?0+$")));
}

/// A command that holds the drive still (speed, torque or power 0) ends the motion.
bool holdsStill(const protocol::Request &r)
{
    if (const auto *s = std::get_if<protocol::SpeedCommand>(&r.payload))
        return s->speedRaw == 0;
    if (const auto *t = std::get_if<protocol::TorqueCommand>(&r.payload))
        return t->iqRaw == 0;
    if (const auto *p = std::get_if<protocol::OpenLoopCommand>(&r.payload))
        return p->power == 0;
    return false;
}
} // namespace

CommandedMotion::CommandedMotion(QObject *parent) : QObject(parent) {}

void CommandedMotion::setSession(bus::BusSession *session)
{
    disconnect(m_connection);
    disconnect(m_multiTorqueConnection);
    m_session = session;
    if (!session)
        return;
    m_connection =
        connect(session, &bus::BusSession::requestCompleted, this, &CommandedMotion::observe);
    // A multi-motor torque frame sets each drive it names going as a torque command would:
    // quitting and the link-loss warnings must know them too.
    m_multiTorqueConnection = connect(session, &bus::BusSession::multiTorqueCompleted, this,
                                      [this](const bus::MultiTorqueResult &frame) {
                                          for (const bus::RequestResult &d : frame.drives)
                                              observe(d);
                                      });
}

std::optional<CommandedMotion::Entry> CommandedMotion::last(int id) const
{
    const auto it = m_entries.constFind(id);
    return it == m_entries.cend() ? std::nullopt : std::optional<Entry>(*it);
}

void CommandedMotion::observe(const bus::RequestResult &result)
{
    const protocol::Request &r = result.request;
    const int id = r.id;
    if (r.command == Command::MotorOff || r.command == Command::MotorStop) {
        if (result.ok() && m_entries.remove(id) > 0)
            emit changed();
        return;
    }
    // Never sent (cancelled in the queue, or no link): it cannot have moved anything.
    if (!protocol::CommandTable::info(r.command).movesMotor || result.attempts == 0)
        return;
    if (holdsStill(r) && result.ok()) {
        if (m_entries.remove(id) > 0)
            emit changed();
        return;
    }
    m_entries.insert(id, Entry{r, QDateTime::currentDateTime()});
    emit changed();
}

QString CommandedMotion::describe(const protocol::Request &r)
{
    using namespace protocol;
    if (const auto *s = std::get_if<SpeedCommand>(&r.payload))
        return tr("speed %1 dps").arg(number(s->speedDps()));
    if (const auto *t = std::get_if<TorqueCommand>(&r.payload))
        return tr("torque %1 A").arg(number(t->iqA()));
    if (const auto *p = std::get_if<OpenLoopCommand>(&r.payload))
        return tr("open-loop power %1").arg(Format::power(p->power));
    if (const auto *m = std::get_if<MultiPositionCommand>(&r.payload))
        return tr("position %1\u00b0").arg(number(m->angleRaw * 0.01));
    if (const auto *a = std::get_if<SinglePositionCommand>(&r.payload))
        return tr("single-turn position %1\u00b0").arg(number(a->angleRaw * 0.01));
    if (const auto *i = std::get_if<IncrementPositionCommand>(&r.payload))
        return tr("move by %1\u00b0").arg(number(i->angleRaw * 0.01));
    return text::CommandTitle::name(r.command); // Motor Run, or a command without a value
}

QString CommandedMotion::driveText(int id) const
{
    const std::optional<Entry> e = last(id);
    if (!e)
        return tr("Drive %1").arg(id);
    return tr("Drive %1 (%2 at %3)")
        .arg(id)
        .arg(describe(e->request), e->sentAt.time().toString(QStringLiteral("HH:mm:ss")));
}

} // namespace lk::ui
