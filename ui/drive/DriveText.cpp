#include "DriveText.h"

#include <protocol/Command.h>
#include <safety/DriveLimits.h>
#include <text/CommandTitle.h>
#include <text/VerdictText.h>

namespace lk::ui {

QString DriveText::series(std::optional<protocol::Series> s)
{
    return text::VerdictText::series(s);
}

QString DriveText::fieldError(const protocol::FieldError &e)
{
    // The field and its range are worded once, by FieldError (lkctl prints the same).
    return tr("Refused, nothing sent: %1.").arg(e.message());
}

QString DriveText::motionFailure(const bus::RequestResult &r)
{
    const QString text = failure(r);
    const bool wentOut = r.attempts > 0 && (r.status == bus::RequestStatus::Timeout ||
                                            r.status == bus::RequestStatus::Error);
    if (!wentOut || !protocol::CommandTable::info(r.request.command).movesMotor)
        return text;
    return text + QLatin1Char(' ') +
           tr("It was sent, so drive %1 may have acted on it and may be moving: check it, or "
              "stop it.")
               .arg(r.request.id);
}

QString DriveText::refusal(const safety::Verdict &verdict, std::optional<protocol::Series> series)
{
    // A limit the drive holds itself (lower than the soft one) is named as the drive's.
    return tr("Refused: %1.")
        .arg(verdict.drivesOwn ? safety::DriveLimits::refusal(verdict)
                               : text::VerdictText::verdict(verdict, series));
}

QString DriveText::setpointStop(const bus::SetpointStop &stop,
                                std::optional<protocol::Series> series)
{
    if (stop.reason == bus::SetpointStopReason::Refused)
        return stop.fieldError ? fieldError(*stop.fieldError) : refusal(stop.verdict, series);
    return stopReason(stop.reason);
}

QString DriveText::stopReason(bus::SetpointStopReason reason)
{
    using Reason = bus::SetpointStopReason;
    switch (reason) {
    case Reason::Requested:
        return tr("Stopped by the user.");
    case Reason::Replaced:
        return tr("Stopped: another waveform started.");
    case Reason::Refused:
        return tr("Refused: a setpoint broke a limit.");
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
    case Reason::SpeedLimit:
        return tr("Stopped: the drive went past its speed limit; the speed watch sent Motor Stop.");
    }
    return QString();
}

QString DriveText::command(protocol::Command c)
{
    return text::CommandTitle::withCode(c); // the GUI names commands as people do
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
