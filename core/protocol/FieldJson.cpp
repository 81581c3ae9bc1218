#include "FieldJson.h"

#include "ErrorFlags.h"
#include "OrderedJson.h"
#include "ProtocolFields.h"

#include <QtCore/QJsonValue>

namespace lk::protocol {

namespace {

// ---- values -> JSON -------------------------------------------------------------------------

QJsonValue integer(qint64 v)
{
    return QJsonValue(v);
}

// Divisions by exact decimal powers give the double nearest to the decimal value, so 12345
// becomes 123.45 and not the 123.45000000000002 that 12345 * 0.01 gives.
QJsonValue centi(qint64 raw)
{
    return QJsonValue(static_cast<double>(raw) / 100.0);
}

QJsonObject pidFields(const PidGains &g)
{
    return {{QStringLiteral("angle_kp"), integer(g.angleKp)},
            {QStringLiteral("angle_ki"), integer(g.angleKi)},
            {QStringLiteral("speed_kp"), integer(g.speedKp)},
            {QStringLiteral("speed_ki"), integer(g.speedKi)},
            {QStringLiteral("iq_kp"), integer(g.iqKp)},
            {QStringLiteral("iq_ki"), integer(g.iqKi)}};
}

void addMaxSpeed(QJsonObject &o, const std::optional<quint32> &maxSpeedRaw)
{
    if (!maxSpeedRaw)
        return;
    o.insert(QStringLiteral("max_speed_dps"), centi(*maxSpeedRaw));
    o.insert(QStringLiteral("max_speed_raw"), integer(*maxSpeedRaw));
}

QJsonObject angleFields(qint64 angleRaw, const std::optional<quint32> &maxSpeedRaw)
{
    QJsonObject o{{QStringLiteral("angle_deg"), centi(angleRaw)},
                  {QStringLiteral("angle_raw"), integer(angleRaw)}};
    addMaxSpeed(o, maxSpeedRaw);
    return o;
}

/// {"<key>": its name (or its code when unknown), "<key>_id": the ID byte}.
QJsonObject head(const QString &key, const char *name, quint8 paramId)
{
    return {{key, name ? QString::fromLatin1(name) : CommandTable::codeText(paramId)},
            {key + QLatin1String("_id"), integer(paramId)}};
}

QJsonObject paramHead(quint8 paramId)
{
    const ParamInfo *info = ParamTable::find(paramId);
    return head(QStringLiteral("param"), info ? info->name : nullptr, paramId);
}

/// The six value bytes of a parameter nobody knows, as hex.
QString valueBytes(const std::array<quint8, 6> &bytes)
{
    QByteArray raw;
    for (quint8 b : bytes)
        raw.append(char(b));
    return FieldJson::hexText(raw);
}

// A parameter's value under the field names of V2.3 where they exist (angle_kp ... iq_ki,
// plus *_kd), so scripts read V2.35 gains like V2.3 ones.
QJsonObject parameterFields(const ParameterValue &v)
{
    QJsonObject o = paramHead(v.paramId);
    const std::optional<ParamId> id = v.id();
    if (!id) {
        o.insert(QStringLiteral("value_bytes"), valueBytes(v.bytes));
        return o;
    }
    switch (ParamTable::info(*id).layout) {
    case ParamLayout::Pid: {
        const QString loop = ParamTable::name(*id).chopped(4);
        o.insert(loop + QLatin1String("_kp"), integer(v.pidKp()));
        o.insert(loop + QLatin1String("_ki"), integer(v.pidKi()));
        o.insert(loop + QLatin1String("_kd"), integer(v.pidKd()));
        break;
    }
    case ParamLayout::HalfInt64:
        o.insert(QStringLiteral("max_angle_half_raw"), integer(v.asUInt32()));
        break;
    case ParamLayout::Int16: // one integer field: its name is the field table's
        o.insert(ProtocolFields::ofParam(*id).constFirst().name, integer(v.asInt16()));
        break;
    case ParamLayout::Int32:
        if (*id == ParamId::MaxSpeed) {
            o.insert(QStringLiteral("max_speed_dps"), centi(v.asInt32()));
            o.insert(QStringLiteral("max_speed_raw"), integer(v.asInt32()));
        } else {
            o.insert(ProtocolFields::ofParam(*id).constFirst().name, integer(v.asInt32()));
        }
        break;
    }
    return o;
}

QJsonObject controlParamHead(quint8 paramId)
{
    const ControlParamInfo *info = ControlParamTable::find(paramId);
    return head(QStringLiteral("control_param"), info ? info->name : nullptr, paramId);
}

// A CAN V2.36 control parameter under the field names of its V2.35 counterpart
// (ProtocolFields::ofControlParam): angle_kp..iq_kd, max_torque, max_speed_dps (+ _raw),
// max_angle_deg (+ max_angle_raw), current_ramp_raw (no unit is known), speed_ramp_dps2.
QJsonObject controlParamFields(const ControlParameter &v)
{
    QJsonObject o = controlParamHead(v.paramId);
    const std::optional<ControlParamId> id = v.id();
    if (!id) {
        o.insert(QStringLiteral("value_bytes"), valueBytes(v.bytes));
        return o;
    }
    const QList<FieldSpec> fields = ProtocolFields::ofControlParam(*id);
    if (fields.size() == 3) {
        for (int i = 0; i < 3; ++i)
            o.insert(fields.at(i).name, integer(v.pid()[size_t(i)]));
        return o;
    }
    switch (*id) {
    case ControlParamId::InputSpeedLimit:
        o.insert(QStringLiteral("max_speed_dps"), centi(v.value()));
        o.insert(QStringLiteral("max_speed_raw"), integer(v.value()));
        break;
    case ControlParamId::InputAngleLimit:
        o.insert(QStringLiteral("max_angle_deg"), centi(v.value()));
        o.insert(QStringLiteral("max_angle_raw"), integer(v.value()));
        break;
    default:
        o.insert(fields.constFirst().name, integer(v.value()));
        break;
    }
    return o;
}

QString brakeActionName(BrakeAction a)
{
    switch (a) {
    case BrakeAction::Engage:
        return QStringLiteral("engage");
    case BrakeAction::Release:
        return QStringLiteral("release");
    case BrakeAction::Read:
        return QStringLiteral("read");
    }
    return QStringLiteral("0x%1").arg(quint8(a), 2, 16, QLatin1Char('0'));
}

struct RequestFieldVisitor {
    DecodeContext context;
    QJsonObject operator()(const NoPayload &) const { return {}; }
    QJsonObject operator()(const PidGains &g) const { return pidFields(g); }
    QJsonObject operator()(const Acceleration &a) const
    {
        return {{QStringLiteral("accel_dps2"), integer(a.dps2)}};
    }
    QJsonObject operator()(const EncoderOffset &e) const
    {
        return {{QStringLiteral("encoder_offset"), integer(e.offset)}};
    }
    QJsonObject operator()(const OpenLoopCommand &c) const
    {
        return {{QStringLiteral("power"), integer(c.power)}};
    }
    QJsonObject operator()(const TorqueCommand &c) const
    {
        // V2.3: 32 A per 2000 LSB, the integer product first, then one correctly rounded
        // division. V2.35: the drive's reply scale (a power of two, exact).
        const double a = context.generation == Generation::V2_3
                             ? ProtocolFields::field(FieldId::TorqueIqA).physical(c.iqRaw)
                             : c.iqRaw * iqCommandAmpsPerLsb(context);
        return {{QStringLiteral("iq_a"), QJsonValue(a)},
                {QStringLiteral("iq_raw"), integer(c.iqRaw)}};
    }
    QJsonObject operator()(const SpeedCommand &c) const
    {
        return {{QStringLiteral("speed_dps"),
                 ProtocolFields::field(FieldId::SpeedDps).physical(c.speedRaw)},
                {QStringLiteral("speed_raw"), integer(c.speedRaw)}};
    }
    QJsonObject operator()(const MultiPositionCommand &c) const
    {
        return angleFields(c.angleRaw, c.maxSpeedRaw);
    }
    QJsonObject operator()(const SinglePositionCommand &c) const
    {
        QJsonObject o = angleFields(c.angleRaw, c.maxSpeedRaw);
        o.insert(QStringLiteral("direction"), c.direction == SpinDirection::Clockwise
                                                  ? QStringLiteral("cw")
                                                  : QStringLiteral("ccw"));
        return o;
    }
    QJsonObject operator()(const IncrementPositionCommand &c) const
    {
        return angleFields(c.angleRaw, c.maxSpeedRaw);
    }
    QJsonObject operator()(const PositionSet &p) const { return angleFields(p.angleRaw, {}); }
    QJsonObject operator()(const ParamRead &p) const { return paramHead(p.paramId); }
    QJsonObject operator()(const ControlParamRead &p) const { return controlParamHead(p.paramId); }
    QJsonObject operator()(const ControlParameter &v) const { return controlParamFields(v); }
    QJsonObject operator()(const ParameterValue &v) const { return parameterFields(v); }
    QJsonObject operator()(const BrakeCommand &b) const
    {
        return {{QStringLiteral("action"), brakeActionName(b.action)}};
    }
};

QJsonObject modelFields(const ModelInfo &m)
{
    QJsonObject o{{QStringLiteral("driver_name"), m.driverName},
                  {QStringLiteral("motor_name"), m.motorName},
                  {QStringLiteral("hardware_version"), QJsonValue(m.hardwareVersion())},
                  {QStringLiteral("hardware_version_raw"), integer(m.hardwareRaw)},
                  {QStringLiteral("firmware_version"), QJsonValue(m.firmwareVersion())},
                  {QStringLiteral("firmware_version_raw"), integer(m.firmwareRaw)}};
    if (m.generation == Generation::V2_35) {
        // The 58-byte layout of newer firmware (ERRATA "Generations"); the motor version's
        // scale is undocumented, so only its wire value is given.
        o.insert(QStringLiteral("motor_id"), FieldJson::hexText(m.motorId));
        o.insert(QStringLiteral("motor_version_raw"), integer(m.motorVersionRaw));
    }
    return o;
}

struct ReplyFieldVisitor {
    QJsonObject operator()(const Acknowledged &) const { return {}; }
    QJsonObject operator()(const PidGains &g) const { return pidFields(g); }
    QJsonObject operator()(const Acceleration &a) const { return RequestFieldVisitor{{}}(a); }
    QJsonObject operator()(const EncoderReading &e) const
    {
        return {{QStringLiteral("encoder"), integer(e.encoder)},
                {QStringLiteral("encoder_raw"), integer(e.encoderRaw)},
                {QStringLiteral("encoder_offset"), integer(e.encoderOffset)}};
    }
    QJsonObject operator()(const EncoderOffset &e) const { return RequestFieldVisitor{{}}(e); }
    QJsonObject operator()(const ZeroWritten &z) const
    {
        if (!z.encoderOffset)
            return {};
        return {{QStringLiteral("encoder_offset"), integer(*z.encoderOffset)}};
    }
    QJsonObject operator()(const MultiTurnAngle &a) const { return angleFields(a.raw, {}); }
    QJsonObject operator()(const SingleTurnAngle &a) const { return angleFields(a.raw, {}); }
    QJsonObject operator()(const State1 &s) const
    {
        // Every flag the drive's generation names, true or false (docs/V2.35.md section 5).
        QJsonObject o{{QStringLiteral("temperature_c"), integer(s.temperatureC)},
                      {QStringLiteral("error_state"), integer(s.errorState)}};
        for (const ErrorFlag &f : ErrorFlags::of(s.generation))
            o.insert(QLatin1String(f.key), bool(s.errorState & (1u << f.bit)));
        if (s.generation == Generation::V2_3) {
            o.insert(QStringLiteral("voltage_v"), QJsonValue(s.voltageRaw / 10.0));
            o.insert(QStringLiteral("voltage_raw"), integer(s.voltageRaw));
            return o;
        }
        o.insert(QStringLiteral("voltage_v"), QJsonValue(qint16(s.voltageRaw) / 100.0));
        o.insert(QStringLiteral("voltage_raw"), integer(qint16(s.voltageRaw)));
        o.insert(QStringLiteral("bus_current_a"), QJsonValue(s.busCurrentRaw / 100.0));
        o.insert(QStringLiteral("bus_current_raw"), integer(s.busCurrentRaw));
        const std::optional<bool> on = s.motorOn();
        o.insert(QStringLiteral("motor_on"), on ? QJsonValue(*on) : QJsonValue());
        o.insert(QStringLiteral("motor_state_raw"), integer(s.motorStateRaw));
        return o;
    }
    QJsonObject operator()(const State2 &s) const
    {
        QJsonObject o{{QStringLiteral("temperature_c"), integer(s.temperatureC)},
                      {QStringLiteral("speed_dps"), QJsonValue(double(s.speedDps))},
                      {QStringLiteral("encoder"), integer(s.encoder)}};
        if (s.isPower) {
            o.insert(QStringLiteral("power"), integer(s.torqueRaw));
        } else {
            o.insert(QStringLiteral("iq_a"), QJsonValue(s.iqA())); // 33/2048 is exact in binary
            o.insert(QStringLiteral("iq_raw"), integer(s.torqueRaw));
        }
        return o;
    }
    QJsonObject operator()(const State3 &s) const
    {
        return {{QStringLiteral("temperature_c"), integer(s.temperatureC)},
                {QStringLiteral("ia_a"), QJsonValue(s.iaA())},
                {QStringLiteral("ia_raw"), integer(s.iaRaw)},
                {QStringLiteral("ib_a"), QJsonValue(s.ibA())},
                {QStringLiteral("ib_raw"), integer(s.ibRaw)},
                {QStringLiteral("ic_a"), QJsonValue(s.icA())},
                {QStringLiteral("ic_raw"), integer(s.icRaw)}};
    }
    QJsonObject operator()(const ModelInfo &m) const { return modelFields(m); }
    QJsonObject operator()(const ParameterValue &v) const { return parameterFields(v); }
    QJsonObject operator()(const ControlParameter &v) const { return controlParamFields(v); }
    QJsonObject operator()(const ParamWriteResult &r) const
    {
        QJsonObject o = paramHead(r.paramId);
        o.insert(QStringLiteral("success"), r.succeeded());
        o.insert(QStringLiteral("success_flag"), integer(r.flag));
        return o;
    }
    QJsonObject operator()(const BrakeState &b) const
    {
        return {{QStringLiteral("brake_released"), b.released()},
                {QStringLiteral("brake_raw"), integer(b.raw)}};
    }
};

} // namespace

// ---- FieldJson ------------------------------------------------------------------------------

QJsonObject FieldJson::requestFields(const Request &request, const DecodeContext &context)
{
    return std::visit(RequestFieldVisitor{context}, request.payload);
}

QJsonObject FieldJson::replyFields(const Reply &reply)
{
    return std::visit(ReplyFieldVisitor{}, reply.payload);
}

std::optional<QJsonObject> FieldJson::frameObject(const Frame &frame, FrameDirection direction,
                                                  const DecodeContext &context)
{
    QJsonObject fields;
    if (direction == FrameDirection::Reply) {
        const ReplyDecodeResult r = decodeReply(frame, context);
        if (!r.reply)
            return std::nullopt;
        fields = replyFields(*r.reply);
    } else {
        // An echo carries the request's bytes: its fields are the values written.
        const RequestDecodeResult r = decodeRequest(frame, context);
        if (!r.request)
            return std::nullopt;
        fields = requestFields(*r.request, context);
    }
    return QJsonObject{{QStringLiteral("direction"), QLatin1String(directionName(direction))},
                       {QStringLiteral("command"), CommandTable::name(Command(frame.command))},
                       {QStringLiteral("code"), CommandTable::codeText(frame.command)},
                       {QStringLiteral("id"), integer(frame.id)},
                       {QStringLiteral("fields"), fields}};
}

QJsonObject FieldJson::errorObject(ParseError error, const QByteArray &bytes)
{
    return {{QStringLiteral("error"), QLatin1String(parseErrorName(error))},
            {QStringLiteral("bytes"), hexText(bytes)}};
}

QJsonObject FieldJson::eventObject(const ParseEvent &event, const DecodeContext &context)
{
    if (!event.isFrame)
        return errorObject(event.error, event.bytes);
    if (auto o = frameObject(event.frame, event.direction, context))
        return *o;
    // The parser takes the direction from the same command table the decoders use, so this
    // is not expected; should they ever disagree, the frame is reported, not dropped.
    return errorObject(ParseError::BadLength, event.bytes);
}

bool FieldJson::isError(const QJsonObject &object)
{
    return object.contains(QStringLiteral("error"));
}

QByteArray FieldJson::toJsonLine(const QJsonObject &object)
{
    return OrderedJson::fieldsText(object);
}

QString FieldJson::hexText(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

} // namespace lk::protocol
