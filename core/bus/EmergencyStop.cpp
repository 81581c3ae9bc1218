#include "EmergencyStop.h"

#include <algorithm>

namespace lk::bus {

EmergencyStop::EmergencyStop(quint64 ticket, StopTargets targets, int retries,
                             protocol::Command halt)
    : m_ticket(ticket), m_halt(halt), m_targets(std::move(targets)),
      m_retries(std::max(0, retries)), m_remaining(m_targets.all().size())
{
}

QVector<BusRequest> EmergencyStop::requests() const
{
    QVector<BusRequest> out;
    // With nothing known (lkctl, before any scan) every ID may be a drive: all are retried.
    const bool retryAll = m_targets.first.isEmpty();
    for (int id : m_targets.all()) {
        BusRequest r;
        r.ticket = m_ticket;
        r.request.command = m_halt;
        r.request.id = static_cast<quint8>(id);
        r.priority = Priority::Emergency;
        r.retries = retryAll || m_targets.first.contains(id) ? m_retries : 0;
        r.origin = RequestOrigin::Emergency;
        out.append(r);
    }
    return out;
}

bool EmergencyStop::record(const RequestResult &result)
{
    (result.ok() ? m_acknowledged : m_silent).append(result.request.id);
    if (result.attempts == 0)
        m_unsent.append(result.request.id);
    if (--m_remaining > 0)
        return false;
    // Retries go to the back of the lane, so completions come in no useful order.
    std::sort(m_acknowledged.begin(), m_acknowledged.end());
    std::sort(m_silent.begin(), m_silent.end());
    std::sort(m_unsent.begin(), m_unsent.end());
    return true;
}

} // namespace lk::bus
