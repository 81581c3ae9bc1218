#pragma once

#include "BusConfig.h"
#include "LatencyWindow.h"

#include <protocol/Command.h>

#include <array>
#include <optional>

namespace lk::bus {

/// Reply timeouts, and the quiet time after one, from the bus formula plus what the link has
/// shown: the extra latency of each reply beyond wire time + turnaround (USB adapters add
/// 1-16 ms, a loaded host more), over the link and per command class.
///
/// margin = 2 x p99 of the extra latency, over the link and over the command's own class,
/// bounded by BusConfig::minMarginMs and maxMarginMs. Until a class has kWarmupSamples
/// replies its margin is at least BusConfig::initialMarginMs, so that a slow adapter is not
/// mistaken for silent drives. A late reply (after its timeout) lifts every margin at once to
/// 1.5 x its extra latency, held while the next kWindow replies come in, so that the next
/// attempts wait long enough instead of timing out too.
class AdaptiveTimeout {
public:
    /// Commands whose replies take the drive similar time: reads (and clear_errors, which
    /// replies with a state), commands that act (RAM writes, motion, motor off/on/stop), flash
    /// writes.
    enum class CommandClass { Read, Write, Flash };
    static constexpr int kWarmupSamples = 4;
    static constexpr int kWindow = 256;
    static constexpr int kPercentileSamples = 100; ///< replies before a p99 means something
    static constexpr double kPercentile = 0.99;
    static constexpr double kPercentileFactor = 2.0;
    static constexpr double kLateFactor = 1.5;

    explicit AdaptiveTimeout(const BusConfig &config = {});
    void setConfig(const BusConfig &config) { m_config = config; }

    static CommandClass classOf(protocol::Command command);

    /// A reply to `command` arrived `latencyS` after the request was written.
    void addReply(protocol::Command command, int baud, double latencyS);
    /// A reply to `command` arrived `latencyS` after a request that had already timed out.
    void addLateReply(protocol::Command command, int baud, double latencyS);
    void reset();
    /// The margin of reads (what polling and scans mostly send).
    double marginS() const { return marginS(CommandClass::Read); }
    double marginS(CommandClass commandClass) const;
    double timeoutS(protocol::Command command, int baud) const;
    /// How long after a timeout a reply to `command` may still arrive: the drive's longest
    /// turnaround, the wire time of its longest reply, and the link's latency (p99 of the
    /// extra latency, or a recent late reply's; at least BusConfig::minMarginMs, and at least
    /// BusConfig::initialMarginMs until kPercentileSamples replies were measured).
    double quietS(protocol::Command command, int baud) const;
    /// How long after its send a reply to `command` can arrive from a drive that keeps its
    /// turnaround: the formula with the longest reply plus that same link latency. A probe's
    /// short timeout may end before it; then the quiet period lasts until it.
    double replyDeadlineS(protocol::Command command, int baud) const;
    int samples() const { return m_link.size(); }
    /// The drives' turnaround as measured: the least latency of recent replies minus their
    /// wire time (it holds the adapter's and host's share too: what a transaction really
    /// costs beyond the wire). nullopt before kWarmupSamples replies.
    std::optional<double> measuredTurnaroundS() const;

private:
    static double extraLatencyS(protocol::Command command, int baud, double latencyS);
    double recentLateS() const { return m_sinceLate < kWindow ? m_lateExtraS : 0; }
    double boundedS(double marginS) const;
    double linkLatencyS() const; ///< p99 extra latency or a recent late reply's, bounded

    BusConfig m_config;
    LatencyWindow m_link{kWindow};       ///< extra latency of every reply but flash writes, seconds
    LatencyWindow m_turnaround{kWindow}; ///< latency minus wire time, the same replies
    std::array<LatencyWindow, 3> m_classes{LatencyWindow(kWindow), LatencyWindow(kWindow),
                                           LatencyWindow(kWindow)};
    double m_lateExtraS = 0;   ///< extra latency of the latest late reply
    int m_sinceLate = kWindow; ///< replies since then
};

} // namespace lk::bus
