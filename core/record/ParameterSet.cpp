#include "ParameterSet.h"

#include <system/AtomicFile.h>
#include <system/BoundedFile.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonValue>
#include <QtCore/QSet>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lk::record {

namespace {

using Kind = ParameterFileError::Kind;
using ValueType = ParameterFileError::ValueType;

const char *const kFormat = ParameterSet::kFormatName;
constexpr double kMaxVersionShown = 65535 / 10.0; // u16 raw / 10 (V2.3) or / 100 (V2.35)
constexpr int kGainMax = 255;
constexpr int kGainMaxV235 = 65535;

// V2.35 keys in the order of ParameterSet::pidV235.
const char *const kGainsV235[] = {"angle_kp", "angle_ki", "angle_kd", "speed_kp", "speed_ki",
                                  "speed_kd", "iq_kp",    "iq_ki",    "iq_kd"};

struct GainField {
    const char *key;
    quint8 protocol::PidGains::*member;
};
const GainField kGains[] = {
    {"angle_kp", &protocol::PidGains::angleKp}, {"angle_ki", &protocol::PidGains::angleKi},
    {"speed_kp", &protocol::PidGains::speedKp}, {"speed_ki", &protocol::PidGains::speedKi},
    {"iq_kp", &protocol::PidGains::iqKp},       {"iq_ki", &protocol::PidGains::iqKi},
};

/// One key of the format: what it holds, its range, whether a file must have it.
struct Field {
    const char *key;
    ValueType type;
    double min = 0;
    double max = 0;
    bool required = true;
};

const std::vector<Field> &rootFields()
{
    static const std::vector<Field> fields = {
        {"format", ValueType::Text},
        {"version", ValueType::Integer, 1, 1000000},
        {"saved_at", ValueType::Text, 0, 0, false},
        {"generation", ValueType::Text, 0, 0, false},
        {"drive", ValueType::Object},
        {"pid", ValueType::Object},
        {"accel_dps2", ValueType::Integer, 0, std::numeric_limits<qint32>::max(), false},
    };
    return fields;
}

const std::vector<Field> &driveFields()
{
    static const std::vector<Field> fields = {
        {"id", ValueType::Integer, 1, 32},
        {"driver_name", ValueType::Text, 0, 0, false},
        {"motor_name", ValueType::Text, 0, 0, false},
        {"series", ValueType::Text, 0, 0, false},
        {"hardware_version", ValueType::Number, 0, kMaxVersionShown, false},
        {"firmware_version", ValueType::Number, 0, kMaxVersionShown, false},
    };
    return fields;
}

const std::vector<Field> &pidFields(protocol::Generation generation)
{
    static const std::vector<Field> v23 = [] {
        std::vector<Field> f;
        for (const GainField &g : kGains)
            f.push_back({g.key, ValueType::Integer, 0, kGainMax});
        return f;
    }();
    static const std::vector<Field> v235 = [] {
        std::vector<Field> f;
        for (const char *key : kGainsV235)
            f.push_back({key, ValueType::Integer, 0, kGainMaxV235});
        return f;
    }();
    return generation == protocol::Generation::V2_3 ? v23 : v235;
}

bool refuse(ParameterFileError *error, ParameterFileError e)
{
    if (error)
        *error = std::move(e);
    return false;
}

QString jsonText(const QJsonValue &v)
{
    const QByteArray array = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(array.mid(1, array.size() - 2)); // without the brackets
}

ParameterFileError keyError(Kind kind, const QString &key, const Field &field,
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

// A text key whose text means nothing here (an unknown series, a date that is not one).
ParameterFileError textError(Kind kind, const QString &key, const QJsonValue &found)
{
    ParameterFileError e;
    e.kind = kind;
    e.key = key;
    e.expected = ValueType::Text;
    e.found = jsonText(found);
    return e;
}

bool checkValue(const QJsonValue &v, const Field &f, const QString &key, ParameterFileError *error)
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

// Every key known, every required key there, every value of its type and in its range.
bool checkObject(const QJsonObject &o, const QString &prefix, const std::vector<Field> &fields,
                 ParameterFileError *error)
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

// QJsonDocument keeps one of two equal keys without a word; a hand-edited file that gives
// "iq_kp" twice must be refused instead. Runs on text QJsonDocument has accepted, so the
// syntax is valid and only strings, objects and arrays need following. Returns the dotted
// path of the first key given twice.
std::optional<QString> findDuplicateKey(const QByteArray &json)
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

bool readHeader(const QJsonObject &root, ParameterFileError *error)
{
    const QJsonValue format = root.value(QStringLiteral("format"));
    if (format.toString() != QLatin1String(kFormat)) {
        ParameterFileError e;
        e.kind = Kind::WrongFormat;
        e.key = QStringLiteral("format");
        if (!format.isUndefined())
            e.found = jsonText(format);
        return refuse(error, e);
    }
    // Checked before the other keys: a newer format may have keys this one does not know.
    const Field &versionField =
        *std::find_if(rootFields().begin(), rootFields().end(),
                      [](const Field &f) { return qstrcmp(f.key, "version") == 0; });
    const QJsonValue version = root.value(QLatin1String(versionField.key));
    if (version.isUndefined())
        return refuse(error, keyError(Kind::MissingKey, QLatin1String(versionField.key),
                                      versionField, version));
    if (!checkValue(version, versionField, QLatin1String(versionField.key), error))
        return false;
    if (version.toInteger() > ParameterSet::kFormatVersion) {
        ParameterFileError e;
        e.kind = Kind::NewerVersion;
        e.key = QLatin1String(versionField.key);
        e.found = jsonText(version);
        e.max = ParameterSet::kFormatVersion;
        return refuse(error, e);
    }
    return true;
}

bool readDrive(const QJsonObject &d, ParameterSet &set, ParameterFileError *error)
{
    if (!checkObject(d, QStringLiteral("drive."), driveFields(), error))
        return false;
    set.driveId = d.value(QStringLiteral("id")).toInt();
    set.driverName = d.value(QStringLiteral("driver_name")).toString();
    set.motorName = d.value(QStringLiteral("motor_name")).toString();
    const QJsonValue series = d.value(QStringLiteral("series"));
    if (series.isString()) {
        set.series = protocol::seriesFromName(series.toString());
        if (!set.series)
            return refuse(error,
                          textError(Kind::UnknownSeries, QStringLiteral("drive.series"), series));
    }
    set.hardwareVersion = d.value(QStringLiteral("hardware_version")).toDouble();
    set.firmwareVersion = d.value(QStringLiteral("firmware_version")).toDouble();
    return true;
}

bool readBody(const QJsonObject &root, ParameterSet &set, ParameterFileError *error)
{
    if (!readHeader(root, error) || !checkObject(root, QString(), rootFields(), error))
        return false;
    if (!readDrive(root.value(QStringLiteral("drive")).toObject(), set, error))
        return false;
    const QJsonValue savedAt = root.value(QStringLiteral("saved_at"));
    if (savedAt.isString()) {
        set.savedAt = QDateTime::fromString(savedAt.toString(), Qt::ISODateWithMs);
        if (!set.savedAt.isValid())
            return refuse(error,
                          textError(Kind::BadTimestamp, QStringLiteral("saved_at"), savedAt));
    }
    const QJsonValue generation = root.value(QStringLiteral("generation"));
    if (generation.isString()) {
        const auto g = protocol::generationFromName(generation.toString());
        if (!g)
            return refuse(error, textError(Kind::UnknownGeneration, QStringLiteral("generation"),
                                           generation));
        set.generation = *g;
    }
    const QJsonObject pid = root.value(QStringLiteral("pid")).toObject();
    if (!checkObject(pid, QStringLiteral("pid."), pidFields(set.generation), error))
        return false;
    const QJsonValue accel = root.value(QStringLiteral("accel_dps2"));
    if (set.generation == protocol::Generation::V2_35) {
        if (!accel.isUndefined()) // V2.35 has no 0x33/0x34: its ramps are drive limits
            return refuse(error, textError(Kind::UnknownKey, QStringLiteral("accel_dps2"), accel));
        for (std::size_t i = 0; i < set.pidV235.size(); ++i)
            set.pidV235[i] = static_cast<quint16>(pid.value(QLatin1String(kGainsV235[i])).toInt());
        return true;
    }
    for (const GainField &g : kGains)
        set.pid.*(g.member) = static_cast<quint8>(pid.value(QLatin1String(g.key)).toInt());
    if (accel.isDouble())
        set.accelDps2 = static_cast<qint32>(accel.toInteger());
    return true;
}

} // namespace

QJsonObject ParameterSet::toJson() const
{
    QJsonObject drive;
    drive.insert(QStringLiteral("id"), driveId);
    drive.insert(QStringLiteral("driver_name"), driverName);
    drive.insert(QStringLiteral("motor_name"), motorName);
    if (series)
        drive.insert(QStringLiteral("series"), protocol::seriesName(*series));
    drive.insert(QStringLiteral("hardware_version"), hardwareVersion);
    drive.insert(QStringLiteral("firmware_version"), firmwareVersion);

    QJsonObject gains;
    if (generation == protocol::Generation::V2_35) {
        for (std::size_t i = 0; i < pidV235.size(); ++i)
            gains.insert(QLatin1String(kGainsV235[i]), int(pidV235[i]));
    } else {
        for (const GainField &g : kGains)
            gains.insert(QLatin1String(g.key), int(pid.*(g.member)));
    }

    QJsonObject o;
    o.insert(QStringLiteral("format"), QLatin1String(kFormat));
    o.insert(QStringLiteral("version"), kFormatVersion);
    o.insert(QStringLiteral("saved_at"), savedAt.toUTC().toString(Qt::ISODateWithMs));
    o.insert(QStringLiteral("generation"), protocol::generationName(generation));
    o.insert(QStringLiteral("drive"), drive);
    o.insert(QStringLiteral("pid"), gains);
    if (accelDps2 && generation == protocol::Generation::V2_3)
        o.insert(QStringLiteral("accel_dps2"), qint64(*accelDps2));
    return o;
}

QByteArray ParameterSet::toJsonBytes() const
{
    return QJsonDocument(toJson()).toJson(QJsonDocument::Indented);
}

std::optional<ParameterSet> ParameterSet::fromJson(const QByteArray &bytes,
                                                   ParameterFileError *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        ParameterFileError e;
        e.kind = Kind::NotJson;
        e.detail = parseError.errorString();
        e.offset = parseError.offset;
        refuse(error, e);
        return std::nullopt;
    }
    if (!doc.isObject()) {
        ParameterFileError e;
        e.kind = Kind::NotObject;
        refuse(error, e);
        return std::nullopt;
    }
    if (const std::optional<QString> twice = findDuplicateKey(bytes)) {
        ParameterFileError e;
        e.kind = Kind::DuplicateKey;
        e.key = *twice;
        refuse(error, e);
        return std::nullopt;
    }
    ParameterSet set;
    if (!readBody(doc.object(), set, error))
        return std::nullopt;
    return set;
}

QString ParameterSet::save(const QString &path) const
{
    return writeFileAtomically(path, toJsonBytes());
}

std::optional<ParameterSet> ParameterSet::load(const QString &path, ParameterFileError *error)
{
    ParameterFileError e;
    const system::BoundedRead file = system::BoundedFile::read(path, kMaxFileBytes);
    std::optional<ParameterSet> set;
    if (file.ok()) {
        set = fromJson(file.bytes, &e);
    } else if (file.error->kind == system::FileReadError::Kind::TooLarge) {
        e.kind = Kind::TooLarge;
        e.max = double(kMaxFileBytes);
        e.found = QString::number(file.error->size);
        e.detail = file.error->reason();
    } else {
        e.kind = Kind::CannotRead; // a directory, a FIFO, a device: refused unopened
        e.detail = file.error->reason();
    }
    e.path = path;
    if (!set && error)
        *error = e;
    return set;
}

QString writeFileAtomically(const QString &path, const QByteArray &bytes)
{
    const QString why = system::AtomicFile::writeAll(path, bytes);
    if (why.isEmpty())
        return QString();
    return QCoreApplication::translate("lk::record::ParameterSet", "cannot write %1: %2")
        .arg(path, why);
}

} // namespace lk::record
