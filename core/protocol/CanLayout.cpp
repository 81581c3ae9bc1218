#include "CanLayout.h"

#include "Command.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QtEndian>

#include <cmath>
#include <limits>

namespace lk::protocol::can {

namespace {

constexpr quint32 kLastDrive = 32;
constexpr quint32 kMaxSpeedDpsOnCan = 0xFFFF; ///< uint16 of 1 dps
constexpr qint64 kCentiPerUnit = 100;         ///< 0.01 dps per LSB on RS485 and in the values

/// B0..B7 of one frame, written at the document's byte positions (little-endian).
class Bytes8 {
public:
    explicit Bytes8(quint8 command) : m_bytes(kDataSize, '\0') { m_bytes[0] = char(command); }
    template <typename T> Bytes8 &at(int b, T v)
    {
        Q_ASSERT(b >= 1 && b + int(sizeof(T)) <= kDataSize);
        qToLittleEndian(v, m_bytes.data() + b);
        return *this;
    }
    QByteArray bytes() const { return m_bytes; }

private:
    QByteArray m_bytes;
};

/// Reads B1..B7 (a Frame's data) at the document's byte positions.
class Bytes7 {
public:
    explicit Bytes7(const QByteArray &data) : m_data(data) {}
    template <typename T> T at(int b) const
    {
        Q_ASSERT(b >= 1 && b - 1 + int(sizeof(T)) <= m_data.size());
        return qFromLittleEndian<T>(m_data.constData() + b - 1);
    }

private:
    const QByteArray &m_data;
};

CanEncodeResult refused(const QString &field, const QString &range, const QString &problem)
{
    CanEncodeResult r;
    r.error = FieldError{field, range, problem};
    return r;
}

CanEncodeResult encoded(quint32 canId, const Bytes8 &bytes)
{
    CanEncodeResult r;
    r.data = CanData{canId, bytes.bytes()};
    return r;
}

bool isV236(const DecodeContext &c)
{
    return c.generation == Generation::V2_35;
}

/// A max speed of 0.01 dps as CAN's uint16 of 1 dps: rounded down (never faster than
/// asked), at most 65535 dps; nullopt under 1 dps, which CAN cannot say.
std::optional<quint16> canMaxSpeed(quint32 centiDps)
{
    const quint32 dps = std::min<quint32>(centiDps / kCentiPerUnit, kMaxSpeedDpsOnCan);
    if (dps == 0)
        return std::nullopt;
    return static_cast<quint16>(dps);
}

CanEncodeResult refuseMaxSpeed(quint32 centiDps)
{
    return refused(QStringLiteral("max_speed_dps"), QStringLiteral("1..65535 dps"),
                   QCoreApplication::translate("lk::protocol::can::CanLayout",
                                               "got %1 dps: CAN carries whole dps")
                       .arg(centiDps / 100.0));
}

/// Encodes a typed request payload at the CAN positions of `context`'s generation.
struct RequestEncoder {
    Command command;
    quint32 canId;
    const DecodeContext &context;

    Bytes8 head() const { return Bytes8(static_cast<quint8>(command)); }

