#include "RequestBuilder.h"

#include "Checksum.h"
#include "ProtocolFields.h"

#include <QtCore/QCoreApplication>

#include <algorithm>
#include <cmath>

namespace lk::protocol::build {

namespace {

BuildResult fail(const QString &field, const QString &range, const QString &problem = {})
{
    BuildResult r;
    r.error = FieldError{field, range, problem};
    return r;
}

BuildResult done(Command cmd, int id, RequestPayload payload)
{
    BuildResult r;
    r.request = Request{cmd, static_cast<quint8>(id), std::move(payload)};
    return r;
}

QString got(double v)
{
    return QCoreApplication::translate("lk::protocol::RequestBuilder", "got %1").arg(v, 0, 'g', 12);
}

/// The refusal of a value of `id`, with the name and range of its row in the field table.
FieldError refusal(FieldId id, const QString &problem)
{
    const ProtocolField &f = ProtocolFields::field(id);
    return FieldError{QLatin1String(f.name), QLatin1String(f.range), problem};
}

BuildResult refuse(FieldId id, double value)
{
    BuildResult r;
    r.error = refusal(id, got(value));
    return r;
}

bool inRange(FieldId id, qint64 value)
{
    const ProtocolField &f = ProtocolFields::field(id);
    return value >= f.min && value <= f.max;
}

/// A physical value scaled to wire units and rounded, if finite and within [min, max] raw.
std::optional<qint64> scaled(double value, double unitsPerLsb, qint64 min, qint64 max)
{
    if (!std::isfinite(value))
        return std::nullopt;
    const double raw = std::round(value / unitsPerLsb);
    if (raw < static_cast<double>(min) || raw > static_cast<double>(max))
        return std::nullopt;
    return static_cast<qint64>(raw);
}

/// A physical value of field `id` in its wire units, if within the field's wire range.
std::optional<qint64> scaled(FieldId id, double value)
{
    const ProtocolField &f = ProtocolFields::field(id);
    return scaled(value, f.unitsPerLsb(), f.min, f.max);
}

/// max_speed_dps of the limited position commands (uint32 of 0.01 dps).
std::optional<quint32> maxSpeedRaw(double maxSpeedDps)
{
    const auto raw = scaled(FieldId::MaxSpeedDps, maxSpeedDps);
    if (!raw)
        return std::nullopt;
    return static_cast<quint32>(*raw);
}

} // namespace

std::optional<FieldError> checkId(int id)
{
    if (!inRange(FieldId::Id, id))
        return refusal(FieldId::Id, got(id));
    return std::nullopt;
}

BuildResult plain(Command command, int id)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const CommandInfo *info = CommandTable::find(static_cast<quint8>(command));
    if (!info)
        return fail(QStringLiteral("command"), QStringLiteral("the commands of the protocol"),
                    QStringLiteral("unknown code %1").arg(CommandTable::codeText(quint8(command))));
    if (info->requestLength != 0)
        return fail(QStringLiteral("command"), QStringLiteral("commands without data"),
                    QStringLiteral("%1 needs data").arg(CommandTable::name(command)));
    return done(command, id, NoPayload{});
}

BuildResult writePid(int id, int angleKp, int angleKi, int speedKp, int speedKi, int iqKp, int iqKi,
                     bool rom)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const std::pair<FieldId, int> gains[] = {
        {FieldId::AngleKp, angleKp}, {FieldId::AngleKi, angleKi}, {FieldId::SpeedKp, speedKp},
        {FieldId::SpeedKi, speedKi}, {FieldId::IqKp, iqKp},       {FieldId::IqKi, iqKi}};
    for (const auto &[field, value] : gains) {
        if (!inRange(field, value))
            return refuse(field, value);
    }
    const PidGains g{quint8(angleKp), quint8(angleKi), quint8(speedKp),
                     quint8(speedKi), quint8(iqKp),    quint8(iqKi)};
    return done(rom ? Command::WritePidRom : Command::WritePidRam, id, g);
}

BuildResult writePid(int id, const PidGains &g, bool rom)
{
    return writePid(id, g.angleKp, g.angleKi, g.speedKp, g.speedKi, g.iqKp, g.iqKi, rom);
}

BuildResult writeAcceleration(int id, qint64 accelDps2)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (!inRange(FieldId::AccelDps2, accelDps2))
        return refuse(FieldId::AccelDps2, double(accelDps2));
    return done(Command::WriteAccelRam, id, Acceleration{static_cast<qint32>(accelDps2)});
}

BuildResult writeEncoderOffset(int id, qint64 offset)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (!inRange(FieldId::EncoderOffset, offset))
        return refuse(FieldId::EncoderOffset, double(offset));
    return done(Command::WriteEncoderOffset, id, EncoderOffset{static_cast<quint16>(offset)});
}

