#include "ProtocolFields.h"

#include "Checksum.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QHash>
#include <QtCore/QSet>
#include <QtCore/QStringList>

#include <algorithm>
#include <limits>

namespace lk::protocol {

namespace {

constexpr qint64 kInt32Min = std::numeric_limits<qint32>::min();
constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
constexpr qint64 kUInt32Max = std::numeric_limits<quint32>::max();
// Multi-turn angles stop at 9e16 deg: beyond it the 0.01-deg value, rounded through a double,
// may not fit an int64.
constexpr qint64 kMultiTurnLimitRaw = 9'000'000'000'000'000'000;

using K = FieldKind;

/// A field that is only written: frame keys, reply values, `<field>_raw`.
constexpr ProtocolField out(const char *name, const char *unit = "", bool real = false)
{
    return {name, FieldId::None, real, unit};
}

constexpr ProtocolField real(const char *name, const char *unit)
{
    return out(name, unit, true);
}

/// A request field of integer wire units.
constexpr ProtocolField integer(FieldId id, const char *name, qint64 min, qint64 max,
                                const char *range, const char *unit = "")
{
    return {name, id, false, unit, 1, 1, K::Integer, min, max, range};
}

/// A request field in physical units, rounded to the nearest wire unit (scaleNum/scaleDen
/// each); `real`: JSON writes it as a real.
constexpr ProtocolField number(FieldId id, const char *name, bool real, const char *unit,
                               qint64 scaleNum, qint64 scaleDen, qint64 min, qint64 max,
                               const char *range)
{
    return {name, id, real, unit, scaleNum, scaleDen, K::Number, min, max, range};
}

constexpr ProtocolField pidGain(FieldId id, const char *name)
{
    return integer(id, name, 0, 255, "0..255"); // V2.3 0x31/0x32: one byte each
}

constexpr ProtocolField paramGain(FieldId id, const char *name)
{
    return integer(id, name, 0, 65535, "0..65535"); // V2.35 loop parameters: uint16
}

// A function's static: built on first use, whatever the order of static initialisation.
const QList<ProtocolField> &table()
{
    static const QList<ProtocolField> kFields{
        // The frame keys; "direction" doubles as single_position's spin direction, "id" as the
        // drive ID every request takes.
        ProtocolField{"direction", FieldId::Direction, false, "", 1, 1, K::Direction, 0, 1,
                      "cw|ccw"}
            .shown("direction"),
        out("command"),
        out("code"),
        integer(FieldId::Id, "id", kMinId, kMaxId, "1..32"),
        out("fields"),
        out("error"),
        out("bytes"),
        // read_state1 (docs/V2.35.md section 5).
        out("temperature_c", "C").shown("temperature", "C"),
        real("voltage_v", "V").shown("voltage", "V", 1, false),
        out("voltage_raw"),
        real("bus_current_a", "A").shown("bus current", "A", 2, false),
        out("bus_current_raw"),
        out("motor_on").shown("motor on"),
        out("motor_state_raw"),
        out("error_state").shown("errors"),
        out("low_voltage"),
        out("over_voltage"),
        out("driver_over_temperature"),
        out("over_temperature"),
        out("motor_over_temperature"),
        out("over_current"),
        out("short_circuit"),
        out("stall"),
        out("input_timeout"),
        // Torque and speed: V2.3 32 A per 2000 LSB; V2.35 allows +-2048 at its own scale, the
        // stricter +-2000 serves both (ERRATA).
        number(FieldId::TorqueIqA, "iq_a", true, "A", 32, 2000, -2000, 2000, "-32..32 A")
            .shown("torque current", "A", 3),
        out("iq_raw"),
        // V2.3 allows +-1000, V2.35 +-850: the stricter bound serves both (docs/V2.35.md section
        // 11).
        integer(FieldId::Power, "power", -850, 850, "-850..850").shown("power", "(of 1000)"),
        number(FieldId::SpeedDps, "speed_dps", true, "dps", 1, 100, kInt32Min, kInt32Max,
               "-21474836.48..21474836.47 dps")
            .shown("speed", "dps", 2),
        out("speed_raw"),
        real("ia_a", "A").shown("phase A current", "A", 3),
        out("ia_raw"),
        real("ib_a", "A").shown("phase B current", "A", 3),
        out("ib_raw"),
        real("ic_a", "A").shown("phase C current", "A", 3),
        out("ic_raw"),
        out("encoder").shown("encoder", "counts"),
        out("encoder_raw").shown("encoder raw", "counts"),
        integer(FieldId::EncoderOffset, "encoder_offset", 0, 65535, "0..65535")
            .shown("encoder offset", "counts"),
        {"action", FieldId::Action, false, "", 1, 1, K::Choice, 0, 0, "engage|release|read"},
        // The words are ParamTable's names (see spec()).
        {"param", FieldId::Param, false, "", 1, 1, K::Choice, 0, 0, ""},
        out("param_id"),
        number(FieldId::MultiAngleDeg, "angle_deg", true, "deg", 1, 100, -kMultiTurnLimitRaw,
               kMultiTurnLimitRaw, "-9e16..9e16 deg")
            .shown("angle", "deg", 2, false),
        number(FieldId::SingleAngleDeg, "angle_deg", true, "deg", 1, 100, 0, 35999,
               "0..359.99 deg"),
        number(FieldId::IncrementAngleDeg, "angle_deg", true, "deg", 1, 100, kInt32Min, kInt32Max,
               "-21474836.48..21474836.47 deg"),
        out("angle_raw"),
        // uint32 of 0.01 dps in the limited position commands, int32 as a V2.35 parameter.
        number(FieldId::MaxSpeedDps, "max_speed_dps", true, "dps", 1, 100, 0, kUInt32Max,
               "0..42949672.95 dps")
            .shown("max speed", "dps", 2, false),
        number(FieldId::ParamMaxSpeedDps, "max_speed_dps", true, "dps", 1, 100, 0, kInt32Max,
               "0..21474836.47 dps"),
        out("max_speed_raw"),
        pidGain(FieldId::AngleKp, "angle_kp").shown("angle Kp"),
        paramGain(FieldId::AngleKpParam, "angle_kp"),
        pidGain(FieldId::AngleKi, "angle_ki").shown("angle Ki"),
        paramGain(FieldId::AngleKiParam, "angle_ki"),
        paramGain(FieldId::AngleKdParam, "angle_kd").shown("angle Kd"),
        pidGain(FieldId::SpeedKp, "speed_kp").shown("speed Kp"),
        paramGain(FieldId::SpeedKpParam, "speed_kp"),
        pidGain(FieldId::SpeedKi, "speed_ki").shown("speed Ki"),
        paramGain(FieldId::SpeedKiParam, "speed_ki"),
        paramGain(FieldId::SpeedKdParam, "speed_kd").shown("speed Kd"),
        pidGain(FieldId::IqKp, "iq_kp").shown("iq Kp"),
        paramGain(FieldId::IqKpParam, "iq_kp"),
        pidGain(FieldId::IqKi, "iq_ki").shown("iq Ki"),
        paramGain(FieldId::IqKiParam, "iq_ki"),
        paramGain(FieldId::IqKdParam, "iq_kd").shown("iq Kd"),
        // int32 on the wire (ERRATA); a negative acceleration has no meaning.
        integer(FieldId::AccelDps2, "accel_dps2", 0, kInt32Max, "0..2147483647 dps/s", "dps/s")
            .shown("acceleration", "dps/s"),
        // V2.35 parameters (docs/V2.35.md section 6); max_torque is in iq command units.
        // One name per series for ParamID 0x99 (paramLabel()): MS drives carry power.
        number(FieldId::MaxTorque, "max_torque", false, "", 1, 1, 0, 2048, "0..2048")
            .shown(QT_TRANSLATE_NOOP("lk::protocol::ProtocolFields", "max torque current"),
                   "(of 2048)"),
        out("max_power")
            .shown(QT_TRANSLATE_NOOP("lk::protocol::ProtocolFields", "max power"), "(of 1000)"),
        number(FieldId::MaxAngleDeg, "max_angle_deg", true, "deg", 1, 100, 0, kMultiTurnLimitRaw,
               "0..9e16 deg")
            .shown("max angle", "deg", 2, false),
        // CAN V2.36's input angle limit (docs/CAN.md section 4.1): an int32, not V2.35's int64.
        number(FieldId::ControlMaxAngleDeg, "max_angle_deg", true, "deg", 1, 100, 0, kInt32Max,
               "0..21474836.47 deg"),
        out("max_angle_raw"),
        out("max_angle_half_raw"),
        number(FieldId::CurrentRamp, "current_ramp", false, "", 1, 1, 0, 32767, "0..32767")
            .shown("current ramp"),
        number(FieldId::SpeedRampDps2, "speed_ramp_dps2", false, "dps/s", 1, 1, 0, kInt32Max,
               "0..2147483647 dps/s")
            .shown("speed ramp", "dps/s"),
        // CAN V2.36 control parameters (docs/CAN.md section 4.1): the current ramp is an int32
        // where V2.35 has an int16, and its unit is unknown, so its raw value.
        {"control_param", FieldId::ControlParam, false, "", 1, 1, K::Choice, 0, 0, ""},
        out("control_param_id"),
        integer(FieldId::ControlCurrentRampRaw, "current_ramp_raw", 0, kInt32Max,
                "0..2147483647 (unit unknown)")
            .shown("current ramp (raw, unit unknown)"),
        out("value_bytes"),
        out("success"),
        out("success_flag"),
        out("brake_released"),
        out("brake_raw"),
        out("driver_name").shown("driver"),
        out("motor_name").shown("motor"),
        real("hardware_version", "").shown("hardware version", "", 1),
        out("hardware_version_raw"),
        real("firmware_version", "").shown("firmware version", "", 2),
        out("firmware_version_raw"),
        out("motor_id").shown("motor ID"), // V2.35: the 12-byte unique ID, hex
        out("motor_version_raw"),
    };
    return kFields;
}

QString paramWords()
{
    QStringList names;
    for (const ParamInfo &p : ParamTable::all())
        names << QString::fromLatin1(p.name);
    return names.join(QLatin1Char('|'));
}

QString controlParamWords()
{
    QStringList names;
    for (const ControlParamInfo &p : ControlParamTable::all())
        names << QString::fromLatin1(p.name);
    return names.join(QLatin1Char('|'));
}

QList<FieldSpec> specs(std::initializer_list<FieldId> ids)
{
    QList<FieldSpec> list;
    for (FieldId id : ids)
        list.append(ProtocolFields::spec(id));
    return list;
}

} // namespace

const QList<ProtocolField> &ProtocolFields::all()
{
    return table();
}

const ProtocolField &ProtocolFields::field(FieldId id)
{
    static const QHash<FieldId, qsizetype> index = [] {
        QHash<FieldId, qsizetype> h;
        for (qsizetype i = 0; i < table().size(); ++i) {
            if (table().at(i).isRequestField())
                h.insert(table().at(i).id, i);
        }
        return h;
    }();
    Q_ASSERT(index.contains(id));
    return table().at(index.value(id));
}

FieldSpec ProtocolFields::spec(FieldId id)
{
    const ProtocolField &f = field(id);
    const QString range = id == FieldId::Param          ? paramWords()
                          : id == FieldId::ControlParam ? controlParamWords()
                                                        : QString::fromLatin1(f.range);
    return {QString::fromLatin1(f.name), f.kind, range, id};
}

FieldSpec ProtocolFields::idSpec()
{
    return spec(FieldId::Id);
}

int ProtocolFields::rank(const QString &name)
{
    // A name shared by several rows ranks at its first.
    static const QHash<QString, int> ranks = [] {
        QHash<QString, int> r;
        for (qsizetype i = 0; i < table().size(); ++i) {
            const QString name = QString::fromLatin1(table().at(i).name);
            if (!r.contains(name))
                r.insert(name, int(r.size()));
        }
        return r;
    }();
    return ranks.value(name, int(ranks.size()));
}

bool ProtocolFields::isReal(const QString &name)
{
    static const QSet<QString> reals = [] {
        QSet<QString> s;
        for (const ProtocolField &f : table()) {
            if (f.real)
                s.insert(QString::fromLatin1(f.name));
        }
        return s;
    }();
    return reals.contains(name);
}

QList<FieldSpec> ProtocolFields::ofCommand(Command command)
{
    switch (command) {
    case Command::WritePidRam:
    case Command::WritePidRom:
        return specs({FieldId::AngleKp, FieldId::AngleKi, FieldId::SpeedKp, FieldId::SpeedKi,
                      FieldId::IqKp, FieldId::IqKi});
    case Command::WriteAccelRam:
        return specs({FieldId::AccelDps2});
    case Command::WriteEncoderOffset:
        return specs({FieldId::EncoderOffset});
    case Command::OpenLoop:
        return specs({FieldId::Power});
    case Command::Torque:
        return specs({FieldId::TorqueIqA});
    case Command::Speed:
        return specs({FieldId::SpeedDps});
    case Command::MultiPosition:
        return specs({FieldId::MultiAngleDeg});
    case Command::MultiPositionLimited:
        return specs({FieldId::MultiAngleDeg, FieldId::MaxSpeedDps});
    case Command::SinglePosition:
        return specs({FieldId::Direction, FieldId::SingleAngleDeg});
    case Command::SinglePositionLimited:
        return specs({FieldId::Direction, FieldId::SingleAngleDeg, FieldId::MaxSpeedDps});
    case Command::IncrementPosition:
        return specs({FieldId::IncrementAngleDeg});
    case Command::IncrementPositionLimited:
        return specs({FieldId::IncrementAngleDeg, FieldId::MaxSpeedDps});
    case Command::ReadParam:
    case Command::WriteParamRam:
    case Command::WriteParamRom:
        return specs({FieldId::Param});
    case Command::Brake:
        return specs({FieldId::Action});
    case Command::ReadControlParam:
    case Command::WriteControlParam:
        return specs({FieldId::ControlParam});
    default:
        return {};
    }
}

const ProtocolField &ProtocolFields::paramRow(ParamId param, std::optional<Series> series)
{
    // A name shared by several rows is labelled on its first.
    const char *name = param == ParamId::MaxTorqueCurrent && series == Series::MS
                           ? "max_power"
                           : field(ofParam(param).constFirst().id).name;
    return *std::find_if(table().cbegin(), table().cend(), [name](const ProtocolField &f) {
        return f.label && qstrcmp(f.name, name) == 0;
    });
}

QString ProtocolFields::paramLabel(ParamId param, std::optional<Series> series)
{
    return QString::fromLatin1(paramRow(param, series).label);
}

QString ProtocolFields::paramLabelTranslated(ParamId param, std::optional<Series> series)
{
    return QCoreApplication::translate("lk::protocol::ProtocolFields",
                                       paramRow(param, series).label);
}

QList<FieldSpec> ProtocolFields::ofParam(ParamId param)
{
    switch (param) {
    case ParamId::AnglePid:
        return specs({FieldId::AngleKpParam, FieldId::AngleKiParam, FieldId::AngleKdParam});
    case ParamId::SpeedPid:
        return specs({FieldId::SpeedKpParam, FieldId::SpeedKiParam, FieldId::SpeedKdParam});
    case ParamId::CurrentPid:
        return specs({FieldId::IqKpParam, FieldId::IqKiParam, FieldId::IqKdParam});
    case ParamId::MaxTorqueCurrent:
        return specs({FieldId::MaxTorque});
    case ParamId::MaxSpeed:
        return specs({FieldId::ParamMaxSpeedDps});
    case ParamId::MaxAngleLow:
    case ParamId::MaxAngleHigh:
        return specs({FieldId::MaxAngleDeg});
    case ParamId::CurrentRamp:
        return specs({FieldId::CurrentRamp});
    case ParamId::SpeedRamp:
        return specs({FieldId::SpeedRampDps2});
    }
    return {};
}

QList<FieldSpec> ProtocolFields::ofControlParam(ControlParamId param)
{
    switch (param) {
    case ControlParamId::AnglePid:
        return ofParam(ParamId::AnglePid);
    case ControlParamId::SpeedPid:
        return ofParam(ParamId::SpeedPid);
    case ControlParamId::CurrentPid:
        return ofParam(ParamId::CurrentPid);
    case ControlParamId::InputTorqueLimit:
        return specs({FieldId::MaxTorque});
    case ControlParamId::InputSpeedLimit:
        return specs({FieldId::ParamMaxSpeedDps});
    case ControlParamId::InputAngleLimit:
        return specs({FieldId::ControlMaxAngleDeg});
    case ControlParamId::InputCurrentRamp:
        return specs({FieldId::ControlCurrentRampRaw});
    case ControlParamId::InputSpeedRamp:
        return specs({FieldId::SpeedRampDps2});
    }
    return {};
}

} // namespace lk::protocol