    CanEncodeResult operator()(const NoPayload &) const { return encoded(canId, head()); }
    CanEncodeResult operator()(const PidGains &g) const
    {
        Bytes8 b = head();
        b.at(2, g.angleKp).at(3, g.angleKi).at(4, g.speedKp).at(5, g.speedKi);
        b.at(6, g.iqKp).at(7, g.iqKi);
        return encoded(canId, b);
    }
    CanEncodeResult operator()(const Acceleration &a) const
    {
        return encoded(canId, head().at(4, a.dps2));
    }
    CanEncodeResult operator()(const EncoderOffset &o) const
    {
        return encoded(canId, head().at(6, o.offset));
    }
    CanEncodeResult operator()(const OpenLoopCommand &c) const
    {
        return int16InB4("power", c.power, isV236(context) ? 850 : 1000);
    }
    CanEncodeResult operator()(const TorqueCommand &c) const
    {
        return int16InB4("iq_raw", c.iqRaw, isV236(context) ? 2048 : 2000);
    }
    /// Power and iq: int16 in B4-B5, within the generation's +-max.
    CanEncodeResult int16InB4(const char *field, qint16 value, qint16 max) const
    {
        if (value < -max || value > max)
            return refused(
                QLatin1String(field), QStringLiteral("-%1..%1").arg(max),
                QCoreApplication::translate("lk::protocol::can::CanLayout", "got %1").arg(value));
        return encoded(canId, head().at(4, value));
    }
    CanEncodeResult operator()(const SpeedCommand &c) const
    {
        Bytes8 b = head();
        b.at(4, c.speedRaw);
        if (!isV236(context))
            return encoded(canId, b);
        // CAN V2.36 reads B2-B3 as the torque limit of this speed command. What 0 means is
        // unknown (unlimited or no torque): never send it, always a real limit.
        if (!c.iqLimitRaw || *c.iqLimitRaw < 1 || *c.iqLimitRaw > kSpeedIqLimitMax)
            return refused(
                QStringLiteral("iq_limit_raw"), QStringLiteral("1..2048"),
                c.iqLimitRaw
                    ? QCoreApplication::translate("lk::protocol::can::CanLayout", "got %1")
                          .arg(*c.iqLimitRaw)
                    : QCoreApplication::translate("lk::protocol::can::CanLayout",
                                                  "none given: CAN V2.36 speed commands carry the "
                                                  "torque limit of the soft limits"));
        return encoded(canId, b.at(2, *c.iqLimitRaw));
    }
    CanEncodeResult operator()(const MultiPositionCommand &c) const
    {
        if (c.angleRaw < std::numeric_limits<qint32>::min() ||
            c.angleRaw > std::numeric_limits<qint32>::max())
            return refused(QStringLiteral("angle_deg"),
                           QStringLiteral("-21474836.48..21474836.47 deg"),
                           QCoreApplication::translate("lk::protocol::can::CanLayout",
                                                       "got %1 deg: CAN carries an int32 angle")
                               .arg(c.angleRaw / 100.0));
        Bytes8 b = head();
        b.at(4, static_cast<qint32>(c.angleRaw));
        return withMaxSpeed(b, c.maxSpeedRaw);
    }
    CanEncodeResult operator()(const SinglePositionCommand &c) const
    {
        Bytes8 b = head();
        b.at(1, static_cast<quint8>(c.direction));
        if (isV236(context)) {
            b.at(4, c.angleRaw);
        } else {
            if (c.angleRaw > 35999)
                return refused(
                    QStringLiteral("angle_deg"), QStringLiteral("0..359.99 deg"),
                    QCoreApplication::translate("lk::protocol::can::CanLayout", "got %1 deg")
                        .arg(c.angleRaw / 100.0));
            b.at(4, static_cast<quint16>(c.angleRaw));
        }
        return withMaxSpeed(b, c.maxSpeedRaw);
    }
    CanEncodeResult operator()(const IncrementPositionCommand &c) const
    {
        Bytes8 b = head();
        b.at(4, c.angleRaw);
        return withMaxSpeed(b, c.maxSpeedRaw);
    }
    CanEncodeResult operator()(const PositionSet &p) const
    {
        if (command != Command::ClearAngle || !isV236(context))
            return notOnCan(); // only V2.36's 0x95 carries an angle
        return encoded(canId, head().at(4, p.angleRaw));
    }
    CanEncodeResult operator()(const BrakeCommand &c) const
    {
        return encoded(canId, head().at(1, static_cast<quint8>(c.action)));
    }
    CanEncodeResult operator()(const ControlParamRead &p) const
    {
        return encoded(canId, head().at(1, p.paramId));
    }
    CanEncodeResult operator()(const ControlParameter &v) const
    {
        Bytes8 b = head();
        b.at(1, v.paramId);
        for (int i = 0; i < 6; ++i)
            b.at(2 + i, v.bytes[size_t(i)]);
        return encoded(canId, b);
    }
    CanEncodeResult operator()(const ParamRead &) const { return notOnCan(); }
    CanEncodeResult operator()(const ParameterValue &) const { return notOnCan(); }

