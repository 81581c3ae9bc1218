#pragma once

#include <QtCore/QCoreApplication>
#include <QtCore/QMetaType>
#include <QtCore/QString>

namespace lk::bus {

/// How a session uses its link. Active: it is the bus master (scan, poll, command). ListenOnly:
/// it transmits nothing, ever; the port opens read-only and what another master and its drives
/// say is decoded from the one stream both directions share. Only BusSession::takeOver() goes
/// from ListenOnly to Active, and only when the user asked for it.
enum class LinkMode { Active, ListenOnly };

/// Why the bus sent nothing for a call that would have transmitted (RequestResult::refusal,
/// SetpointStop::refusal, ScanSummary::refusal, BusSession::emergencyStopRefused).
enum class SendRefusal {
    None,
    ListenOnly, ///< the session listens only: nothing was sent, 0 bytes written
};

/// "active", "listen_only": the words of lkctl's JSON and the logs.
inline const char *linkModeName(LinkMode mode)
{
    return mode == LinkMode::ListenOnly ? "listen_only" : "active";
}

/// The reason a listen-only refusal carries: "listen-only: nothing was sent" (translated).
inline QString listenOnlyReason()
{
    return QCoreApplication::translate("lk::bus::LinkMode", "listen-only: nothing was sent");
}

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::LinkMode)
Q_DECLARE_METATYPE(lk::bus::SendRefusal)
