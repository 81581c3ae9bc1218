#include "FieldText.h"

#include "ErrorFlags.h"
#include "ProtocolFields.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>

namespace lk::protocol {

namespace {

QString fixed(double v, int decimals)
{
    return QString::number(v, 'f', decimals);
}

QString centi(qint64 raw)
{
    return fixed(static_cast<double>(raw) / 100.0, 2);
}

/// A request field's wire value in its physical unit, at the field table's scale.
QString physical(FieldId field, qint64 raw)
{
    return fixed(ProtocolFields::field(field).physical(raw), 2);
}

QString pidText(const PidGains &g)
{
    return QCoreApplication::translate("lk::protocol::FieldText",
                                       "angle Kp %1 Ki %2, speed Kp %3 Ki %4, iq Kp %5 Ki %6")
        .arg(g.angleKp)
        .arg(g.angleKi)
        .arg(g.speedKp)
        .arg(g.speedKi)
        .arg(g.iqKp)
        .arg(g.iqKi);
}

QString withMaxSpeed(QString text, const std::optional<quint32> &maxSpeedRaw)
{
    if (maxSpeedRaw)
        text += QCoreApplication::translate("lk::protocol::FieldText", ", max %1 dps")
                    .arg(physical(FieldId::MaxSpeedDps, *maxSpeedRaw));
    return text;
}

QString paramName(quint8 paramId)
{
    const ParamInfo *info = ParamTable::find(paramId);
    return info ? QString::fromLatin1(info->name)
                : QStringLiteral("param 0x%1").arg(paramId, 2, 16, QLatin1Char('0'));
}

QString parameterText(const ParameterValue &v)
{
    const std::optional<ParamId> id = v.id();
    if (!id)
        return paramName(v.paramId);
    switch (ParamTable::info(*id).layout) {
    case ParamLayout::Pid:
        return QCoreApplication::translate("lk::protocol::FieldText", "%1 Kp %2 Ki %3 Kd %4")
            .arg(paramName(v.paramId))
            .arg(v.pidKp())
            .arg(v.pidKi())
            .arg(v.pidKd());
    case ParamLayout::HalfInt64:
        return QStringLiteral("%1 0x%2")
            .arg(paramName(v.paramId))
            .arg(v.asUInt32(), 8, 16, QLatin1Char('0'));
    case ParamLayout::Int16:
        return QStringLiteral("%1 %2").arg(paramName(v.paramId)).arg(v.asInt16());
    case ParamLayout::Int32:
        return *id == ParamId::MaxSpeed
                   ? QStringLiteral("%1 %2 dps")
                         .arg(paramName(v.paramId),
                              physical(FieldId::ParamMaxSpeedDps, v.asInt32()))
                   : QStringLiteral("%1 %2 dps/s").arg(paramName(v.paramId)).arg(v.asInt32());
    }
    return paramName(v.paramId);
}

QString controlParamName(quint8 paramId)
{
    const ControlParamInfo *info = ControlParamTable::find(paramId);
    return info ? QString::fromLatin1(info->name)
                : QStringLiteral("control param 0x%1").arg(paramId, 2, 16, QLatin1Char('0'));
}

/// A CAN V2.36 control parameter: its value in the unit inferred for it (docs/CAN.md section
/// 4.1); the input current ramp has none, so its raw number and "unit unknown".
QString controlParamText(const ControlParameter &v)
{
    const QString name = controlParamName(v.paramId);
    const std::optional<ControlParamId> id = v.id();
    if (!id)
        return name;
    switch (*id) {
    case ControlParamId::AnglePid:
    case ControlParamId::SpeedPid:
    case ControlParamId::CurrentPid:
        return QCoreApplication::translate("lk::protocol::FieldText", "%1 Kp %2 Ki %3 Kd %4")
            .arg(name)
            .arg(v.pid()[0])
            .arg(v.pid()[1])
            .arg(v.pid()[2]);
    case ControlParamId::InputTorqueLimit:
        return QStringLiteral("%1 %2").arg(name).arg(v.value());
    case ControlParamId::InputSpeedLimit:
        return QStringLiteral("%1 %2 dps").arg(name, centi(v.value()));
    case ControlParamId::InputAngleLimit:
        return QStringLiteral("%1 %2 deg").arg(name, centi(v.value()));
    case ControlParamId::InputCurrentRamp:
        return QCoreApplication::translate("lk::protocol::FieldText", "%1 %2 (unit unknown)")
            .arg(name)
            .arg(v.value());
    case ControlParamId::InputSpeedRamp:
        return QStringLiteral("%1 %2 dps/s").arg(name).arg(v.value());
    }
    return name;
}

QString brakeText(BrakeAction a)
{
    switch (a) {
    case BrakeAction::Engage:
        return QCoreApplication::translate("lk::protocol::FieldText", "engage brake");
    case BrakeAction::Release:
        return QCoreApplication::translate("lk::protocol::FieldText", "release brake");
    case BrakeAction::Read:
        return QCoreApplication::translate("lk::protocol::FieldText", "read brake");
    }
    return {};
}

struct RequestTextVisitor {
    DecodeContext context;
    QString operator()(const NoPayload &) const { return {}; }
    QString operator()(const ParamRead &p) const { return paramName(p.paramId); }
    QString operator()(const ControlParamRead &p) const { return controlParamName(p.paramId); }
    QString operator()(const ControlParameter &v) const { return controlParamText(v); }
    QString operator()(const ParameterValue &v) const { return parameterText(v); }
    QString operator()(const BrakeCommand &b) const { return brakeText(b.action); }
    QString operator()(const PidGains &g) const { return pidText(g); }
    QString operator()(const Acceleration &a) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "accel %1 dps/s").arg(a.dps2);
    }
    QString operator()(const EncoderOffset &e) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "offset %1").arg(e.offset);
    }
    QString operator()(const OpenLoopCommand &c) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "power %1").arg(c.power);
    }
    QString operator()(const TorqueCommand &c) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "iq %1 A")
            .arg(fixed(c.iqRaw * iqCommandAmpsPerLsb(context), 2));
    }
    QString operator()(const SpeedCommand &c) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "speed %1 dps")
            .arg(physical(FieldId::SpeedDps, c.speedRaw));
    }
    QString operator()(const MultiPositionCommand &c) const
    {
        return withMaxSpeed(QCoreApplication::translate("lk::protocol::FieldText", "angle %1 deg")
                                .arg(physical(FieldId::MultiAngleDeg, c.angleRaw)),
                            c.maxSpeedRaw);
    }
    QString operator()(const SinglePositionCommand &c) const
    {
        const QString dir = c.direction == SpinDirection::Clockwise
                                ? QCoreApplication::translate("lk::protocol::FieldText", "cw")
                                : QCoreApplication::translate("lk::protocol::FieldText", "ccw");
        return withMaxSpeed(QCoreApplication::translate("lk::protocol::FieldText", "%1 to %2 deg")
                                .arg(dir, physical(FieldId::SingleAngleDeg, c.angleRaw)),
                            c.maxSpeedRaw);
    }
    QString operator()(const PositionSet &p) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "position := %1 deg")
            .arg(physical(FieldId::MultiAngleDeg, p.angleRaw));
    }
    QString operator()(const IncrementPositionCommand &c) const
    {
        const QString sign = c.angleRaw > 0 ? QStringLiteral("+") : QString();
        return withMaxSpeed(QCoreApplication::translate("lk::protocol::FieldText", "by %1%2 deg")
                                .arg(sign, physical(FieldId::IncrementAngleDeg, c.angleRaw)),
                            c.maxSpeedRaw);
    }
};

