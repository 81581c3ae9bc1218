#pragma once

#include "MultiTorque.h"
#include "Priority.h"
#include "RequestResult.h"

#include <protocol/Request.h>

#include <QtCore/QByteArray>

#include <functional>

namespace lk::bus {

/// Where a queued request came from: decides who hears about its end.
enum class RequestOrigin { User, Emergency, Poll, Scan, Setpoint };

/// A request as queued on the bus thread.
struct BusRequest {
    quint64 ticket = 0;
    protocol::Request request;
    Priority priority = Priority::Operator;
    int retries = -1; ///< < 0: BusConfig::retries
    RequestOrigin origin = RequestOrigin::User;
    /// > 0: reply timeout of the first attempt, seconds, instead of the adaptive one. Scan
    /// probes and emergency stops use a short one so that silent IDs cost little; retries
    /// always wait the adaptive timeout.
    double firstTimeoutS = 0;
    /// Non-empty: the old CAN generation's multi-motor torque frame (0x280), one torque
    /// request per drive, ascending IDs 1..4; `request` is the first of them. It waits on the
    /// wire for every drive's reply and is never sent again.
    QVector<protocol::Request> group;
};

/// A request waiting in a queue or on the wire, with its progress and its listener.
struct PendingRequest {
    using Completion = std::function<void(const RequestResult &)>;
    BusRequest req;
    QByteArray bytes; ///< the encoded frame
    int attempts = 0;
    bool noRetry = false;  ///< set by emergency stop on an in-flight motion command
    Completion done;       ///< empty: BusWorker::requestCompleted
    quint64 pollCycle = 0; ///< a poll: its round (PollScheduler::cycle()); else 0
    double pollCycleStart = 0;
    /// A multi-motor frame (BusRequest::group): the replies taken so far, in arrival order.
    struct GroupReply {
        protocol::Reply reply;
        double latencyS = 0;
    };
    QVector<GroupReply> groupReplies;
    /// A multi-motor frame's listener (empty: BusWorker::multiTorqueCompleted); `done` is not
    /// used for it.
    std::function<void(const MultiTorqueResult &)> groupDone;
};

} // namespace lk::bus