BuildResult openLoop(int id, qint64 power)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (!inRange(FieldId::Power, power))
        return refuse(FieldId::Power, double(power));
    return done(Command::OpenLoop, id, OpenLoopCommand{static_cast<qint16>(power)});
}

BuildResult torque(int id, double iqA, const DecodeContext &context)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    // The wire range of the field table at the drive's own scale.
    const ProtocolField &f = ProtocolFields::field(FieldId::TorqueIqA);
    const double lsb = iqCommandAmpsPerLsb(context);
    const auto raw = scaled(iqA, lsb, f.min, f.max);
    if (!raw && context.generation == Generation::V2_3)
        return refuse(FieldId::TorqueIqA, iqA); // the table's range is V2.3's
    if (!raw) {
        const QString limit = QString::number(f.max * lsb, 'f', 2);
        return fail(QLatin1String(f.name), QStringLiteral("-%1..%1 A").arg(limit), got(iqA));
    }
    TorqueCommand c;
    c.iqRaw = static_cast<qint16>(*raw);
    c.ampsPerLsb = lsb;
    return done(Command::Torque, id, c);
}

BuildResult speed(int id, double speedDps)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const auto raw = scaled(FieldId::SpeedDps, speedDps);
    if (!raw)
        return refuse(FieldId::SpeedDps, speedDps);
    return done(Command::Speed, id, SpeedCommand{static_cast<qint32>(*raw)});
}

BuildResult speed(int id, double speedDps, const DecodeContext &context, double torqueLimitA)
{
    BuildResult r = speed(id, speedDps);
    if (!r.ok() || context.link != Link::Can || context.generation != Generation::V2_35)
        return r;
    const double lsb = iqCommandAmpsPerLsb(context);
    const double raw = std::isfinite(torqueLimitA) ? std::floor(torqueLimitA / lsb) : 0;
    if (raw < 1)
        return fail(QStringLiteral("torque_limit_a"),
                    QStringLiteral("%1..%2 A").arg(lsb, 0, 'g', 6).arg(2048 * lsb, 0, 'g', 6),
                    got(torqueLimitA));
    auto &c = std::get<SpeedCommand>(r.request->payload);
    c.iqLimitRaw = static_cast<qint16>(std::min(raw, 2048.0));
    return r;
}

namespace {
BuildResult multi(int id, double angleDeg, std::optional<double> maxSpeedDps)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const auto raw = scaled(FieldId::MultiAngleDeg, angleDeg);
    if (!raw)
        return refuse(FieldId::MultiAngleDeg, angleDeg);
    MultiPositionCommand c;
    c.angleRaw = *raw;
    if (!maxSpeedDps)
        return done(Command::MultiPosition, id, c);
    c.maxSpeedRaw = maxSpeedRaw(*maxSpeedDps);
    if (!c.maxSpeedRaw)
        return refuse(FieldId::MaxSpeedDps, *maxSpeedDps);
    return done(Command::MultiPositionLimited, id, c);
}

BuildResult single(int id, SpinDirection dir, double angleDeg, std::optional<double> maxSpeedDps)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const auto raw = scaled(FieldId::SingleAngleDeg, angleDeg);
    if (!raw)
        return refuse(FieldId::SingleAngleDeg, angleDeg);
    SinglePositionCommand c;
    c.direction = dir;
    c.angleRaw = static_cast<quint16>(*raw);
    if (!maxSpeedDps)
        return done(Command::SinglePosition, id, c);
    c.maxSpeedRaw = maxSpeedRaw(*maxSpeedDps);
    if (!c.maxSpeedRaw)
        return refuse(FieldId::MaxSpeedDps, *maxSpeedDps);
    return done(Command::SinglePositionLimited, id, c);
}

BuildResult increment(int id, double deltaDeg, std::optional<double> maxSpeedDps)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const auto raw = scaled(FieldId::IncrementAngleDeg, deltaDeg);
    if (!raw)
        return refuse(FieldId::IncrementAngleDeg, deltaDeg);
    IncrementPositionCommand c;
    c.angleRaw = static_cast<qint32>(*raw);
    if (!maxSpeedDps)
        return done(Command::IncrementPosition, id, c);
    c.maxSpeedRaw = maxSpeedRaw(*maxSpeedDps);
    if (!c.maxSpeedRaw)
        return refuse(FieldId::MaxSpeedDps, *maxSpeedDps);
    return done(Command::IncrementPositionLimited, id, c);
}
} // namespace

BuildResult multiPosition(int id, double angleDeg)
{
    return multi(id, angleDeg, std::nullopt);
}
BuildResult multiPosition(int id, double angleDeg, double maxSpeedDps)
{
    return multi(id, angleDeg, maxSpeedDps);
}
BuildResult singlePosition(int id, SpinDirection dir, double angleDeg)
{
    return single(id, dir, angleDeg, std::nullopt);
}
BuildResult singlePosition(int id, SpinDirection dir, double angleDeg, double maxSpeedDps)
{
    return single(id, dir, angleDeg, maxSpeedDps);
}
BuildResult incrementPosition(int id, double deltaDeg)
{
    return increment(id, deltaDeg, std::nullopt);
}
BuildResult incrementPosition(int id, double deltaDeg, double maxSpeedDps)
{
    return increment(id, deltaDeg, maxSpeedDps);
}

