#include "Parameter.h"

namespace lk::protocol {

namespace {
constexpr std::array<ParamInfo, ParamTable::kCount> kParams{{
    {ParamId::AnglePid, "angle_pid", ParamLayout::Pid},
    {ParamId::SpeedPid, "speed_pid", ParamLayout::Pid},
    {ParamId::CurrentPid, "iq_pid", ParamLayout::Pid},
    {ParamId::MaxTorqueCurrent, "max_torque", ParamLayout::Int16},
    {ParamId::MaxSpeed, "max_speed", ParamLayout::Int32},
    {ParamId::MaxAngleLow, "max_angle_low", ParamLayout::HalfInt64},
    {ParamId::MaxAngleHigh, "max_angle_high", ParamLayout::HalfInt64},
    {ParamId::CurrentRamp, "current_ramp", ParamLayout::Int16},
    {ParamId::SpeedRamp, "speed_ramp", ParamLayout::Int32},
}};

void putLe(std::array<quint8, 6> &b, int at, quint64 v, int n)
{
    for (int i = 0; i < n; ++i)
        b[at + i] = static_cast<quint8>(v >> (8 * i));
}
} // namespace

const std::array<ParamInfo, ParamTable::kCount> &ParamTable::all()
{
    return kParams;
}

const ParamInfo *ParamTable::find(quint8 code)
{
    for (const ParamInfo &p : kParams) {
        if (static_cast<quint8>(p.id) == code)
            return &p;
    }
    return nullptr;
}

const ParamInfo &ParamTable::info(ParamId id)
{
    const ParamInfo *p = find(static_cast<quint8>(id));
    return p ? *p : kParams[0]; // a ParamId outside the table can only come from a cast
}

std::optional<ParamId> ParamTable::fromName(const QString &name)
{
    for (const ParamInfo &p : kParams) {
        if (name == QLatin1String(p.name))
            return p.id;
    }
    return std::nullopt;
}

QString ParamTable::name(ParamId id)
{
    const ParamInfo *p = find(static_cast<quint8>(id));
    return p ? QString::fromLatin1(p->name)
             : QStringLiteral("0x%1").arg(static_cast<quint8>(id), 2, 16, QLatin1Char('0'));
}

ParameterValue ParameterValue::pid(ParamId id, quint16 kp, quint16 ki, quint16 kd)
{
    ParameterValue v;
    v.paramId = static_cast<quint8>(id);
    putLe(v.bytes, 0, kp, 2);
    putLe(v.bytes, 2, ki, 2);
    putLe(v.bytes, 4, kd, 2);
    return v;
}

ParameterValue ParameterValue::int16(ParamId id, qint16 value)
{
    ParameterValue v;
    v.paramId = static_cast<quint8>(id);
    putLe(v.bytes, 0, static_cast<quint16>(value), 2);
    return v;
}

ParameterValue ParameterValue::int32(ParamId id, qint32 value)
{
    ParameterValue v;
    v.paramId = static_cast<quint8>(id);
    putLe(v.bytes, 0, static_cast<quint32>(value), 4);
    return v;
}

ParameterValue ParameterValue::maxAngleHalf(qint64 maxAngleRaw, bool high)
{
    const auto u = static_cast<quint64>(maxAngleRaw);
    ParameterValue v;
    v.paramId = static_cast<quint8>(high ? ParamId::MaxAngleHigh : ParamId::MaxAngleLow);
    putLe(v.bytes, 0, high ? (u >> 32) : (u & 0xFFFFFFFFu), 4);
    return v;
}

std::optional<ParamId> ParameterValue::id() const
{
    const ParamInfo *p = ParamTable::find(paramId);
    return p ? std::optional<ParamId>(p->id) : std::nullopt;
}

qint32 ParameterValue::asInt32() const
{
    quint32 u = 0;
    for (int i = 0; i < 4; ++i)
        u |= quint32(bytes[i]) << (8 * i);
    return static_cast<qint32>(u);
}

qint64 joinMaxAngle(const ParameterValue &low, const ParameterValue &high)
{
    return static_cast<qint64>((quint64(high.asUInt32()) << 32) | low.asUInt32());
}

} // namespace lk::protocol
