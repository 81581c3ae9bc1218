#include "AdaptiveTimeout.h"

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

double AdaptiveTimeout::wireS(Command command, const LinkTiming &timing, int replyFrameBytes)
{
    // The reply as it came: a V2.35 drive's 58-byte model reply takes 17 ms more at 9600 baud
    // than the usual 42 bytes, which is wire time, not latency.
    const double replyS =
        replyFrameBytes > 0 ? timing.frameWireS(replyFrameBytes) : timing.replyWireS(command);
    return timing.requestWireS(command) + replyS;
}

double AdaptiveTimeout::extraLatencyS(Command command, const LinkTiming &timing, double latencyS,
                                      int replyFrameBytes)
{
    return std::max(0.0, latencyS - wireS(command, timing, replyFrameBytes) - timing.turnaroundS());
}

void AdaptiveTimeout::addReply(Command command, const LinkTiming &timing, double latencyS, int id,
                               int replyFrameBytes)
{
    const double extra = extraLatencyS(command, timing, latencyS, replyFrameBytes);
    decayLate(id, extra);
    const CommandClass c = classOf(command);
    // Writing flash takes the drive itself longer: that teaches its own class only, while
    // the link's latency (adapter, host) shows in every other reply.
    if (c != CommandClass::Flash) {
        m_link.add(extra);
        m_turnaround.add(std::max(0.0, latencyS - wireS(command, timing, replyFrameBytes)));
    }
    m_classes[static_cast<size_t>(c)].add(extra);
}

void AdaptiveTimeout::decayLate(int id, double extraS)
{
    const auto it = m_lateExtraS.find(id);
    if (it == m_lateExtraS.end())
        return;
    *it = std::max(extraS, *it * kLateDecay);
    if (kLateFactor * *it < m_config.minMarginMs * 1e-3)
        m_lateExtraS.erase(it);
}

std::optional<double> AdaptiveTimeout::measuredTurnaroundS() const
{
    if (m_turnaround.size() < kWarmupSamples)
        return std::nullopt;
    return m_turnaround.min();
}

void AdaptiveTimeout::addLateReply(Command command, const LinkTiming &timing, double latencyS,
                                   int id, int replyFrameBytes)
{
    // Not into the link's windows: one drive's late answer is that drive's, and a p99 of a
    // few replies would otherwise lift every drive's timeout (and each silent ID's wait).
    const double extra = extraLatencyS(command, timing, latencyS, replyFrameBytes);
    double &lift = m_lateExtraS[id];
    lift = std::max(lift, extra);
}

void AdaptiveTimeout::reset()
{
    m_link.clear();
    m_turnaround.clear();
    for (LatencyWindow &w : m_classes)
        w.clear();
    m_lateExtraS.clear();
}

double AdaptiveTimeout::boundedS(double marginS) const
{
    const double minS = m_config.minMarginMs * 1e-3;
    const double maxS = std::max(minS, m_config.maxMarginMs * 1e-3);
    return std::clamp(marginS, minS, maxS);
}

double AdaptiveTimeout::marginS(CommandClass commandClass, int id) const
{
    const LatencyWindow &own = m_classes[static_cast<size_t>(commandClass)];
    double margin =
        kPercentileFactor * std::max(m_link.quantile(kPercentile), own.quantile(kPercentile));
    margin = std::max(margin, kLateFactor * lateExtraS(id));
    if (own.size() < kWarmupSamples)
        margin = std::max(margin, m_config.initialMarginMs * 1e-3);
    return boundedS(margin);
}

double AdaptiveTimeout::timeoutS(Command command, const LinkTiming &timing, int id) const
{
    return timing.replyTimeoutS(command, marginS(classOf(command), id));
}

double AdaptiveTimeout::linkLatencyS(int id) const
{
    return boundedS(std::max(m_link.quantile(kPercentile), lateExtraS(id)));
}

double AdaptiveTimeout::quietS(Command command, const LinkTiming &timing, int id) const
{
    // A 99th percentile of fewer than a hundred replies says little: until then the link is
    // not trusted to be faster than BusConfig::initialMarginMs.
    double latency = linkLatencyS(id);
    if (m_link.size() < kPercentileSamples)
        latency = std::max(latency, boundedS(m_config.initialMarginMs * 1e-3));
    return timing.turnaroundS() + timing.maxReplyWireS(command) + latency;
}

double AdaptiveTimeout::replyDeadlineS(Command command, const LinkTiming &timing, int id) const
{
    return timing.replyTimeoutS(command, linkLatencyS(id));
}

} // namespace lk::bus
