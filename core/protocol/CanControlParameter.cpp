#include "CanLayout.h"

#include <QtCore/QtEndian>

// The CAN V2.36 control parameters (0xC0 read, 0xC1 write): their value bytes, apart from the
// frame layouts in CanLayout.cpp.
namespace lk::protocol::can {

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

std::optional<ControlParameter> decodeControlParam(const CanData &data)
{
    if (data.bytes.size() != kDataSize || !driveAddressOf(data.canId))
        return std::nullopt;
    const auto cmd = static_cast<quint8>(data.bytes[0]);
    if (cmd != kReadControlParam && cmd != kWriteControlParam)
        return std::nullopt;
    ControlParameter p;
    p.paramId = static_cast<quint8>(data.bytes[1]);
    for (int i = 0; i < 6; ++i)
        p.bytes[static_cast<size_t>(i)] = static_cast<quint8>(data.bytes[2 + i]);
    return p;
}

} // namespace lk::protocol::can
