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

    /// Declare --limits, --max-torque-a, --max-speed-dps and --max-power.
    static void declare(ArgParser &parser);
    /// The options' help section ("Limits (defaults per series: ...").
    static QString helpText();
    /// Read and check the flags and the whole file; nullopt with a usage `error`.
    static std::optional<MotionLimitOptions> read(const ArgParser &parser, QString *error);
    /// The series' defaults, the --limits file over them, then the --max-* flags; nullopt
    /// with `error` (naming the file's key) when the file does not fit.
    std::optional<safety::SoftLimits> limitsFor(std::optional<protocol::Series> series,
                                                QString *error) const;

    /// `{"source":"soft_limit","dps":720}`: the speed bound a move went out with (the
    /// `speed_bound` of control's and step's JSON).
    static QByteArray boundJson(safety::SpeedBound bound, double dps);

private:
    std::optional<QByteArray> m_limitsText; ///< --limits FILE, already checked
    QString m_limitsPath;
    std::optional<double> m_maxTorqueA, m_maxSpeedDps;
    std::optional<int> m_maxPower;
};

} // namespace lk::lkctl
