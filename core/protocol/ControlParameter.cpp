#include "ControlParameter.h"

#include <QtCore/QtEndian>

namespace lk::protocol {

namespace {
constexpr std::array<ControlParamInfo, ControlParamTable::kCount> kControlParams{{
    {ControlParamId::AnglePid, "angle_pid", ControlParamLayout::Pid, true},
    {ControlParamId::SpeedPid, "speed_pid", ControlParamLayout::Pid, true},
    {ControlParamId::CurrentPid, "iq_pid", ControlParamLayout::Pid, true},
    {ControlParamId::InputTorqueLimit, "input_torque_limit", ControlParamLayout::Int16, true},
    {ControlParamId::InputSpeedLimit, "input_speed_limit", ControlParamLayout::Int32, true},
    {ControlParamId::InputAngleLimit, "input_angle_limit", ControlParamLayout::Int32, true},
    {ControlParamId::InputCurrentRamp, "input_current_ramp", ControlParamLayout::Int32, false},
    {ControlParamId::InputSpeedRamp, "input_speed_ramp", ControlParamLayout::Int32, true},
}};
} // namespace

const std::array<ControlParamInfo, ControlParamTable::kCount> &ControlParamTable::all()
{
    return kControlParams;
}

const ControlParamInfo *ControlParamTable::find(quint8 code)
{
    for (const ControlParamInfo &p : kControlParams) {
        if (static_cast<quint8>(p.id) == code)
            return &p;
    }
    return nullptr;
}

const ControlParamInfo &ControlParamTable::info(ControlParamId id)
{
    const ControlParamInfo *p = find(static_cast<quint8>(id));
    return p ? *p : kControlParams[0];
}

std::optional<ControlParamId> ControlParamTable::fromName(const QString &name)
{
    for (const ControlParamInfo &p : kControlParams) {
        if (name == QLatin1String(p.name))
            return p.id;
    }
    return std::nullopt;
}

QString ControlParamTable::name(ControlParamId id)
{
    return QString::fromLatin1(info(id).name);
}

std::optional<ControlParamId> ControlParameter::id() const
{
    const ControlParamInfo *p = ControlParamTable::find(paramId);
    return p ? std::optional<ControlParamId>(p->id) : std::nullopt;
}

std::array<quint16, 3> ControlParameter::pid() const
{
    std::array<quint16, 3> k{};
    for (size_t i = 0; i < 3; ++i)
        k[i] = static_cast<quint16>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
    return k;
}

qint32 ControlParameter::value() const
{
    // Value bytes 3-4 (int16) for the torque limit, 3-6 (int32) for the rest.
    if (paramId == quint8(ControlParamId::InputTorqueLimit))
        return qFromLittleEndian<qint16>(bytes.data() + 2);
    return qFromLittleEndian<qint32>(bytes.data() + 2);
}

ControlParameter ControlParameter::ofPid(ControlParamId id, quint16 kp, quint16 ki, quint16 kd)
{
    ControlParameter p;
    p.paramId = static_cast<quint8>(id);
    qToLittleEndian(kp, p.bytes.data());
    qToLittleEndian(ki, p.bytes.data() + 2);
    qToLittleEndian(kd, p.bytes.data() + 4);
    return p;
}

ControlParameter ControlParameter::ofValue(ControlParamId id, qint32 value)
{
    ControlParameter p;
    p.paramId = static_cast<quint8>(id);
    if (id == ControlParamId::InputTorqueLimit)
        qToLittleEndian(static_cast<qint16>(value), p.bytes.data() + 2);
    else
        qToLittleEndian(value, p.bytes.data() + 2);
    return p;
}

} // namespace lk::protocol
