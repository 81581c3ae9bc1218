#pragma once

#include "BusStatistics.h"
#include "LatencyWindow.h"

#include <protocol/StreamParser.h>

#include <QtCore/QMap>

namespace lk::bus {

/// Counts bus events on the bus thread and turns them into BusStatistics snapshots.
/// Per-frame faults are counted here and nowhere else: they are never fatal.
class StatisticsCollector {
public:
    void reset();

    void requestSent(int id, bool retry);
    void replyReceived(int id, double latencyS);
    void timedOut(int id);
    /// A scan or stop probe of `id`, which never answered, stayed silent (see silentProbes).
    void silentProbe() { ++m_bus.stats.silentProbes; }
    void lateReply(int id);
    void unexpectedFrame(int id);
    void undecodable(int id); ///< a matching frame that did not decode
    void localEcho() { ++m_localEchoes; }
    void canErrorFrame() { ++m_canErrorFrames; } ///< CAN: an error frame on the bus
    void otherFrame() { ++m_otherFrames; }       ///< CAN: a frame of no drive (0x280, others)
    /// A parser fault: checksum/length/unknown go to the ID when the header was readable.
    void parseFault(const protocol::ParseEvent &event);

    /// Snapshot; transactions/s cover the time since the previous snapshot.
    BusStatistics snapshot(double now);
    /// The bus-wide counters now (latency and rate are filled in by snapshot() only).
    const LinkStatistics &busCounters() const { return m_bus.stats; }

private:
    struct Counters {
        LinkStatistics stats;
        LatencyWindow latency;
        quint64 completedAtLastSnapshot = 0;
    };
    Counters &perId(int id);
    static quint64 completed(const LinkStatistics &s) { return s.replies + s.timeouts; }
    static void finish(Counters &c, double dt);

    Counters m_bus;
    QMap<int, Counters> m_ids;
    quint64 m_localEchoes = 0;
    quint64 m_canErrorFrames = 0;
    quint64 m_otherFrames = 0;
    double m_lastSnapshot = -1;
};

} // namespace lk::bus
