#pragma once

#include "BusConfig.h"
#include "LatencyWindow.h"
#include "LinkTiming.h"

#include <protocol/Command.h>

#include <QtCore/QHash>

#include <array>
#include <optional>

namespace lk::bus {

/// Reply timeouts, and the quiet time after one, from the link's timing (LinkTiming: RS485's
/// bus formula, or CAN's frames and reply time) plus what the link has
/// shown: the extra latency of each reply beyond wire time + turnaround (USB adapters add
/// 1-16 ms, a loaded host more), over the link and per command class.
///
/// margin = 2 x p99 of the extra latency, over the link and over the command's own class,
/// bounded by BusConfig::minMarginMs and maxMarginMs. Until a class has kWarmupSamples
/// replies its margin is at least BusConfig::initialMarginMs, so that a slow adapter is not
/// mistaken for silent drives.
///
/// A late reply (after its timeout) lifts the margins of its own drive at once to 1.5 x its
/// extra latency, so that the next attempts to that drive wait long enough instead of timing
/// out too. The lift decays: each reply of that drive in time halves it, but never below that
/// reply's own extra latency (a drive that is slow every time stays waited for), and it is
/// gone once under BusConfig::minMarginMs. Other drives, and the emergency stop's probes of
/// silent IDs, never wait for one drive's late reply: it does not stall the bus.
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
    static constexpr double kLateDecay = 0.5; ///< per reply in time of the late drive

    explicit AdaptiveTimeout(const BusConfig &config = {});
    void setConfig(const BusConfig &config) { m_config = config; }

    static CommandClass classOf(protocol::Command command);

    /// A reply to `command` from drive `id` arrived `latencyS` after the request was written.
    /// `replyFrameBytes` > 0: the reply's length on the wire (a V2.35 model reply is longer
    /// than the usual one); else the usual length of the command's reply.
    void addReply(protocol::Command command, const LinkTiming &timing, double latencyS, int id = 0,
                  int replyFrameBytes = 0);
    /// A reply to `command` from drive `id` arrived `latencyS` after a request that had
    /// already timed out: that drive's margins are lifted (see the class comment).
    void addLateReply(protocol::Command command, const LinkTiming &timing, double latencyS,
                      int id = 0, int replyFrameBytes = 0);
    void reset();
    /// The margin of reads (what polling and scans mostly send), over the link.
    double marginS() const { return marginS(CommandClass::Read); }
    /// The margin of a class for drive `id` (0: the link's, without any drive's late lift).
    double marginS(CommandClass commandClass, int id = 0) const;
    double timeoutS(protocol::Command command, const LinkTiming &timing, int id = 0) const;
    /// How long after a timeout a reply to `command` from drive `id` may still arrive: the
    /// drive's longest turnaround, the wire time of its longest reply, and the link's latency
    /// (p99 of the extra latency, or that drive's recent late reply's; at least
    /// BusConfig::minMarginMs, and at least BusConfig::initialMarginMs until
    /// kPercentileSamples replies were measured).
    double quietS(protocol::Command command, const LinkTiming &timing, int id = 0) const;
    /// How long after its send a reply to `command` can arrive from drive `id` when it keeps
    /// its turnaround: the formula with the longest reply plus that same latency. A probe's
    /// short timeout may end before it; then the quiet period lasts until it.
    double replyDeadlineS(protocol::Command command, const LinkTiming &timing, int id = 0) const;
    /// The lift a late reply of drive `id` still gives its margins' base (0: none).
    double lateExtraS(int id) const { return m_lateExtraS.value(id, 0.0); }
    int samples() const { return m_link.size(); }
    /// The drives' turnaround as measured: the least latency of recent replies minus their
    /// wire time (it holds the adapter's and host's share too: what a transaction really
    /// costs beyond the wire). nullopt before kWarmupSamples replies.
    std::optional<double> measuredTurnaroundS() const;

private:
    /// Request and reply on the wire (see addReply for `replyFrameBytes`).
    static double wireS(protocol::Command command, const LinkTiming &timing, int replyFrameBytes);
    static double extraLatencyS(protocol::Command command, const LinkTiming &timing,
                                double latencyS, int replyFrameBytes);
    /// A reply of `id` came in time with `extraS` of extra latency: its late lift decays.
    void decayLate(int id, double extraS);
    double boundedS(double marginS) const;
    /// p99 extra latency or drive `id`'s late lift, bounded.
    double linkLatencyS(int id) const;

    BusConfig m_config;
    LatencyWindow m_link{kWindow};       ///< extra latency of every reply but flash writes, seconds
    LatencyWindow m_turnaround{kWindow}; ///< latency minus wire time, the same replies
    std::array<LatencyWindow, 3> m_classes{LatencyWindow(kWindow), LatencyWindow(kWindow),
                                           LatencyWindow(kWindow)};
    QHash<int, double> m_lateExtraS; ///< per drive: the decaying extra latency of a late reply
};

} // namespace lk::bus
