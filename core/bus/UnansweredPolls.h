#pragma once

#include <protocol/Command.h>

#include <QtCore/QHash>
#include <QtCore/QSet>

namespace lk::bus {

/// Learns which polls a drive leaves unanswered while it answers its others: a command that
/// some series lack (0x9D on MS), polled while the drive's series is unknown (a CAN drive has
/// no model read; the user has not chosen its series yet). After kMisses timeouts in a row,
/// with another poll of the same drive answered since the first of them, the pair is left out
/// of polling until clear(): each of those polls cost a timeout and the quiet after it, tens
/// a second, and buried the timeouts that mean something. A drive that answers nothing (cut
/// off, powered down) is never muted this way, and neither is a command every series answers.
class UnansweredPolls {
public:
    /// In a row. A bus that loses 1 % of its replies loses five in a row once in 10^10 polls;
    /// three would have muted a drive's phase currents within the hour at the full poll rate.
    static constexpr int kMisses = 5;

    /// A poll of (id, command) ended. True when this result made the pair muted.
    bool noteResult(int id, protocol::Command command, bool answered);
    bool isMuted(int id, protocol::Command command) const
    {
        return !m_muted.isEmpty() && m_muted.contains(key(id, command));
    }
    bool isEmpty() const { return m_muted.isEmpty(); }
    void clear();

    /// Whether some series does not answer `command` (only such commands are ever muted).
    static bool someSeriesLacks(protocol::Command command);

private:
    struct Misses {
        int count = 0;
        bool otherAnswered = false; ///< another poll of the drive answered since the first miss
    };
    static int key(int id, protocol::Command command)
    {
        return (id << 8) | static_cast<int>(command);
    }

    QHash<int, Misses> m_misses;
    QSet<int> m_muted;
};

} // namespace lk::bus
