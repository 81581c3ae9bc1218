#include "DriveLimits.h"

#include <protocol/Values.h>

#include <QtCore/QCoreApplication>

#include <algorithm>
#include <cmath>

namespace lk::safety {

namespace {

using protocol::ParamId;

const char *const kContext = "lk::safety::DriveLimits";

QString tr(const char *text)
{
    return QCoreApplication::translate(kContext, text);
}

QString num(double v)
{
    return QString::number(v, 'g', 8);
}

/// A positive limit; 0 (and a negative value, which no drive should hold) bounds nothing.
template <typename T> std::optional<T> positive(T v)
{
    return v > 0 ? std::optional<T>(v) : std::nullopt;
}

/// The lower of a soft bound and the drive's own, if read.
template <typename T> T lower(T soft, const std::optional<T> &drive)
{
    return drive ? std::min(soft, *drive) : soft;
}

/// Whether `limit` is the drive's value and lower than the soft one.
template <typename T> bool drivesOwn(double limit, T soft, const std::optional<T> &drive)
{
    return drive && *drive < soft && limit == static_cast<double>(*drive);
}

} // namespace

const QList<ParamId> &DriveLimits::params()
{
    static const QList<ParamId> kParams{ParamId::MaxTorqueCurrent, ParamId::MaxSpeed,
                                        ParamId::MaxAngleLow, ParamId::MaxAngleHigh};
    return kParams;
}

DriveLimits DriveLimits::fromParams(const QList<protocol::ParameterValue> &values,
                                    const protocol::DecodeContext &drive)
{
    DriveLimits d;
    std::optional<protocol::ParameterValue> low, high;
    for (const protocol::ParameterValue &v : values) {
        switch (v.id().value_or(ParamId::CurrentRamp)) {
        case ParamId::MaxTorqueCurrent:
            if (drive.reportsPower())
                d.maxPower = positive<int>(v.asInt16());
            else
                d.maxTorqueA = positive<double>(v.asInt16() * protocol::iqCommandAmpsPerLsb(drive));
            break;
        case ParamId::MaxSpeed:
            d.maxSpeedDps = positive<double>(v.asInt32() / 100.0);
            break;
        case ParamId::MaxAngleLow:
            low = v;
            break;
        case ParamId::MaxAngleHigh:
            high = v;
            break;
        default:
            break;
        }
    }
    if (low && high)
        d.maxAngleDeg =
            positive<double>(static_cast<double>(protocol::joinMaxAngle(*low, *high)) / 100.0);
    return d;
}

SoftLimits DriveLimits::narrow(const SoftLimits &soft) const
{
    SoftLimits l = soft;
    l.maxSpeedDps = lower(soft.maxSpeedDps, maxSpeedDps);
    l.maxTorqueA = lower(soft.maxTorqueA, maxTorqueA);
    l.maxPower = lower(soft.maxPower, maxPower);
    if (maxAngleDeg) {
        l.maxAngleDeg = std::min(soft.maxAngleDeg.value_or(*maxAngleDeg), *maxAngleDeg);
        l.minAngleDeg = std::max(soft.minAngleDeg.value_or(-*maxAngleDeg), -*maxAngleDeg);
    }
    return l;
}

bool DriveLimits::capsSpeed(const SoftLimits &soft) const
{
    return maxSpeedDps && *maxSpeedDps < soft.maxSpeedDps;
}

bool DriveLimits::decided(const Verdict &v, const SoftLimits &soft) const
{
    switch (v.kind) {
    case LimitKind::SoftSpeed:
        return drivesOwn(v.limit, soft.maxSpeedDps, maxSpeedDps);
    case LimitKind::SoftTorque:
        return drivesOwn(v.limit, soft.maxTorqueA, maxTorqueA);
    case LimitKind::SoftPower:
        return drivesOwn(v.limit, soft.maxPower, maxPower);
    case LimitKind::AngleAboveMax:
        return maxAngleDeg && v.limit == *maxAngleDeg &&
               (!soft.maxAngleDeg || *maxAngleDeg < *soft.maxAngleDeg);
    case LimitKind::AngleBelowMin:
        return maxAngleDeg && v.limit == -*maxAngleDeg &&
               (!soft.minAngleDeg || -*maxAngleDeg > *soft.minAngleDeg);
    default:
        return false;
    }
}

QString DriveLimits::refusal(const Verdict &v)
{
    const bool maxSpeed = v.command && *v.command != protocol::Command::Speed;
    switch (v.kind) {
    case LimitKind::SoftSpeed:
        return (maxSpeed ? tr("the max speed %1 dps is over the drive's own Max Speed of %2 dps "
                              "(read from it), which is lower than your speed limit")
                         : tr("the speed %1 dps is over the drive's own Max Speed of %2 dps (read "
                              "from it), which is lower than your speed limit"))
            .arg(num(v.value), num(v.limit));
    case LimitKind::SoftTorque:
        return tr("the torque current %1 A is over the drive's own max torque current of %2 A "
                  "(read from it), which is lower than your torque limit")
            .arg(QString::number(v.value, 'f', 2), QString::number(v.limit, 'f', 2));
    case LimitKind::SoftPower:
        return tr("the open-loop power %1 is over the drive's own Max Power of %2 (read from it), "
                  "which is lower than your power limit")
            .arg(num(v.value), num(v.limit));
    case LimitKind::AngleAboveMax:
    case LimitKind::AngleBelowMin:
        return tr("the target %1\u00b0 is outside the drive's own Max Angle of \u00b1%2\u00b0 "
                  "(read "
                  "from it), which is narrower than your angle range")
            .arg(num(v.value), num(std::fabs(v.limit)));
    default:
        return QString();
    }
}

QString DriveLimits::speedBound(SpeedBound bound, double dps)
{
    const QString value = QString::number(dps, 'g', 10);
    return bound == SpeedBound::Command
               ? tr("within the drive's own Max Speed of %1 dps (read from it)").arg(value)
               : tr("max speed %1 dps (the drive's own Max Speed, read from it)").arg(value);
}

} // namespace lk::safety
