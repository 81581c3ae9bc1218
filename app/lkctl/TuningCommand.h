#pragma once

#include "LiveBus.h"
#include "LiveCommand.h"
#include "MotionLimitOptions.h"

#include <optional>

namespace lk::lkctl {

/// What lkctl freq and lkctl tune share: the bus opened, the drive identified (series and
/// generation) and the soft limits for its series, before anything is read or moved.
class TuningCommand : public LiveCommand {
protected:
    /// Opens `bus`, identifies drive `id` and lays `options` over its series' limits; nullopt
    /// after printing why, with `status` set (failure, or a usage error for the limits).
    std::optional<safety::SoftLimits> openDrive(LiveBus &bus, const BusOptions &busOptions, int id,
                                                const MotionLimitOptions &options, Console &console,
                                                int *status) const;
};

} // namespace lk::lkctl
