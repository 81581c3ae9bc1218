#include "QuietPeriod.h"

#include <algorithm>

namespace lk::bus {

void QuietPeriod::begin(qint64 untilNs, qint64 lengthNs, int id, quint8 command)
{
    m_untilNs = untilNs;
    m_lengthNs = lengthNs;
    m_id = id;
    m_command = command;
}

void QuietPeriod::bytesArrived(qint64 nowNs)
{
    if (nowNs >= m_untilNs)
        return; // over already: bytes now are a new conversation, not the old one's tail
    m_untilNs = std::max(m_untilNs, nowNs + m_lengthNs);
}

void QuietPeriod::lateFrameParsed(int id, quint8 command)
{
    m_answered = m_answered || (id == m_id && command == m_command);
}

bool QuietPeriod::endIfAnswered(bool parserIdle, qint64 nowNs)
{
    if (!m_answered || !parserIdle || !isQuiet(nowNs))
        return false;
    m_untilNs = 0;
    return true;
}

} // namespace lk::bus
