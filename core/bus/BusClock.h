#pragma once

#include <QtCore/QtGlobal>

#include <memory>

namespace lk::bus {

/// The bus thread's monotonic clock. An interface so that tests can hand the worker a clock
/// they advance by hand, and check its timing without waiting on the wall clock.
class BusClock {
public:
    virtual ~BusClock() = default;
    /// Nanoseconds since an arbitrary fixed start; never goes back.
    virtual qint64 nowNs() const = 0;
};

/// The product's clock: steady (QElapsedTimer), starting at 0 when made.
std::shared_ptr<BusClock> makeSteadyBusClock();

} // namespace lk::bus
