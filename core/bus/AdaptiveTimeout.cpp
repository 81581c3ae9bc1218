#include "AdaptiveTimeout.h"

#include "BusTiming.h"

#include <algorithm>

namespace lk::bus {

AdaptiveTimeout::AdaptiveTimeout(const BusConfig &config) : m_config(config) {}

void AdaptiveTimeout::addReply(protocol::Command command, int baud, double latencyS)
{
    // The actual reply may be the shorter layout; measure against the usual one so that a
    // long 0x12 reply shows up as extra latency rather than as a negative figure.
    const double expected = BusTiming::transactionTimeS(command, baud);
    m_extra.add(std::max(0.0, latencyS - expected));
}

double AdaptiveTimeout::marginS() const
{
    const double minS = m_config.minMarginMs * 1e-3;
    const double maxS = std::max(minS, m_config.maxMarginMs * 1e-3);
    double margin = std::max(minS, kP95Factor * m_extra.p95());
    if (m_extra.size() < kWarmupSamples)
        margin = std::max(margin, m_config.initialMarginMs * 1e-3);
    return std::clamp(margin, minS, maxS);
}

double AdaptiveTimeout::timeoutS(protocol::Command command, int baud) const
{
    return BusTiming::replyTimeoutS(command, baud, marginS());
}

} // namespace lk::bus
