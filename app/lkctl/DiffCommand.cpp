#include "DiffCommand.h"

#include "Console.h"
#include "FleetBus.h"
#include "LiveBus.h"

#include <fleet/IdMap.h>

#include <fleet/ParamDiff.h>

#include <QtCore/QJsonDocument>

namespace lk::lkctl {

QString DiffCommand::summary() const
{
    return QStringLiteral("compare drives' parameters with a backup or with another drive");
}

QString DiffCommand::example() const
{
    return QStringLiteral("lkctl diff 3 5 6 --port /dev/ttyUSB0");
}

QString DiffCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl diff FILE [--map OLD:NEW,...] (--port DEV [--baud N] | --sim SPEC) "
               "[--json]\n"
               "       lkctl diff ID ID... (--port DEV [--baud N] | --sim SPEC) [--json]\n"
               "\n"
               "Read every parameter of drives now and compare: with a backup file (each\n"
               "drive of the file against the drive of the same ID, or of the ID --map gives),\n"
               "or with the first ID given (the reference). A value that was not read is\n"
               "unknown, never equal. The encoder offset (each motor's own zero) is shown but\n"
               "does not count as a difference. Nothing is written. A file that is not a\n"
               "valid backup is refused with the key and the problem named (exit 2).\n"
               "\n"
               "Options:\n"
               "  --map OLD:NEW,...  compare the file's drive OLD with drive NEW (e.g. 3:5)\n"
               "  --json             one line: {\"command\":\"diff\",\"drives\":[{\"id\":5,"
               "\"reference\":3,\"differing\":1,\"rows\":[...]}]}\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl diff 3 5 6 --port /dev/ttyUSB0\n"
               "  lkctl diff machine.json --port /dev/ttyUSB0 --json\n"
               "  lkctl diff machine.json --map 3:5 --port /dev/ttyUSB0\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(),
             exitStatusText(QStringLiteral("  5  some value differs (or is unknown)\n")));
}

int DiffCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    parser.addOption(QStringLiteral("map"), true);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const QStringList &pos = parser.positionals();
    if (pos.isEmpty())
        return usageError(console, QStringLiteral("expected FILE, or two or more IDs"));
    QString error;
    const bool drives = pos.size() >= 2 && parseId(pos.first(), &error);
    QVector<int> ids;
    std::optional<fleet::BackupFile> file;
    QMap<int, int> map;
    if (drives) {
        if (parser.isSet(QStringLiteral("map")))
            return usageError(console, QStringLiteral("--map goes with a backup FILE"));
        for (const QString &p : pos) {
            const std::optional<int> id = parseId(p, &error);
            if (!id)
                return usageError(console, error);
            ids << *id;
        }
    } else {
        if (pos.size() > 1)
            return usageError(console, QStringLiteral("unexpected argument '%1'").arg(pos.at(1)));
        if (parser.isSet(QStringLiteral("map"))) {
            const auto m = fleet::IdMap::parseMap(parser.value(QStringLiteral("map")), &error);
            if (!m)
                return usageError(console, QStringLiteral("--map: ") + error);
            map = *m;
        }
        file = FleetBus::loadBackup(console, name(), pos.first());
        if (!file)
            return kExitUsage;
        for (const fleet::DriveSnapshot &d : std::as_const(file->drives))
            ids << map.value(d.id(), d.id());
    }
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    const QVector<fleet::DriveSnapshot> read = FleetBus::read(bus, ids);
    QVector<QPair<fleet::DriveSnapshot, fleet::DriveSnapshot>> pairs;
    for (qsizetype i = drives ? 1 : 0; i < read.size(); ++i)
        pairs.append({drives ? read.first() : file->drives.at(i), read.at(i)});
    for (const fleet::DriveSnapshot &d : read) {
        if (!d.failure.isEmpty())
            bus.error(FleetBus::failureText(bus, d));
    }
    return report(console, parser.isSet(QStringLiteral("json")), pairs);
}

int DiffCommand::report(
    Console &console, bool json,
    const QVector<QPair<fleet::DriveSnapshot, fleet::DriveSnapshot>> &pairs) const
{
    bool anyDiffers = false;
    bool anyFailed = false;
    QJsonArray out;
    for (const auto &[reference, drive] : pairs) {
        int differing = 0;
        const QJsonArray rows = FleetBus::diffJson(reference, drive, &differing);
        anyDiffers |= differing > 0;
        anyFailed |= !drive.failure.isEmpty() || !reference.failure.isEmpty();
        out.append(QJsonObject{{QStringLiteral("id"), drive.id()},
                               {QStringLiteral("reference"), reference.id()},
                               {QStringLiteral("differing"), differing},
                               {QStringLiteral("rows"), rows}});
        if (json)
            continue;
        console.outLine(QStringLiteral("Drive %1 against %2: %3")
                            .arg(drive.id())
                            .arg(reference.id())
                            .arg(differing == 0 ? QStringLiteral("identical")
                                                : QStringLiteral("%1 differ").arg(differing)));
        for (const fleet::DiffRow &r : fleet::ParamDiff::rows(reference, drive)) {
            if (r.state() != fleet::DiffRow::State::Same)
                console.outLine(
                    QStringLiteral("  %1 %2 -> %3 (%4%5)")
                        .arg(r.key.leftJustified(16), FleetBus::valueText(r.a),
                             FleetBus::valueText(r.b),
                             QLatin1String(fleet::ParamDiff::stateName(r.state())),
                             FleetBus::isRestorable(drive, r.key)
                                 ? QString()
                                 : QStringLiteral(", the motor's own zero: never restored")));
        }
    }
    if (json) {
        const QJsonObject o{{QStringLiteral("command"), name()}, {QStringLiteral("drives"), out}};
        console.out(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n');
    }
    if (anyFailed)
        return kExitFailure;
    return anyDiffers ? kExitMismatch : kExitOk;
}

} // namespace lk::lkctl
