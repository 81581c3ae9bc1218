#pragma once

#include "DriveLimits.h"
#include "MotionGuard.h"
#include "SoftLimits.h"
#include "SpeedBound.h"

#include <protocol/Request.h>
#include <protocol/Series.h>

#include <optional>

namespace lk::safety {

/// Where a drive is and how its output shaft relates to the rotor: what the position rules
/// need besides the limits.
struct DrivePosition {
    std::optional<double> angleDeg; ///< multi-turn rotor angle last read (0x92); nullopt: unknown
    double gearRatio = 1.0;         ///< rotor turns per output turn (ModelNameInfo)
    /// One turn of the output shaft in rotor degrees: the largest position move allowed.
    double outputTurnDeg() const { return 360.0 * gearRatio; }
};

/// What to send for a motion request, or the limit that refused it.
struct MotionPlan {
    std::optional<protocol::Request> request; ///< the request to send; nullopt: refused
    Verdict verdict;                          ///< the refusal (kind None when allowed)
    SpeedBound bound = SpeedBound::None;
    double boundDps = 0;  ///< the speed bound's value (dps) when bound is not None
    bool limited = false; ///< an unlimited position command became its limited form
    /// The speed bound (SoftLimit, or Command for a speed command) is the drive's own Max
    /// Speed, lower than the soft limit: DriveLimits::speedBound() words it.
    bool drivesOwnSpeed = false;
    bool allowed() const { return request.has_value(); }
};

/// The one conversion every motion request passes before it is sent, for lkstudio and lkctl
/// alike. Position commands without a speed cap (0xA3, 0xA5, 0xA7) become their limited forms
/// (0xA4, 0xA6, 0xA8) with the speed limit (or the series top speed, if lower) unless the
/// user gave a lower max speed. A multi-turn target needs the drive's current angle and may
/// lie at most one output turn away; an increment may be at most one output turn; with an
/// angle range set, where an increment or a single-turn move ends must lie inside it. Then
/// MotionGuard checks the result against the series and the soft limits. Where the drive's
/// own limits were read (`drive`), each bound is the lower of it and the soft limit, and the
/// plan says when the drive's was the one (Verdict::drivesOwn, MotionPlan::drivesOwnSpeed).
class MotionPlanner {
public:
    static MotionPlan plan(const protocol::Request &request, std::optional<protocol::Series> series,
                           const SoftLimits &limits, const DrivePosition &position,
                           const DriveLimits &drive = {});
    /// True when plan() needs DrivePosition::angleDeg for `request`: every multi-turn target,
    /// and an increment or a single-turn move while an angle range is set. Read 0x92 first.
    static bool needsAngle(const protocol::Request &request, const SoftLimits &limits);
    /// True for the six position commands (0xA3..0xA8).
    static bool isPosition(protocol::Command command);

private:
    /// plan() within one set of limits (the soft ones narrowed to the drive's).
    static MotionPlan planWithin(const protocol::Request &request,
                                 std::optional<protocol::Series> series, const SoftLimits &limits,
                                 const DrivePosition &position);
};

} // namespace lk::safety
