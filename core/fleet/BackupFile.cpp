#include "BackupFile.h"

#include <protocol/Checksum.h>
#include <record/ParameterFileCheck.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QJsonDocument>

#include <algorithm>
#include <vector>

namespace lk::fleet {

namespace {

using record::FileField;
using record::ParameterFileError;
using Check = record::ParameterFileCheck;
using Kind = ParameterFileError::Kind;
using ValueType = ParameterFileError::ValueType;

const QString kRead = QStringLiteral("read");
const QString kFailed = QStringLiteral("failed");

const std::vector<FileField> &rootFields()
{
    static const std::vector<FileField> fields = {
        {"format", ValueType::Text},
        {"version", ValueType::Integer, 1, 1000000},
        {"saved_at", ValueType::Text},
        {"drives", ValueType::Object},
    };
    return fields;
}

const QString kDeclared = QStringLiteral("declared");

const std::vector<FileField> &driveFields(bool read, bool declared)
{
    // A failed drive may lack what read_model would have told; a declared one (CAN) never
    // has the names and versions only read_model tells.
    auto make = [](bool read, bool modelRead) {
        const bool named = read && modelRead;
        return std::vector<FileField>{
            {"status", ValueType::Text},
            {"failure", ValueType::Text, 0, 0, false},
            {"read_at", ValueType::Text},
            {"link", ValueType::Text, 0, 0, false},
            {"identity", ValueType::Text, 0, 0, false},
            {"driver_name", ValueType::Text, 0, 0, named},
            {"motor_name", ValueType::Text, 0, 0, named},
            {"series", ValueType::Text, 0, 0, false},
            {"generation", ValueType::Text, 0, 0, read},
            {"gear_ratio", ValueType::Number, 1, 1000000, false},
            {"hardware_version_raw", ValueType::Integer, 0, 65535, named},
            {"firmware_version_raw", ValueType::Integer, 0, 65535, named},
            {"unique_id", ValueType::Text, 0, 0, false},
            {"params", ValueType::Object, 0, 0, read},
        };
    };
    static const std::vector<FileField> fields[2][2] = {{make(false, true), make(false, false)},
                                                        {make(true, true), make(true, false)}};
    return fields[read ? 1 : 0][declared ? 1 : 0];
}

/// How a CAN drive's generation is written: the words of `--drives` ("can", "can236").
QString canGenerationWord(protocol::Generation g)
{
    return g == protocol::Generation::V2_3 ? QStringLiteral("can") : QStringLiteral("can236");
}

// Every parameter of the generation, each an object {"value": N, "read_at": T}.
const std::vector<FileField> &paramFields(protocol::Generation g, protocol::Link link)
{
    static QList<QByteArray> names[3]; // FileField keeps the key as a C string
    static std::vector<FileField> fields[3];
    const int i = FleetCatalog::isCan236(g, link) ? 2 : g == protocol::Generation::V2_3 ? 0 : 1;
    if (fields[i].empty()) {
        for (const FleetParam &p : FleetCatalog::params(g, link))
            names[i] << p.key.toLatin1();
        for (const QByteArray &n : std::as_const(names[i]))
            fields[i].push_back({n.constData(), ValueType::Object});
    }
    return fields[i];
}

QString timeText(const QDateTime &t)
{
    return t.toUTC().toString(Qt::ISODateWithMs);
}

bool readTime(const QJsonValue &v, const QString &key, QDateTime &into, ParameterFileError *error)
{
    into = QDateTime::fromString(v.toString(), Qt::ISODateWithMs);
    return into.isValid() || Check::refuse(error, Check::textError(Kind::BadTimestamp, key, v));
}

bool readParams(const QJsonObject &params, const QString &prefix, DriveSnapshot &drive,
                ParameterFileError *error)
{
    const protocol::Generation g = drive.identity.generation;
    const protocol::Link link = drive.identity.link;
    if (!Check::checkObject(params, prefix, paramFields(g, link), error))
        return false;
    for (const FleetParam &p : FleetCatalog::params(g, link)) {
        const QString at = prefix + p.key + QLatin1Char('.');
        const QJsonObject o = params.value(p.key).toObject();
        const std::vector<FileField> valueFields = {
            {"value", ValueType::Integer, double(p.min), double(p.max)},
            {"read_at", ValueType::Text},
        };
        if (!Check::checkObject(o, at, valueFields, error))
            return false;
        ReadValue v;
        v.value = o.value(QStringLiteral("value")).toInteger();
        if (!readTime(o.value(QStringLiteral("read_at")), at + QStringLiteral("read_at"), v.readAt,
                      error))
            return false;
        drive.values.insert(p.key, v);
    }
    return true;
}

bool readIdentity(const QJsonObject &d, const QString &prefix, DriveSnapshot &drive,
                  ParameterFileError *error)
{
    DriveIdentity &who = drive.identity;
    const QJsonValue generation = d.value(QStringLiteral("generation"));
    drive.identified = !generation.isUndefined();
    if (!drive.identified)
        return true;
    const bool can = who.link == protocol::Link::Can;
    std::optional<protocol::Generation> g;
    for (protocol::Generation each : {protocol::Generation::V2_3, protocol::Generation::V2_35}) {
        if (generation.toString() ==
            (can ? canGenerationWord(each) : protocol::generationName(each)))
            g = each;
    }
    if (!g) {
        ParameterFileError e = Check::textError(Kind::UnknownGeneration,
                                                prefix + QStringLiteral("generation"), generation);
        if (can)
            e.detail = QStringLiteral("\"can\" or \"can236\" (the drive is on CAN)");
        return Check::refuse(error, e);
    }
    who.generation = *g;
    if (const QJsonValue gear = d.value(QStringLiteral("gear_ratio")); gear.isDouble())
        who.gearRatio = gear.toDouble();
    who.driverName = d.value(QStringLiteral("driver_name")).toString();
    who.motorName = d.value(QStringLiteral("motor_name")).toString();
    who.hardwareRaw = quint16(d.value(QStringLiteral("hardware_version_raw")).toInt());
    who.firmwareRaw = quint16(d.value(QStringLiteral("firmware_version_raw")).toInt());
    who.uniqueId = QByteArray::fromHex(d.value(QStringLiteral("unique_id")).toString().toLatin1());
    const QJsonValue series = d.value(QStringLiteral("series"));
    if (series.isString()) {
        who.series = protocol::seriesFromName(series.toString());
        if (!who.series)
            return Check::refuse(
                error,
                Check::textError(Kind::UnknownSeries, prefix + QStringLiteral("series"), series));
    }
    return true;
}

/// "link" (absent: RS485, as every file before CAN) and "identity": a CAN drive's identity is
/// always "declared", since CAN has no model read; an RS485 one's is read.
bool readLink(const QJsonObject &d, const QString &prefix, DriveIdentity &who,
              ParameterFileError *error)
{
    const QJsonValue link = d.value(QStringLiteral("link"));
    if (!link.isUndefined()) {
        const std::optional<protocol::Link> l = protocol::linkFromName(link.toString());
        if (!link.isString() || !l) {
            ParameterFileError e =
                Check::textError(Kind::WrongType, prefix + QStringLiteral("link"), link);
            e.detail = QStringLiteral("\"rs485\" or \"can\"");
            return Check::refuse(error, e);
        }
        who.link = *l;
    }
    const QJsonValue identity = d.value(QStringLiteral("identity"));
    const bool can = who.link == protocol::Link::Can;
    const QString expected = can ? kDeclared : kRead;
    if (identity.isUndefined() ? can : identity.toString() != expected) {
        ParameterFileError e =
            Check::textError(Kind::WrongType, prefix + QStringLiteral("identity"), identity);
        if (identity.isUndefined())
            e.found = QStringLiteral("missing");
        e.detail = can ? QStringLiteral("\"declared\": CAN has no model read")
                       : QStringLiteral("\"read\" (RS485 reads the model)");
        return Check::refuse(error, e);
    }
    who.declared = can;
    return true;
}

bool readDrive(const QString &idKey, const QJsonValue &value, DriveSnapshot &drive,
               ParameterFileError *error)
{
    const QString prefix = QStringLiteral("drives.%1.").arg(idKey);
    bool idOk = false;
    const int id = idKey.toInt(&idOk);
    if (!idOk || id < protocol::kMinId || id > protocol::kMaxId || idKey != QString::number(id)) {
        ParameterFileError e;
        e.kind = Kind::OutOfRange;
        e.key = QStringLiteral("drives.%1").arg(idKey);
        e.expected = ValueType::Integer;
        e.min = protocol::kMinId;
        e.max = protocol::kMaxId;
        e.found = Check::jsonText(idKey);
        return Check::refuse(error, e);
    }
    const FileField whole{"", ValueType::Object};
    if (!Check::checkValue(value, whole, prefix.chopped(1), error))
        return false;
    const QJsonObject d = value.toObject();
    const QJsonValue status = d.value(QStringLiteral("status"));
    const bool read = status.toString() == kRead;
    if (!read && status.toString() != kFailed) {
        ParameterFileError e =
            Check::textError(Kind::WrongType, prefix + QStringLiteral("status"), status);
        e.found = status.isUndefined() ? QStringLiteral("missing") : Check::jsonText(status);
        e.detail = QStringLiteral("\"read\" or \"failed\"");
        return Check::refuse(error, e);
    }
    if (!readLink(d, prefix, drive.identity, error) ||
        !Check::checkObject(d, prefix, driveFields(read, drive.identity.declared), error))
        return false;
    drive.identity.id = id;
    drive.failure = d.value(QStringLiteral("failure")).toString();
    if (!readTime(d.value(QStringLiteral("read_at")), prefix + QStringLiteral("read_at"),
                  drive.readAt, error) ||
        !readIdentity(d, prefix, drive, error))
        return false;
    const QJsonValue params = d.value(QStringLiteral("params"));
    if (!read) { // never values of a failed read
        if (!params.isUndefined() && !params.toObject().isEmpty()) {
            ParameterFileError e;
            e.kind = Kind::UnknownKey;
            e.key = prefix + QStringLiteral("params");
            e.detail = QStringLiteral("a failed drive has no values");
            return Check::refuse(error, e);
        }
        if (drive.failure.isEmpty())
            drive.failure = QStringLiteral("failed");
        return true;
    }
    return readParams(params.toObject(), prefix + QStringLiteral("params."), drive, error);
}

QJsonObject driveJson(const DriveSnapshot &d)
{
    const bool read = d.complete() && d.failure.isEmpty();
    QJsonObject o;
    o.insert(QStringLiteral("status"), read ? kRead : kFailed);
    if (!read)
        o.insert(QStringLiteral("failure"), d.failure.isEmpty() ? kFailed : d.failure);
    o.insert(QStringLiteral("read_at"), timeText(d.readAt));
    if (!d.identified)
        return o;
    const DriveIdentity &who = d.identity;
    const bool can = who.link == protocol::Link::Can;
    if (can) {
        // The user's word, not a read: no names or versions, which only read_model tells.
        o.insert(QStringLiteral("link"), protocol::linkName(who.link));
        o.insert(QStringLiteral("identity"), kDeclared);
    } else {
        o.insert(QStringLiteral("driver_name"), who.driverName);
        o.insert(QStringLiteral("motor_name"), who.motorName);
    }
    if (who.series)
        o.insert(QStringLiteral("series"), protocol::seriesName(*who.series));
    o.insert(QStringLiteral("generation"),
             can ? canGenerationWord(who.generation) : protocol::generationName(who.generation));
    if (who.gearRatio)
        o.insert(QStringLiteral("gear_ratio"), *who.gearRatio);
    if (!can) {
        o.insert(QStringLiteral("hardware_version_raw"), who.hardwareRaw);
        o.insert(QStringLiteral("firmware_version_raw"), who.firmwareRaw);
    }
    if (!who.uniqueId.isEmpty())
        o.insert(QStringLiteral("unique_id"), QString::fromLatin1(who.uniqueId.toHex(' ')));
    if (!read)
        return o;
    QJsonObject params;
    for (const FleetParam &p : FleetCatalog::params(who.generation, who.link)) {
        const ReadValue v = d.values.value(p.key);
        params.insert(p.key, QJsonObject{{QStringLiteral("value"), v.value},
                                         {QStringLiteral("read_at"), timeText(v.readAt)}});
    }
    o.insert(QStringLiteral("params"), params);
    return o;
}

} // namespace

const DriveSnapshot *BackupFile::drive(int id) const
{
    for (const DriveSnapshot &d : drives) {
        if (d.id() == id)
            return &d;
    }
    return nullptr;
}

QJsonObject BackupFile::toJson() const
{
    QJsonObject byId;
    for (const DriveSnapshot &d : drives)
        byId.insert(QString::number(d.id()), driveJson(d));
    // Version 2 added CAN drives (link, declared identity): a file without one stays version
    // 1, which older releases read.
    const bool anyCan = std::any_of(drives.begin(), drives.end(), [](const DriveSnapshot &d) {
        return d.identity.link == protocol::Link::Can;
    });
    QJsonObject o;
    o.insert(QStringLiteral("format"), QLatin1String(kFormatName));
    o.insert(QStringLiteral("version"), anyCan ? kFormatVersion : 1);
    o.insert(QStringLiteral("saved_at"), timeText(savedAt));
    o.insert(QStringLiteral("drives"), byId);
    return o;
}

QByteArray BackupFile::toJsonBytes() const
{
    return QJsonDocument(toJson()).toJson(QJsonDocument::Indented);
}

std::optional<BackupFile> BackupFile::fromJson(const QByteArray &bytes, ParameterFileError *error)
{
    QJsonObject root;
    if (!Check::parseObject(bytes, root, error) ||
        !Check::checkHeader(root, kFormatName, kFormatVersion, error) ||
        !Check::checkObject(root, QString(), rootFields(), error))
        return std::nullopt;
    BackupFile file;
    if (!readTime(root.value(QStringLiteral("saved_at")), QStringLiteral("saved_at"), file.savedAt,
                  error))
        return std::nullopt;
    const QJsonObject drives = root.value(QStringLiteral("drives")).toObject();
    for (auto it = drives.begin(); it != drives.end(); ++it) {
        DriveSnapshot d;
        if (!readDrive(it.key(), it.value(), d, error))
            return std::nullopt;
        file.drives << d;
    }
    std::sort(file.drives.begin(), file.drives.end(),
              [](const DriveSnapshot &a, const DriveSnapshot &b) { return a.id() < b.id(); });
    return file;
}

QString BackupFile::save(const QString &path) const
{
    return record::writeFileAtomically(path, toJsonBytes());
}

std::optional<BackupFile> BackupFile::load(const QString &path, ParameterFileError *error)
{
    ParameterFileError e;
    std::optional<BackupFile> file;
    if (const std::optional<QByteArray> bytes = Check::readFile(path, kMaxFileBytes, &e))
        file = fromJson(*bytes, &e);
    e.path = path;
    if (!file && error)
        *error = e;
    return file;
}

QString BackupFile::errorText(const ParameterFileError &e)
{
    auto tr = [](const char *text) {
        return QCoreApplication::translate("lk::fleet::BackupFile", text);
    };
    auto number = [](double v) { return QString::number(v, 'g', 19); };
    QString expected;
    switch (e.expected) {
    case ValueType::Integer:
    case ValueType::Number:
        expected = tr("a number in %1..%2").arg(number(e.min), number(e.max));
        break;
    case ValueType::Text:
        expected = e.detail.isEmpty() ? tr("text in quotes") : e.detail;
        break;
    case ValueType::Object:
        expected = tr("an object ({ ... })");
        break;
    }
    switch (e.kind) {
    case Kind::CannotRead:
        return tr("cannot read %1: %2").arg(e.path, e.detail);
    case Kind::TooLarge:
        return tr("%1 is too large to be a backup (more than %2 bytes)").arg(e.path, number(e.max));
    case Kind::NotJson:
        return tr("damaged or truncated: not valid JSON (%1 at byte %2)")
            .arg(e.detail)
            .arg(e.offset);
    case Kind::NotObject:
        return tr("not a JSON object");
    case Kind::WrongFormat:
        return tr("format is %1, not \"%2\": not a bus backup")
            .arg(e.found.isEmpty() ? tr("missing") : e.found, QLatin1String(kFormatName));
    case Kind::NewerVersion:
        return tr("version is %1: written by a newer release (this one reads up to %2)")
            .arg(e.found, number(e.max));
    case Kind::MissingKey:
        return tr("%1 is missing: it must be %2").arg(e.key, expected);
    case Kind::UnknownKey:
        return tr("%1 is not a key of a bus backup here").arg(e.key) +
               (e.detail.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(e.detail));
    case Kind::DuplicateKey:
        return tr("%1 is given twice: which one is meant is not known").arg(e.key);
    case Kind::WrongType:
        return tr("%1 is %2: it must be %3").arg(e.key, e.found, expected);
    case Kind::OutOfRange:
        return tr("%1 is %2, out of range: it must be %3").arg(e.key, e.found, expected);
    case Kind::UnknownSeries:
        return tr("%1 is %2: it must be MS, MF, MG or MH").arg(e.key, e.found);
    case Kind::UnknownGeneration:
        if (!e.detail.isEmpty())
            return tr("%1 is %2: it must be %3").arg(e.key, e.found, e.detail);
        return tr("%1 is %2: it must be \"v2.3\" or \"v2.35\"").arg(e.key, e.found);
    case Kind::BadTimestamp:
        return tr("%1 is %2: it must be a date and time such as \"2026-05-04T03:02:01.000Z\"")
            .arg(e.key, e.found);
    }
    return QString();
}

} // namespace lk::fleet
