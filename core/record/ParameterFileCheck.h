#pragma once

#include "ParameterSet.h"

#include <QtCore/QJsonObject>
#include <QtCore/QJsonValue>
#include <QtCore/QString>

#include <optional>
#include <vector>

namespace lk::record {

/// One key of a parameter file format: what it holds, its range, whether a file must have it.
struct FileField {
    const char *key;
    ParameterFileError::ValueType type;
    double min = 0;
    double max = 0;
    bool required = true;
};

/// The checks every parameter file format of lkstudio shares (ParameterSet, fleet::BackupFile):
/// each refusal names the key, what it must hold and what the file holds.
class ParameterFileCheck {
public:
    /// Sets `*error` (when given) and returns false.
    static bool refuse(ParameterFileError *error, ParameterFileError e);
    /// A JSON value as the file spells it ("12", "\"MF\"").
    static QString jsonText(const QJsonValue &v);
    static ParameterFileError keyError(ParameterFileError::Kind kind, const QString &key,
                                       const FileField &field, const QJsonValue &found);
    /// A text key whose text means nothing here (an unknown series, a date that is not one).
    static ParameterFileError textError(ParameterFileError::Kind kind, const QString &key,
                                        const QJsonValue &found);
    /// `v` is of the field's type and within its range.
    static bool checkValue(const QJsonValue &v, const FileField &f, const QString &key,
                           ParameterFileError *error);
    /// Every key known, every required key there, every value of its type and in its range;
    /// `prefix` ("drive.") makes the dotted key a refusal names.
    static bool checkObject(const QJsonObject &o, const QString &prefix,
                            const std::vector<FileField> &fields, ParameterFileError *error);
    /// The dotted path of the first key given twice in one object (QJsonDocument keeps one of
    /// them without a word); `json` must be text QJsonDocument accepted.
    static std::optional<QString> findDuplicateKey(const QByteArray &json);
    /// Parses `bytes` as one JSON object without duplicate keys; false with `error` set.
    static bool parseObject(const QByteArray &bytes, QJsonObject &object,
                            ParameterFileError *error);
    /// The bytes of the regular file `path` (at most `maxBytes`); nullopt with `error` set
    /// (CannotRead, TooLarge) otherwise: a directory, a FIFO, a device is refused unopened.
    static std::optional<QByteArray> readFile(const QString &path, qint64 maxBytes,
                                              ParameterFileError *error);
    /// The "format" and "version" keys: `format` expected, version 1..`newest`.
    static bool checkHeader(const QJsonObject &root, const char *format, int newest,
                            ParameterFileError *error);
};

} // namespace lk::record