    CanEncodeResult withMaxSpeed(Bytes8 &b, std::optional<quint32> maxSpeedRaw) const
    {
        if (!maxSpeedRaw)
            return encoded(canId, b);
        const std::optional<quint16> dps = canMaxSpeed(*maxSpeedRaw);
        if (!dps)
            return refuseMaxSpeed(*maxSpeedRaw);
        return encoded(canId, b.at(2, *dps));
    }
    CanEncodeResult notOnCan() const
    {
        return refused(
            QStringLiteral("command"), dialectName(context),
            QCoreApplication::translate("lk::protocol::can::CanLayout", "%1 is not on this link")
                .arg(CommandTable::name(command)));
    }
};

/// Encodes a typed reply payload at the CAN positions (the simulator's side).
struct ReplyEncoder {
    Command command;
    quint32 canId;
    const DecodeContext &context;

    Bytes8 head() const { return Bytes8(static_cast<quint8>(command)); }
    /// B1..B7 carry the RS485 reply's seven bytes unchanged (0x9A..0x9D, 0xA0..0xA8).
    CanEncodeResult sameAsRs485(const ReplyPayload &payload) const
    {
        const QByteArray d = Reply{command, 1, payload}.toFrame().data;
        Q_ASSERT(d.size() == kDataSize - 1);
        QByteArray bytes = head().bytes();
        bytes.replace(1, kDataSize - 1, d);
        CanEncodeResult r;
        r.data = CanData{canId, bytes};
        return r;
    }

