#include "ParameterSet.h"

#include "ParameterFileCheck.h"

#include <system/AtomicFile.h>

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

using Field = FileField;
using Check = ParameterFileCheck;

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

bool readDrive(const QJsonObject &d, ParameterSet &set, ParameterFileError *error)
{
    if (!Check::checkObject(d, QStringLiteral("drive."), driveFields(), error))
        return false;
    set.driveId = d.value(QStringLiteral("id")).toInt();
    set.driverName = d.value(QStringLiteral("driver_name")).toString();
    set.motorName = d.value(QStringLiteral("motor_name")).toString();
    const QJsonValue series = d.value(QStringLiteral("series"));
    if (series.isString()) {
        set.series = protocol::seriesFromName(series.toString());
        if (!set.series)
            return Check::refuse(error, Check::textError(Kind::UnknownSeries,
                                                         QStringLiteral("drive.series"), series));
    }
    set.hardwareVersion = d.value(QStringLiteral("hardware_version")).toDouble();
    set.firmwareVersion = d.value(QStringLiteral("firmware_version")).toDouble();
    return true;
}

bool readBody(const QJsonObject &root, ParameterSet &set, ParameterFileError *error)
{
    if (!Check::checkHeader(root, kFormat, ParameterSet::kFormatVersion, error) ||
        !Check::checkObject(root, QString(), rootFields(), error))
        return false;
    if (!readDrive(root.value(QStringLiteral("drive")).toObject(), set, error))
        return false;
    const QJsonValue savedAt = root.value(QStringLiteral("saved_at"));
    if (savedAt.isString()) {
        set.savedAt = QDateTime::fromString(savedAt.toString(), Qt::ISODateWithMs);
        if (!set.savedAt.isValid())
            return Check::refuse(
                error, Check::textError(Kind::BadTimestamp, QStringLiteral("saved_at"), savedAt));
    }
    const QJsonValue generation = root.value(QStringLiteral("generation"));
    if (generation.isString()) {
        const auto g = protocol::generationFromName(generation.toString());
        if (!g)
            return Check::refuse(error, Check::textError(Kind::UnknownGeneration,
                                                         QStringLiteral("generation"), generation));
        set.generation = *g;
    }
    const QJsonObject pid = root.value(QStringLiteral("pid")).toObject();
    if (!Check::checkObject(pid, QStringLiteral("pid."), pidFields(set.generation), error))
        return false;
    const QJsonValue accel = root.value(QStringLiteral("accel_dps2"));
    if (set.generation == protocol::Generation::V2_35) {
        if (!accel.isUndefined()) // V2.35 has no 0x33/0x34: its ramps are drive limits
            return Check::refuse(
                error, Check::textError(Kind::UnknownKey, QStringLiteral("accel_dps2"), accel));
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
    QJsonObject root;
    if (!Check::parseObject(bytes, root, error))
        return std::nullopt;
    ParameterSet set;
    if (!readBody(root, set, error))
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
    std::optional<ParameterSet> set;
    if (const std::optional<QByteArray> bytes = Check::readFile(path, kMaxFileBytes, &e))
        set = fromJson(*bytes, &e);
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
