#pragma once

#include "ControllerLogFile.h"
#include "StatsFile.h"
#include "WireMonitor.h"

#include <sim/ControllerSpec.h>
#include <sim/ForeignController.h>

#include <QtCore/QByteArray>
#include <QtCore/QString>

#include <atomic>
#include <deque>
#include <optional>

namespace lk::sim {
class SimBus;
} // namespace lk::sim

namespace lk::app {

class PtyDevice;

/// lksim --controller: a simulated foreign master (sim::ForeignController) drives the bus,
/// and the pty carries what an RS485 tap on that bus receives, both directions in bus order,
/// each frame when its last byte has left the wire (at --baud, plus --adapter-latency-us).
/// The tool on the pty is expected to listen; bytes it writes anyway are a second master on
/// the same wire: over the controller's traffic both frames are lost (a collision, logged and
/// counted), on an idle wire the drives answer them. Every finished request of the
/// controller is a JSON line in the ground-truth log (ControllerTransaction::toJsonLine).
///
/// Nobody may be reading the pty: when the kernel's buffer is full, the oldest unread bytes
/// are discarded so that a tool opening it later reads the current traffic, and counted.
class TapBusServer {
public:
    struct Options {
        int baud = 115200;
        double adapterLatencyS = 0;
        bool verbose = false;
        QString statsFile;
        QString logFile; ///< empty: none
    };

    TapBusServer(PtyDevice &pty, sim::SimBus &bus, const sim::ControllerSpec &spec,
                 const Options &options);

    /// Open the log file (if any) and write the stats file; false with a message on standard
    /// error.
    bool open();
    /// Serve until `stop`; rewrite the stats file whenever `dumpStats` is raised. 0, or 1
    /// after an I/O error.
    int run(const std::atomic<bool> &stop, std::atomic<bool> &dumpStats);
    bool writeStats(bool running);
    /// "lksim: controller: N requests (N answered, ...), second master: ..." for the exit.
    QString summary() const;

private:
    struct Pending {
        double due = 0;
        QByteArray bytes;
    };
    void record(const QList<sim::ControllerTransaction> &done);
    /// Run the controller to `now`: its wire bytes join the queue, its finished requests the
    /// log.
    void advance(double now);
    void onSecondMaster(const QByteArray &bytes, double now);
    bool flushDue(double now);
    void log(const char *direction, const QByteArray &bytes) const;

    PtyDevice &m_pty;
    sim::SimBus &m_bus;
    sim::ControllerSpec m_spec;
    Options m_options;
    std::optional<sim::ForeignController> m_controller; ///< made when serving starts
    StatsFile m_stats;
    ControllerLogFile m_log; ///< the ground truth, and the outcomes' counts
    std::deque<Pending> m_pending;
    /// The controller's requests and replies; collisions: its requests lost to the second
    /// master (before: the request was hit; during: its reply was)
    WireCounters m_wire;
    qint64 m_secondMasterWrites = 0;
    qint64 m_secondMasterCollisions = 0; ///< writes that met the controller's frames
    qint64 m_tapBytesDiscarded = 0;
};

} // namespace lk::app
