#include "FleetBus.h"

#include "Console.h"
#include "LiveBus.h"

#include <fleet/FleetReader.h>
#include <fleet/ParamDiff.h>
#include <protocol/Checksum.h>

namespace lk::lkctl {

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
    const fleet::DriveIdentity &who = d.identity;
    const bool modelRead = d.identified && !who.declared;
    // A declared identity (CAN) says so, and names nothing only read_model could tell.
    QJsonObject o{
        {QStringLiteral("id"), d.id()},
        {QStringLiteral("status"), read ? QStringLiteral("read") : QStringLiteral("failed")},
        {QStringLiteral("failure"), read ? QJsonValue() : QJsonValue(d.failure)},
        {QStringLiteral("link"), protocol::linkName(who.link)},
        {QStringLiteral("identity"), !d.identified  ? QJsonValue()
                                     : who.declared ? QStringLiteral("declared")
                                                    : QStringLiteral("read")},
        {QStringLiteral("generation"),
         d.identified ? QJsonValue(generationText(who)) : QJsonValue()},
        {QStringLiteral("series"),
         who.series ? QJsonValue(protocol::seriesName(*who.series)) : QJsonValue()},
        {QStringLiteral("motor_name"), modelRead ? QJsonValue(who.motorName) : QJsonValue()}};
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

QString FleetBus::generationText(const fleet::DriveIdentity &who)
{
    if (who.link != protocol::Link::Can)
        return protocol::generationName(who.generation);
    return who.generation == protocol::Generation::V2_3 ? QStringLiteral("can")
                                                        : QStringLiteral("can236");
}

QString FleetBus::failureText(LiveBus &bus, const fleet::DriveSnapshot &d)
{
    QString text = QStringLiteral("drive %1 was not read: %2").arg(d.id()).arg(d.failure);
    if (bus.link() == protocol::Link::Can && !d.identified)
        text += QStringLiteral(". Declare it with --drives, e.g. --drives %1:MG@can (old CAN) "
                               "or %1:MF@can236 (CAN V2.36)")
                    .arg(d.id());
    return text;
}

bool FleetBus::isRestorable(const fleet::DriveSnapshot &drive, const QString &key)
{
    const auto p = fleet::FleetCatalog::find(drive.identity.generation, key, drive.identity.link);
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
