#include "DriveText.h"

#include <protocol/Command.h>

namespace lk::ui {

using safety::LimitKind;

namespace {
QString num(double v)
{
    return QString::number(v, 'g', 8);
}

// Currents to 10 mA: the wire's 0.016 A steps would otherwise show as "3.008 A" for 3 A.
QString amps(double v)
{
    return QString::number(v, 'f', 2);
}
} // namespace

QString DriveText::series(std::optional<protocol::Series> s)
{
    return s ? protocol::seriesName(*s) : tr("unknown series");
}

QString DriveText::verdict(const safety::Verdict &v, std::optional<protocol::Series> s)
{
    switch (v.kind) {
    case LimitKind::None:
        return QString();
    case LimitKind::UnknownSeries:
        return tr("Refused: the drive's series is unknown, so its current limits are unknown. "
                  "Scan the bus first.");
    case LimitKind::Unsupported:
        return tr("Refused: %1 drives do not implement this command.").arg(series(s));
    case LimitKind::SeriesCurrent:
        return tr("Refused by the series limit: %1 A is over the %2 rating of %3 A.")
            .arg(amps(v.value), series(s), amps(v.limit));
    case LimitKind::SoftTorque:
        return tr("Refused by your torque limit: %1 A is over %2 A.")
            .arg(amps(v.value), amps(v.limit));
    case LimitKind::SoftPower:
        return tr("Refused by your open-loop power limit: %1 is over %2 (of 1000).")
            .arg(num(v.value), num(v.limit));
    case LimitKind::SeriesSpeed:
        return tr("Refused by the series limit: %1 dps is over the %2 top speed of %3 dps.")
            .arg(num(v.value), series(s), num(v.limit));
    case LimitKind::SoftSpeed:
        return tr("Refused by your speed limit: %1 dps is over %2 dps.")
            .arg(num(v.value), num(v.limit));
    case LimitKind::AngleBelowMin:
        return tr("Refused by your angle range: %1\u00b0 is below the minimum of %2\u00b0.")
            .arg(num(v.value), num(v.limit));
    case LimitKind::AngleAboveMax:
        return tr("Refused by your angle range: %1\u00b0 is above the maximum of %2\u00b0.")
            .arg(num(v.value), num(v.limit));
    case LimitKind::SoftIncrement:
        return tr("Refused by your step limit: a move of %1\u00b0 is more than %2\u00b0.")
            .arg(num(v.value), num(v.limit));
    case LimitKind::AngleUnknown:
        return tr("Refused: the drive's current angle is not known (read with 0x92 first), so "
                  "the move cannot be checked. Nothing sent.");
    case LimitKind::OutputTurn:
        return tr("Refused: a move of %1\u00b0 is more than one output turn (%2\u00b0). Move in "
                  "smaller steps.")
            .arg(num(v.value), num(v.limit));
    }
    return v.message;
}

QString DriveText::fieldError(const protocol::FieldError &e)
{
    if (e.problem.isEmpty())
        return tr("Refused, nothing sent: %1 must be in %2.").arg(e.field, e.range);
    return tr("Refused, nothing sent: %1 must be in %2 (%3).").arg(e.field, e.range, e.problem);
}

QString DriveText::setpointStop(const bus::SetpointStop &stop,
                                std::optional<protocol::Series> series)
{
    using Reason = bus::SetpointStopReason;
    switch (stop.reason) {
    case Reason::Requested:
        return tr("Stopped by the user.");
    case Reason::Replaced:
        return tr("Stopped: another waveform started.");
    case Reason::Refused:
        return stop.fieldError ? fieldError(*stop.fieldError) : verdict(stop.verdict, series);
    case Reason::EmergencyStop:
        return tr("Stopped by the emergency stop.");
    case Reason::Cancelled:
        return tr("Stopped: the bus cancelled motion commands (emergency stop).");
    case Reason::Disconnected:
        return tr("Stopped: the connection was lost.");
    case Reason::Closed:
        return tr("Stopped: the bus was closed.");
    case Reason::BusChanged:
        return tr("Stopped: the port was reopened at another baud.");
    }
    return QString();
}

QString DriveText::command(protocol::Command c)
{
    return QStringLiteral("%1 (%2)").arg(protocol::CommandTable::name(c),
                                         protocol::CommandTable::codeText(quint8(c)));
}

QString DriveText::failure(const bus::RequestResult &r)
{
    const QString what = command(r.request.command);
    switch (r.status) {
    case bus::RequestStatus::Ok:
        return QString();
    case bus::RequestStatus::Timeout:
        return tr("%1: drive %2 did not answer.").arg(what).arg(r.request.id);
    case bus::RequestStatus::Disconnected:
        return tr("%1: the bus is not connected.").arg(what);
    case bus::RequestStatus::Cancelled:
        return tr("%1: cancelled (emergency stop or disconnect).").arg(what);
    case bus::RequestStatus::Error:
        return tr("%1: the reply was corrupt (%2).").arg(what, r.reason);
    }
    return what;
}

} // namespace lk::ui
