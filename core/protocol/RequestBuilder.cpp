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
        return fail(QStringLiteral("command"), QStringLiteral("the 28 commands of the protocol"),
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
    if (power < -1000 || power > 1000)
        return fail(QStringLiteral("power"), QStringLiteral("-1000..1000"), got(double(power)));
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

} // namespace lk::protocol::build
