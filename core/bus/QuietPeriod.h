#pragma once

#include <QtCore/QtGlobal>

namespace lk::bus {

/// Half duplex after a timeout: the drive may still be answering, so the bus transmits
/// nothing until the wire has been silent long enough. Bytes that arrive meanwhile push the
/// end back (someone is still talking); the late reply to the request that timed out, once it
/// has come whole with nothing after it, ends the wait at once (the wire is free again).
/// Pure bookkeeping on the worker's clock (nanoseconds); the worker owns the timer.
class QuietPeriod {
public:
    /// Request (`id`, `command`) got no reply: hold until `untilNs`; bytes arriving before
    /// then hold until `lengthNs` after them.
    void begin(qint64 untilNs, qint64 lengthNs, int id, quint8 command);
    /// A chunk of bytes arrived at `nowNs` while no request was waiting for its reply.
    void bytesArrived(qint64 nowNs);
    /// A new chunk of bytes is about to be parsed.
    void chunkStarted() { m_answered = false; }
    /// A frame parsed from the chunk came too late for its request: if it is the reply the
    /// quiet period waits for, the chunk may end it (endIfAnswered()).
    void lateFrameParsed(int id, quint8 command);
    /// The chunk is parsed: when it held the awaited late reply and nothing follows it
    /// (`parserIdle`), the quiet period ends; true if it did.
    bool endIfAnswered(bool parserIdle, qint64 nowNs);

    bool isQuiet(qint64 nowNs) const { return m_untilNs > nowNs; }
    /// Hold no later than `untilNs` (bytes arriving from now on still extend it).
    void shortenTo(qint64 untilNs) { m_untilNs = qMin(m_untilNs, untilNs); }
    quint8 command() const { return m_command; } ///< of the request that got no reply
    /// Nanoseconds left (<= 0: transmit).
    qint64 leftNs(qint64 nowNs) const { return m_untilNs - nowNs; }

private:
    qint64 m_untilNs = 0;  ///< no transmission before this
    qint64 m_lengthNs = 0; ///< the hold after bytes that arrive meanwhile
    int m_id = -1;         ///< the timed-out request whose late reply ends it early
    quint8 m_command = 0;
    bool m_answered = false; ///< that late reply was parsed in the current chunk
};

} // namespace lk::bus
