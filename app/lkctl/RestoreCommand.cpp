#include "RestoreCommand.h"

#include "Console.h"
#include "FleetBus.h"
#include "LiveBus.h"

#include <fleet/IdMap.h>

#include <QtCore/QJsonDocument>

namespace lk::lkctl {

using fleet::DriveReport;
using fleet::FleetRestore;

namespace {

QJsonArray texts(const QStringList &list)
{
    return QJsonArray::fromStringList(list);
}

/// The first CAN V2.36 drive among `identities` (by ID), or 0: its control parameters are RAM
/// only, so a ROM restore onto it has nothing to write.
int firstCan236(const QVector<fleet::DriveIdentity> &identities)
{
    for (const fleet::DriveIdentity &who : identities) {
        if (!fleet::FleetCatalog::hasRom(who.generation, who.link))
            return who.id;
    }
    return 0;
}

QJsonObject reportJson(const fleet::RestorePlan &plan, const DriveReport *report)
{
    QJsonArray changes;
    for (const fleet::ParamChange &c : plan.changes)
        changes.append(QJsonObject{{QStringLiteral("key"), c.key},
                                   {QStringLiteral("from"), c.from},
                                   {QStringLiteral("to"), c.to}});
    const QString outcome = report ? QLatin1String(DriveReport::outcomeName(report->outcome))
                            : plan.refusal ? QStringLiteral("refused")
                                           : QStringLiteral("not_sent");
    QString reason = plan.refusal ? plan.refusal->reason : QString();
    if (report && !report->reason.isEmpty())
        reason = report->reason;
    return QJsonObject{
        {QStringLiteral("source"), plan.source.id()},
        {QStringLiteral("target"), plan.targetId()},
        {QStringLiteral("outcome"), outcome},
        {QStringLiteral("refused_key"),
         plan.refusal ? QJsonValue(plan.refusal->key) : QJsonValue()},
        {QStringLiteral("reason"), reason.isEmpty() ? QJsonValue() : QJsonValue(reason)},
        {QStringLiteral("changes"), changes},
        {QStringLiteral("mismatches"), texts(report ? report->mismatches : QStringList())},
        {QStringLiteral("not_verified"), texts(report ? report->notVerified : QStringList())},
        {QStringLiteral("notes"), texts(report ? report->notes : QStringList())},
    };
}

void printPlan(Console &console, const fleet::RestorePlan &plan)
{
    const QString head =
        QStringLiteral("Drive %1 from %2: ").arg(plan.targetId()).arg(plan.source.id());
    if (plan.refusal) {
        console.outLine(
            head + QStringLiteral("refused (%1): %2").arg(plan.refusal->key, plan.refusal->reason));
        return;
    }
    console.outLine(head + (plan.changes.isEmpty()
                                ? QStringLiteral("already holds every value")
                                : QStringLiteral("%1 value(s) change").arg(plan.changes.size())));
    for (const fleet::ParamChange &c : plan.changes)
        console.outLine(
            QStringLiteral("  %1 %2 -> %3").arg(c.key.leftJustified(16)).arg(c.from).arg(c.to));
}

} // namespace

QString RestoreCommand::name() const
{
    return m_kind == Kind::Restore ? QStringLiteral("restore") : QStringLiteral("clone");
}

QString RestoreCommand::summary() const
{
    return m_kind == Kind::Restore
               ? QStringLiteral("write a backup's parameters onto drives (RAM, or ROM with --yes), "
                                "read back")
               : QStringLiteral("copy one drive's parameters onto others (RAM, or ROM with "
                                "--yes), read back");
}

QString RestoreCommand::example() const
{
    return m_kind == Kind::Restore
               ? QStringLiteral("lkctl restore machine.json --map 3:5 --ram --port /dev/ttyUSB0")
               : QStringLiteral("lkctl clone 1 2 3 4 --ram --port /dev/ttyUSB0");
}

QString RestoreCommand::usage() const
{
    const QString synopsis =
        m_kind == Kind::Restore
            ? QStringLiteral("Usage: lkctl restore FILE [IDS] [--map OLD:NEW,...] (--ram | --rom "
                             "--yes)\n"
                             "                     [--undo FILE] (--port DEV [--baud N] | --sim "
                             "SPEC) [--json]\n"
                             "\n"
                             "Write the parameters of a backup (lkctl backup) onto the drives: "
                             "each entry\n"
                             "of FILE (or the IDS of it given: 3, 1,2,5, 1-4) onto the drive of "
                             "the same ID,\n"
                             "or of the ID --map gives (a replaced drive: --map 3:5).\n")
            : QStringLiteral("Usage: lkctl clone FROM TO... (--ram | --rom --yes) [--undo FILE]\n"
                             "                   (--port DEV [--baud N] | --sim SPEC) [--json]\n"
                             "\n"
                             "Read every parameter of drive FROM and write them onto the drives "
                             "TO\n"
                             "(commissioning identical axes from one tuned drive).\n");
    const QString text =
        synopsis +
        QStringLiteral(
            "\n"
            "Before anything is written every target is read: its values are saved in the\n"
            "undo file (a backup: 'lkctl restore UNDO' puts them back), and the values that\n"
            "will change are printed. Nothing at all is sent when any target is refused:\n"
            "its read failed, its generation or series differs from the source's, or a\n"
            "value is outside its range (exit 4, the key named; a drive the file lists as\n"
            "failed is refused as a source). Then RAM is written (only\n"
            "the values that change) and read back; a difference is exit 5. With --rom,\n"
            "and only where RAM read back equal, each ROM frame is sent once, never\n"
            "repeated (not even when its reply is lost), and read back: V2.35 drives read\n"
            "the values again; V2.3 cannot read ROM (RAM is compared, the ROM copy is not\n"
            "verified) and has no ROM command for acceleration. The encoder offset is the\n"
            "motor's own zero: compared, never written.\n"
            "On CAN, which has no model read, the targets' series and generation are the\n"
            "ones --drives declares, and they must match the source's (else refused, the key\n"
            "named). The old CAN generation restores as V2.3. CAN V2.36 keeps its control\n"
            "parameters in RAM only (0xC1): --ram writes them there, lost at power-off, and\n"
            "--rom is refused with nothing sent.\n"
            "Per drive: verified, written (acknowledged, not all verifiable), unchanged,\n"
            "differs, refused or failed.\n"
            "\n"
            "Options:\n") +
        (m_kind == Kind::Restore
             ? QStringLiteral("  --map OLD:NEW,...  the backup's drive OLD goes onto drive NEW\n")
             : QString()) +
        QStringLiteral(
            "  --ram         write RAM: takes effect now, lost at power-off\n"
            "  --rom         RAM first, then ROM (the drive's flash, kept across power-off;\n"
            "                it wears out after a limited number of writes): needs --yes\n"
            "  --yes         confirm the ROM write\n"
            "  --undo FILE   where the targets' values are saved before writing (default\n"
            "                lkctl-undo-DATE-TIME.json in the working directory)\n"
            "  --json        one line: {\"command\":...,\"rom\":false,\"undo\":...,\"sent\":"
            "true,\"drives\":[{\"source\":3,\"target\":5,\"outcome\":\"verified\",...}]}\n"
            "\n"
            "%1"
            "\n"
            "Examples:\n") +
        (m_kind == Kind::Restore
             ? QStringLiteral("  lkctl restore machine.json --ram --port /dev/ttyUSB0\n"
                              "  lkctl restore machine.json 3 --map 3:5 --rom --yes --port "
                              "/dev/ttyUSB0 --json\n")
             : QStringLiteral("  lkctl clone 1 2 3 4 --ram --port /dev/ttyUSB0\n"
                              "  lkctl clone 1 2-10 --rom --yes --port /dev/ttyUSB0 --json\n")) +
        QStringLiteral("\n") +
        exitStatusText(QStringLiteral(
            "     (also: a file that is not a valid backup, the key and the problem named)\n"
            "  4  refused for safety, nothing was sent: --rom without --yes, or a target\n"
            "     refused (read failed, other generation or series, value out of range)\n"
            "  5  a value read back differs from the value written\n"));
    return text.arg(BusOptions::helpText());
}

std::optional<QVector<FleetRestore::Job>> RestoreCommand::restoreJobs(const ArgParser &parser,
                                                                      Console &console) const
{
    const QStringList &pos = parser.positionals();
    QString error;
    std::optional<QVector<int>> only = QVector<int>();
    if (pos.size() > 2 ||
        (pos.size() == 2 && !(only = fleet::IdMap::parseIds(pos.at(1), &error)))) {
        usageError(console, error.isEmpty()
                                ? QStringLiteral("unexpected argument '%1'").arg(pos.at(2))
                                : error);
        return std::nullopt;
    }
    QMap<int, int> map;
    if (parser.isSet(QStringLiteral("map"))) {
        const auto m = fleet::IdMap::parseMap(parser.value(QStringLiteral("map")), &error);
        if (!m) {
            usageError(console, QStringLiteral("--map: ") + error);
            return std::nullopt;
        }
        map = *m;
    }
    const std::optional<fleet::BackupFile> file = FleetBus::loadBackup(console, name(), pos.at(0));
    if (!file)
        return std::nullopt;
    QVector<FleetRestore::Job> jobs;
    for (const fleet::DriveSnapshot &d : file->drives) {
        if (only->isEmpty() || only->contains(d.id()))
            jobs << FleetRestore::Job{d, map.value(d.id(), d.id())};
    }
    for (int id : *only) {
        if (!file->drive(id)) {
            usageError(console, QStringLiteral("%1 holds no drive %2").arg(pos.at(0)).arg(id));
            return std::nullopt;
        }
    }
    for (auto it = map.begin(); it != map.end(); ++it) {
        if (!file->drive(it.key())) {
            usageError(console, QStringLiteral("--map %1:%2: %3 holds no drive %1")
                                    .arg(it.key())
                                    .arg(it.value())
                                    .arg(pos.at(0)));
            return std::nullopt;
        }
    }
    return jobs;
}

int RestoreCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    for (const char *flag : {"ram", "rom", "yes"})
        parser.addOption(QLatin1String(flag), false);
    parser.addOption(QStringLiteral("undo"), true);
    if (m_kind == Kind::Restore)
        parser.addOption(QStringLiteral("map"), true);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const bool rom = parser.isSet(QStringLiteral("rom"));
    if (rom == parser.isSet(QStringLiteral("ram")))
        return usageError(console, QStringLiteral("give exactly one of --ram and --rom"));
    const QStringList &pos = parser.positionals();
    if (pos.size() < (m_kind == Kind::Restore ? 1 : 2))
        return usageError(console, m_kind == Kind::Restore
                                       ? QStringLiteral("expected FILE")
                                       : QStringLiteral("expected FROM and TO"));
    QVector<FleetRestore::Job> jobs;
    std::optional<int> from;
    QVector<int> targets;
    QString error;
    if (m_kind == Kind::Restore) {
        const auto restoreList = restoreJobs(parser, console);
        if (!restoreList)
            return kExitUsage;
        jobs = *restoreList;
    } else {
        from = parseId(pos.first(), &error, QStringLiteral("FROM"));
        for (const QString &p : pos.mid(1)) {
            const auto ids = fleet::IdMap::parseIds(p, &error);
            if (!from || !ids || ids->isEmpty() || ids->contains(*from))
                return usageError(console, error.isEmpty()
                                               ? QStringLiteral("TO must be drives other than "
                                                                "FROM (got '%1')")
                                                     .arg(p)
                                               : error);
            targets << *ids;
        }
    }
    if (rom) {
        // Known before the bus opens: the file's drives, or FROM as --drives declares it.
        QVector<fleet::DriveIdentity> sources;
        for (const FleetRestore::Job &job : std::as_const(jobs))
            sources << job.source.identity;
        for (const bus::DriveIdentity &d : busOptions->drives) {
            if (!from || d.id != *from || !busOptions->isCan())
                continue;
            fleet::DriveIdentity who;
            who.id = d.id;
            who.generation = d.generation;
            who.link = protocol::Link::Can;
            sources << who;
        }
        if (const int id = firstCan236(sources))
            return refuseRamOnly(console, id);
    }
    if (rom && !parser.isSet(QStringLiteral("yes"))) {
        console.errLine(
            QStringLiteral(
                "lkctl %1: refused for safety, nothing was sent: --rom writes the drives' flash, "
                "which wears out; try the values with --ram, then confirm ROM with --rom --yes")
                .arg(name()));
        return kExitRefused;
    }
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    if (from) {
        const fleet::DriveSnapshot source = FleetBus::read(bus, {*from}).value(0);
        if (!source.failure.isEmpty())
            bus.error(FleetBus::failureText(bus, source));
        if (rom && firstCan236({source.identity}))
            return refuseRamOnly(console, *from);
        for (int t : std::as_const(targets))
            jobs << FleetRestore::Job{source, t};
    }
    const QString undo =
        parser.isSet(QStringLiteral("undo"))
            ? parser.value(QStringLiteral("undo"))
            : QStringLiteral("lkctl-undo-%1.json")
                  .arg(QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    return restore(bus, jobs, rom, undo, parser.isSet(QStringLiteral("json")));
}

int RestoreCommand::refuseRamOnly(Console &console, int id) const
{
    console.errLine(QStringLiteral("lkctl %1: refused, nothing was sent: drive %2 is CAN V2.36, "
                                   "whose control parameters (0xC1) are RAM only: there is no "
                                   "ROM write. Restore with --ram (lost at power-off).")
                        .arg(name())
                        .arg(id));
    return kExitRefused;
}

int RestoreCommand::restore(LiveBus &bus, const QVector<FleetRestore::Job> &jobs, bool rom,
                            const QString &undoPath, bool json) const
{
    Console &console = bus.console();
    FleetRestore restore(&bus.session());
    bool prepared = false;
    QObject::connect(&restore, &FleetRestore::prepared, [&prepared] { prepared = true; });
    restore.prepare(jobs);
    bus.waitUntil([&prepared] { return prepared; });
    fleet::BackupFile undo;
    undo.savedAt = QDateTime::currentDateTimeUtc();
    undo.drives = restore.undo();
    if (const QString why = undo.save(undoPath); !why.isEmpty()) {
        bus.error(why + QStringLiteral("; without the undo file nothing was sent"));
        return kExitFailure;
    }
    const bool refused =
        std::any_of(restore.plans().begin(), restore.plans().end(),
                    [](const fleet::RestorePlan &p) { return p.refusal.has_value(); });
    if (!json) {
        console.outLine(QStringLiteral("Undo file: %1").arg(undoPath));
        for (const fleet::RestorePlan &p : restore.plans())
            printPlan(console, p);
    }
    if (!refused) {
        bool finished = false;
        QObject::connect(&restore, &FleetRestore::finished, [&finished] { finished = true; });
        restore.execute(rom);
        bus.waitUntil([&finished] { return finished; });
    }
    QJsonArray drives;
    int status = kExitOk;
    for (qsizetype i = 0; i < restore.plans().size(); ++i) {
        const DriveReport *r = i < restore.reports().size() ? &restore.reports().at(i) : nullptr;
        drives.append(reportJson(restore.plans().at(i), r));
        if (!r)
            continue;
        if (r->outcome == DriveReport::Outcome::Differs)
            status = kExitMismatch;
        else if (r->outcome == DriveReport::Outcome::Failed && status == kExitOk)
            status = kExitFailure;
        QStringList notes = r->mismatches + r->notVerified + r->notes;
        if (!r->reason.isEmpty())
            notes.prepend(r->reason);
        if (!json)
            console.outLine(QStringLiteral("Drive %1: %2%3")
                                .arg(r->targetId)
                                .arg(QLatin1String(DriveReport::outcomeName(r->outcome)),
                                     notes.isEmpty() ? QString()
                                                     : QStringLiteral(": ") +
                                                           notes.join(QStringLiteral("; "))));
    }
    if (refused) {
        bus.refused(QStringLiteral("a target was refused (see above); no drive was written"));
        status = kExitRefused;
    }
    if (json) {
        const QJsonObject o{{QStringLiteral("command"), name()},
                            {QStringLiteral("rom"), rom},
                            {QStringLiteral("undo"), undoPath},
                            {QStringLiteral("sent"), !refused},
                            {QStringLiteral("drives"), drives}};
        console.out(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n');
    }
    return status;
}

} // namespace lk::lkctl