QString temperature(qint8 c)
{
    return QCoreApplication::translate("lk::protocol::FieldText", "T %1 C").arg(int(c));
}

QString state1Text(const State1 &s)
{
    const bool v23 = s.generation == Generation::V2_3;
    QStringList parts{temperature(s.temperatureC),
                      QStringLiteral("%1 V").arg(fixed(s.voltageV(), v23 ? 1 : 2))};
    if (const std::optional<double> a = s.busCurrentA())
        parts << QStringLiteral("%1 A").arg(fixed(*a, 2));
    if (const std::optional<bool> on = s.motorOn())
        parts << (*on ? QCoreApplication::translate("lk::protocol::FieldText", "motor on")
                      : QCoreApplication::translate("lk::protocol::FieldText", "motor off"));
    for (const ErrorFlag &f : ErrorFlags::set(s.errorState, s.generation))
        parts << QCoreApplication::translate("lk::protocol::ErrorFlags", f.text);
    if (const quint8 otherBits = ErrorFlags::unnamedBits(s.errorState, s.generation))
        parts << QCoreApplication::translate("lk::protocol::FieldText", "error bits 0x%1")
                     .arg(otherBits, 2, 16, QLatin1Char('0'));
    return parts.join(QStringLiteral(", "));
}

QString state2Text(const State2 &s)
{
    const QString torque =
        s.isPower
            ? QCoreApplication::translate("lk::protocol::FieldText", "power %1").arg(s.torqueRaw)
            : QCoreApplication::translate("lk::protocol::FieldText", "iq %1 A")
                  .arg(fixed(s.iqA(), 2));
    return QCoreApplication::translate("lk::protocol::FieldText", "%1, %2, %3 dps, enc %4")
        .arg(temperature(s.temperatureC), torque)
        .arg(s.speedDps)
        .arg(s.encoder);
}

