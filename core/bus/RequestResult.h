#pragma once

#include "LinkMode.h"
#include "Priority.h"

#include <protocol/Reply.h>
#include <protocol/Request.h>

#include <QtCore/QMetaType>
#include <QtCore/QString>

#include <optional>

namespace lk::bus {

/// How a request ended. Every request ends exactly once.
enum class RequestStatus {
    Ok,           ///< a matching reply arrived and decoded
    Timeout,      ///< no reply after all attempts (also: a command the series does not answer)
    Disconnected, ///< the transport closed or vanished before a reply arrived
    Cancelled,    ///< dropped by emergency stop, cancelScan, stopPolling or close
    Error,        ///< the reply was corrupt or undecodable on the last attempt, or not sent
};
const char *requestStatusName(RequestStatus s); ///< "ok", "timeout", ...

/// The outcome of one request, delivered once (BusSession::requestCompleted).
struct RequestResult {
    quint64 ticket = 0; ///< the number BusSession::send returned
    protocol::Request request;
    Priority priority = Priority::Operator;
    RequestStatus status = RequestStatus::Error;
    std::optional<protocol::Reply> reply; ///< set when status is Ok
    QString reason;                       ///< English detail for anything but Ok ("unplugged", ...)
    double latencyMs = 0;                 ///< write of the last attempt to its reply (Ok only)
    int attempts = 0;                     ///< times the request went on the wire
    /// Set when the bus refused to send it (status Error, attempts 0, nothing written).
    SendRefusal refusal = SendRefusal::None;
    bool ok() const { return status == RequestStatus::Ok; }
    bool refused() const { return refusal != SendRefusal::None; }
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::RequestResult)
