#include "Request.h"

#include "CanLayout.h"
#include "WireBytes.h"

namespace lk::protocol {

namespace {

QByteArray pidBytes(const PidGains &g)
{
    return WireWriter(6)
        .put(g.angleKp)
        .put(g.angleKi)
        .put(g.speedKp)
        .put(g.speedKi)
        .put(g.iqKp)
        .put(g.iqKi)
        .bytes();
}

QByteArray parameterBytes(quint8 paramId, const std::array<quint8, 6> &bytes)
{
    WireWriter w(7);
    w.put(paramId);
    for (quint8 b : bytes)
        w.put(b);
    return w.bytes();
}

struct PayloadEncoder {
    QByteArray operator()(const NoPayload &) const { return {}; }
    QByteArray operator()(const PidGains &g) const { return pidBytes(g); }
    QByteArray operator()(const Acceleration &a) const { return WireWriter().put(a.dps2).bytes(); }
    QByteArray operator()(const EncoderOffset &o) const
    {
        return WireWriter().put(o.offset).bytes();
    }
    QByteArray operator()(const OpenLoopCommand &c) const
    {
        return WireWriter().put(c.power).bytes();
    }
    QByteArray operator()(const TorqueCommand &c) const
    {
        return WireWriter().put(c.iqRaw).bytes();
    }
    QByteArray operator()(const SpeedCommand &c) const
    {
        return WireWriter().put(c.speedRaw).bytes();
    }
    QByteArray operator()(const MultiPositionCommand &c) const
    {
        WireWriter w;
        w.put(c.angleRaw);
        if (c.maxSpeedRaw)
            w.put(*c.maxSpeedRaw);
        return w.bytes();
    }
    QByteArray operator()(const SinglePositionCommand &c) const
    {
        // direction, then the low three bytes of the angle (V2.35); for 0..35999 these are
        // V2.3's uint16 angle and its 0x00 pad, byte for byte. Then the optional max speed.
        WireWriter w;
        w.put(static_cast<quint8>(c.direction))
            .put(static_cast<quint16>(c.angleRaw & 0xFFFF))
            .put(static_cast<quint8>((c.angleRaw >> 16) & 0xFF));
        if (c.maxSpeedRaw)
            w.put(*c.maxSpeedRaw);
        return w.bytes();
    }
    QByteArray operator()(const IncrementPositionCommand &c) const
    {
        WireWriter w;
        w.put(c.angleRaw);
        if (c.maxSpeedRaw)
            w.put(*c.maxSpeedRaw);
        return w.bytes();
    }
    QByteArray operator()(const ParamRead &p) const
    {
        return WireWriter().put(p.paramId).put(quint8(0)).bytes();
    }
    QByteArray operator()(const ParameterValue &v) const
    {
        return parameterBytes(v.paramId, v.bytes);
    }
    // CAN V2.36 only: B1..B7 of the CAN frame (LinkCodec never sends them on RS485).
    QByteArray operator()(const ControlParamRead &p) const { return parameterBytes(p.paramId, {}); }
    QByteArray operator()(const ControlParameter &v) const
    {
        return parameterBytes(v.paramId, v.bytes);
    }
    QByteArray operator()(const BrakeCommand &b) const
    {
        return WireWriter().put(static_cast<quint8>(b.action)).bytes();
    }
    // CAN V2.36 only: B1..B7 of the CAN frame (LinkCodec refuses it on RS485).
    QByteArray operator()(const PositionSet &p) const
    {
        return WireWriter().put(quint8(0)).put(quint16(0)).put(p.angleRaw).bytes();
    }
};

PidGains readPid(const QByteArray &d)
{
    PidGains g;
    g.angleKp = static_cast<quint8>(d[0]);
    g.angleKi = static_cast<quint8>(d[1]);
    g.speedKp = static_cast<quint8>(d[2]);
    g.speedKi = static_cast<quint8>(d[3]);
    g.iqKp = static_cast<quint8>(d[4]);
    g.iqKi = static_cast<quint8>(d[5]);
    return g;
}

// Decodes the payload of a request whose LEN has already been checked against the table.
RequestPayload decodePayload(Command cmd, const QByteArray &d)
{
    const WireReader r(d);
    switch (cmd) {
    case Command::WritePidRam:
    case Command::WritePidRom:
        return readPid(d);
    case Command::WriteAccelRam:
        return Acceleration{r.get<qint32>(0)};
    case Command::WriteEncoderOffset:
        return EncoderOffset{r.get<quint16>(0)};
    case Command::OpenLoop:
        return OpenLoopCommand{r.get<qint16>(0)};
    case Command::Torque:
        return TorqueCommand{r.get<qint16>(0)};
    case Command::Speed:
        return SpeedCommand{r.get<qint32>(0)};
    case Command::MultiPosition:
        return MultiPositionCommand{r.get<qint64>(0), std::nullopt};
    case Command::MultiPositionLimited:
        return MultiPositionCommand{r.get<qint64>(0), r.get<quint32>(8)};
    case Command::SinglePosition:
    case Command::SinglePositionLimited: {
        SinglePositionCommand c;
        c.direction =
            static_cast<quint8>(d[0]) ? SpinDirection::CounterClockwise : SpinDirection::Clockwise;
        c.angleRaw = r.get<quint16>(1) | (quint32(static_cast<quint8>(d[3])) << 16);
        if (cmd == Command::SinglePositionLimited)
            c.maxSpeedRaw = r.get<quint32>(4);
        return c;
    }
    case Command::IncrementPosition:
        return IncrementPositionCommand{r.get<qint32>(0), std::nullopt};
    case Command::IncrementPositionLimited:
        return IncrementPositionCommand{r.get<qint32>(0), r.get<quint32>(4)};
    case Command::ReadParam:
        return ParamRead{static_cast<quint8>(d[0])};
    case Command::WriteParamRam:
    case Command::WriteParamRom:
        return readParameter(d);
    case Command::Brake:
        return BrakeCommand{static_cast<BrakeAction>(static_cast<quint8>(d[0]))};
    default:
        return NoPayload{};
    }
}

} // namespace

ParameterValue readParameter(const QByteArray &d)
{
    ParameterValue v;
    v.paramId = static_cast<quint8>(d[0]);
    for (int i = 0; i < 6; ++i)
        v.bytes[i] = static_cast<quint8>(d[1 + i]);
    return v;
}

Frame Request::toFrame() const
{
    return Frame{static_cast<quint8>(command), id, std::visit(PayloadEncoder{}, payload)};
}

RequestDecodeResult decodeRequest(const Frame &frame)
{
    RequestDecodeResult result;
    const CommandInfo *info = CommandTable::findOnRs485(frame.command);
    if (!info) {
        result.error = DecodeError::UnknownCommand;
        return result;
    }
    if (frame.data.size() != info->requestLength) {
        const auto len = frame.data.size();
        const bool isReply = len == info->replyLength || len == info->altReplyLength;
        result.error = isReply ? DecodeError::WrongDirection : DecodeError::BadLength;
        return result;
    }
    result.request = Request{info->command, frame.id, decodePayload(info->command, frame.data)};
    return result;
}

RequestDecodeResult decodeRequest(const Frame &frame, const DecodeContext &context)
{
    if (context.link == Link::Can)
        return can::decodeRequest(frame, context);
    return decodeRequest(frame);
}

} // namespace lk::protocol
