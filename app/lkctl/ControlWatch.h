#pragma once

#include <protocol/Request.h>
#include <safety/SoftLimits.h>

#include <QtCore/QString>

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

private:
    int watch(LiveBus &bus, const protocol::Request &request, bool json, int status) const;
    /// Motor Stop to `id` from the emergency lane; whether the drive acknowledged it.
    static bool stop(LiveBus &bus, int id);

    double m_seconds = 0; ///< 0: no --watch
    safety::SoftLimits m_limits;
};

} // namespace lk::lkctl
