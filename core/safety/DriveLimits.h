#pragma once

#include "MotionGuard.h"
#include "SoftLimits.h"
#include "SpeedBound.h"

#include <protocol/Parameter.h>
#include <protocol/Series.h>

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace lk::safety {

/// The limits a V2.35 drive holds itself, as read from it (ParamIDs 0x99 max torque current,
/// or max power on MS; 0x9A max speed; 0x9B/0x9C max angle; docs/V2.35.md section 6). Where one
/// was read, motion is bounded by the lower of it and the soft limit (narrow()), and a refusal
/// or speed bound that the drive's value decided says so (decided(), refusal(), speedBound()).
/// A value of 0 bounds nothing: a drive given Max Speed 0 uses its maximum (section 12), and
/// Max Angle 0 is read as "no angle limit".
struct DriveLimits {
    std::optional<double> maxSpeedDps;
    std::optional<double> maxTorqueA; ///< MF/MG/MH: 0x99 at the drive's iq command scale
    std::optional<int> maxPower;      ///< MS: 0x99 as power (of 1000)
    std::optional<double> maxAngleDeg;

    bool any() const { return maxSpeedDps || maxTorqueA || maxPower || maxAngleDeg; }
    /// From the parameter values read from a drive of `drive`'s series and generation; the
    /// max angle needs both halves. Values of other ParamIDs are ignored.
    static DriveLimits fromParams(const QList<protocol::ParameterValue> &values,
                                  const protocol::DecodeContext &drive);
    /// The parameters fromParams() reads.
    static const QList<protocol::ParamId> &params();

    /// `soft` with each bound lowered to the drive's own where that is lower (the angle range
    /// within -maxAngle..maxAngle).
    SoftLimits narrow(const SoftLimits &soft) const;
    /// True when the limit `verdict` broke (checked against narrow(soft)) is the drive's own,
    /// lower than the soft one.
    bool decided(const Verdict &verdict, const SoftLimits &soft) const;
    /// True when narrow(soft)'s speed limit is the drive's Max Speed, not the soft limit.
    bool capsSpeed(const SoftLimits &soft) const;

    /// The refusal of a verdict the drive's own limit decided, naming it (translated).
    static QString refusal(const Verdict &verdict);
    /// A speed bound that is the drive's Max Speed (MotionPlan::drivesOwnSpeed), translated:
    /// "max speed 720 dps (the drive's own Max Speed)" for a position move (SoftLimit),
    /// "within the drive's own Max Speed of 720 dps" for a speed command (Command).
    static QString speedBound(SpeedBound bound, double dps);

    bool operator==(const DriveLimits &o) const
    {
        return maxSpeedDps == o.maxSpeedDps && maxTorqueA == o.maxTorqueA &&
               maxPower == o.maxPower && maxAngleDeg == o.maxAngleDeg;
    }
    bool operator!=(const DriveLimits &o) const { return !(*this == o); }
};

} // namespace lk::safety
