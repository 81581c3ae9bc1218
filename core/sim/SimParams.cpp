#include "SimParams.h"

#include <algorithm>
#include <cstdint>

namespace lk::sim {

using protocol::ParameterValue;
using protocol::ParamId;

namespace {
quint8 saturate(quint16 v)
{
    return static_cast<quint8>(std::min<quint16>(v, 255));
}
} // namespace

std::optional<ParameterValue> SimParams::read(quint8 paramId) const
{
    const protocol::ParamInfo *info = protocol::ParamTable::find(paramId);
    if (!info)
        return std::nullopt;
    switch (info->id) {
    case ParamId::AnglePid:
        return ParameterValue::pid(info->id, anglePid[0], anglePid[1], anglePid[2]);
    case ParamId::SpeedPid:
        return ParameterValue::pid(info->id, speedPid[0], speedPid[1], speedPid[2]);
    case ParamId::CurrentPid:
        return ParameterValue::pid(info->id, currentPid[0], currentPid[1], currentPid[2]);
    case ParamId::MaxTorqueCurrent:
        return ParameterValue::int16(info->id, maxTorque);
    case ParamId::MaxSpeed:
        return ParameterValue::int32(info->id, maxSpeedRaw);
    case ParamId::MaxAngleLow:
        return ParameterValue::maxAngleHalf(maxAngleRaw, false);
    case ParamId::MaxAngleHigh:
        return ParameterValue::maxAngleHalf(maxAngleRaw, true);
    case ParamId::CurrentRamp:
        return ParameterValue::int16(info->id, static_cast<qint16>(currentRamp));
    case ParamId::SpeedRamp:
        return ParameterValue::int32(info->id, speedRampDps2);
    }
    return std::nullopt;
}

bool SimParams::write(const ParameterValue &v)
{
    const std::optional<ParamId> id = v.id();
    if (!id)
        return false;
    const Pid pid{v.pidKp(), v.pidKi(), v.pidKd()};
    const auto half = static_cast<quint64>(v.asUInt32());
    auto angle = static_cast<quint64>(maxAngleRaw);
    switch (*id) {
    case ParamId::AnglePid:
        anglePid = pid;
        break;
    case ParamId::SpeedPid:
        speedPid = pid;
        break;
    case ParamId::CurrentPid:
        currentPid = pid;
        break;
    case ParamId::MaxTorqueCurrent:
        maxTorque = v.asInt16();
        break;
    case ParamId::MaxSpeed:
        maxSpeedRaw = v.asInt32();
        break;
    case ParamId::MaxAngleLow: // each half replaces its 32 bits of the int64
        maxAngleRaw = static_cast<qint64>((angle & 0xFFFFFFFF00000000ull) | half);
        break;
    case ParamId::MaxAngleHigh:
        maxAngleRaw = static_cast<qint64>((angle & 0xFFFFFFFFull) | (half << 32));
        break;
    case ParamId::CurrentRamp:
        currentRamp = v.asInt16();
        break;
    case ParamId::SpeedRamp:
        speedRampDps2 = v.asInt32();
        break;
    }
    return true;
}

std::optional<protocol::ControlParameter> SimParams::readControl(quint8 paramId) const
{
    using protocol::ControlParameter;
    using protocol::ControlParamId;
    const protocol::ControlParamInfo *info = protocol::ControlParamTable::find(paramId);
    if (!info)
        return std::nullopt;
    switch (info->id) {
    case ControlParamId::AnglePid:
        return ControlParameter::ofPid(info->id, anglePid[0], anglePid[1], anglePid[2]);
    case ControlParamId::SpeedPid:
        return ControlParameter::ofPid(info->id, speedPid[0], speedPid[1], speedPid[2]);
    case ControlParamId::CurrentPid:
        return ControlParameter::ofPid(info->id, currentPid[0], currentPid[1], currentPid[2]);
    case ControlParamId::InputTorqueLimit:
        return ControlParameter::ofValue(info->id, maxTorque);
    case ControlParamId::InputSpeedLimit:
        return ControlParameter::ofValue(info->id, maxSpeedRaw);
    case ControlParamId::InputAngleLimit:
        return ControlParameter::ofValue(
            info->id, static_cast<qint32>(std::clamp<qint64>(maxAngleRaw, INT32_MIN, INT32_MAX)));
    case ControlParamId::InputCurrentRamp:
        return ControlParameter::ofValue(info->id, currentRamp);
    case ControlParamId::InputSpeedRamp:
        return ControlParameter::ofValue(info->id, speedRampDps2);
    }
    return std::nullopt;
}

bool SimParams::writeControl(const protocol::ControlParameter &v)
{
    using protocol::ControlParamId;
    const std::optional<ControlParamId> id = v.id();
    if (!id)
        return false;
    const std::array<quint16, 3> k = v.pid();
    switch (*id) {
    case ControlParamId::AnglePid:
        anglePid = k;
        break;
    case ControlParamId::SpeedPid:
        speedPid = k;
        break;
    case ControlParamId::CurrentPid:
        currentPid = k;
        break;
    case ControlParamId::InputTorqueLimit:
        maxTorque = static_cast<qint16>(v.value());
        break;
    case ControlParamId::InputSpeedLimit:
        maxSpeedRaw = v.value();
        break;
    case ControlParamId::InputAngleLimit:
        maxAngleRaw = v.value();
        break;
    case ControlParamId::InputCurrentRamp:
        currentRamp = v.value();
        break;
    case ControlParamId::InputSpeedRamp:
        speedRampDps2 = v.value();
        break;
    }
    return true;
}

protocol::PidGains SimParams::physicsGains() const
{
    return {saturate(anglePid[0]), saturate(anglePid[1]),   saturate(speedPid[0]),
            saturate(speedPid[1]), saturate(currentPid[0]), saturate(currentPid[1])};
}

DerivativeGains SimParams::derivativeGains() const
{
    return {anglePid[2], speedPid[2], currentPid[2]};
}

bool SimParams::operator==(const SimParams &o) const
{
    return anglePid == o.anglePid && speedPid == o.speedPid && currentPid == o.currentPid &&
           maxTorque == o.maxTorque && maxSpeedRaw == o.maxSpeedRaw &&
           maxAngleRaw == o.maxAngleRaw && currentRamp == o.currentRamp &&
           speedRampDps2 == o.speedRampDps2;
}

} // namespace lk::sim
