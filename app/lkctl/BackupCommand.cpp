#include "BackupCommand.h"

#include "Console.h"
#include "FleetBus.h"
#include "LiveBus.h"

#include <fleet/IdMap.h>

#include <QtCore/QJsonDocument>

namespace lk::lkctl {

QString BackupCommand::summary() const
{
    return QStringLiteral("read every parameter of several drives into one backup file");
}

QString BackupCommand::example() const
{
    return QStringLiteral("lkctl backup all --out machine.json --port /dev/ttyUSB0");
}

QString BackupCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl backup [IDS|all] --out FILE (--port DEV [--baud N] | --sim SPEC) "
               "[--json]\n"
               "\n"
               "Read every parameter of the drives IDS (all: every drive that answers a scan;\n"
               "3, 1,2,5 or 1-4) and write them into FILE (format lkstudio-bus-backup, see\n"
               "CLI.md). Per drive: ID, series, model, driver name, firmware and hardware,\n"
               "generation, the unique ID where the drive has one, and each parameter with\n"
               "the value read and when. V2.3: the six gains, acceleration and encoder\n"
               "offset; V2.35: the three loops' Kp/Ki/Kd, the drive limits and encoder offset.\n"
               "On CAN, which has no model read, each drive must be declared with --drives\n"
               "(ID:SERIES@can or @can236): the file says the identity was declared, not read,\n"
               "and has no model, names or versions. The old CAN generation is saved as V2.3;\n"
               "CAN V2.36 holds its control parameters (0xC0: the three loops' Kp/Ki/Kd, the\n"
               "input limits and ramps) and encoder offset.\n"
               "A drive whose read failed is listed as failed, with no values, and the exit\n"
               "status is 1. Nothing is written to any drive.\n"
               "\n"
               "Options:\n"
               "  --out FILE  the backup file (written atomically)\n"
               "  --json      one line: {\"command\":\"backup\",\"file\":...,\"drives\":[{\"id\":3,"
               "\"status\":\"read\",...}]}\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl backup all --out machine.json --port /dev/ttyUSB0\n"
               "  lkctl backup 1-4 --out axes.json --sim 1:MF,2:MF,3:MF,4:MF --json\n"
               "  lkctl backup 1,2 --out can.json --can socketcan:can0 --drives "
               "1:MG@can,2:MF@can236\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(), exitStatusText());
}

int BackupCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    parser.addOption(QStringLiteral("out"), true);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const QStringList &pos = parser.positionals();
    if (pos.size() > 1)
        return usageError(console, QStringLiteral("unexpected argument '%1'").arg(pos.at(1)));
    QString error;
    const std::optional<QVector<int>> asked =
        fleet::IdMap::parseIds(pos.value(0, QStringLiteral("all")), &error);
    if (!asked)
        return usageError(console, error);
    const QString out = parser.value(QStringLiteral("out"));
    if (out.isEmpty())
        return usageError(console, QStringLiteral("--out FILE is required"));

    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    const QVector<int> ids = asked->isEmpty() ? FleetBus::scanIds(bus) : *asked;
    fleet::BackupFile file;
    file.savedAt = QDateTime::currentDateTimeUtc();
    file.drives = FleetBus::read(bus, ids);
    if (const QString why = file.save(out); !why.isEmpty()) {
        bus.error(why);
        return kExitFailure;
    }
    bool allRead = true;
    QJsonArray drives;
    for (const fleet::DriveSnapshot &d : std::as_const(file.drives)) {
        allRead &= d.complete() && d.failure.isEmpty();
        drives.append(FleetBus::driveJson(d));
        if (!d.failure.isEmpty())
            bus.error(FleetBus::failureText(bus, d));
    }
    if (parser.isSet(QStringLiteral("json"))) {
        const QJsonObject o{{QStringLiteral("command"), name()},
                            {QStringLiteral("file"), out},
                            {QStringLiteral("drives"), drives}};
        console.out(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n');
    } else {
        console.outLine(QStringLiteral("%1 drive(s) backed up into %2%3")
                            .arg(file.drives.size())
                            .arg(out, allRead ? QString() : QStringLiteral(" (some failed)")));
    }
    return allRead ? kExitOk : kExitFailure;
}

} // namespace lk::lkctl
