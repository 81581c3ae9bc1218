#include "RequestBuilder.h"

#include "Checksum.h"

#include <QtCore/QCoreApplication>

#include <cmath>
#include <limits>

namespace lk::protocol::build {

namespace {

constexpr qint64 kInt32Min = std::numeric_limits<qint32>::min();
constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
constexpr qint64 kUInt32Max = std::numeric_limits<quint32>::max();
// Largest angle whose 0.01-deg value still fits an int64 after rounding through a double.
constexpr double kMultiTurnLimitDeg = 9.0e16;

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

std::optional<quint32> maxSpeedRaw(double maxSpeedDps)
{
    const auto raw = scaled(maxSpeedDps, kCentiUnits, 0, kUInt32Max);
    if (!raw)
        return std::nullopt;
    return static_cast<quint32>(*raw);
}

const QString kMaxSpeedRange = QStringLiteral("0..42949672.95 dps");

} // namespace

std::optional<FieldError> checkId(int id)
{
    if (id < kMinId || id > kMaxId)
        return FieldError{QStringLiteral("id"), QStringLiteral("1..32"), got(id)};
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
    const std::pair<const char *, int> gains[] = {{"angle_kp", angleKp}, {"angle_ki", angleKi},
                                                  {"speed_kp", speedKp}, {"speed_ki", speedKi},
                                                  {"iq_kp", iqKp},       {"iq_ki", iqKi}};
    for (const auto &[name, value] : gains) {
        if (value < 0 || value > 255)
            return fail(QString::fromLatin1(name), QStringLiteral("0..255"), got(value));
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
    // int32 on the wire (ERRATA); a negative acceleration has no meaning, so it is refused.
    if (accelDps2 < 0 || accelDps2 > kInt32Max)
        return fail(QStringLiteral("accel_dps2"), QStringLiteral("0..2147483647 dps/s"),
                    got(double(accelDps2)));
    return done(Command::WriteAccelRam, id, Acceleration{static_cast<qint32>(accelDps2)});
}

BuildResult writeEncoderOffset(int id, qint64 offset)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (offset < 0 || offset > 65535)
        return fail(QStringLiteral("encoder_offset"), QStringLiteral("0..65535"),
                    got(double(offset)));
    return done(Command::WriteEncoderOffset, id, EncoderOffset{static_cast<quint16>(offset)});
}

BuildResult openLoop(int id, qint64 power)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    // V2.3 allows +-1000, V2.35 +-850: the stricter bound serves both (V2.35.md section 11).
    if (power < -850 || power > 850)
        return fail(QStringLiteral("power"), QStringLiteral("-850..850"), got(double(power)));
    return done(Command::OpenLoop, id, OpenLoopCommand{static_cast<qint16>(power)});
}

BuildResult torque(int id, double iqA)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const auto raw = scaled(iqA, kIqCommandAmpsPerLsb, -2000, 2000);
    if (!raw)
        return fail(QStringLiteral("iq_a"), QStringLiteral("-32..32 A"), got(iqA));
    return done(Command::Torque, id, TorqueCommand{static_cast<qint16>(*raw)});
}

BuildResult torque(int id, double iqA, const DecodeContext &context)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const double lsb = iqCommandAmpsPerLsb(context);
    const auto raw = scaled(iqA, lsb, -2000, 2000);
    if (!raw) {
        const QString limit = QString::number(2000 * lsb, 'f', 2);
        return fail(QStringLiteral("iq_a"), QStringLiteral("-%1..%1 A").arg(limit), got(iqA));
    }
    return done(Command::Torque, id, TorqueCommand{static_cast<qint16>(*raw)});
}

BuildResult speed(int id, double speedDps)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const auto raw = scaled(speedDps, kCentiUnits, kInt32Min, kInt32Max);
    if (!raw)
        return fail(QStringLiteral("speed_dps"), QStringLiteral("-21474836.48..21474836.47 dps"),
                    got(speedDps));
    return done(Command::Speed, id, SpeedCommand{static_cast<qint32>(*raw)});
}

namespace {
BuildResult multi(int id, double angleDeg, std::optional<double> maxSpeedDps)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    if (!std::isfinite(angleDeg) || std::fabs(angleDeg) > kMultiTurnLimitDeg)
        return fail(QStringLiteral("angle_deg"), QStringLiteral("-9e16..9e16 deg"), got(angleDeg));
    MultiPositionCommand c;
    c.angleRaw = static_cast<qint64>(std::llround(angleDeg / kCentiUnits));
    if (!maxSpeedDps)
        return done(Command::MultiPosition, id, c);
    c.maxSpeedRaw = maxSpeedRaw(*maxSpeedDps);
    if (!c.maxSpeedRaw)
        return fail(QStringLiteral("max_speed_dps"), kMaxSpeedRange, got(*maxSpeedDps));
    return done(Command::MultiPositionLimited, id, c);
}

