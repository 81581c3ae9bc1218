#pragma once

#include "SoftLimits.h"

#include <protocol/Request.h>
#include <protocol/Series.h>

#include <optional>

namespace lk::safety {

/// Which limit stopped a command: lktext's VerdictText words it for lkstudio and lkctl alike.
enum class LimitKind {
    None,          ///< allowed
    UnknownSeries, ///< torque/open loop need a known series
    Unsupported,   ///< the series does not implement the command
    SeriesCurrent, ///< |iq| over the series' rated current
    SoftTorque,    ///< |iq| over the user's torque limit
    SoftPower,     ///< |power| over the user's open-loop limit
    SeriesSpeed,   ///< speed or max speed over the series' top speed
    SoftSpeed,     ///< speed or max speed over the user's speed limit
    AngleBelowMin, ///< multi-turn target under the user's range
    AngleAboveMax, ///< multi-turn target over the user's range
    SoftIncrement, ///< incremental move larger than the user allows
    AngleUnknown,  ///< a position move needs the drive's current angle, not yet read
    OutputTurn,    ///< a position move of more than one output turn
};

/// The outcome of a check: allowed, or the limit that refused it with both numbers. Typed data
/// only: the core never words it (VerdictText does, once).
struct Verdict {
    LimitKind kind = LimitKind::None;
    double value = 0; ///< what was asked (A, power, dps or deg)
    double limit = 0; ///< the limit it broke, same unit
    /// The command refused: says whether a speed was its speed or its max speed, and whether
    /// a move over one output turn was an increment. nullopt for a bare target check.
    std::optional<protocol::Command> command;
    /// OutputTurn of a multi-turn target: the angle (deg) the move would start from.
    std::optional<double> fromDeg;
    /// The limit broken is the drive's own (a V2.35 parameter read from it, DriveLimits),
    /// lower than the soft limit of the same kind: DriveLimits::refusal() words it.
    bool drivesOwn = false;
    bool allowed() const { return kind == LimitKind::None; }
};

/// The one gate every command that can move a motor passes before it is sent: series
/// capabilities and hard limits first, then the user's soft limits. Reads and writes that
/// cannot move the shaft always pass.
class MotionGuard {
public:
    static Verdict check(const protocol::Request &request, std::optional<protocol::Series> series,
                         const SoftLimits &limits);
    /// A multi-turn target (rotor deg) against the user's angle range.
    static Verdict checkTarget(double deg, const SoftLimits &limits);
    /// The series' top speed; when the series is unknown, the slowest series' (a guess never
    /// overspeeds).
    static double topSpeedDps(std::optional<protocol::Series> series);
};

} // namespace lk::safety
