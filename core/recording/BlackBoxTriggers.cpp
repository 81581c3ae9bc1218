#include "BlackBoxTriggers.h"

namespace lk::recording {

const char *blackBoxReasonName(BlackBoxTriggers::Reason reason)
{
    switch (reason) {
    case BlackBoxTriggers::Reason::EmergencyStop:
        return "emergency stop";
    case BlackBoxTriggers::Reason::FaultFlag:
        return "fault flag";
    case BlackBoxTriggers::Reason::LinkLost:
        return "link lost";
    case BlackBoxTriggers::Reason::TimeoutBurst:
        return "timeout burst";
    }
    return "?";
}

std::optional<BlackBoxTriggers::Reason> BlackBoxTriggers::fire(Reason reason, qint64 ns)
{
    if (reason != Reason::EmergencyStop && m_lastSaveNs &&
        ns - *m_lastSaveNs < m_settings.holdoffNs)
        return std::nullopt;
    m_lastSaveNs = ns;
    return reason;
}

std::optional<BlackBoxTriggers::Reason> BlackBoxTriggers::emergencyStop(qint64 ns)
{
    return fire(Reason::EmergencyStop, ns);
}

std::optional<BlackBoxTriggers::Reason> BlackBoxTriggers::faultFlags(int id, quint32 flags,
                                                                     qint64 ns)
{
    const quint32 before = m_flags.value(id, 0);
    m_flags.insert(id, flags);
    if ((flags & ~before) == 0)
        return std::nullopt;
    return fire(Reason::FaultFlag, ns);
}

std::optional<BlackBoxTriggers::Reason> BlackBoxTriggers::linkLost(qint64 ns)
{
    return fire(Reason::LinkLost, ns);
}

std::optional<BlackBoxTriggers::Reason> BlackBoxTriggers::timeout(qint64 ns)
{
    m_timeouts.append(ns);
    m_timeouts.removeIf([&](qint64 t) { return t <= ns - m_settings.timeoutBurstNs; });
    if (m_timeouts.size() < m_settings.timeoutBurstCount)
        return std::nullopt;
    const auto reason = fire(Reason::TimeoutBurst, ns);
    if (reason)
        m_timeouts.clear(); // the next burst counts afresh
    return reason;
}

} // namespace lk::recording