BuildResult single(int id, SpinDirection dir, double angleDeg, std::optional<double> maxSpeedDps)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const auto raw = scaled(angleDeg, kCentiUnits, 0, 35999);
    if (!raw)
        return fail(QStringLiteral("angle_deg"), QStringLiteral("0..359.99 deg"), got(angleDeg));
    SinglePositionCommand c;
    c.direction = dir;
    c.angleRaw = static_cast<quint16>(*raw);
    if (!maxSpeedDps)
        return done(Command::SinglePosition, id, c);
    c.maxSpeedRaw = maxSpeedRaw(*maxSpeedDps);
    if (!c.maxSpeedRaw)
        return fail(QStringLiteral("max_speed_dps"), kMaxSpeedRange, got(*maxSpeedDps));
    return done(Command::SinglePositionLimited, id, c);
}

BuildResult increment(int id, double deltaDeg, std::optional<double> maxSpeedDps)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const auto raw = scaled(deltaDeg, kCentiUnits, kInt32Min, kInt32Max);
    if (!raw)
        return fail(QStringLiteral("angle_deg"), QStringLiteral("-21474836.48..21474836.47 deg"),
                    got(deltaDeg));
    IncrementPositionCommand c;
    c.angleRaw = static_cast<qint32>(*raw);
    if (!maxSpeedDps)
        return done(Command::IncrementPosition, id, c);
    c.maxSpeedRaw = maxSpeedRaw(*maxSpeedDps);
    if (!c.maxSpeedRaw)
        return fail(QStringLiteral("max_speed_dps"), kMaxSpeedRange, got(*maxSpeedDps));
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
    const QString loop = ParamTable::name(param).chopped(4); // "speed_pid" -> "speed"
    const std::pair<const char *, qint64> gains[] = {{"_kp", kp}, {"_ki", ki}, {"_kd", kd}};
    for (const auto &[suffix, value] : gains) {
        if (value < 0 || value > 65535)
            return fail(loop + QLatin1String(suffix), QStringLiteral("0..65535"),
                        got(double(value)));
    }
    return done(rom ? Command::WriteParamRom : Command::WriteParamRam, id,
                ParameterValue::pid(param, quint16(kp), quint16(ki), quint16(kd)));
}

namespace {
struct ParamRange {
    const char *field;
    double unitsPerLsb;
    qint64 min, max;
    const char *text;
};

std::optional<ParamRange> paramRange(ParamId param)
{
    switch (param) {
    case ParamId::MaxTorqueCurrent:
        return ParamRange{"max_torque", 1, 0, 2048, "0..2048"};
    case ParamId::MaxSpeed:
        return ParamRange{"max_speed_dps", kCentiUnits, 0, kInt32Max, "0..21474836.47 dps"};
    case ParamId::CurrentRamp:
        return ParamRange{"current_ramp", 1, 0, 32767, "0..32767"};
    case ParamId::SpeedRamp:
        return ParamRange{"speed_ramp_dps2", 1, 0, kInt32Max, "0..2147483647 dps/s"};
    case ParamId::MaxAngleLow:
    case ParamId::MaxAngleHigh:
        return ParamRange{"max_angle_deg", kCentiUnits, 0, std::numeric_limits<qint64>::max(),
                          "0..9e16 deg"};
    default:
        return std::nullopt;
    }
}
} // namespace

BuildResult writeParam(int id, ParamId param, double value, bool rom)
{
    if (auto e = checkId(id))
        return fail(e->field, e->range, e->problem);
    const std::optional<ParamRange> range = paramRange(param);
    if (!range)
        return fail(QStringLiteral("param"),
                    QStringLiteral("max_torque|max_speed|max_angle_low|max_angle_high|"
                                   "current_ramp|speed_ramp"),
                    ParamTable::name(param));
    const bool angle = param == ParamId::MaxAngleLow || param == ParamId::MaxAngleHigh;
    if (angle && (!std::isfinite(value) || value < 0 || value > kMultiTurnLimitDeg))
        return fail(QLatin1String(range->field), QLatin1String(range->text), got(value));
    const auto raw = angle ? std::optional<qint64>(std::llround(value / kCentiUnits))
                           : scaled(value, range->unitsPerLsb, range->min, range->max);
    if (!raw)
        return fail(QLatin1String(range->field), QLatin1String(range->text), got(value));
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

} // namespace lk::protocol::build
