#include "AdaptiveTimeout.h"

#include "BusTiming.h"

#include <algorithm>

namespace lk::bus {

using protocol::Command;
using protocol::CommandTable;

AdaptiveTimeout::AdaptiveTimeout(const BusConfig &config) : m_config(config) {}

AdaptiveTimeout::CommandClass AdaptiveTimeout::classOf(Command command)
{
    const protocol::CommandInfo &info = CommandTable::info(command);
    if (info.writesFlash)
        return CommandClass::Flash;
    // A read carries no data and gets a report back; everything else makes the drive do
    // something first (set gains or targets, switch the motor, clear the angle).
    const bool read = info.requestLength == 0 && !info.replyEchoesRequest && !info.movesMotor;
    return read ? CommandClass::Read : CommandClass::Write;
}

double AdaptiveTimeout::extraLatencyS(Command command, int baud, double latencyS)
{
    // The actual reply may be the shorter layout; measure against the usual one so that a
    // long 0x12 reply shows up as extra latency rather than as a negative figure.
    return std::max(0.0, latencyS - BusTiming::transactionTimeS(command, baud));
}

void AdaptiveTimeout::addReply(Command command, int baud, double latencyS)
{
    const double extra = extraLatencyS(command, baud, latencyS);
    const CommandClass c = classOf(command);
    // Writing flash takes the drive itself longer: that teaches its own class only, while
    // the link's latency (adapter, host) shows in every other reply.
    if (c != CommandClass::Flash) {
        m_link.add(extra);
        const double wire = BusTiming::transactionTimeS(command, baud, 0);
        m_turnaround.add(std::max(0.0, latencyS - wire));
    }
    m_classes[static_cast<size_t>(c)].add(extra);
    if (m_sinceLate < kWindow)
        ++m_sinceLate;
}

std::optional<double> AdaptiveTimeout::measuredTurnaroundS() const
{
    if (m_turnaround.size() < kWarmupSamples)
        return std::nullopt;
    return m_turnaround.min();
}

void AdaptiveTimeout::addLateReply(Command command, int baud, double latencyS)
{
    addReply(command, baud, latencyS);
    const double extra = extraLatencyS(command, baud, latencyS);
    m_lateExtraS = m_sinceLate < kWindow ? std::max(m_lateExtraS, extra) : extra;
    m_sinceLate = 0;
}

void AdaptiveTimeout::reset()
{
    m_link.clear();
    m_turnaround.clear();
    for (LatencyWindow &w : m_classes)
        w.clear();
    m_lateExtraS = 0;
    m_sinceLate = kWindow;
}

double AdaptiveTimeout::boundedS(double marginS) const
{
    const double minS = m_config.minMarginMs * 1e-3;
    const double maxS = std::max(minS, m_config.maxMarginMs * 1e-3);
    return std::clamp(marginS, minS, maxS);
}

double AdaptiveTimeout::marginS(CommandClass commandClass) const
{
    const LatencyWindow &own = m_classes[static_cast<size_t>(commandClass)];
    double margin =
        kPercentileFactor * std::max(m_link.quantile(kPercentile), own.quantile(kPercentile));
    margin = std::max(margin, kLateFactor * recentLateS());
    if (own.size() < kWarmupSamples)
        margin = std::max(margin, m_config.initialMarginMs * 1e-3);
    return boundedS(margin);
}

double AdaptiveTimeout::timeoutS(Command command, int baud) const
{
    return BusTiming::replyTimeoutS(command, baud, marginS(classOf(command)));
}

double AdaptiveTimeout::linkLatencyS() const
{
    return boundedS(std::max(m_link.quantile(kPercentile), recentLateS()));
}

double AdaptiveTimeout::quietS(Command command, int baud) const
{
    // A 99th percentile of fewer than a hundred replies says little: until then the link is
    // not trusted to be faster than BusConfig::initialMarginMs.
    double latency = linkLatencyS();
    if (m_link.size() < kPercentileSamples)
        latency = std::max(latency, boundedS(m_config.initialMarginMs * 1e-3));
    return BusTiming::kTurnaroundS +
           BusTiming::wireTimeS(0, BusTiming::maxReplyBytes(command), baud) + latency;
}

double AdaptiveTimeout::replyDeadlineS(Command command, int baud) const
{
    return BusTiming::replyTimeoutS(command, baud, linkLatencyS());
}

} // namespace lk::bus
