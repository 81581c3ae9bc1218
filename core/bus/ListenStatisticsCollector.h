#pragma once

#include "LatencyWindow.h"
#include "ListenStatistics.h"
#include "PassivePairing.h"

#include <protocol/FrameParser.h>

#include <QtCore/QMap>

namespace lk::bus {

/// Counts what a listen-only session sees of another master (ListenStatistics): the pairing's
/// counters, and per drive and command what it sent, what was answered and how fast. Rates
/// are over the time between two snapshots. Pure, on the bus thread.
class ListenStatisticsCollector {
public:
    /// What the bytes are: RS485 bytes, or CAN records (the bus load counts their frames).
    void setLink(protocol::Link link) { m_link = link; }
    void addBytes(qsizetype n) { m_bytes += static_cast<quint64>(n); }
    void canErrorFrame() { ++m_canErrorFrames; }
    void otherFrame() { ++m_otherFrames; }
    void request(const protocol::Frame &request);
    void reply(const protocol::Frame &reply, const std::optional<protocol::Frame> &request,
               qint64 latencyNs);
    void unanswered(const protocol::Frame &request);
    void fault(const protocol::ParseEvent &event);
    /// The statistics now, `time` seconds into the session; rates since the last snapshot.
    ListenStatistics snapshot(double time, int baud, const PassivePairing::Counts &counts);
    void reset();

private:
    double busLoad(quint64 bytes, int baud, double dt) const;

    struct Drive {
        ListenDriveStatistics stats;
        LatencyWindow latency;
        quint64 requestsAtSnapshot = 0;
    };
    QMap<int, Drive> m_drives;
    QMap<quint8, ListenCommandStatistics> m_commands;
    QMap<quint8, quint64> m_commandRequestsAtSnapshot;
    protocol::Link m_link = protocol::Link::Rs485;
    quint64 m_bytes = 0;
    quint64 m_canErrorFrames = 0;
    quint64 m_otherFrames = 0;
    quint64 m_checksumErrors = 0;
    quint64 m_garbageBytes = 0;
    quint64 m_requestsAtSnapshot = 0;
    quint64 m_bytesAtSnapshot = 0;
    double m_snapshotTime = 0;
};

} // namespace lk::bus
