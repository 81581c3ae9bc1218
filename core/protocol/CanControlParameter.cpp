#include "CanLayout.h"

// The CAN V2.36 control parameters (0xC0 read, 0xC1 write) as whole frames, apart from the
// frame layouts in CanLayout.cpp; their value bytes are ControlParameter's.
namespace lk::protocol::can {

namespace {
CanData frame(quint8 driveId, quint8 command, quint8 paramId, const std::array<quint8, 6> &value)
{
    QByteArray b(kDataSize, '\0');
    b[0] = char(command);
    b[1] = char(paramId);
    for (int i = 0; i < 6; ++i)
        b[2 + i] = char(value[static_cast<size_t>(i)]);
    return CanData{requestCanId(driveId), b};
}
} // namespace

CanData encodeControlParamRead(quint8 driveId, ControlParamId param)
{
    return frame(driveId, kReadControlParam, static_cast<quint8>(param), {});
}

CanData encodeControlParamWrite(quint8 driveId, const ControlParameter &value)
{
    return frame(driveId, kWriteControlParam, value.paramId, value.bytes);
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
