#pragma once

#include "LinkMode.h"

#include <protocol/Series.h>

#include <QtCore/QMap>
#include <QtCore/QMetaType>

namespace lk::bus {

/// Latency figures over a bounded window of recent replies, in milliseconds.
struct LatencySummary {
    int samples = 0; ///< replies in the window (0: the figures below mean nothing)
    double minMs = 0;
    double medianMs = 0;
    double p95Ms = 0;
    double maxMs = 0;
};

/// Counters for one drive or for the whole bus. Counters only grow during a session.
struct LinkStatistics {
    quint64 requests = 0; ///< attempts put on the wire (retries count again)
    quint64 replies = 0;  ///< matching replies that decoded
    quint64 timeouts = 0; ///< attempts that got no reply in time
    /// Scan and emergency-stop probes of IDs that never answered on this connection: the
    /// silence expected from an ID with no drive, not counted as timeouts (bus level only).
    quint64 silentProbes = 0;
    quint64 retries = 0;          ///< attempts beyond the first
    quint64 checksumErrors = 0;   ///< bad header or data checksum
    quint64 garbageBytes = 0;     ///< bytes skipped while resynchronising (bus level only)
    quint64 parseErrors = 0;      ///< bad length, unknown command, undecodable reply
    quint64 lateReplies = 0;      ///< a reply to a request that had already timed out
    quint64 unexpectedFrames = 0; ///< valid frames nobody asked for (other master? stray echo)
    LatencySummary latency;
    double transactionsPerSecond = 0; ///< completed attempts per second, recent
};

/// A snapshot of the bus statistics (BusSession::statisticsUpdated, ~2 Hz).
struct BusStatistics {
    double time = 0; ///< seconds since the session started
    int baud = 0;    ///< the bit rate on CAN
    protocol::Link link = protocol::Link::Rs485;
    LinkMode mode = LinkMode::Active;
    quint64 listenOnlyRefusals = 0; ///< calls that would have transmitted, refused (ListenOnly)
    LinkStatistics bus;
    QMap<int, LinkStatistics> perId;
    quint64 localEchoes = 0;    ///< our own request read back (adapter echo), skipped
    quint64 canErrorFrames = 0; ///< CAN: error frames the controller reported
    quint64 otherFrames = 0;    ///< CAN: frames of no drive (other devices, the 0x280 frame)
    double timeoutMarginMs = 0; ///< the adaptive margin added to the wire time just now
    /// Bus limit in transactions/s for the active poll mix (0: no polling), with the
    /// turnaround below: what the drives and the link were measured to need, not a guess.
    double pollLimitPerSecond = 0;
    double pollCycleLimitHz = 0; ///< full poll rounds per second at that limit
    double turnaroundMs = 0;     ///< measured (min latency - wire time) or the assumed 0.5 ms
    bool turnaroundMeasured = false;
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::BusStatistics)
