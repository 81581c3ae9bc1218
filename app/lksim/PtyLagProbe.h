#pragma once

#include "PtyDevice.h"

#include <QtCore/QString>

namespace lk::app {

/// How long the kernel holds bytes written to a pseudo-terminal before the reading side can
/// see them. A pty hands written bytes to a kernel worker thread, which on a loaded machine
/// may wait milliseconds for a CPU; lksim, reading at once, cannot see that wait, and would
/// time a drive's reply from a request the host wrote long before. This probe keeps a canary
/// byte going through a second pty of its own, one every period, and reports how long the
/// canaries in flight around a moment were held: the host's bytes went through the same
/// kernel workers then. Times are monotonic seconds.
class PtyLagProbe {
public:
    /// `periodS`: the least time between two canaries.
    explicit PtyLagProbe(double periodS);
    PtyLagProbe(const PtyLagProbe &) = delete;
    PtyLagProbe &operator=(const PtyLagProbe &) = delete;

    /// Create the probe's pty; on failure returns false and sets errorString().
    bool open();
    QString errorString() const { return m_pty.errorString(); }
    /// Poll this for input: a canary has come through.
    int readFd() const { return m_pty.masterFd(); }
    /// Read what came through and write the next canary when one is due; false on an I/O
    /// error (errorString()).
    bool service(double nowS);
    /// How long from `nowS` until the next canary is due (0: now); a large value while one
    /// is in flight, whose arrival wakes the poll.
    double untilNextSendS(double nowS) const;

    /// How long bytes that became readable at `nowS` may have been held: the age of a
    /// canary still in flight, or the hold of one that came through just before, plus one
    /// period when that shows a hold at all (the host may have written up to a period
    /// before the canary). 0 when the pty is passing bytes at once.
    double heldS(double nowS) const;

    /// The bookkeeping behind heldS(), without I/O (service() calls these).
    void noteSent(double nowS);
    void noteArrived(double nowS);
    qint64 arrivals() const { return m_arrivals; }

private:
    double m_periodS;
    PtyDevice m_pty;            ///< canaries are written to its slave and read from its master
    double m_sentAt = -1;       ///< when the canary in flight was written; < 0: none
    double m_lastSentAt = -1e9; ///< when the last canary was written
    double m_arrivedAt = -1e9;  ///< when the last canary came through
    double m_lastHoldS = 0;     ///< how long the kernel held it
    qint64 m_arrivals = 0;
};

} // namespace lk::app
