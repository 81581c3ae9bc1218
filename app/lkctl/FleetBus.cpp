#include "FleetBus.h"

#include "Console.h"
#include "LiveBus.h"

#include <fleet/FleetReader.h>
#include <fleet/ParamDiff.h>
#include <protocol/Checksum.h>

namespace lk::lkctl {

namespace {
std::optional<int> idOf(const QString &text)
{
    bool ok = false;
    const int id = text.trimmed().toInt(&ok);
    if (!ok || id < protocol::kMinId || id > protocol::kMaxId)
        return std::nullopt;
    return id;
}
} // namespace

std::optional<QVector<int>> FleetBus::parseIds(const QString &text, QString *error)
{
    QVector<int> ids;
    if (text == QLatin1String("all"))
        return ids;
    for (const QString &part : text.split(QLatin1Char(','))) {
        const QStringList range = part.split(QLatin1Char('-'));
        const std::optional<int> from = idOf(range.first());
        const std::optional<int> to = range.size() == 2 ? idOf(range.last()) : from;
        if (range.size() > 2 || !from || !to || *to < *from) {
            *error = QStringLiteral("'%1' is not a drive ID 1..32 or a range such as 1-4 (IDS is "
                                    "all, 3, 1,2,5 or 1-4)")
                         .arg(part);
            return std::nullopt;
        }
        for (int id = *from; id <= *to; ++id) {
            if (!ids.contains(id))
                ids << id;
        }
    }
    return ids;
}

std::optional<QMap<int, int>> FleetBus::parseMap(const QString &text, QString *error)
{
    QMap<int, int> map;
    QList<int> targets;
    for (const QString &part : text.split(QLatin1Char(','))) {
        const QStringList ab = part.split(QLatin1Char(':'));
        const std::optional<int> a = ab.size() == 2 ? idOf(ab.first()) : std::nullopt;
        const std::optional<int> b = ab.size() == 2 ? idOf(ab.last()) : std::nullopt;
        if (!a || !b) {
            *error = QStringLiteral("--map entry '%1' is not OLD:NEW with two drive IDs 1..32 "
                                    "(e.g. --map 3:5,4:6)")
                         .arg(part);
            return std::nullopt;
        }
        if (map.contains(*a) || targets.contains(*b)) {
            *error = QStringLiteral("--map entry '%1' maps a drive already mapped").arg(part);
            return std::nullopt;
        }
        map.insert(*a, *b);
        targets << *b;
    }
    return map;
}

QVector<int> FleetBus::scanIds(LiveBus &bus)
{
    bus::ScanOptions options;
    options.readState = false;
    QVector<int> ids;
    for (const bus::FoundMotor &m : bus.scan(options).motors)
        ids << m.id;
    return ids;
}

QVector<fleet::DriveSnapshot> FleetBus::read(LiveBus &bus, const QVector<int> &ids)
{
    fleet::FleetReader reader(&bus.session());
    bool done = false;
    QObject::connect(&reader, &fleet::FleetReader::finished, [&done] { done = true; });
    reader.start(ids);
    bus.waitUntil([&done] { return done; });
    return reader.snapshots();
}

QJsonObject FleetBus::driveJson(const fleet::DriveSnapshot &d)
{
    const bool read = d.complete() && d.failure.isEmpty();
    QJsonObject o{
        {QStringLiteral("id"), d.id()},
        {QStringLiteral("status"), read ? QStringLiteral("read") : QStringLiteral("failed")},
        {QStringLiteral("failure"), read ? QJsonValue() : QJsonValue(d.failure)},
        {QStringLiteral("generation"),
         d.identified ? QJsonValue(protocol::generationName(d.identity.generation)) : QJsonValue()},
        {QStringLiteral("series"),
         d.identity.series ? QJsonValue(protocol::seriesName(*d.identity.series)) : QJsonValue()},
        {QStringLiteral("motor_name"),
         d.identified ? QJsonValue(d.identity.motorName) : QJsonValue()}};
    return o;
}

QJsonArray FleetBus::diffJson(const fleet::DriveSnapshot &reference,
                              const fleet::DriveSnapshot &against, int *differing)
{
    QJsonArray rows;
    for (const fleet::DiffRow &r : fleet::ParamDiff::rows(reference, against)) {
        const bool restorable = isRestorable(against, r.key);
        if (restorable && r.state() != fleet::DiffRow::State::Same)
            ++*differing;
        auto json = [](const std::optional<qint64> &v) {
            return v ? QJsonValue(*v) : QJsonValue();
        };
        rows.append(QJsonObject{
            {QStringLiteral("key"), r.key},
            {QStringLiteral("reference"), json(r.a)},
            {QStringLiteral("value"), json(r.b)},
            {QStringLiteral("state"), QLatin1String(fleet::ParamDiff::stateName(r.state()))}});
    }
    return rows;
}

bool FleetBus::isRestorable(const fleet::DriveSnapshot &drive, const QString &key)
{
    const auto p = fleet::FleetCatalog::find(drive.identity.generation, key);
    return !p || p->restorable;
}

QString FleetBus::valueText(const std::optional<qint64> &v)
{
    return v ? QString::number(*v) : QStringLiteral("unknown");
}

std::optional<fleet::BackupFile> FleetBus::loadBackup(Console &console, const QString &command,
                                                      const QString &path)
{
    record::ParameterFileError error;
    std::optional<fleet::BackupFile> file = fleet::BackupFile::load(path, &error);
    if (!file)
        console.errLine(QStringLiteral("lkctl %1: %2: %3; nothing was sent")
                            .arg(command, path, fleet::BackupFile::errorText(error)));
    return file;
}

} // namespace lk::lkctl
