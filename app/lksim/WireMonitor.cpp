#include "WireMonitor.h"

#include <protocol/Command.h>

namespace lk::app {

QString WireMonitor::Collision::describe() const
{
    const QString reply = QStringLiteral("ID %1's reply to %2")
                              .arg(id)
                              .arg(protocol::CommandTable::codeText(command));
    if (beforeReply)
        return QStringLiteral("before %1 began (due in %2 ms)")
            .arg(reply)
            .arg(offsetS * 1e3, 0, 'f', 3);
    return QStringLiteral("%1 ms into %2 (%3 ms on the wire)")
        .arg(offsetS * 1e3, 0, 'f', 3)
        .arg(reply)
        .arg(replyS * 1e3, 0, 'f', 3);
}

void WireMonitor::replyScheduled(double startS, double endS, int id, quint8 command)
{
    ++m_counters.replies;
    m_windows.push_back(Window{startS, endS, id, command});
}

std::optional<WireMonitor::Collision> WireMonitor::overlapAt(double nowS)
{
    while (!m_windows.empty() && m_windows.front().endS <= nowS)
        m_windows.pop_front();
    if (m_windows.empty())
        return std::nullopt;
    // The reply on the wire now, else the next one to start (the drive is about to answer).
    const Window &hit = m_windows.front();
    Collision c;
    c.beforeReply = nowS < hit.startS;
    c.id = hit.id;
    c.command = hit.command;
    c.offsetS = c.beforeReply ? hit.startS - nowS : nowS - hit.startS;
    c.replyS = hit.endS - hit.startS;
    return c;
}

void WireMonitor::requestEnded(const std::optional<Collision> &collision)
{
    ++m_counters.requests;
    if (collision)
        ++(collision->beforeReply ? m_counters.collisionsBefore : m_counters.collisionsDuring);
}

} // namespace lk::app
