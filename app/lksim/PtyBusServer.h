#pragma once

#include "StatsFile.h"
#include "WireMonitor.h"

#include <QtCore/QByteArray>

#include <atomic>
#include <deque>
#include <optional>

namespace lk::sim {
class SimBus;
struct SimReply;
} // namespace lk::sim

namespace lk::app {

class PtyDevice;

/// Serves a SimBus on a pseudo-terminal with sub-millisecond reply timing.
///
/// Qt timers have millisecond resolution, too coarse for a 1 Mbps bus (a whole transaction
/// takes ~0.7 ms), so this is a plain ppoll() loop on a monotonic clock. With wire-time
/// emulation a reply's last byte leaves at: request written + request wire time + the
/// drive's turnaround + reply wire time, and replies never overlap (half duplex). A request
/// that arrives while a reply is due or on the wire is a collision (WireMonitor): counted,
/// logged on standard error and in the stats file.
class PtyBusServer {
public:
    struct Options {
        int baud = 115200;
        bool emulateWireTime = false;
        bool verbose = false; ///< log every frame to standard error
        /// Spin instead of sleeping while the bus is busy (a request in the last 20 ms): a
        /// sleeping process wakes 30-100 us late, a third of a 1 Mbps transaction, where a
        /// real adapter has no such delay. Costs one CPU core while the host is polling.
        bool busyPoll = false;
        /// The host receives each reply this long after its last byte left the wire (a USB
        /// adapter's latency timer). The wire itself is free meanwhile.
        double adapterLatencyS = 0;
        /// > 0: time how long the kernel holds the host's bytes with a canary through a
        /// second pty this often (PtyLagProbe), and widen the unjudged margin by it.
        double ptyLagProbePeriodS = 0;
        QString statsFile; ///< empty: none
    };

    PtyBusServer(PtyDevice &pty, sim::SimBus &bus, const Options &options);

    /// Serve until `stop` becomes true; rewrite the stats file whenever `dumpStats` is raised.
    /// Returns 0, or 1 after an I/O error.
    int run(const std::atomic<bool> &stop, std::atomic<bool> &dumpStats);

    const WireCounters &counters() const { return m_wire.counters(); }
    /// Write the stats file now (if there is one); false with a message on standard error.
    bool writeStats(bool running);
    /// V2.35 0xA4 replies sent with a bad data checksum (--bad-checksum-pct).
    qint64 badChecksumReplies() const;
    static double monotonicSeconds();

private:
    struct Pending {
        double due = 0; ///< monotonic seconds at which the bytes are written to the pty
        QByteArray bytes;
    };
    /// Host bytes read at `now`; `blindS`: how long before that they may have arrived.
    void onInput(const QByteArray &bytes, double now, double blindS);
    void schedule(const sim::SimReply &reply, double now, double blindS);
    void noteRequestEnd(double now);
    bool flushDue(double now);
    double requestWireSeconds(quint8 command) const;
    void log(const char *direction, const QByteArray &bytes) const;

    PtyDevice &m_pty;
    sim::SimBus &m_bus;
    Options m_options;
    std::deque<Pending> m_pending; ///< in due order
    double m_wireFreeAt = 0;       ///< when the last scheduled reply finishes on the wire
    double m_lastInputAt = -1;     ///< when the host last wrote (monotonic seconds)
    double m_lastAdvanceAt = 0;    ///< when the drives' physics last moved on
    WireMonitor m_wire;
    StatsFile m_stats;
    QByteArray m_frameBytes;                           ///< host bytes since the last frame end
    std::optional<WireMonitor::Collision> m_collision; ///< what those bytes collided with
    qint64 m_frameEvents = 0; ///< host frames and faults the SimBus has parsed
};

} // namespace lk::app
