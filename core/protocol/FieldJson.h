#pragma once

#include "Command.h"
#include "FieldError.h"
#include "Frame.h"
#include "Reply.h"
#include "Request.h"
#include "Series.h"
#include "StreamParser.h"

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QMap>
#include <QtCore/QString>

#include <optional>

namespace lk::protocol {

/// How a request field is written on the command line (`lkctl encode`).
enum class FieldKind {
    Integer,   ///< decimal integer (PID gains, accel_dps2, encoder_offset, power, id)
    Number,    ///< physical value, decimal or exponent notation (dps, deg, A)
    Direction, ///< "cw" or "ccw"
    Choice,    ///< one of the words in FieldSpec::range, separated by '|'
};

/// One request field of a command: CLI.md name, how it is written, its allowed range.
struct FieldSpec {
    QString name; ///< e.g. "speed_dps"; on the command line `--speed-dps`
    FieldKind kind = FieldKind::Number;
    QString range; ///< the same text the builder puts in its FieldError
};

/// Field values as typed by a user: CLI.md field name -> text ("id" included).
using FieldValues = QMap<QString, QString>;

/// Outcome of building a request from text fields.
struct FieldBuildResult {
    std::optional<Request> request;
    std::optional<FieldError> fieldError; ///< set when one field's value was missing or refused
    QString message;                      ///< why it failed, one line naming the field and range
    bool ok() const { return request.has_value(); }
};

/// The CLI.md JSON face of the protocol: typed requests and replies as `fields` objects,
/// whole frames and parse faults as one JSON object each (`lkctl decode`, the GUI's traffic
/// export), and the reverse, text fields to a validated request (`lkctl encode`).
///
/// Physical values are JSON numbers in A, dps, deg, V, C, dps/s; where the wire value is
/// scaled, the integer on the wire is given too as `<field>_raw`.
class FieldJson {
public:
    /// The context gives the torque command's scale (it differs for V2.35 MF drives).
    static QJsonObject requestFields(const Request &request, const DecodeContext &context = {});
    static QJsonObject replyFields(const Reply &reply);

    /// {"direction","command","code","id","fields"} for a valid frame. An echo is read as the
    /// request it repeats. nullopt when the frame does not decode in that direction.
    static std::optional<QJsonObject> frameObject(const Frame &frame, FrameDirection direction,
                                                  const DecodeContext &context);
    /// {"error":"bad_data_checksum","bytes":"3E A4 ..."}.
    static QJsonObject errorObject(ParseError error, const QByteArray &bytes);
    /// One StreamParser event as its CLI.md object (frame or error).
    static QJsonObject eventObject(const ParseEvent &event, const DecodeContext &context);
    /// True when the object describes a fault rather than a frame.
    static bool isError(const QJsonObject &object);

    /// One compact JSON line (no newline) with the keys in CLI.md order (direction, command,
    /// code, id, fields; error, bytes; fields in the order of CLI.md's field table) and
    /// physical values always written with a decimal point ("100.0"). Unknown keys follow,
    /// sorted. QJsonDocument would sort keys and write 100.0 as 100.
    static QByteArray toJsonLine(const QJsonObject &object);

    /// "3E 80 01 00 BF": upper-case hex bytes separated by single spaces.
    static QString hexText(const QByteArray &bytes);

    /// The request fields of a command besides "id", in CLI.md order; empty for commands
    /// without data. write_param_ram/rom take `param` and then the fields of paramFieldSpecs().
    static QList<FieldSpec> requestFieldSpecs(Command command);
    /// The value fields of one V2.35 parameter (write_param_ram/rom after `param`).
    static QList<FieldSpec> paramFieldSpecs(ParamId param);
    static FieldSpec idSpec();
    /// Build a request from text fields via the builders of RequestBuilder.h: nothing is
    /// clamped; missing, unknown, non-numeric and out-of-range fields are refused.
    static FieldBuildResult buildRequest(Command command, const FieldValues &values);
    static FieldBuildResult buildRequest(const QString &commandName, const FieldValues &values);
};

} // namespace lk::protocol
