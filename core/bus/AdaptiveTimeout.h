#pragma once

#include "BusConfig.h"
#include "LatencyWindow.h"

#include <protocol/Command.h>

namespace lk::bus {

/// Reply timeouts from the bus formula plus a margin that follows the link's measured extra
/// latency (USB adapters add 1-16 ms): margin = max(min, 3 x p95 extra), bounded by max.
/// Until kWarmupSamples replies were measured the margin is at least BusConfig::initialMarginMs
/// so that a slow adapter is not mistaken for silent drives.
class AdaptiveTimeout {
public:
    static constexpr int kWarmupSamples = 4;
    static constexpr double kP95Factor = 3.0;

    explicit AdaptiveTimeout(const BusConfig &config = {});
    void setConfig(const BusConfig &config) { m_config = config; }

    /// A reply to `command` arrived `latencyS` after the request was written.
    void addReply(protocol::Command command, int baud, double latencyS);
    void reset() { m_extra.clear(); }
    double marginS() const;
    double timeoutS(protocol::Command command, int baud) const;
    int samples() const { return m_extra.size(); }

private:
    BusConfig m_config;
    LatencyWindow m_extra{64}; ///< latency beyond wire time + turnaround, seconds
};

} // namespace lk::bus
