#include "VerdictText.h"

#include "CommandTitle.h"

#include <protocol/Command.h>

#include <atomic>

namespace lk::text {

using protocol::Command;
using safety::LimitKind;

namespace {
std::atomic<VerdictText::CommandNames> g_commandNames{VerdictText::CommandNames::Titles};

QString num(double v)
{
    return QString::number(v, 'g', 8);
}

// Currents to 10 mA: the wire's 0.016 A steps would otherwise show as "3.008 A" for 3 A.
QString amps(double v)
{
    return QString::number(v, 'f', 2);
}

// A speed refusal is about the command's own speed or about a position move's max speed.
bool isMaxSpeed(const safety::Verdict &v)
{
    return v.command && *v.command != Command::Speed;
}

bool isIncrement(const safety::Verdict &v)
{
    return v.command && (*v.command == Command::IncrementPosition ||
                         *v.command == Command::IncrementPositionLimited);
}

QString commandName(const safety::Verdict &v)
{
    if (!v.command)
        return VerdictText::tr("this command");
    return VerdictText::commandNames() == VerdictText::CommandNames::Cli
               ? protocol::CommandTable::name(*v.command)
               : CommandTitle::withCode(*v.command);
}

// Whole sentences for each case: a translation cannot be glued together from "the" + "max"
// + "speed".
QString seriesSpeed(const safety::Verdict &v, std::optional<protocol::Series> s)
{
    if (!s)
        return (isMaxSpeed(v) ? VerdictText::tr("the max speed %1 dps is over %2 dps, the top "
                                                "speed of the slowest series (the drive's series "
                                                "is unknown)")
                              : VerdictText::tr("the speed %1 dps is over %2 dps, the top speed of "
                                                "the slowest series (the drive's series is "
                                                "unknown)"))
            .arg(num(v.value), num(v.limit));
    return (isMaxSpeed(v) ? VerdictText::tr("the max speed %1 dps is over the %2 series top speed "
                                            "of %3 dps")
                          : VerdictText::tr("the speed %1 dps is over the %2 series top speed of "
                                            "%3 dps"))
        .arg(num(v.value), protocol::seriesName(*s), num(v.limit));
}

QString softSpeed(const safety::Verdict &v)
{
    // A speed limit always exists: none at all (0) is refused, never read as "any".
    if (!(v.limit > 0))
        return VerdictText::tr("no speed limit is set: set one first");
    return (isMaxSpeed(v)
                ? VerdictText::tr("the max speed %1 dps is over your speed limit of %2 dps")
                : VerdictText::tr("the speed %1 dps is over your speed limit of %2 dps"))
        .arg(num(v.value), num(v.limit));
}

QString outputTurn(const safety::Verdict &v)
{
    if (v.fromDeg)
        return VerdictText::tr("a move of %1\u00b0 from the current angle %2\u00b0 is more than "
                               "one output turn (%3\u00b0): move in smaller steps")
            .arg(num(v.value), num(*v.fromDeg), num(v.limit));
    if (isIncrement(v))
        return VerdictText::tr("an increment of %1\u00b0 is more than one output turn (%2\u00b0): "
                               "move in smaller steps")
            .arg(num(v.value), num(v.limit));
    return VerdictText::tr("a move of %1\u00b0 is more than one output turn (%2\u00b0): move in "
                           "smaller steps")
        .arg(num(v.value), num(v.limit));
}

const char *roleName(tuning::StepSetpoint::Role role)
{
    using Role = tuning::StepSetpoint::Role;
    switch (role) {
    case Role::PreRoll:
        return QT_TRANSLATE_NOOP("lk::text::VerdictText", "pre-roll to FROM");
    case Role::Edge:
        return QT_TRANSLATE_NOOP("lk::text::VerdictText", "step");
    case Role::Return:
        return QT_TRANSLATE_NOOP("lk::text::VerdictText", "return to FROM");
    }
    return "";
}
} // namespace

void VerdictText::setCommandNames(CommandNames names)
{
    g_commandNames = names;
}

VerdictText::CommandNames VerdictText::commandNames()
{
    return g_commandNames;
}

QString VerdictText::series(std::optional<protocol::Series> s)
{
    return s ? protocol::seriesName(*s) : tr("unknown series");
}

QString VerdictText::listenOnlyNoSend()
{
    return tr("Listen-only: this tool transmits nothing. Take over the bus to send.");
}

QString VerdictText::listenOnlyStop()
{
    // Worded so that nobody reads it as a stop: the machine is still under its own controller.
    return tr("Listen-only: NOTHING was sent. Stop the machine with its own emergency stop.");
}

QString VerdictText::verdict(const safety::Verdict &v, std::optional<protocol::Series> s)
{
    switch (v.kind) {
    case LimitKind::None:
        return QString();
    case LimitKind::UnknownSeries:
        return tr("%1 needs the drive's series, whose current limits are unknown: scan the bus "
                  "first")
            .arg(commandName(v));
    case LimitKind::Unsupported:
        return tr("%1 drives do not implement %2").arg(series(s), commandName(v));
    case LimitKind::SeriesCurrent:
        return tr("the torque current %1 A is over the %2 series rating of %3 A")
            .arg(amps(v.value), series(s), amps(v.limit));
    case LimitKind::SoftTorque:
        return tr("the torque current %1 A is over your torque limit of %2 A")
            .arg(amps(v.value), amps(v.limit));
    case LimitKind::SoftPower:
        return tr("the open-loop power %1 is over your power limit of %2 (of 1000)")
            .arg(num(v.value), num(v.limit));
    case LimitKind::SeriesSpeed:
        return seriesSpeed(v, s);
    case LimitKind::SoftSpeed:
        return softSpeed(v);
    case LimitKind::AngleBelowMin:
        return tr("the target %1\u00b0 is below your angle range (min %2\u00b0)")
            .arg(num(v.value), num(v.limit));
    case LimitKind::AngleAboveMax:
        return tr("the target %1\u00b0 is above your angle range (max %2\u00b0)")
            .arg(num(v.value), num(v.limit));
    case LimitKind::SoftIncrement:
        return tr("an increment of %1\u00b0 is over your step limit of %2\u00b0")
            .arg(num(v.value), num(v.limit));
    case LimitKind::AngleUnknown:
        return tr("the drive's current angle is not known, so the move cannot be checked: read "
                  "it (0x92) first");
    case LimitKind::OutputTurn:
        return outputTurn(v);
    }
    return QString();
}

QString VerdictText::speedBound(safety::SpeedBound bound, double dps)
{
    const QString value = QString::number(dps, 'g', 10);
    switch (bound) {
    case safety::SpeedBound::None:
        return QString();
    case safety::SpeedBound::Command:
        return tr("within your speed limit of %1 dps").arg(value);
    case safety::SpeedBound::SoftLimit:
        return tr("max speed %1 dps (your speed limit)").arg(value);
    case safety::SpeedBound::SeriesTop:
        return tr("max speed %1 dps (the series top speed)").arg(value);
    case safety::SpeedBound::UserMaxSpeed:
        return tr("max speed %1 dps (the max speed you gave)").arg(value);
    }
    return QString();
}

QString VerdictText::stepRefusal(const tuning::StepRefusal &r)
{
    if (r.verdict.allowed())
        return QString();
    const tuning::StepSetpoint &s = r.setpoint;
    const bool speed = r.loop == tuning::StepLoop::Speed;
    QString move;
    if (s.role == tuning::StepSetpoint::Role::PreRoll)
        move = (speed ? tr("%1 dps") : tr("%1\u00b0")).arg(num(s.target));
    else
        move = (speed ? tr("%1 -> %2 dps") : tr("%1\u00b0 -> %2\u00b0"))
                   .arg(num(s.previous), num(s.target));
    return tr("setpoint %1 of %2 (%3, %4 at %5 s): %6")
        .arg(r.index + 1)
        .arg(r.count)
        .arg(tr(roleName(s.role)), move, num(s.atS), verdict(r.verdict, r.series));
}

} // namespace lk::text
