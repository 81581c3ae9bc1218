#include "UnansweredPolls.h"

#include <motor/SeriesLimits.h>
#include <protocol/Series.h>

namespace lk::bus {

using protocol::Command;

bool UnansweredPolls::someSeriesLacks(Command command)
{
    using protocol::Series;
    for (Series s : {Series::MS, Series::MF, Series::MG, Series::MH}) {
        if (!motor::supports(s, command))
            return true;
    }
    return false;
}

bool UnansweredPolls::noteResult(int id, Command command, bool answered)
{
    if (answered) {
        m_misses.remove(key(id, command));
        for (auto it = m_misses.begin(); it != m_misses.end(); ++it) {
            if (it.key() >> 8 == id)
                it->otherAnswered = true;
        }
        return false;
    }
    if (!someSeriesLacks(command) || isMuted(id, command))
        return false;
    Misses &m = m_misses[key(id, command)];
    if (m.count == 0)
        m.otherAnswered = false; // a new run of misses: the drive must answer something during it
    ++m.count;
    if (m.count < kMisses || !m.otherAnswered)
        return false;
    m_misses.remove(key(id, command));
    m_muted.insert(key(id, command));
    return true;
}

void UnansweredPolls::clear()
{
    m_misses.clear();
    m_muted.clear();
}

} // namespace lk::bus
