#pragma once

#include "Command.h"
#include "ControlParameter.h"
#include "Parameter.h"
#include "Series.h"

#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include <optional>

namespace lk::protocol {

/// A request field with a wire range of its own. A name used with two ranges (angle_deg of
/// multi_position and of single_position) is two fields.
enum class FieldId : quint8 {
    None, ///< a field only written (frame keys, reply values, `<field>_raw`)
    Direction,
    Id,
    Power,
    TorqueIqA,
    SpeedDps,
    Action,
    Param,
    MultiAngleDeg,
    SingleAngleDeg,
    IncrementAngleDeg,
    MaxSpeedDps,
    AngleKp,
    AngleKpParam,
    AngleKi,
    AngleKiParam,
    AngleKdParam,
    SpeedKp,
    SpeedKpParam,
    SpeedKi,
    SpeedKiParam,
    SpeedKdParam,
    IqKp,
    IqKpParam,
    IqKi,
    IqKiParam,
    IqKdParam,
    AccelDps2,
    EncoderOffset,
    MaxTorque,
    ParamMaxSpeedDps,
    MaxAngleDeg,
    CurrentRamp,
    SpeedRampDps2,
    ControlParam,          ///< CAN V2.36 0xC0/0xC1: which control parameter
    ControlMaxAngleDeg,    ///< CAN V2.36 input angle limit: int32 of 0.01 deg
    ControlCurrentRampRaw, ///< CAN V2.36 input current ramp: int32, unit unknown
};

/// How a request field is written on the command line (`lkctl encode`).
enum class FieldKind {
    Integer,   ///< decimal integer (PID gains, accel_dps2, encoder_offset, power, id)
    Number,    ///< physical value, decimal or exponent notation (dps, deg, A)
    Direction, ///< "cw" or "ccw"
    Choice,    ///< one of the words in FieldSpec::range, separated by '|'
};

/// One row of the field table: a CLI.md field name with how it is written and, for a request
/// field, its wire range. Physical value = wire value * scaleNum / scaleDen.
struct ProtocolField {
    const char *name; ///< CLI.md spelling; on the command line `--` + name with '-' for '_'
    FieldId id;       ///< FieldId::None for fields that are only written
    bool real;        ///< JSON writes it with a decimal point ("100.0") whatever its value
    const char *unit; ///< "dps", "deg", "A", "dps/s", "V", "C" or ""
    qint64 scaleNum = 1, scaleDen = 1; ///< request fields; replies' scales vary by drive
    FieldKind kind = FieldKind::Integer;
    qint64 min = 0, max = 0; ///< the wire range (request fields)
    const char *range = "";  ///< its text, as FieldError and `lkctl encode --help` print it
    /// How lkctl's text mode shows the field (ReplyText): nullptr for fields it leaves out
    /// (`*_raw` values, the flags folded into "errors", frame keys). A name shared by several
    /// rows is labelled on its first.
    const char *label = nullptr;
    const char *textUnit = ""; ///< "counts", "(of 1000)": what a person needs beside the value
    int places = -1;           ///< digits after the point for reals; -1: as the JSON has it
    bool trim = true;          ///< drop trailing zeros (speeds); keep them (voltage, angles)

    /// This row as lkctl's text mode shows it.
    constexpr ProtocolField shown(const char *textLabel, const char *unitText = "",
                                  int decimals = -1, bool trimZeros = true) const
    {
        ProtocolField f = *this;
        f.label = textLabel;
        f.textUnit = unitText;
        f.places = decimals;
        f.trim = trimZeros;
        return f;
    }

    bool isRequestField() const { return id != FieldId::None; }
    /// The physical unit of one wire LSB (0.01 for 0.01 dps).
    double unitsPerLsb() const { return double(scaleNum) / double(scaleDen); }
    /// The wire value in physical units; a division by an exact decimal power gives the
    /// double nearest the decimal value (12345 -> 123.45).
    double physical(qint64 wire) const
    {
        return double(wire) * double(scaleNum) / double(scaleDen);
    }
};

/// One request field of a command as text: CLI.md name, how it is written, its allowed range.
struct FieldSpec {
    QString name; ///< e.g. "speed_dps"; on the command line `--speed-dps`
    FieldKind kind = FieldKind::Number;
    QString range; ///< the same text the builder puts in its FieldError
    FieldId id = FieldId::None;
};

/// The table of protocol fields, in CLI.md order (the frame keys, then every field in the
/// order of CLI.md's field table): names, units, scales, integer or real, and the wire ranges
/// the request builders enforce (the stricter bound where V2.3 and V2.35 differ). The JSON
/// writer orders keys by it; `lkctl encode` lists and parses fields by it.
class ProtocolFields {
public:
    static const QList<ProtocolField> &all();
    /// The row of a request field (FieldId::None is not one).
    static const ProtocolField &field(FieldId id);
    static FieldSpec spec(FieldId id);
    static FieldSpec idSpec();

    /// Position of a JSON key in CLI.md order; keys not in the table rank after all of them.
    static int rank(const QString &name);
    /// True for fields written as reals (QJsonValue keeps 100.0 as the integer 100).
    static bool isReal(const QString &name);

    /// The request fields of a command besides "id", in CLI.md order; empty for commands
    /// without data. write_param_ram/rom take `param` and then the fields of ofParam().
    static QList<FieldSpec> ofCommand(Command command);
    /// The value fields of one V2.35 parameter (write_param_ram/rom after `param`).
    static QList<FieldSpec> ofParam(ParamId param);
    /// The value fields of one CAN V2.36 control parameter (write_control_param after
    /// `control_param`): the V2.35 parameter's where the wire range is the same (gains, torque
    /// limit, speed limit, speed ramp), int32 ones for the angle limit and the current ramp.
    static QList<FieldSpec> ofControlParam(ControlParamId param);
    /// The row that names a one-value V2.35 parameter on a drive of `series`: ParamID 0x99 is
    /// "max power" on MS (whose commands and replies carry power) and "max torque current"
    /// on MF/MG/MH (and an unknown series). The one place both names live.
    static const ProtocolField &paramRow(ParamId param, std::optional<Series> series);
    /// paramRow()'s label, as lkctl prints it ("max power").
    static QString paramLabel(ParamId param, std::optional<Series> series);
    /// The same label translated for lkstudio.
    static QString paramLabelTranslated(ParamId param, std::optional<Series> series);
};

} // namespace lk::protocol
