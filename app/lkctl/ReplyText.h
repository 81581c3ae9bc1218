#pragma once

#include <protocol/Series.h>

#include <QtCore/QJsonObject>
#include <QtCore/QList>
#include <QtCore/QString>
#include <QtCore/QStringList>

namespace lk::lkctl {

/// Readable text for people at a terminal: CLI.md fields as "label  value unit" lines, with
/// the labels, units and places of the field table (ProtocolField::label). Scripts read
/// --json instead; this text is not a contract.
class ReplyText {
public:
    /// One line per field in the field table's order (ProtocolFields::all(), which puts
    /// driver/motor last: `info` orders its groups itself), labels aligned; *_raw fields and the
    /// flag booleans (folded into "errors") are left out.
    static QStringList lines(const QJsonObject &fields, const QString &indent = QString());
    /// The lines of several objects, one after the other, labels aligned across them.
    static QStringList lines(const QList<QJsonObject> &groups, const QString &indent = QString());
    /// The same lines on one line, comma-separated (error messages).
    static QString oneLine(const QJsonObject &fields);
    /// "none" or "low voltage, over temperature (0x09)".
    /// "over-current, stall (0x50)" with the flags `generation` names, or "none".
    static QString errorText(int errorState, protocol::Generation generation);
    /// The same for a read_state1 `fields` object, whose keys tell the generation.
    static QString errorText(int errorState, const QJsonObject &fields);
    /// A number as a person reads it: `decimals` places, trailing zeros trimmed.
    static QString number(double value, int decimals);
};

} // namespace lk::lkctl