BuildResult readParam(int id, ParamId param)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    return done(Command::ReadParam, id, ParamRead{static_cast<quint8>(param)});
}

BuildResult writeParamPid(int id, ParamId param, qint64 kp, qint64 ki, qint64 kd, bool rom)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const ParamInfo &info = ParamTable::info(param);
    if (info.layout != ParamLayout::Pid)
        return fail(QStringLiteral("param"), QStringLiteral("angle_pid|speed_pid|iq_pid"),
                    ParamTable::name(param));
    const QList<FieldSpec> fields = ProtocolFields::ofParam(param); // Kp, Ki, Kd
    const qint64 gains[] = {kp, ki, kd};
    for (qsizetype i = 0; i < fields.size(); ++i) {
        if (!inRange(fields.at(i).id, gains[i]))
            return refuse(fields.at(i).id, double(gains[i]));
    }
    return done(rom ? Command::WriteParamRom : Command::WriteParamRam, id,
                ParameterValue::pid(param, quint16(kp), quint16(ki), quint16(kd)));
}

BuildResult writeParam(int id, ParamId param, double value, bool rom)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (ParamTable::info(param).layout == ParamLayout::Pid)
        return fail(QStringLiteral("param"),
                    QStringLiteral("max_torque|max_speed|max_angle_low|max_angle_high|"
                                   "current_ramp|speed_ramp"),
                    ParamTable::name(param));
    const FieldId field = ProtocolFields::ofParam(param).constFirst().id;
    const bool angle = param == ParamId::MaxAngleLow || param == ParamId::MaxAngleHigh;
    // A negative limit has no meaning, not even one that rounds to 0.
    const auto raw = angle && value < 0 ? std::nullopt : scaled(field, value);
    if (!raw)
        return refuse(field, value);
    ParameterValue v;
    if (angle)
        v = ParameterValue::maxAngleHalf(*raw, param == ParamId::MaxAngleHigh);
    else if (ParamTable::info(param).layout == ParamLayout::Int16)
        v = ParameterValue::int16(param, static_cast<qint16>(*raw));
    else
        v = ParameterValue::int32(param, static_cast<qint32>(*raw));
    return done(rom ? Command::WriteParamRom : Command::WriteParamRam, id, v);
}

BuildResult brake(int id, BrakeAction action)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    return done(Command::Brake, id, BrakeCommand{action});
}

BuildResult readControlParam(int id, ControlParamId param)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    return done(Command::ReadControlParam, id, ControlParamRead{static_cast<quint8>(param)});
}

BuildResult writeControlParamPid(int id, ControlParamId param, qint64 kp, qint64 ki, qint64 kd)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (ControlParamTable::info(param).layout != ControlParamLayout::Pid)
        return fail(QStringLiteral("control_param"), QStringLiteral("angle_pid|speed_pid|iq_pid"),
                    ControlParamTable::name(param));
    const QList<FieldSpec> fields = ProtocolFields::ofControlParam(param); // Kp, Ki, Kd
    const qint64 gains[] = {kp, ki, kd};
    for (qsizetype i = 0; i < fields.size(); ++i) {
        if (!inRange(fields.at(i).id, gains[i]))
            return refuse(fields.at(i).id, double(gains[i]));
    }
    return done(Command::WriteControlParam, id,
                ControlParameter::ofPid(param, quint16(kp), quint16(ki), quint16(kd)));
}

BuildResult writeControlParam(int id, ControlParamId param, double value)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (ControlParamTable::info(param).layout == ControlParamLayout::Pid)
        return fail(QStringLiteral("control_param"),
                    QStringLiteral("input_torque_limit|input_speed_limit|input_angle_limit|"
                                   "input_current_ramp|input_speed_ramp"),
                    ControlParamTable::name(param));
    const FieldId field = ProtocolFields::ofControlParam(param).constFirst().id;
    const auto raw = value < 0 ? std::nullopt : scaled(field, value); // no negative limits
    if (!raw)
        return refuse(field, value);
    return done(Command::WriteControlParam, id,
                ControlParameter::ofValue(param, static_cast<qint32>(*raw)));
}

BuildResult writeControlParam(int id, const ControlParameter &value)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (!value.id())
        return fail(QStringLiteral("control_param"), QStringLiteral("0x0A..0x26"),
                    CommandTable::codeText(value.paramId));
    return done(Command::WriteControlParam, id, value);
}

} // namespace lk::protocol::build
