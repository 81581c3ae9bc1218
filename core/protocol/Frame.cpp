#include "Frame.h"

#include "Checksum.h"
#include "Command.h"
#include "Values.h"

namespace lk::protocol {

QByteArray encodeFrame(quint8 command, quint8 id, const QByteArray &data)
{
    // Typed requests and replies never exceed 58 bytes; the LEN byte could not say more.
    Q_ASSERT(data.size() <= kMaxDataLength);
    const auto len = static_cast<quint8>(data.size());
    QByteArray out;
    out.reserve(kHeaderSize + data.size() + 1);
    out.append(static_cast<char>(kFrameHead));
    out.append(static_cast<char>(command));
    out.append(static_cast<char>(id));
    out.append(static_cast<char>(len));
    out.append(static_cast<char>(headerChecksum(command, id, len)));
    if (!data.isEmpty()) {
        out.append(data);
        out.append(static_cast<char>(byteSum(data.constData(), data.size())));
    }
    return out;
}

QByteArray Frame::encode() const
{
    return encodeFrame(command, id, data);
}

std::optional<FrameDirection> Frame::direction() const
{
    const CommandInfo *info = CommandTable::find(command);
    if (!info)
        return std::nullopt;
    const auto len = data.size();
    if (info->replyEchoesRequest && len == info->requestLength)
        return FrameDirection::Echo;
    // 0x8C has LEN 1 both ways: engage (0x00) and release (0x01) are answered with the same
    // byte, so only the read code 0x10 is a request for certain.
    if (info->command == Command::Brake && len == 1)
        return quint8(data[0]) == kBrakeReadCode ? FrameDirection::Request : FrameDirection::Echo;
    if (len == info->requestLength)
        return FrameDirection::Request;
    if (len == info->replyLength || len == info->altReplyLength)
        return FrameDirection::Reply;
    return std::nullopt;
}

const char *directionName(FrameDirection d)
{
    switch (d) {
    case FrameDirection::Request:
        return "request";
    case FrameDirection::Reply:
        return "reply";
    case FrameDirection::Echo:
        return "echo";
    }
    return "?";
}

} // namespace lk::protocol
