#pragma once

#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include <deque>
#include <optional>

namespace lk::app {

/// What lksim counted on its simulated wire: host requests, drive replies and collisions.
struct WireCounters {
    qint64 requests = 0;         ///< well-formed requests from the host
    qint64 replies = 0;          ///< replies the drives put on the wire
    qint64 collisionsBefore = 0; ///< requests while a drive was about to answer
    qint64 collisionsDuring = 0; ///< requests while a reply was on the wire
    qint64 collisions() const { return collisionsBefore + collisionsDuring; }
};

/// The half-duplex wire as lksim sees it: when each scheduled reply starts and ends, and
/// whether a host request collides with one. A request collides when it arrives after the
/// drive was asked (so it is about to answer) and before that reply's last byte has left, on
/// a real RS485 bus both frames would be corrupted. Times are monotonic seconds.
class WireMonitor {
public:
    /// One collision, described for the log.
    struct Collision {
        bool beforeReply = false; ///< the drive had not begun its reply yet
        int id = 0;               ///< the drive whose reply was hit
        quint8 command = 0;
        double offsetS = 0; ///< beforeReply: until it begins; else: since it began
        double replyS = 0;  ///< the reply's wire time
        QString describe() const;
    };

    /// A reply will occupy the wire from `startS` to `endS` (equal without wire-time
    /// emulation: it leaves at once).
    void replyScheduled(double startS, double endS, int id, quint8 command);
    /// What a host byte arriving at `nowS` would collide with: a reply due or on the wire
    /// then (replies already sent are forgotten). Nothing is counted here.
    std::optional<Collision> overlapAt(double nowS);
    /// A request from the host ended; `collision`: what its first colliding byte hit.
    void requestEnded(const std::optional<Collision> &collision);

    const WireCounters &counters() const { return m_counters; }

private:
    struct Window {
        double startS = 0;
        double endS = 0;
        int id = 0;
        quint8 command = 0;
    };
    std::deque<Window> m_windows; ///< in wire order
    WireCounters m_counters;
};

} // namespace lk::app
