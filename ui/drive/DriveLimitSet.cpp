#include "DriveLimitSet.h"

#include <protocol/ProtocolFields.h>
#include <protocol/RequestBuilder.h>
#include <protocol/Values.h>

#include <limits>

namespace lk::ui {

namespace {
using protocol::ParamId;
using protocol::ProtocolFields;

constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
// The largest max angle (0.01 deg) an editor holds exactly (a double's 53-bit mantissa).
constexpr qint64 kAngleMax = (qint64(1) << 53) - 1;

/// The ParamID of each field but the max angle (a pair, handled apart).
ParamId paramOf(int field)
{
    switch (field) {
    case DriveLimitSet::MaxTorque:
        return ParamId::MaxTorqueCurrent;
    case DriveLimitSet::MaxSpeed:
        return ParamId::MaxSpeed;
    case DriveLimitSet::CurrentRamp:
        return ParamId::CurrentRamp;
    default:
        return ParamId::SpeedRamp;
    }
}

double shownValue(int field, qint64 raw)
{
    const bool centi = field == DriveLimitSet::MaxSpeed || field == DriveLimitSet::MaxAngle;
    return centi ? double(raw) * protocol::kCentiUnits : double(raw);
}
} // namespace

QVector<ParamField> DriveLimitSet::fields() const
{
    // The name of 0x99 for the series comes from the field table, as lkctl's does.
    QString torqueName = ProtocolFields::paramLabelTranslated(
        ParamId::MaxTorqueCurrent, m_power ? protocol::Series::MS : protocol::Series::MF);
    torqueName[0] = torqueName[0].toUpper();
    ParamField torque{QStringLiteral("max_torque"),
                      tr("%1 (0x99)").arg(torqueName),
                      TunedLoop::Current,
                      0,
                      2048,
                      0,
                      QString(),
                      m_power ? tr("On MS drives ParamID 0x99 limits power (0..1000 is the "
                                   "power command's range); the unit is not documented.")
                              : tr("In iq command units: 2048 is full scale (MF 16.5 A, MG 33 A "
                                   "on V2.35).")};
    ParamField speed{QStringLiteral("max_speed_dps"),
                     tr("Max speed (0x9A)"),
                     TunedLoop::Speed,
                     0,
                     kInt32Max,
                     2,
                     tr(" dps"),
                     tr("Bounds speed and position commands (0xA2..0xA8); 0.01 dps on the wire."),
                     100};
    ParamField angle{QStringLiteral("max_angle_deg"),
                     tr("Max angle (0x9B/0x9C)"),
                     TunedLoop::Angle,
                     0,
                     kAngleMax,
                     2,
                     tr(" deg"),
                     tr("Bounds multi-turn position commands (0xA3/0xA4); an int64 of 0.01 deg "
                        "split over two ParamIDs, always written and read as a pair."),
                     100};
    ParamField currentRamp{QStringLiteral("current_ramp"),
                           tr("Current ramp (0x9D)"),
                           TunedLoop::Current,
                           0,
                           32767,
                           0,
                           QString(),
                           tr("0..32767; the vendor does not document the unit.")};
    ParamField speedRamp{QStringLiteral("speed_ramp_dps2"),
                         tr("Speed ramp (0x9E)"),
                         TunedLoop::Speed,
                         0,
                         kInt32Max,
                         0,
                         tr(" dps/s"),
                         tr("Replaces the acceleration (0x33/0x34) of protocol V2.3."),
                         1000};
    return {torque, speed, angle, currentRamp, speedRamp};
}

ParamSetTexts DriveLimitSet::texts() const
{
    return {tr("Drive limits (protocol V2.35)"),
            tr("The drive enforces these limits itself, also against commands from other "
               "software; the tool's soft limits (Control view) only bound what this tool "
               "sends."),
            tr("read_param (0x40) for 0x99..0x9E"),
            tr("0x42 for each changed limit, lost at power-off; read back."),
            tr("0x44 for every limit, writes flash (asks first); read back.")};
}

QVector<protocol::Request> DriveLimitSet::reads(int id) const
{
    QVector<protocol::Request> out;
    for (ParamId p : {ParamId::MaxTorqueCurrent, ParamId::MaxSpeed, ParamId::MaxAngleLow,
                      ParamId::MaxAngleHigh, ParamId::CurrentRamp, ParamId::SpeedRamp})
        out << *protocol::build::readParam(id, p).request;
    return out;
}

HeldValues DriveLimitSet::decode(const QVector<protocol::Reply> &replies) const
{
    HeldValues held(kFieldCount);
    std::optional<protocol::ParameterValue> low, high;
    for (const protocol::Reply &r : replies) {
        const auto *v = std::get_if<protocol::ParameterValue>(&r.payload);
        const std::optional<ParamId> id = v ? v->id() : std::nullopt;
        if (!id)
            continue;
        switch (*id) {
        case ParamId::MaxTorqueCurrent:
            held[MaxTorque] = v->asInt16();
            break;
        case ParamId::MaxSpeed:
            held[MaxSpeed] = v->asInt32();
            break;
        case ParamId::MaxAngleLow:
            low = *v;
            break;
        case ParamId::MaxAngleHigh:
            high = *v;
            break;
        case ParamId::CurrentRamp:
            held[CurrentRamp] = v->asInt16();
            break;
        case ParamId::SpeedRamp:
            held[SpeedRamp] = v->asInt32();
            break;
        default:
            break;
        }
    }
    if (low && high) // half an angle is no angle
        held[MaxAngle] = protocol::joinMaxAngle(*low, *high);
    return held;
}

QVector<ParamWrite> DriveLimitSet::writes(int id, const ParamValues &values,
                                          const ParamValues &held, bool rom) const
{
    QVector<ParamWrite> out;
    for (int f = 0; f < kFieldCount; ++f) {
        if (!rom && values.at(f) == held.at(f))
            continue;
        const double value = shownValue(f, values.at(f));
        if (f == MaxAngle) {
            out << ParamWrite{protocol::build::writeParam(id, ParamId::MaxAngleLow, value, rom),
                              {f}};
            out << ParamWrite{protocol::build::writeParam(id, ParamId::MaxAngleHigh, value, rom),
                              {f}};
        } else {
            out << ParamWrite{protocol::build::writeParam(id, paramOf(f), value, rom), {f}};
        }
    }
    return out;
}

ConfirmRequest DriveLimitSet::romQuestion(int id, const ParamValues &values) const
{
    ConfirmRequest q;
    q.key = QStringLiteral("write_limits_rom");
    q.title = tr("Write drive limits to ROM");
    q.question =
        tr("Write these limits to the ROM of drive %1?\n%2").arg(id).arg(valuesText(values));
    q.reason = tr("ROM is the drive's flash memory: each write wears it, and the limits stay "
                  "after power-off and bound every program that drives this motor. Each "
                  "parameter is sent once with 0x44 (never retried), then read back with 0x40.");
    q.acceptText = tr("Write to ROM");
    return q;
}

QString DriveLimitSet::written(const SentValues &sent, int id) const
{
    return sent.rom ? tr("Limits written to the ROM of drive %1 and read back: the drive holds "
                         "what was sent.")
                          .arg(id)
                    : tr("Limits written to the RAM of drive %1 and read back: the drive holds "
                         "what was sent. Lost at power-off unless written to ROM.")
                          .arg(id);
}

} // namespace lk::ui
