#pragma once

#include "RequestResult.h"
#include "SpeedWatchTrip.h"
#include "TelemetrySample.h"

#include <protocol/Request.h>
#include <protocol/Series.h>
#include <safety/SoftLimits.h>

#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QVector>

#include <functional>
#include <optional>

namespace lk::bus {

/// Bounds the speed of drives under a torque (0xA1) or open-loop (0xA0) command, which the
/// drives do not bound themselves (docs/ERRATA.md): a free motor under 0.3 A runs up to the
/// series' top speed. Lives on the bus thread (owned by BusWorker) and sees every request's
/// end and every reply's telemetry there, whoever sent the command (GUI, lkctl, a setpoint
/// stream, a step test).
///
/// A torque or open-loop command with a non-zero value that went on the wire (acknowledged or
/// not: the drive may have acted) puts its drive under watch; an acknowledged speed or
/// position command, Motor Off or a zero torque/power ends it; an acknowledged Motor Stop
/// holds it (Motor Run resumes a held command on V2.3, so it watches again). A watched drive
/// whose reported speed exceeds thresholdDps(limit) gets Motor Stop (0x81) from the emergency
/// lane at once, through the stop sender, once per trip; tripped() follows with the stop's end.
/// A stop that was not acknowledged leaves the drive watched: the next fast reply sends again.
///
/// The limit is the drive's soft speed limit (setSoftLimits), else the series' default
/// (SoftLimits::defaults: its top speed; 6000 dps for an unknown series). watchedChanged()
/// tells the poll scheduler which drives to read often (PollScheduler::setWatched): every other
/// poll at least, so that with one drive watched a speed past the threshold is read within two
/// exchanges and the stop acknowledged one exchange later, within about 6 ms at 115200 baud and
/// 2 ms at 1 Mbaud (2N exchanges between reads with N drives watched; bench_torque_watch gives
/// the overshoot, docs/SUPERVISION.md).
class SpeedWatch : public QObject {
    Q_OBJECT
public:
    /// The margin above the limit before the watch stops a drive: 5 % of the limit, at least
    /// 30 dps (speed readings of a free motor jitter by a few dps; a 720 dps limit trips above
    /// 756 dps).
    static constexpr double kMarginFraction = 0.05;
    static constexpr double kMarginMinDps = 30;
    static double thresholdDps(double limitDps);
    static bool isWatchedMode(protocol::Command command);
    /// A torque or open-loop command with a non-zero value: one the watch follows (zero adds
    /// no energy).
    static bool drives(const protocol::Request &request);

    /// Sends Motor Stop to `id` from the emergency lane; `done` runs once with its end.
    using StopSender = std::function<void(int id, std::function<void(const RequestResult &)> done)>;
    using SeriesLookup = std::function<std::optional<protocol::Series>(int id)>;

    /// `now`: the session clock in seconds (the stop's end is stamped with it).
    SpeedWatch(StopSender stop, SeriesLookup series, std::function<double()> now,
               QObject *parent = nullptr);

    /// The user's soft limits of drive `id` (their maxSpeedDps bounds the watch).
    void setSoftLimits(int id, const safety::SoftLimits &limits);
    /// The limit drive `id` is watched against now, and where it came from.
    double limitDps(int id, SpeedWatchSource *source = nullptr) const;

    /// A request ended (every request, any status): arms, holds or ends a drive's watch.
    void noteRequestEnded(const protocol::Request &request, RequestStatus status, int attempts);
    /// A reply's telemetry: a watched drive past its threshold is stopped.
    void noteSample(const TelemetrySample &sample);
    /// Forget every drive's watch (the link was replaced); the limits stay.
    void clear();

    QVector<int> watchedIds() const; ///< under watch now (stopping ones included), ascending
    bool isWatched(int id) const { return watchedIds().contains(id); }
    /// The torque or open-loop command drive `id` is watched under; nullopt when it is not.
    std::optional<protocol::Command> modeOf(int id) const;

signals:
    /// The set of watched drives changed (ascending IDs).
    void watchedChanged(const QVector<int> &ids);
    /// A watched drive went past its threshold; the Motor Stop has ended (see stopStatus).
    void tripped(const lk::bus::SpeedWatchTrip &trip);

private:
    enum class State {
        Watching, ///< under a torque or open-loop command
        Stopping, ///< our Motor Stop is queued or on the wire
        Held,     ///< stopped with its command kept (Motor Run resumes it on V2.3)
    };
    struct Drive {
        State state = State::Watching;
        protocol::Command mode = protocol::Command::Torque;
    };
    void arm(int id, protocol::Command mode);
    void setState(int id, std::optional<State> state);
    void trip(int id, const TelemetrySample &sample);
    void onStopEnded(SpeedWatchTrip trip, const RequestResult &result);

    StopSender m_stop;
    SeriesLookup m_series;
    std::function<double()> m_now;
    QMap<int, double> m_limits; ///< soft speed limit by drive
    QMap<int, Drive> m_drives;  ///< drives under a torque or open-loop command
};

} // namespace lk::bus
