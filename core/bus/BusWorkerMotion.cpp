// BusWorker's multi-motor torque frame (0x280) and the speed watch's stop: member functions of
// BusWorker kept apart from BusWorker.cpp, which is at the size the house style allows.

#include "BusWorker.h"

#include "BusLog.h"

#include <safety/MultiTorqueGuard.h>

#include <algorithm>
#include <utility>

namespace lk::bus {

using protocol::Command;

bool BusWorker::commands(const Pending &p, int id)
{
    if (p.req.group.isEmpty())
        return p.req.request.id == id;
    return std::any_of(p.req.group.cbegin(), p.req.group.cend(),
                       [id](const protocol::Request &r) { return r.id == id; });
}

void BusWorker::stopForSpeedWatch(int id, Completion done)
{
    // Drives a multi-motor frame set turning together are stopped together: one past its
    // limit stops the others as well (they may be coupled to it, and the next frame would
    // drive them all again).
    QVector<int> targets{id};
    if (m_multiTorqueIds.contains(id)) {
        for (int other : std::as_const(m_multiTorqueIds)) {
            if (other != id)
                targets.append(other);
        }
        m_multiTorqueIds.clear();
    }
    for (int t : std::as_const(targets)) {
        if (m_setpointDrive == t)
            haltSetpoints(SetpointStopReason::SpeedLimit);
        const auto motionTo = [t](const Pending &p) {
            return commands(p, t) && protocol::CommandTable::info(p.req.request.command).movesMotor;
        };
        cancelQueued(motionTo, RequestStatus::Cancelled,
                     tr("cancelled: drive %1 went past its speed limit").arg(id));
        if (Pending *p = m_wire.inflight(); p && motionTo(*p))
            p->noRetry = true;
    }
    for (int t : std::as_const(targets)) {
        BusRequest stop;
        stop.request.command = Command::MotorStop;
        stop.request.id = static_cast<quint8>(t);
        stop.priority = Priority::Emergency;
        stop.origin = RequestOrigin::Emergency;
        // Its end reaches requestCompleted (ticket 0) as well: whoever follows a drive's
        // motion hears that it was stopped.
        if (t != id) {
            submit(stop, [this](const RequestResult &r) { emit requestCompleted(r); });
            continue;
        }
        submit(stop, [this, done](const RequestResult &r) {
            emit requestCompleted(r);
            done(r);
        });
    }
}

std::optional<QString>
BusWorker::multiTorqueRefusal(const QVector<protocol::Request> &torques) const
{
    // Who is on the bus: every drive that answered or that the user declared.
    QSet<int> onBus = m_motors.answered();
    for (auto it = m_motors.all().cbegin(); it != m_motors.all().cend(); ++it)
        onBus.insert(it.key());
    const safety::MultiTorqueVerdict v = safety::MultiTorqueGuard::check(
        torques, link(),
        [this](int id) {
            safety::MultiTorqueDrive d;
            d.series = m_motors.series(id);
            const auto known = m_motors.all().constFind(id);
            if (known != m_motors.all().cend() && known->generationKnown())
                d.generation = known->generation;
            const auto limits = m_softLimits.constFind(id);
            d.limits =
                limits != m_softLimits.cend() ? *limits : safety::SoftLimits::defaults(d.series);
            return d;
        },
        onBus);
    if (v.allowed())
        return std::nullopt;
    return safety::MultiTorqueGuard::text(v);
}

void BusWorker::submitMultiTorque(quint64 ticket, const MultiTorqueRequest &request,
                                  MultiTorqueCompletion done)
{
    Pending p;
    p.req.ticket = ticket;
    p.req.group = request.torques;
    std::sort(p.req.group.begin(), p.req.group.end(),
              [](const protocol::Request &a, const protocol::Request &b) { return a.id < b.id; });
    if (!p.req.group.isEmpty())
        p.req.request = p.req.group.first();
    p.req.priority = Priority::Operator;
    p.req.retries = 0;
    p.req.origin = RequestOrigin::User;
    p.noRetry = true; // some drives may have acted: a second frame is the caller's decision
    p.groupDone = std::move(done);
    if (refuseListenOnly()) {
        completeMultiTorque(std::move(p), RequestStatus::Error, listenOnlyReason(),
                            SendRefusal::ListenOnly);
        return;
    }
    if (m_shutDown || !isOpen()) {
        const QString why =
            m_link.lastError().isEmpty() ? tr("the bus is not open") : m_link.lastError();
        completeMultiTorque(std::move(p), RequestStatus::Disconnected, why, SendRefusal::None);
        return;
    }
    if (const std::optional<QString> why = multiTorqueRefusal(p.req.group)) {
        completeMultiTorque(std::move(p), RequestStatus::Error, *why, SendRefusal::None);
        return;
    }
    m_queue.push(std::move(p)); // checked again when it goes out
    schedulePump();
}

bool BusWorker::encodeMultiTorque(Pending &p)
{
    // The link or a drive's identity may have changed while it was queued.
    std::optional<QString> why = multiTorqueRefusal(p.req.group);
    if (!why) {
        p.bytes = lk::bus::encodeMultiTorque(p.req.group);
        if (!p.bytes.isEmpty())
            return true;
        why = tr("the multi-motor torque frame could not be encoded; nothing was sent");
    }
    completeMultiTorque(std::move(p), RequestStatus::Error, *why, SendRefusal::None);
    return false;
}

void BusWorker::completeMultiTorque(Pending p, RequestStatus status, const QString &reason,
                                    SendRefusal refusal)
{
    MultiTorqueResult out;
    out.ticket = p.req.ticket;
    out.attempts = p.attempts;
    out.refusal = refusal;
    const bool sent = p.attempts > 0;
    QVector<int> turning;
    for (const protocol::Request &t : std::as_const(p.req.group)) {
        RequestResult r;
        r.ticket = p.req.ticket;
        r.request = t;
        r.priority = p.req.priority;
        r.attempts = p.attempts;
        r.refusal = refusal;
        const auto reply =
            std::find_if(p.groupReplies.cbegin(), p.groupReplies.cend(),
                         [&t](const PendingRequest::GroupReply &g) { return g.reply.id == t.id; });
        if (reply != p.groupReplies.cend()) {
            r.status = RequestStatus::Ok;
            r.reply = reply->reply;
            r.latencyMs = reply->latencyS * 1e3;
        } else {
            // A drive that stayed silent to a frame on the wire timed out; otherwise the
            // frame's own end is its end.
            r.status = sent && status == RequestStatus::Timeout ? RequestStatus::Timeout : status;
            r.reason = reason;
        }
        // As for a torque command: on the wire, the drive may have acted, answered or not.
        m_speedWatch.noteRequestEnded(t, r.status, p.attempts);
        if (sent && SpeedWatch::drives(t))
            turning.append(t.id);
        out.drives.append(r);
    }
    if (sent)
        m_multiTorqueIds = turning;
    out.status = status;
    out.reason = reason;
    // The watch is armed first: a reply to this very frame past the limit trips it.
    for (const PendingRequest::GroupReply &g : std::as_const(p.groupReplies))
        noteReply(g.reply, now(), p);
    qCDebug(lcBus) << "multi-motor torque frame ended:" << requestStatusName(status)
                   << p.groupReplies.size() << "of" << p.req.group.size() << "replies";
    if (p.groupDone)
        p.groupDone(out);
    else
        emit multiTorqueCompleted(out);
}

} // namespace lk::bus
