#pragma once

#include <QtCore/QMetaType>

namespace lk::bus {

/// Tunables of one bus. The defaults suit a drive behind a USB-RS485 adapter.
struct BusConfig {
    int retries = 1; ///< extra attempts after a timeout or a corrupt reply (not for increments
                     ///< and ROM writes, which are never repeated)
    int emergencyRetries = 2; ///< extra attempts for emergency motor_off
    /// The adapter echoes our own bytes back (some RS485 adapters without echo suppression).
    /// When set, a frame identical to the request just sent is skipped once even when the
    /// command's reply is itself an echo (motor_off...). When clear, only frames with a
    /// request's layout identical to the request are skipped (they can never be a reply).
    bool localEcho = false;
    /// Smallest timeout margin over wire time + turnaround; also the least time allowed for
    /// the link's latency in the quiet period after a timeout (AdaptiveTimeout::quietS).
    double minMarginMs = 2;
    double initialMarginMs = 20; ///< margin until enough replies were measured (FTDI: 16 ms)
    double maxMarginMs = 200;    ///< largest margin, whatever the link does
    double telemetryHz = 60;     ///< most telemetry batches per second
    double statisticsHz = 2;     ///< statistics snapshots per second
    bool resumePollingOnReconnect = true; ///< resume the poll plan when the link comes back
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::BusConfig)
