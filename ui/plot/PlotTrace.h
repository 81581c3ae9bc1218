#pragma once

#include "TelemetryChannel.h"

namespace lk::ui {

/// One plotted line: a drive's channel and whether its torque channel holds power (MS).
struct PlotTrace {
    int driveId = 0;
    TelemetryChannel channel = TelemetryChannel::Torque;
    bool power = false;

    Quantity quantity() const { return channelQuantity(channel, power); }
    bool operator==(const PlotTrace &o) const
    {
        return driveId == o.driveId && channel == o.channel && power == o.power;
    }
    bool operator!=(const PlotTrace &o) const { return !(*this == o); }
};

} // namespace lk::ui
