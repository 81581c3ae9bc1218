#include "PollRunner.h"

#include "BusLog.h"

#include <protocol/Command.h>

#include <algorithm>
#include <cmath>

namespace lk::bus {

PollRunner::PollRunner(const SingleShotTimerFactory &timers, std::function<void()> due,
                       std::function<void()> ended, QObject *parent)
    : QObject(parent), m_ended(std::move(ended))
{
    // It paces the wire: precise.
    m_timer = timers(this, std::move(due), Qt::PreciseTimer);
}

PollRunner::~PollRunner() = default;

void PollRunner::start(const PollPlan &plan, double now, bool linkOpen)
{
    m_poller.setPlan(plan, now);
    m_suspended = !linkOpen;
    emit pollingChanged(m_poller.isActive() && !m_suspended);
}

void PollRunner::stop()
{
    const bool was = m_poller.isActive() && !m_suspended;
    m_poller.clear();
    m_timer->stop();
    m_suspended = false;
    if (was)
        emit pollingChanged(false);
}

void PollRunner::clear()
{
    m_poller.clear();
    m_timer->stop();
}

void PollRunner::setSuspended(bool suspended)
{
    if (!m_poller.isActive() || m_suspended == suspended)
        return;
    m_suspended = suspended;
    if (suspended)
        m_timer->stop();
    emit pollingChanged(!suspended);
}

void PollRunner::noteAnswer(const RequestResult &res)
{
    // Only a reply or its absence says something about the drive; a closed link says nothing.
    if (res.status != RequestStatus::Ok && res.status != RequestStatus::Timeout)
        return;
    const int id = res.request.id;
    const protocol::Command command = res.request.command;
    if (!m_poller.noteAnswer(id, command, res.ok()))
        return;
    qCInfo(lcBus,
           "drive %d answers its other polls but left %s (0x%02X) unanswered %d times in a row: "
           "not polled any more on this connection (a series without it, e.g. 0x9D on MS, while "
           "the drive's series is not known)",
           id, qPrintable(protocol::CommandTable::name(command)), unsigned(command),
           UnansweredPolls::kMisses);
}

std::optional<PendingRequest> PollRunner::next(double now)
{
    if (!m_poller.hasWork())
        return std::nullopt;
    const std::optional<protocol::Request> r =
        m_suspended || !m_poller.isActive() ? m_poller.nextWatch() : m_poller.next(now);
    if (r) {
        PendingRequest p;
        p.req.request = *r;
        p.req.priority = Priority::Background;
        p.req.retries = 0; // a missed sample is read again next cycle
        p.req.origin = RequestOrigin::Poll;
        p.done = [this](const RequestResult &res) {
            m_poller.completed(res.request.id, res.request.command);
            noteAnswer(res);
            m_ended();
        };
        if (!m_poller.lastWasWatch()) { // a watch poll answers no round of the plan
            p.pollCycle = m_poller.cycle();
            p.pollCycleStart = m_poller.cycleStart();
        }
        return p;
    }
    if (m_suspended || !m_poller.isActive())
        return std::nullopt; // a watch poll's end pumps again
    const double due = m_poller.nextDueTime(now);
    if (std::isfinite(due))
        m_timer->start(std::max(0, static_cast<int>(std::ceil((due - now) * 1e3))));
    return std::nullopt;
}

} // namespace lk::bus
