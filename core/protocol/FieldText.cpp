#include "FieldText.h"

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
                    .arg(centi(*maxSpeedRaw));
    return text;
}

struct RequestTextVisitor {
    QString operator()(const NoPayload &) const { return {}; }
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
            .arg(fixed(c.iqRaw * 32.0 / 2000.0, 2));
    }
    QString operator()(const SpeedCommand &c) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "speed %1 dps")
            .arg(centi(c.speedRaw));
    }
    QString operator()(const MultiPositionCommand &c) const
    {
        return withMaxSpeed(QCoreApplication::translate("lk::protocol::FieldText", "angle %1 deg")
                                .arg(centi(c.angleRaw)),
                            c.maxSpeedRaw);
    }
    QString operator()(const SinglePositionCommand &c) const
    {
        const QString dir = c.direction == SpinDirection::Clockwise
                                ? QCoreApplication::translate("lk::protocol::FieldText", "cw")
                                : QCoreApplication::translate("lk::protocol::FieldText", "ccw");
        return withMaxSpeed(QCoreApplication::translate("lk::protocol::FieldText", "%1 to %2 deg")
                                .arg(dir, centi(c.angleRaw)),
                            c.maxSpeedRaw);
    }
    QString operator()(const IncrementPositionCommand &c) const
    {
        const QString sign = c.angleRaw > 0 ? QStringLiteral("+") : QString();
        return withMaxSpeed(QCoreApplication::translate("lk::protocol::FieldText", "by %1%2 deg")
                                .arg(sign, centi(c.angleRaw)),
                            c.maxSpeedRaw);
    }
};

QString temperature(qint8 c)
{
    return QCoreApplication::translate("lk::protocol::FieldText", "T %1 C").arg(int(c));
}

QString state1Text(const State1 &s)
{
    QStringList parts{temperature(s.temperatureC),
                      QStringLiteral("%1 V").arg(fixed(s.voltageRaw / 10.0, 1))};
    if (s.lowVoltage())
        parts << QCoreApplication::translate("lk::protocol::FieldText", "low voltage");
    if (s.overTemperature())
        parts << QCoreApplication::translate("lk::protocol::FieldText", "over temperature");
    const quint8 otherBits = s.errorState & ~quint8(0x09);
    if (otherBits)
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
    QString operator()(const Acceleration &a) const { return RequestTextVisitor{}(a); }
    QString operator()(const EncoderReading &e) const
    {
        return QCoreApplication::translate("lk::protocol::FieldText", "enc %1, raw %2, offset %3")
            .arg(e.encoder)
            .arg(e.encoderRaw)
            .arg(e.encoderOffset);
    }
    QString operator()(const EncoderOffset &e) const { return RequestTextVisitor{}(e); }
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
};

} // namespace

QString FieldText::request(const Request &request)
{
    return std::visit(RequestTextVisitor{}, request.payload);
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
    return r.request ? request(*r.request) : QString();
}

} // namespace lk::protocol
