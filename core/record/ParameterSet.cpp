#include "ParameterSet.h"

#include <QtCore/QCoreApplication>

#include <QtCore/QFile>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonValue>
#include <QtCore/QSaveFile>

#include <cmath>
#include <limits>

namespace lk::record {

namespace {

const char kFormat[] = "lkstudio-parameters";
constexpr qint64 kMaxFileBytes = 1 << 20; // a parameter set is a few hundred bytes

struct GainField {
    const char *key;
    quint8 protocol::PidGains::*member;
};
const GainField kGains[] = {
    {"angle_kp", &protocol::PidGains::angleKp}, {"angle_ki", &protocol::PidGains::angleKi},
    {"speed_kp", &protocol::PidGains::speedKp}, {"speed_ki", &protocol::PidGains::speedKi},
    {"iq_kp", &protocol::PidGains::iqKp},       {"iq_ki", &protocol::PidGains::iqKi},
};

bool fail(QString *error, const QString &text)
{
    if (error)
        *error = text;
    return false;
}

// An integral JSON number in [lo, hi]; false (with the reason) otherwise.
bool readInteger(const QJsonObject &o, const char *key, qint64 lo, qint64 hi, qint64 &out,
                 QString *error)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return fail(error, QStringLiteral("%1 is missing").arg(QLatin1String(key)));
    const double d = v.toDouble(std::numeric_limits<double>::quiet_NaN());
    if (!v.isDouble() || !std::isfinite(d) || d != std::floor(d) || d < double(lo) ||
        d > double(hi))
        return fail(error, QStringLiteral("%1 must be an integer in %2..%3")
                               .arg(QLatin1String(key))
                               .arg(lo)
                               .arg(hi));
    out = static_cast<qint64>(d);
    return true;
}

bool readDrive(const QJsonObject &d, ParameterSet &set, QString *error)
{
    qint64 id = 0;
    if (!readInteger(d, "id", 1, 32, id, error))
        return fail(error, QStringLiteral("drive.") + (error ? *error : QString()));
    set.driveId = int(id);
    set.driverName = d.value(QStringLiteral("driver_name")).toString();
    set.motorName = d.value(QStringLiteral("motor_name")).toString();
    const QJsonValue series = d.value(QStringLiteral("series"));
    if (series.isString()) {
        set.series = protocol::seriesFromName(series.toString());
        if (!set.series)
            return fail(error, QStringLiteral("drive.series \"%1\" is not MS, MF, MG or MH")
                                   .arg(series.toString()));
    }
    set.hardwareVersion = d.value(QStringLiteral("hardware_version")).toDouble();
    set.firmwareVersion = d.value(QStringLiteral("firmware_version")).toDouble();
    return true;
}

bool readBody(const QJsonObject &root, ParameterSet &set, QString *error)
{
    if (root.value(QStringLiteral("format")).toString() != QLatin1String(kFormat))
        return fail(error,
                    QCoreApplication::translate("lk::record::ParameterSet",
                                                "not an LK Servo Studio parameter file (format is "
                                                "not \"%1\")")
                        .arg(QLatin1String(kFormat)));
    qint64 version = 0;
    if (!readInteger(root, "version", 1, 1000000, version, error))
        return false;
    if (version > ParameterSet::kFormatVersion)
        return fail(error, QCoreApplication::translate(
                               "lk::record::ParameterSet",
                               "written by a newer release (format version %1, this "
                               "one reads up to %2)")
                               .arg(version)
                               .arg(ParameterSet::kFormatVersion));
    if (!root.value(QStringLiteral("drive")).isObject())
        return fail(error,
                    QCoreApplication::translate("lk::record::ParameterSet", "drive is missing"));
    if (!readDrive(root.value(QStringLiteral("drive")).toObject(), set, error))
        return false;
    set.savedAt =
        QDateTime::fromString(root.value(QStringLiteral("saved_at")).toString(), Qt::ISODateWithMs);
    if (!root.value(QStringLiteral("pid")).isObject())
        return fail(error,
                    QCoreApplication::translate("lk::record::ParameterSet", "pid is missing"));
    const QJsonObject pid = root.value(QStringLiteral("pid")).toObject();
    for (const GainField &g : kGains) {
        qint64 v = 0;
        if (!readInteger(pid, g.key, 0, 255, v, error))
            return fail(error, QStringLiteral("pid.") + (error ? *error : QString()));
        set.pid.*(g.member) = static_cast<quint8>(v);
    }
    const QJsonValue accel = root.value(QStringLiteral("accel_dps2"));
    if (!accel.isUndefined() && !accel.isNull()) {
        qint64 a = 0;
        if (!readInteger(root, "accel_dps2", 0, std::numeric_limits<qint32>::max(), a, error))
            return false;
        set.accelDps2 = static_cast<qint32>(a);
    }
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
    for (const GainField &g : kGains)
        gains.insert(QLatin1String(g.key), int(pid.*(g.member)));

    QJsonObject o;
    o.insert(QStringLiteral("format"), QLatin1String(kFormat));
    o.insert(QStringLiteral("version"), kFormatVersion);
    o.insert(QStringLiteral("saved_at"), savedAt.toUTC().toString(Qt::ISODateWithMs));
    o.insert(QStringLiteral("drive"), drive);
    o.insert(QStringLiteral("pid"), gains);
    if (accelDps2)
        o.insert(QStringLiteral("accel_dps2"), qint64(*accelDps2));
    return o;
}

QByteArray ParameterSet::toJsonBytes() const
{
    return QJsonDocument(toJson()).toJson(QJsonDocument::Indented);
}

std::optional<ParameterSet> ParameterSet::fromJson(const QByteArray &bytes, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        fail(error, QCoreApplication::translate("lk::record::ParameterSet",
                                                "not valid JSON (%1 at byte %2)")
                        .arg(parseError.errorString())
                        .arg(parseError.offset));
        return std::nullopt;
    }
    if (!doc.isObject()) {
        fail(error, QCoreApplication::translate("lk::record::ParameterSet", "not a JSON object"));
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

std::optional<ParameterSet> ParameterSet::load(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        fail(error, QCoreApplication::translate("lk::record::ParameterSet", "cannot read %1: %2")
                        .arg(path, file.errorString()));
        return std::nullopt;
    }
    if (file.size() > kMaxFileBytes) {
        fail(error, QStringLiteral("%1 is too large to be a parameter file").arg(path));
        return std::nullopt;
    }
    return fromJson(file.readAll(), error);
}

QString writeFileAtomically(const QString &path, const QByteArray &bytes)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QCoreApplication::translate("lk::record::ParameterSet", "cannot write %1: %2")
            .arg(path, file.errorString());
    if (file.write(bytes) != bytes.size()) {
        const QString why = file.errorString();
        file.cancelWriting();
        return QCoreApplication::translate("lk::record::ParameterSet", "cannot write %1: %2")
            .arg(path, why);
    }
    if (!file.commit())
        return QCoreApplication::translate("lk::record::ParameterSet", "cannot write %1: %2")
            .arg(path, file.errorString());
    return QString();
}

} // namespace lk::record