    CanEncodeResult operator()(const Acknowledged &) const { return encoded(canId, head()); }
    CanEncodeResult operator()(const PidGains &g) const
    {
        return RequestEncoder{command, canId, context}(g);
    }
    CanEncodeResult operator()(const Acceleration &a) const
    {
        return encoded(canId, head().at(4, a.dps2));
    }
    CanEncodeResult operator()(const EncoderReading &e) const
    {
        return encoded(canId, head().at(2, e.encoder).at(4, e.encoderRaw).at(6, e.encoderOffset));
    }
    CanEncodeResult operator()(const EncoderOffset &o) const
    {
        return encoded(canId, head().at(6, o.offset));
    }
    CanEncodeResult operator()(const ZeroWritten &z) const
    {
        return encoded(canId, head().at(6, z.encoderOffset.value_or(0)));
    }
    CanEncodeResult operator()(const MultiTurnAngle &a) const
    {
        // The low seven bytes of the int64: B1..B7.
        QByteArray bytes = head().bytes();
        char v[8];
        qToLittleEndian(a.raw, v);
        bytes.replace(1, kDataSize - 1, QByteArray(v, kDataSize - 1));
        CanEncodeResult r;
        r.data = CanData{canId, bytes};
        return r;
    }
    CanEncodeResult operator()(const SingleTurnAngle &a) const
    {
        return encoded(canId, head().at(4, a.raw));
    }
    CanEncodeResult operator()(const State1 &s) const { return sameAsRs485(s); }
    CanEncodeResult operator()(const State2 &s) const { return sameAsRs485(s); }
    CanEncodeResult operator()(const State3 &s) const { return sameAsRs485(s); }
    CanEncodeResult operator()(const BrakeState &b) const
    {
        return encoded(canId, head().at(1, b.raw));
    }
    CanEncodeResult operator()(const ControlParameter &v) const
    {
        return RequestEncoder{command, canId, context}(v);
    }
    CanEncodeResult operator()(const ModelInfo &) const { return notOnCan(); }
    CanEncodeResult operator()(const ParameterValue &) const { return notOnCan(); }
    CanEncodeResult operator()(const ParamWriteResult &) const { return notOnCan(); }
    CanEncodeResult notOnCan() const { return RequestEncoder{command, canId, context}.notOnCan(); }
};

PidGains pidAt(const Bytes7 &b)
{
    PidGains g;
    g.angleKp = b.at<quint8>(2);
    g.angleKi = b.at<quint8>(3);
    g.speedKp = b.at<quint8>(4);
    g.speedKi = b.at<quint8>(5);
    g.iqKp = b.at<quint8>(6);
    g.iqKi = b.at<quint8>(7);
    return g;
}

/// B1 the control parameter's ID, B2..B7 its value bytes (0xC0 reply, 0xC1 both ways).
ControlParameter controlParamAt(const Bytes7 &b)
{
    ControlParameter p;
    p.paramId = b.at<quint8>(1);
    for (int i = 0; i < 6; ++i)
        p.bytes[size_t(i)] = b.at<quint8>(2 + i);
    return p;
}

std::optional<quint32> centiDps(Command limited, Command cmd, const Bytes7 &b)
{
    if (cmd != limited)
        return std::nullopt;
    return quint32(b.at<quint16>(2)) * kCentiPerUnit;
}

RequestPayload requestPayload(Command cmd, const Bytes7 &b, const DecodeContext &context)
{
    switch (cmd) {
    case Command::WritePidRam:
    case Command::WritePidRom:
        return pidAt(b);
    case Command::WriteAccelRam:
        return Acceleration{b.at<qint32>(4)};
    case Command::WriteEncoderOffset:
        return EncoderOffset{b.at<quint16>(6)};
    case Command::OpenLoop:
        return OpenLoopCommand{b.at<qint16>(4)};
    case Command::Torque:
        return TorqueCommand{b.at<qint16>(4)};
    case Command::Speed: {
        SpeedCommand c{b.at<qint32>(4), std::nullopt};
        if (isV236(context))
            c.iqLimitRaw = b.at<qint16>(2);
        return c;
    }
    case Command::MultiPosition:
    case Command::MultiPositionLimited:
        return MultiPositionCommand{b.at<qint32>(4),
                                    centiDps(Command::MultiPositionLimited, cmd, b)};
    case Command::SinglePosition:
    case Command::SinglePositionLimited: {
        SinglePositionCommand c;
        c.direction = b.at<quint8>(1) ? SpinDirection::CounterClockwise : SpinDirection::Clockwise;
        c.angleRaw = isV236(context) ? b.at<quint32>(4) : b.at<quint16>(4);
        c.maxSpeedRaw = centiDps(Command::SinglePositionLimited, cmd, b);
        return c;
    }
    case Command::IncrementPosition:
    case Command::IncrementPositionLimited:
        return IncrementPositionCommand{b.at<qint32>(4),
                                        centiDps(Command::IncrementPositionLimited, cmd, b)};
    case Command::Brake:
        return BrakeCommand{static_cast<BrakeAction>(b.at<quint8>(1))};
    case Command::ClearAngle:
        // V2.36 sets the position to any angle; 0 (and the old generation's) is the plain one.
        if (isV236(context) && b.at<qint32>(4) != 0)
            return PositionSet{b.at<qint32>(4)};
        return NoPayload{};
    case Command::ReadControlParam:
        return ControlParamRead{b.at<quint8>(1)};
    case Command::WriteControlParam:
        return controlParamAt(b);
    default:
        return NoPayload{};
    }
}

/// The multi-turn angle of B1..B7: seven bytes of an int64, sign-extended from bit 55.
qint64 angleOf7Bytes(const QByteArray &d)
{
    quint64 v = 0;
    for (int i = 6; i >= 0; --i)
        v = (v << 8) | static_cast<quint8>(d[i]);
    if (v & (quint64(1) << 55))
        v |= quint64(0xFF) << 56;
    return static_cast<qint64>(v);
}

std::optional<ReplyPayload> ownLayoutReply(Command cmd, const Frame &frame)
{
    const Bytes7 b(frame.data);
    switch (cmd) {
    case Command::ReadPid:
    case Command::WritePidRam:
    case Command::WritePidRom:
        return pidAt(b);
    case Command::ReadAccel:
    case Command::WriteAccelRam:
        return Acceleration{b.at<qint32>(4)};
    case Command::ReadEncoder:
        return EncoderReading{b.at<quint16>(2), b.at<quint16>(4), b.at<quint16>(6)};
    case Command::WriteEncoderOffset:
        return EncoderOffset{b.at<quint16>(6)};
    case Command::WriteZeroRom:
        return ZeroWritten{b.at<quint16>(6)};
    case Command::ReadMultiTurn:
        return MultiTurnAngle{angleOf7Bytes(frame.data)};
    case Command::ReadSingleTurn:
        return SingleTurnAngle{b.at<quint32>(4)};
    case Command::MotorOff:
    case Command::MotorStop:
    case Command::MotorRun:
    case Command::ClearAngle:
        return Acknowledged{};
    case Command::Brake:
        return BrakeState{b.at<quint8>(1)};
    case Command::ReadControlParam:
    case Command::WriteControlParam:
        return controlParamAt(b);
    default:
        return std::nullopt; // the RS485 reply's seven bytes: read by the RS485 layouts
    }
}

bool knownOn(const Frame &frame, const DecodeContext &context, DecodeError *error)
{
    const CommandInfo *info = CommandTable::find(frame.command);
    if (!info || !CommandTable::availableOn(info->command, context)) {
        *error = DecodeError::UnknownCommand;
        return false;
    }
    if (frame.data.size() != kDataSize - 1) {
        *error = DecodeError::BadLength;
        return false;
    }
    return true;
}

} // namespace

std::optional<DriveAddress> driveAddressOf(quint32 canId)
{
    for (IdBase base : {IdBase::Base140, IdBase::Base180}) {
        const quint32 first = base == IdBase::Base140 ? kRequestBase : kReplyBaseV236;
        if (canId > first && canId <= first + kLastDrive)
            return DriveAddress{static_cast<quint8>(canId - first), base};
    }
    return std::nullopt;
}

quint32 requestCanId(quint8 driveId)
{
    return kRequestBase + driveId;
}

quint32 replyCanId(quint8 driveId, Generation generation)
{
    return (generation == Generation::V2_35 ? kReplyBaseV236 : kRequestBase) + driveId;
}

CanEncodeResult encodeRequest(const Request &request, const DecodeContext &context)
{
    const RequestEncoder encoder{request.command, requestCanId(request.id), context};
    if (!CommandTable::availableOn(request.command, context))
        return encoder.notOnCan();
    return std::visit(encoder, request.payload);
}

CanEncodeResult encodeReply(const Reply &reply, const DecodeContext &context)
{
    const ReplyEncoder encoder{reply.command, replyCanId(reply.id, context.generation), context};
    if (!CommandTable::availableOn(reply.command, context))
        return encoder.notOnCan();
    return std::visit(encoder, reply.payload);
}

std::optional<Frame> frameOf(const CanData &data)
{
    const std::optional<DriveAddress> address = driveAddressOf(data.canId);
    if (!address || data.bytes.size() != kDataSize)
        return std::nullopt;
    return Frame{static_cast<quint8>(data.bytes[0]), address->driveId, data.bytes.mid(1)};
}

QByteArray bytesOf(const Frame &frame)
{
    QByteArray bytes(1, static_cast<char>(frame.command));
    bytes.append(frame.data);
    return bytes;
}

RequestDecodeResult decodeRequest(const Frame &frame, const DecodeContext &context)
{
    RequestDecodeResult result;
    if (!knownOn(frame, context, &result.error))
        return result;
    const Command cmd = CommandTable::find(frame.command)->command;
    result.request = Request{cmd, frame.id, requestPayload(cmd, Bytes7(frame.data), context)};
    return result;
}

ReplyDecodeResult decodeReply(const Frame &frame, const DecodeContext &context)
{
    ReplyDecodeResult result;
    if (!knownOn(frame, context, &result.error))
        return result;
    const Command cmd = CommandTable::find(frame.command)->command;
    if (std::optional<ReplyPayload> p = ownLayoutReply(cmd, frame)) {
        result.reply = Reply{cmd, frame.id, *p};
        return result;
    }
    // 0x9A..0x9D and the motion replies: B1..B7 are the RS485 reply's D0..D6, with the
    // generation's scales (docs/CAN.md section 6).
    DecodeContext rs485 = context;
    rs485.link = Link::Rs485;
    return protocol::decodeReply(frame, rs485);
}

std::optional<Generation> generationHint(const CanData &reply)
{
    const std::optional<DriveAddress> address = driveAddressOf(reply.canId);
    if (!address || reply.bytes.size() != kDataSize)
        return std::nullopt;
    if (address->base == IdBase::Base180)
        return Generation::V2_35;
    const auto cmd = static_cast<quint8>(reply.bytes[0]);
    if (cmd != quint8(Command::ReadState1) && cmd != quint8(Command::ClearErrors))
        return std::nullopt;
    const char *b = reply.bytes.constData();
    const auto plausible = [](double volts) { return volts >= 6.0 && volts <= 60.0; };
    const bool old =
        b[2] == 0 && b[5] == 0 && b[6] == 0 && plausible(qFromLittleEndian<quint16>(b + 3) * 0.1);
    const auto state = static_cast<quint8>(b[6]);
    const bool v236 =
        plausible(qFromLittleEndian<qint16>(b + 2) * 0.01) && (state == 0x00 || state == 0x10);
    if (old == v236)
        return std::nullopt;
    return old ? Generation::V2_3 : Generation::V2_35;
}

CanEncodeResult encodeMultiMotorTorque(const std::array<qint16, kMultiMotorDrives> &iqRaw)
{
    QByteArray bytes(kDataSize, '\0');
    for (int i = 0; i < kMultiMotorDrives; ++i) {
        const qint16 v = iqRaw[static_cast<size_t>(i)];
        if (v < -kMultiMotorIqMax || v > kMultiMotorIqMax)
            return refused(
                QStringLiteral("iq_raw"), QStringLiteral("-2000..2000"),
                QCoreApplication::translate("lk::protocol::can::CanLayout", "got %1 for ID %2")
                    .arg(v)
                    .arg(i + 1));
        qToLittleEndian(v, bytes.data() + 2 * i);
    }
    CanEncodeResult r;
    r.data = CanData{kMultiMotorId, bytes};
    return r;
}

std::optional<std::array<qint16, kMultiMotorDrives>> decodeMultiMotorTorque(const CanData &data)
{
    if (data.canId != kMultiMotorId || data.bytes.size() != kDataSize)
        return std::nullopt;
    std::array<qint16, kMultiMotorDrives> iq{};
    for (int i = 0; i < kMultiMotorDrives; ++i)
        iq[static_cast<size_t>(i)] = qFromLittleEndian<qint16>(data.bytes.constData() + 2 * i);
    return iq;
}

CanData encodeSetPosition(quint8 driveId, qint32 angleRaw)
{
    return CanData{requestCanId(driveId),
                   Bytes8(static_cast<quint8>(Command::ClearAngle)).at(4, angleRaw).bytes()};
}

std::optional<qint32> decodeSetPosition(const CanData &data)
{
    if (data.bytes.size() != kDataSize || !driveAddressOf(data.canId) ||
        static_cast<quint8>(data.bytes[0]) != static_cast<quint8>(Command::ClearAngle))
        return std::nullopt;
    return qFromLittleEndian<qint32>(data.bytes.constData() + 4);
}

} // namespace lk::protocol::can
