#include "DriveText.h"

#include <protocol/Command.h>
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
