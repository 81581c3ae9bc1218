#include "ParameterFileCheck.h"

#include <system/BoundedFile.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QSet>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lk::record {

namespace {

using Kind = ParameterFileError::Kind;
using ValueType = ParameterFileError::ValueType;
using Field = FileField;

// Where the string token starting with the quote at `from` ends (its closing quote).
qsizetype stringEnd(const QByteArray &json, qsizetype from)
{
    qsizetype i = from + 1;
    while (i < json.size() && json.at(i) != '"')
        i += json.at(i) == '\\' ? 2 : 1;
    return i;
}

QString decodeKey(const QByteArray &token)
{
    if (!token.contains('\\'))
        return QString::fromUtf8(token.mid(1, token.size() - 2));
    const QByteArray wrapped = '[' + token + ']';
    return QJsonDocument::fromJson(wrapped).array().at(0).toString();
}

} // namespace

bool ParameterFileCheck::refuse(ParameterFileError *error, ParameterFileError e)
{
    if (error)
        *error = std::move(e);
    return false;
}

QString ParameterFileCheck::jsonText(const QJsonValue &v)
{
    const QByteArray array = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(array.mid(1, array.size() - 2)); // without the brackets
}

ParameterFileError ParameterFileCheck::keyError(Kind kind, const QString &key, const Field &field,
                                                const QJsonValue &found)
{
    ParameterFileError e;
    e.kind = kind;
    e.key = key;
    e.expected = field.type;
    e.min = field.min;
    e.max = field.max;
    if (!found.isUndefined())
        e.found = jsonText(found);
    return e;
}

ParameterFileError ParameterFileCheck::textError(Kind kind, const QString &key,
                                                 const QJsonValue &found)
{
    ParameterFileError e;
    e.kind = kind;
    e.key = key;
    e.expected = ValueType::Text;
    e.found = jsonText(found);
    return e;
}

bool ParameterFileCheck::checkValue(const QJsonValue &v, const Field &f, const QString &key,
                                    ParameterFileError *error)
{
    bool typeOk = false;
    switch (f.type) {
    case ValueType::Object:
        typeOk = v.isObject();
        break;
    case ValueType::Text:
        typeOk = v.isString();
        break;
    case ValueType::Integer:
    case ValueType::Number: {
        const double d = v.toDouble(std::numeric_limits<double>::quiet_NaN());
        typeOk =
            v.isDouble() && std::isfinite(d) && (f.type == ValueType::Number || d == std::floor(d));
        if (typeOk && (d < f.min || d > f.max))
            return refuse(error, keyError(Kind::OutOfRange, key, f, v));
        break;
    }
    }
    return typeOk || refuse(error, keyError(Kind::WrongType, key, f, v));
}

bool ParameterFileCheck::checkObject(const QJsonObject &o, const QString &prefix,
                                     const std::vector<Field> &fields, ParameterFileError *error)
{
    for (auto it = o.begin(); it != o.end(); ++it) {
        const bool known = std::any_of(fields.begin(), fields.end(), [&](const Field &f) {
            return it.key() == QLatin1String(f.key);
        });
        if (!known) {
            ParameterFileError e;
            e.kind = Kind::UnknownKey;
            e.key = prefix + it.key();
            return refuse(error, e);
        }
    }
    for (const Field &f : fields) {
        const QString key = prefix + QLatin1String(f.key);
        const QJsonValue v = o.value(QLatin1String(f.key));
        if (v.isUndefined() || (v.isNull() && !f.required)) {
            if (f.required)
                return refuse(error, keyError(Kind::MissingKey, key, f, QJsonValue::Undefined));
            continue;
        }
        if (!checkValue(v, f, key, error))
            return false;
    }
    return true;
}

std::optional<QString> ParameterFileCheck::findDuplicateKey(const QByteArray &json)
{
    struct Level {
        bool object = false;
        bool expectKey = false;
        QString path;
        QSet<QString> keys;
    };
    std::vector<Level> stack;
    QString lastPath; // the path of the last key read: a '{' or '[' after it is its value
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = json.at(i);
        if (c == '{' || c == '[') {
            const bool inObject = !stack.empty() && stack.back().object;
            const QString path = inObject        ? lastPath
                                 : stack.empty() ? QString()
                                                 : stack.back().path;
            stack.push_back({c == '{', c == '{', path, {}});
        } else if ((c == '}' || c == ']') && !stack.empty()) {
            stack.pop_back();
        } else if (c == ',' && !stack.empty()) {
            stack.back().expectKey = stack.back().object;
        } else if (c == '"') {
            const qsizetype end = stringEnd(json, i);
            if (!stack.empty() && stack.back().expectKey) {
                Level &level = stack.back();
                const QString key = decodeKey(json.mid(i, end - i + 1));
                lastPath = level.path.isEmpty() ? key : level.path + QLatin1Char('.') + key;
                if (level.keys.contains(key))
                    return lastPath;
                level.keys.insert(key);
                level.expectKey = false;
            }
            i = end;
        }
    }
    return std::nullopt;
}

bool ParameterFileCheck::parseObject(const QByteArray &bytes, QJsonObject &object,
                                     ParameterFileError *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    ParameterFileError e;
    if (parseError.error != QJsonParseError::NoError) {
        e.kind = Kind::NotJson;
        e.detail = parseError.errorString();
        e.offset = parseError.offset;
        return refuse(error, e);
    }
    if (!doc.isObject()) {
        e.kind = Kind::NotObject;
        return refuse(error, e);
    }
    if (const std::optional<QString> twice = findDuplicateKey(bytes)) {
        e.kind = Kind::DuplicateKey;
        e.key = *twice;
        return refuse(error, e);
    }
    object = doc.object();
    return true;
}

bool ParameterFileCheck::checkHeader(const QJsonObject &root, const char *format, int newest,
                                     ParameterFileError *error)
{
    const QJsonValue name = root.value(QStringLiteral("format"));
    if (name.toString() != QLatin1String(format)) {
        ParameterFileError e;
        e.kind = Kind::WrongFormat;
        e.key = QStringLiteral("format");
        if (!name.isUndefined())
            e.found = jsonText(name);
        return refuse(error, e);
    }
    // Checked before the other keys: a newer format may have keys this one does not know.
    const FileField versionField{"version", ValueType::Integer, 1, 1000000};
    const QString key = QLatin1String(versionField.key);
    const QJsonValue version = root.value(key);
    if (version.isUndefined())
        return refuse(error, keyError(Kind::MissingKey, key, versionField, version));
    if (!checkValue(version, versionField, key, error))
        return false;
    if (version.toInteger() > newest) {
        ParameterFileError e;
        e.kind = Kind::NewerVersion;
        e.key = key;
        e.found = jsonText(version);
        e.max = newest;
        return refuse(error, e);
    }
    return true;
}

std::optional<QByteArray> ParameterFileCheck::readFile(const QString &path, qint64 maxBytes,
                                                       ParameterFileError *error)
{
    const system::BoundedRead file = system::BoundedFile::read(path, maxBytes);
    if (file.ok())
        return file.bytes;
    ParameterFileError e;
    if (file.error->kind == system::FileReadError::Kind::TooLarge) {
        e.kind = Kind::TooLarge;
        e.max = double(maxBytes);
        e.found = QString::number(file.error->size);
    } else {
        e.kind = Kind::CannotRead;
    }
    e.detail = file.error->reason();
    e.path = path;
    refuse(error, e);
    return std::nullopt;
}

} // namespace lk::record
