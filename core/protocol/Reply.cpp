#include "Reply.h"

#include "CanLayout.h"
#include "WireBytes.h"

namespace lk::protocol {

namespace {

constexpr int kNameSize = 20;
constexpr int kMotorIdSize = 12;
constexpr int kModelLenV23 = 42;

QByteArray nameField(const QString &name)
{
    QByteArray b = name.toLatin1().left(kNameSize);
    b.append(QByteArray(kNameSize - b.size(), '\0'));
    return b;
}

QString nameFromField(const QByteArray &d, int offset)
{
    QByteArray b = d.mid(offset, kNameSize);
    const auto nul = b.indexOf('\0');
    if (nul >= 0)
        b.truncate(nul);
    return QString::fromLatin1(b).trimmed();
}

struct PayloadEncoder {
    QByteArray operator()(const Acknowledged &) const { return {}; }
    QByteArray operator()(const PidGains &g) const
    {
        return Request{Command::WritePidRam, 1, g}.toFrame().data;
    }
    QByteArray operator()(const Acceleration &a) const { return WireWriter().put(a.dps2).bytes(); }
    QByteArray operator()(const EncoderReading &e) const
    {
        return WireWriter().put(e.encoder).put(e.encoderRaw).put(e.encoderOffset).bytes();
    }
    QByteArray operator()(const EncoderOffset &o) const
    {
        return WireWriter().put(o.offset).bytes();
    }
    QByteArray operator()(const ZeroWritten &z) const
    {
        return z.encoderOffset ? WireWriter().put(*z.encoderOffset).bytes() : QByteArray();
    }
    QByteArray operator()(const MultiTurnAngle &a) const { return WireWriter().put(a.raw).bytes(); }
    QByteArray operator()(const SingleTurnAngle &a) const
    {
        return WireWriter().put(a.raw).bytes();
    }
    QByteArray operator()(const State1 &s) const
    {
        if (s.generation == Generation::V2_35)
            return WireWriter()
                .put(s.temperatureC)
                .put(s.voltageRaw)
                .put(s.busCurrentRaw)
                .put(s.motorStateRaw)
                .put(s.errorState)
                .bytes();
        return WireWriter()
            .put(s.temperatureC)
            .put(quint8(0))
            .put(s.voltageRaw)
            .put(quint8(0))
            .put(quint8(0))
            .put(s.errorState)
            .bytes();
    }
    QByteArray operator()(const State2 &s) const
    {
        return WireWriter()
            .put(s.temperatureC)
            .put(s.torqueRaw)
            .put(s.speedDps)
            .put(s.encoder)
            .bytes();
    }
    QByteArray operator()(const State3 &s) const
    {
        return WireWriter().put(s.temperatureC).put(s.iaRaw).put(s.ibRaw).put(s.icRaw).bytes();
    }
    QByteArray operator()(const ParameterValue &v) const
    {
        return Request{Command::WriteParamRam, 1, v}.toFrame().data;
    }
    QByteArray operator()(const ParamWriteResult &r) const
    {
        return WireWriter().put(r.paramId).put(r.flag).bytes();
    }
    QByteArray operator()(const BrakeState &b) const { return WireWriter().put(b.raw).bytes(); }
    QByteArray operator()(const ControlParameter &v) const // CAN V2.36 only: B1..B7
    {
        return Request{Command::WriteControlParam, 1, v}.toFrame().data;
    }
    QByteArray operator()(const ModelInfo &m) const
    {
        WireWriter w(58);
        w.putBytes(nameField(m.driverName)).putBytes(nameField(m.motorName));
        if (m.generation == Generation::V2_3)
            return w.put(static_cast<quint8>(m.hardwareRaw))
                .put(static_cast<quint8>(m.firmwareRaw))
                .bytes();
        QByteArray id = m.motorId.left(kMotorIdSize);
        id.append(QByteArray(kMotorIdSize - id.size(), '\0'));
        return w.putBytes(id).put(m.hardwareRaw).put(m.motorVersionRaw).put(m.firmwareRaw).bytes();
    }
};

State1 readState1(const WireReader &r, Generation generation)
{
    State1 s;
    s.wire = r.bytes();
    s.generation = generation;
    s.temperatureC = r.get<qint8>(0);
    s.errorState = r.get<quint8>(6);
    if (generation == Generation::V2_3) {
        s.voltageRaw = r.get<quint16>(2);
        return s;
    }
    s.voltageRaw = r.get<quint16>(1);
    s.busCurrentRaw = r.get<qint16>(3);
    s.motorStateRaw = r.get<quint8>(5);
    return s;
}

State2 readState2(const WireReader &r, bool isPower, const DecodeContext &ctx)
{
    State2 s;
    s.temperatureC = r.get<qint8>(0);
    s.torqueRaw = r.get<qint16>(1);
    s.isPower = isPower;
    s.speedDps = r.get<qint16>(3);
    s.encoder = r.get<quint16>(5);
    s.iqAmpsPerLsb = iqReplyAmpsPerLsb(ctx);
    return s;
}

ModelInfo readModel(const QByteArray &d, const WireReader &r)
{
    ModelInfo m;
    m.driverName = nameFromField(d, 0);
    m.motorName = nameFromField(d, kNameSize);
    if (d.size() == kModelLenV23) {
        m.generation = Generation::V2_3;
        m.hardwareRaw = r.get<quint8>(40);
        m.firmwareRaw = r.get<quint8>(41);
    } else {
        m.generation = Generation::V2_35;
        m.motorId = d.mid(40, kMotorIdSize);
        m.hardwareRaw = r.get<quint16>(52);
        m.motorVersionRaw = r.get<quint16>(54);
        m.firmwareRaw = r.get<quint16>(56);
    }
    return m;
}

// Decodes a reply whose LEN has already been checked against the command table.
ReplyPayload decodePayload(Command cmd, const QByteArray &d, const DecodeContext &ctx)
{
    const WireReader r(d);
    switch (cmd) {
    case Command::ReadPid:
    case Command::WritePidRam:
    case Command::WritePidRom:
        return std::get<PidGains>(decodeRequest(Frame{0x31, 1, d}).request->payload);
    case Command::ReadAccel:
    case Command::WriteAccelRam:
        return Acceleration{r.get<qint32>(0)};
    case Command::ReadEncoder:
        return EncoderReading{r.get<quint16>(0), r.get<quint16>(2), r.get<quint16>(4)};
    case Command::WriteEncoderOffset:
        return EncoderOffset{r.get<quint16>(0)};
    case Command::WriteZeroRom:
        return d.size() == 2 ? ZeroWritten{r.get<quint16>(0)} : ZeroWritten{};
    case Command::ReadMultiTurn:
        return MultiTurnAngle{r.get<qint64>(0)};
    case Command::ReadSingleTurn:
        return SingleTurnAngle{r.get<quint32>(0)};
    case Command::ReadState1:
    case Command::ClearErrors:
        return readState1(r, ctx.generation);
    case Command::ReadState3:
        return State3{r.get<qint8>(0), r.get<qint16>(1), r.get<qint16>(3), r.get<qint16>(5),
                      phaseAmpsPerLsb(ctx)};
    case Command::ReadModel:
        return readModel(d, r);
    case Command::MotorOff:
    case Command::MotorStop:
    case Command::MotorRun:
    case Command::ClearAngle:
    case Command::ClearTurnCount:
        return Acknowledged{};
    case Command::ReadParam:
        return readParameter(d);
    case Command::WriteParamRam:
    case Command::WriteParamRom:
        return ParamWriteResult{r.get<quint8>(0), r.get<quint8>(1)};
    case Command::Brake:
        return BrakeState{r.get<quint8>(0)};
    case Command::OpenLoop:
        return readState2(r, true, ctx); // 0xA0 exists only on MS: always power
    case Command::ReadState2:
    case Command::Torque:
    case Command::Speed:
    case Command::MultiPosition:
    case Command::MultiPositionLimited:
    case Command::SinglePosition:
    case Command::SinglePositionLimited:
    case Command::IncrementPosition:
    case Command::IncrementPositionLimited:
        return readState2(r, ctx.reportsPower() && cmd != Command::Torque, ctx);
    case Command::ReadControlParam: // CAN only: never decoded from an RS485 frame
    case Command::WriteControlParam:
        break;
    }
    return Acknowledged{};
}

} // namespace

State1 State1::as(Generation g) const
{
    if (wire.size() != 7 || g == generation)
        return *this;
    return readState1(WireReader(wire), g);
}

Frame Reply::toFrame() const
{
    return Frame{static_cast<quint8>(command), id, std::visit(PayloadEncoder{}, payload)};
}

ReplyDecodeResult decodeReply(const Frame &frame, const DecodeContext &context)
{
    if (context.link == Link::Can)
        return can::decodeReply(frame, context);
    ReplyDecodeResult result;
    const CommandInfo *info = CommandTable::findOnRs485(frame.command);
    if (!info) {
        result.error = DecodeError::UnknownCommand;
        return result;
    }
    const auto len = frame.data.size();
    if (len != info->replyLength && len != info->altReplyLength) {
        result.error =
            len == info->requestLength ? DecodeError::WrongDirection : DecodeError::BadLength;
        return result;
    }
    result.reply =
        Reply{info->command, frame.id, decodePayload(info->command, frame.data, context)};
    return result;
}

} // namespace lk::protocol
