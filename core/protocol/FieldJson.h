#pragma once

#include "Command.h"
#include "Frame.h"
#include "ProtocolFields.h"
#include "Reply.h"
#include "Request.h"
#include "Series.h"
#include "StreamParser.h"

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>
#include <QtCore/QString>

#include <optional>

namespace lk::protocol {

/// The CLI.md JSON face of the protocol: typed requests and replies as `fields` objects,
/// whole frames and parse faults as one JSON object each (`lkctl decode`, the GUI's traffic
/// export). Field names, order and real/integer come from ProtocolFields.
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
    /// sorted. QJsonDocument would sort keys and write 100.0 as 100. (OrderedJson::fieldsText)
    static QByteArray toJsonLine(const QJsonObject &object);

    /// "3E 80 01 00 BF": upper-case hex bytes separated by single spaces.
    static QString hexText(const QByteArray &bytes);
};

} // namespace lk::protocol
