#include "WireMonitor.h"

#include <protocol/Command.h>

#include <algorithm>

namespace lk::app {

QString WireMonitor::Collision::describe() const
{
    const QString reply = QStringLiteral("ID %1's reply to %2")
                              .arg(id)
                              .arg(protocol::CommandTable::codeText(command));
    QString text = beforeReply ? QStringLiteral("before %1 began (due in %2 ms)")
                                     .arg(reply)
                                     .arg(offsetS * 1e3, 0, 'f', 3)
                               : QStringLiteral("%1 ms into %2 (%3 ms on the wire)")
                                     .arg(offsetS * 1e3, 0, 'f', 3)
                                     .arg(reply)
                                     .arg(replyS * 1e3, 0, 'f', 3);
    if (!unjudged && sinceAskedS >= 0)
        // What a collision is judged on, for whoever reads the log: how far apart the two
        // requests came, and how late lksim may have read the first.
        text += QStringLiteral("; lksim read ID %1's request %2 ms before this one, at most "
                               "%3 ms late")
                    .arg(id)
                    .arg(sinceAskedS * 1e3, 0, 'f', 3)
                    .arg(blindS * 1e3, 0, 'f', 3);
    if (sameRead)
        text += QStringLiteral("; it came in the same read as ID %1's request, so lksim cannot "
                               "tell how long the kernel held that one")
                    .arg(id);
    else if (unjudged)
        text += QStringLiteral("; lksim may have read ID %1's request up to %2 ms late (it was "
                               "busy, waited for a CPU or the kernel held the bytes in the pty), "
                               "so a drive could have finished "
                               "that reply in time")
                    .arg(id)
                    .arg(blindS * 1e3, 0, 'f', 3);
    return text;
}

void WireMonitor::replyScheduled(double startS, double endS, int id, quint8 command, double blindS,
                                 double askedS)
{
    ++m_counters.replies;
    m_windows.push_back(Window{startS, endS, id, command, blindS, askedS});
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
    // Had the request come as early as it may have, the reply would have ended blindS sooner.
    c.blindS = hit.blindS;
    c.sinceAskedS = hit.askedS >= 0 ? nowS - hit.askedS : -1;
    // Read together with the request the reply answers: lksim has no time at all for that
    // one, only that it came no later than this, which the kernel may have held for as long
    // as the host waited for the reply.
    c.sameRead = c.sinceAskedS == 0;
    c.unjudged = nowS >= hit.endS - hit.blindS || c.sameRead;
    return c;
}

void WireMonitor::requestEnded(const std::optional<Collision> &collision, double nowS)
{
    ++m_counters.requests;
    if (m_lastRequestS >= 0) {
        const double gap = nowS - m_lastRequestS;
        m_counters.longestRequestGapS = std::max(m_counters.longestRequestGapS, gap);
        if (gap > 0.1)
            ++m_counters.requestGapsOver100ms;
    }
    m_lastRequestS = nowS;
    if (!collision)
        return;
    if (collision->unjudged)
        ++m_counters.overlapsUnjudged;
    else
        ++(collision->beforeReply ? m_counters.collisionsBefore : m_counters.collisionsDuring);
}

} // namespace lk::app
