#pragma once

#include <protocol/Series.h>
#include <safety/MotionPlanner.h>
#include <safety/SoftLimits.h>

#include <QtCore/QByteArray>
#include <QtCore/QString>

#include <optional>

namespace lk::lkctl {

class ArgParser;

/// The limit options of the commands that move a motor (control, step): --limits FILE.json
/// and the --max-* overrides, checked before the bus is touched and laid over the series'
/// defaults once the drive's series is known.
class MotionLimitOptions {
public:
    /// A limits file is a few hundred bytes; a larger one is refused unread.
    static constexpr qint64 kMaxFileBytes = 64 * 1024;
    /// The flags' ranges, those of the limits file's keys (SoftLimits).
    static constexpr double kMaxTorqueA = 32;
    static constexpr double kMinSpeedDps = 0.01;
    static constexpr double kMaxSpeedDps = 18000;

    /// Declare --limits, --max-torque-a, --max-speed-dps and --max-power.
    static void declare(ArgParser &parser);
    /// The options' help section ("Limits (defaults per series: ...").
    static QString helpText();
    /// Read and check the flags and the whole file; nullopt with a usage `error`.
    static std::optional<MotionLimitOptions> read(const ArgParser &parser, QString *error);
    /// The series' defaults, the --limits file over them, then the --max-* flags; nullopt
    /// with `error` (naming the file's key, or the flag) when the file does not fit or a
    /// limit is beyond what the series can do (its current limit, its top speed).
    std::optional<safety::SoftLimits> limitsFor(std::optional<protocol::Series> series,
                                                QString *error) const;

    /// `{"source":"soft_limit","dps":720}`: the speed bound a move went out with (the
    /// `speed_bound` of control's and step's JSON).
    static QByteArray boundJson(safety::SpeedBound bound, double dps);

private:
    QString beyondSeries(const safety::SoftLimits &limits, protocol::Series series) const;
    /// Where a limit came from: "--max-torque-a", "--limits FILE: max_torque_a", or the
    /// series default.
    QString sourceOf(const char *option, const char *key) const;

    std::optional<QByteArray> m_limitsText; ///< --limits FILE, already checked
    QString m_limitsPath;
    std::optional<double> m_maxTorqueA, m_maxSpeedDps;
    std::optional<int> m_maxPower;
};

} // namespace lk::lkctl
