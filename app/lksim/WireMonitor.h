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
    /// Requests that overlapped a reply only because lksim may have read the request that
    /// asked for it late (it waited for a CPU): not counted as collisions, see WireMonitor.
    qint64 overlapsUnjudged = 0;
    /// The longest silence between two host requests, and how many silences passed 100 ms:
    /// a host that polls without pause shows short ones only, so these show when it paused.
    double longestRequestGapS = 0;
    qint64 requestGapsOver100ms = 0;
    qint64 collisions() const { return collisionsBefore + collisionsDuring; }
};

/// The half-duplex wire as lksim sees it: when each scheduled reply starts and ends, and
/// whether a host request collides with one. A request collides when it arrives after the
/// drive was asked (so it is about to answer) and before that reply's last byte has left, on
/// a real RS485 bus both frames would be corrupted. Times are monotonic seconds.
///
/// lksim times a reply from the moment it read the request. On a loaded machine that read can
/// come late (lksim was busy or waited for a CPU), and the reply is then modelled later than a
/// drive would send it: a host that moved on after the drive's real reply time would seem to
/// collide. Each reply therefore carries how late its request may have been read ("blind"
/// time); a request that overlaps it only within that uncertainty, or that lksim read together
/// with the reply's own request, is an unjudged overlap, logged and counted apart, never a
/// collision.
class WireMonitor {
public:
    /// One collision, described for the log.
    struct Collision {
        bool beforeReply = false; ///< the drive had not begun its reply yet
        int id = 0;               ///< the drive whose reply was hit
        quint8 command = 0;
        double offsetS = 0; ///< beforeReply: until it begins; else: since it began
        double replyS = 0;  ///< the reply's wire time
        /// The overlap lies within how late lksim may have read the reply's request.
        bool unjudged = false;
        double blindS = 0; ///< that lateness bound
        /// How long before this request lksim read the one the reply answers (0: in the
        /// same read); < 0: unknown.
        double sinceAskedS = -1;
        bool sameRead = false; ///< lksim read both requests at once: unjudged
        QString describe() const;
    };

    /// A reply will occupy the wire from `startS` to `endS` (equal without wire-time
    /// emulation: it leaves at once). `blindS`: its request may have arrived this much
    /// earlier than lksim read it, so a drive could have finished the reply that much sooner.
    /// `askedS`: when lksim read the request it answers (< 0: unknown), for the log.
    void replyScheduled(double startS, double endS, int id, quint8 command, double blindS = 0,
                        double askedS = -1);
    /// What a host byte arriving at `nowS` would collide with: a reply due or on the wire
    /// then (replies already sent are forgotten). Nothing is counted here.
    std::optional<Collision> overlapAt(double nowS);
    /// A request from the host ended at `nowS`; `collision`: what its first colliding byte
    /// hit.
    void requestEnded(const std::optional<Collision> &collision, double nowS);

    const WireCounters &counters() const { return m_counters; }

private:
    struct Window {
        double startS = 0;
        double endS = 0;
        int id = 0;
        quint8 command = 0;
        double blindS = 0;
        double askedS = -1;
    };
    std::deque<Window> m_windows; ///< in wire order
    double m_lastRequestS = -1;   ///< when the previous request ended; < 0: none yet
    WireCounters m_counters;
};

} // namespace lk::app
