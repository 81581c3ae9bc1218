#pragma once

#include <bus/SpeedWatchTrip.h>
#include <protocol/Request.h>
#include <safety/SoftLimits.h>

#include <QtCore/QMap>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::lkctl {

class ArgParser;
class LiveBus;

/// What `lkctl control` does after a torque or open-loop command, which no drive bounds in
/// speed. Without --watch it says that the drive stays under that command, unwatched, once
/// lkctl exits. With --watch SECONDS the bus thread's speed watch (bus::SpeedWatch) bounds the
/// drive by the speed limit for that long: past it (SpeedWatch::thresholdDps) the drive gets
/// Motor Stop at once (exit kExitWatchStopped); at the end, on Ctrl+C or SIGTERM, it gets
/// Motor Stop too, and the output says whether the drive acknowledged it.
class ControlWatch {
public:
    /// The speed watch stopped the drive past the speed limit.
    static constexpr int kExitWatchStopped = 6;
    static constexpr double kMaxSeconds = 86400;

    static void declare(ArgParser &parser);
    /// The option's line for the command's --help.
    static QString helpText();
    /// The exit status line for the command's --help.
    static QString exitStatusLine();
    /// --watch as given (with MODE, the second positional); nullopt with `error` when unusable.
    static std::optional<ControlWatch> read(const ArgParser &parser, QString *error);

    /// Before the command is sent: the bus thread's speed watch gets the drive's soft limits.
    void arm(LiveBus &bus, int id, const safety::SoftLimits &limits);
    /// After `request` was sent (with exit status `status`): the note, or the watch and the
    /// final stop. Returns the command's exit status.
    int follow(LiveBus &bus, const protocol::Request &request, bool json, int status) const;
    /// The same after a multi-motor torque frame (`torques`, one per drive, each arm()ed):
    /// every drive it set turning is watched, and all of them get Motor Stop at the end, on
    /// a signal, and when the speed watch stopped one of them.
    int followGroup(LiveBus &bus, const QVector<protocol::Request> &torques, bool json,
                    int status) const;

    /// Why a watch ended.
    enum class End { Time, Signal, SpeedLimit, LinkLost };

private:
    struct Outcome {
        End end = End::Time;
        std::optional<bus::SpeedWatchTrip> trip;
        QMap<int, double> peak; ///< |speed| seen, by drive
        QMap<int, bool> acked;  ///< whether its final Motor Stop was acknowledged, by drive
        double seconds = 0;
    };
    int watch(LiveBus &bus, const QVector<int> &ids, bool json, int status) const;
    void reportOne(LiveBus &bus, int id, bool json, const Outcome &o) const;
    void reportGroup(LiveBus &bus, const QVector<int> &ids, bool json, const Outcome &o) const;
    static QString idList(const QVector<int> &ids);
    QString thresholdList(const QVector<int> &ids) const;
    /// Motor Stop to `id` from the emergency lane; whether the drive acknowledged it.
    static bool stop(LiveBus &bus, int id);
    double limitOf(int id) const { return m_limits.value(id).maxSpeedDps; }

    double m_seconds = 0;                   ///< 0: no --watch
    QMap<int, safety::SoftLimits> m_limits; ///< by drive, as arm()ed
};

} // namespace lk::lkctl