QString modelText(const ModelInfo &m)
{
    const int decimals = m.generation == Generation::V2_3 ? 1 : 2;
    return QCoreApplication::translate("lk::protocol::FieldText", "%1 / %2, hw %3, fw %4")
        .arg(m.driverName, m.motorName, fixed(m.hardwareVersion(), decimals),
             fixed(m.firmwareVersion(), decimals));
}

struct ReplyTextVisitor {
    QString operator()(const Acknowledged &) const { return {}; }
    QString operator()(const PidGains &g) const { return pidText(g); }
    QString operator()(const Acceleration &a) const { return RequestTextVisitor{{}}(a); }
    QString operator()(const EncoderReading &e) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "enc %1, raw %2, offset %3")
            .arg(e.encoder)
            .arg(e.encoderRaw)
            .arg(e.encoderOffset);
    }
    QString operator()(const EncoderOffset &e) const { return RequestTextVisitor{{}}(e); }
    QString operator()(const ZeroWritten &z) const
    {
        return z.encoderOffset ? QCoreApplication::translate("lk::protocol::FieldText", "offset %1")
                                     .arg(*z.encoderOffset)
                               : QString();
    }
    QString operator()(const MultiTurnAngle &a) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "angle %1 deg")
            .arg(centi(a.raw));
    }
    QString operator()(const SingleTurnAngle &a) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "angle %1 deg")
            .arg(centi(a.raw));
    }
    QString operator()(const State1 &s) const { return state1Text(s); }
    QString operator()(const State2 &s) const { return state2Text(s); }
    QString operator()(const State3 &s) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText",
                                           "%1, ia %2 A, ib %3 A, ic %4 A")
            .arg(temperature(s.temperatureC), fixed(s.iaA(), 2), fixed(s.ibA(), 2),
                 fixed(s.icA(), 2));
    }
    QString operator()(const ModelInfo &m) const { return modelText(m); }
    QString operator()(const ParameterValue &v) const { return parameterText(v); }
    QString operator()(const ControlParameter &v) const { return controlParamText(v); }
    QString operator()(const ParamWriteResult &r) const
    {
        return r.succeeded()
                   ? QCoreApplication::translate("lk::protocol::FieldText", "%1 written")
                         .arg(paramName(r.paramId))
                   : QCoreApplication::translate("lk::protocol::FieldText", "%1 refused (flag %2)")
                         .arg(paramName(r.paramId))
                         .arg(r.flag);
    }
    QString operator()(const BrakeState &b) const
    {
        return b.released()
                   ? QCoreApplication::translate("lk::protocol::FieldText", "brake released")
                   : QCoreApplication::translate("lk::protocol::FieldText", "brake applied");
    }
};

} // namespace

QString FieldText::request(const Request &request, const DecodeContext &context)
{
    return std::visit(RequestTextVisitor{context}, request.payload);
}

QString FieldText::reply(const Reply &reply)
{
    return std::visit(ReplyTextVisitor{}, reply.payload);
}

QString FieldText::frame(const Frame &frame, FrameDirection direction, const DecodeContext &context)
{
    if (direction == FrameDirection::Reply) {
        const ReplyDecodeResult r = decodeReply(frame, context);
        return r.reply ? reply(*r.reply) : QString();
    }
    const RequestDecodeResult r = decodeRequest(frame);
    return r.request ? request(*r.request, context) : QString();
}

} // namespace lk::protocol
