#include "StatisticsCollector.h"

namespace lk::bus {

void StatisticsCollector::reset()
{
    m_bus = Counters{};
    m_ids.clear();
    m_localEchoes = 0;
    m_canErrorFrames = 0;
    m_otherFrames = 0;
    m_lastSnapshot = -1;
}

StatisticsCollector::Counters &StatisticsCollector::perId(int id)
{
    return m_ids[id];
}

void StatisticsCollector::requestSent(int id, bool retry)
{
    for (Counters *c : {&m_bus, &perId(id)}) {
        ++c->stats.requests;
        if (retry)
            ++c->stats.retries;
    }
}

void StatisticsCollector::replyReceived(int id, double latencyS)
{
    for (Counters *c : {&m_bus, &perId(id)}) {
        ++c->stats.replies;
        c->latency.add(latencyS);
    }
}

void StatisticsCollector::timedOut(int id)
{
    ++m_bus.stats.timeouts;
    ++perId(id).stats.timeouts;
}

void StatisticsCollector::lateReply(int id)
{
    ++m_bus.stats.lateReplies;
    ++perId(id).stats.lateReplies;
}

void StatisticsCollector::unexpectedFrame(int id)
{
    ++m_bus.stats.unexpectedFrames;
    if (id >= 1 && id <= 32)
        ++perId(id).stats.unexpectedFrames;
}

void StatisticsCollector::undecodable(int id)
{
    ++m_bus.stats.parseErrors;
    ++perId(id).stats.parseErrors;
}

void StatisticsCollector::parseFault(const protocol::ParseEvent &event)
{
    using protocol::ParseError;
    // A readable header (bad data checksum, bad length, unknown command) names its drive;
    // IDs outside 1..32 are noise and stay on the bus counters only.
    const int id = event.frame.id;
    const bool headerTrusted = event.error == ParseError::BadDataChecksum ||
                               event.error == ParseError::BadLength ||
                               event.error == ParseError::UnknownCommand;
    Counters *drive = headerTrusted && id >= 1 && id <= 32 ? &perId(id) : nullptr;
    switch (event.error) {
    case ParseError::Garbage:
        m_bus.stats.garbageBytes += static_cast<quint64>(event.bytes.size());
        return;
    case ParseError::BadHeaderChecksum:
    case ParseError::BadDataChecksum:
        ++m_bus.stats.checksumErrors;
        if (drive)
            ++drive->stats.checksumErrors;
        return;
    case ParseError::BadLength:
    case ParseError::UnknownCommand:
    case ParseError::Truncated:
        ++m_bus.stats.parseErrors;
        if (drive)
            ++drive->stats.parseErrors;
        return;
    }
}

void StatisticsCollector::finish(Counters &c, double dt)
{
    const quint64 done = completed(c.stats);
    c.stats.transactionsPerSecond =
        dt > 0 ? static_cast<double>(done - c.completedAtLastSnapshot) / dt : 0;
    c.completedAtLastSnapshot = done;
    c.stats.latency = c.latency.summaryMs();
}

BusStatistics StatisticsCollector::snapshot(double now)
{
    const double dt = m_lastSnapshot < 0 ? 0 : now - m_lastSnapshot;
    m_lastSnapshot = now;
    BusStatistics s;
    s.time = now;
    finish(m_bus, dt);
    s.bus = m_bus.stats;
    for (auto it = m_ids.begin(); it != m_ids.end(); ++it) {
        finish(it.value(), dt);
        s.perId.insert(it.key(), it.value().stats);
    }
    s.localEchoes = m_localEchoes;
    s.canErrorFrames = m_canErrorFrames;
    s.otherFrames = m_otherFrames;
    return s;
}

} // namespace lk::bus
