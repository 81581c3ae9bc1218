#include "ListenStatisticsCollector.h"

#include "BusTiming.h"
#include "LinkTiming.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecord.h>

namespace lk::bus {

void ListenStatisticsCollector::request(const protocol::Frame &request)
{
    ++m_drives[request.id].stats.requests;
    ++m_commands[request.command].requests;
}

void ListenStatisticsCollector::reply(const protocol::Frame &reply,
                                      const std::optional<protocol::Frame> &request,
                                      qint64 latencyNs)
{
    Drive &d = m_drives[reply.id];
    ++d.stats.replies;
    if (request)
        d.latency.add(static_cast<double>(latencyNs) * 1e-9);
}

void ListenStatisticsCollector::unanswered(const protocol::Frame &request)
{
    ++m_drives[request.id].stats.unanswered;
}

void ListenStatisticsCollector::fault(const protocol::ParseEvent &event)
{
    if (event.error == protocol::ParseError::BadHeaderChecksum ||
        event.error == protocol::ParseError::BadDataChecksum)
        ++m_checksumErrors;
    else if (event.error == protocol::ParseError::Garbage)
        m_garbageBytes += static_cast<quint64>(event.bytes.size());
}

double ListenStatisticsCollector::busLoad(quint64 bytes, int baud, double dt) const
{
    if (baud <= 0 || dt <= 0)
        return 0;
    const double bits = m_link == protocol::Link::Can
                            ? static_cast<double>(bytes / protocol::CanRecord::kSize) *
                                  LinkTiming::canFrameBits(protocol::can::kDataSize)
                            : static_cast<double>(bytes) * BusTiming::kBitsPerByte;
    return bits / (baud * dt);
}

ListenStatistics ListenStatisticsCollector::snapshot(double time, int baud,
                                                     const PassivePairing::Counts &counts)
{
    ListenStatistics s;
    s.time = time;
    s.periodS = time - m_snapshotTime;
    s.baud = baud;
    s.requests = counts.requests;
    s.replies = counts.replies;
    s.paired = counts.paired;
    s.unanswered = counts.unanswered;
    s.orphanReplies = counts.orphanReplies;
    s.ambiguous = counts.ambiguous;
    s.corruptReplies = counts.corruptReplies;
    s.brokenPairs = counts.brokenPairs;
    s.checksumErrors = m_checksumErrors;
    s.garbageBytes = m_garbageBytes;
    s.bytes = m_bytes;
    s.canErrorFrames = m_canErrorFrames;
    s.otherFrames = m_otherFrames;
    const double dt = s.periodS;
    const auto rate = [dt](quint64 now, quint64 before) {
        return dt > 0 ? static_cast<double>(now - before) / dt : 0.0;
    };
    s.requestsPerSecond = rate(counts.requests, m_requestsAtSnapshot);
    s.busLoad = busLoad(m_bytes - m_bytesAtSnapshot, baud, dt);
    for (auto it = m_drives.begin(); it != m_drives.end(); ++it) {
        Drive &d = it.value();
        d.stats.requestsPerSecond = rate(d.stats.requests, d.requestsAtSnapshot);
        d.stats.latency = d.latency.summaryMs();
        d.requestsAtSnapshot = d.stats.requests;
        s.perDrive.insert(it.key(), d.stats);
    }
    for (auto it = m_commands.begin(); it != m_commands.end(); ++it) {
        quint64 &before = m_commandRequestsAtSnapshot[it.key()];
        it->requestsPerSecond = rate(it->requests, before);
        before = it->requests;
        s.perCommand.insert(it.key(), it.value());
    }
    m_requestsAtSnapshot = counts.requests;
    m_bytesAtSnapshot = m_bytes;
    m_snapshotTime = time;
    return s;
}

void ListenStatisticsCollector::reset()
{
    const protocol::Link link = m_link;
    *this = ListenStatisticsCollector{};
    m_link = link;
}

} // namespace lk::bus
