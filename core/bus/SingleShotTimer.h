#pragma once

#include <QtCore/QObject>

#include <functional>
#include <memory>

namespace lk::bus {

/// A one-shot timer as bus-thread objects use it. An interface so that tests can hand an
/// object timers they fire by hand, and check its timing without waiting on the wall clock.
class SingleShotTimer {
public:
    virtual ~SingleShotTimer() = default;
    /// (Re)start: the timeout callback runs once, `ms` from now.
    virtual void start(int ms) = 0;
    virtual void stop() = 0;
    virtual bool isActive() const = 0;
};

/// Makes a timer whose timeout calls `onTimeout`; `owner` is the object that uses it (a Qt
/// timer becomes its child, so that it moves threads with it). `type`: how precisely it must
/// keep its interval (Qt::PreciseTimer for reply timeouts; Qt::CoarseTimer may fire up to 5 %
/// late, which saves wake-ups where that does not matter).
using SingleShotTimerFactory = std::function<std::unique_ptr<SingleShotTimer>(
    QObject *owner, std::function<void()> onTimeout, Qt::TimerType type)>;

/// The product's timers: a QTimer of the given type.
std::unique_ptr<SingleShotTimer>
makeQtSingleShotTimer(QObject *owner, std::function<void()> onTimeout, Qt::TimerType type);

} // namespace lk::bus
