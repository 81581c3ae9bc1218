#pragma once

#include <system/SignalWatcher.h>

#include <QtCore/QObject>
#include <QtCore/QTimer>

#include <optional>

namespace lk::lkctl {

class LiveBus;

/// What ends a streaming subcommand (monitor, listen): SIGINT or SIGTERM, --duration, the
/// subcommand itself (stop()), or the bus going away, which is said once on standard error
/// and makes lost() true (exit 1).
class StreamEnd {
public:
    StreamEnd(LiveBus &bus, std::optional<double> durationS);

    /// Starts the --duration clock (from now).
    void startClock();
    /// Runs the event loop until stopped.
    void wait();
    void stop() { m_stop = true; }
    /// Ends the stream as a failure: the bus went away or went quiet.
    void lose() { m_lost = m_stop = true; }
    bool stopped() const { return m_stop; }
    bool lost() const { return m_lost; }

private:
    LiveBus &m_bus;
    std::optional<double> m_durationS;
    bool m_stop = false;
    bool m_lost = false;
    QObject m_context; ///< every connection ends with it
    system::SignalWatcher m_watcher;
    QTimer m_duration;
};

} // namespace lk::lkctl
