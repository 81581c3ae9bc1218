#pragma once

namespace lk::bus {

/// Queue class of a request. Lower value runs first; within a class requests run in order.
enum class Priority {
    /// Motor off/stop only: ahead of everything. Other commands sent with this priority are
    /// demoted to Operator so that nothing can move a motor from the emergency lane.
    Emergency = 0,
    Operator = 1,   ///< control, writes, off/stop, one-off reads from the UI or CLI
    Background = 2, ///< polls
};

} // namespace lk::bus
