#pragma once

#include "BusClock.h"
#include "SingleShotTimer.h"

#include <memory>

namespace lk::bus {

/// Where the bus engine's time comes from: the clock it reads and the timers it starts.
/// Default-made, the product's (a steady clock and QTimers); tests give manual ones.
struct BusTimeSource {
    std::shared_ptr<BusClock> clock = makeSteadyBusClock();
    SingleShotTimerFactory timers = makeQtSingleShotTimer;
};

} // namespace lk::bus
