#include "WriteCommand.h"

#include "Console.h"
#include "ControlParamWrite.h"
#include "DriveParams.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ParamWrite.h"
#include "ReplyText.h"
#include "RequestText.h"

#include <protocol/FieldJson.h>

namespace lk::lkctl {

using protocol::Command;
using protocol::FieldJson;

namespace {

const QStringList kPidFields{"angle_kp", "angle_ki", "speed_kp", "speed_ki", "iq_kp", "iq_ki"};

/// --drives says drive `id` is a CAN V2.36 drive (its gains are control parameters, RAM only).
bool declaresCan236(const BusOptions &options, int id)
{
    if (!options.isCan())
        return false;
    for (const bus::DriveIdentity &d : options.drives) {
        if (d.id == id)
            return d.generation == protocol::Generation::V2_35;
    }
    return false;
}

} // namespace

QString WriteCommand::summary() const
{
    return QStringLiteral("write PID gains (RAM or ROM), acceleration or a V2.35 parameter, then "
                          "read them back");
}

QString WriteCommand::example() const
{
    return QStringLiteral("lkctl write 3 pid 100 100 50 40 50 50 --ram --port /dev/ttyUSB0");
}

QString WriteCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl write ID pid ANGLE_KP ANGLE_KI SPEED_KP SPEED_KI IQ_KP IQ_KI\n"
               "                   (--ram | --rom --yes) (--port DEV [--baud N] | --sim SPEC) "
               "[--json]\n"
               "       lkctl write ID accel DPS2 --ram (--port DEV [--baud N] | --sim SPEC) "
               "[--json]\n"
               "       lkctl write ID param NAME VALUE... (--ram | --rom --yes)\n"
               "                   (--port DEV [--baud N] | --sim SPEC) [--json]\n"
               "\n"
               "Write drive ID's PID gains (each 0..255) or acceleration (0..2147483647 dps/s),\n"
               "then read them back (read_pid, read_accel) and print what the drive now holds.\n"
               "The model is read first: pid and accel exist on V2.3 drives only (a V2.35\n"
               "drive is refused, exit 1: write its param instead).\n"
               "\n"
               "param (firmware 2.35 and later, protocol V2.35) writes one parameter with\n"
               "write_param_ram / write_param_rom, then reads it back with read_param:\n"
               "%3"
               "max_torque is in iq command units (max power on MS); current_ramp's unit is\n"
               "undocumented; max_angle_deg is sent as the pair 0x9B then 0x9C.\n"
               "A drive that answers a write with flag 1 (failure) makes the command fail\n"
               "(exit 1), naming the parameter; the rest of a pair is then not sent. A V2.3\n"
               "drive has no parameter table: refused after read_model (exit 1).\n"
               "\n"
               "On CAN the old generation writes pid and accel as V2.3. A CAN V2.36 drive\n"
               "(--drives ID:SERIES@can236) keeps its gains and limits as control parameters,\n"
               "in RAM only: pid (gains 0..65535) and param go out as write_control_param\n"
               "(0xC1) and are read back with 0xC0; pid reads each loop's Kd first and writes\n"
               "it back as read. Its param names: %4.\n"
               "--rom to it is refused (exit 1, nothing sent), as is param --rom on any CAN\n"
               "drive.\n"
               "\n"
               "  --ram   write_pid_ram / write_accel_ram / write_param_ram: takes effect now,\n"
               "          lost at power-off\n"
               "  --rom   write_pid_rom / write_param_rom: kept across power-off. ROM is the\n"
               "          drive's flash, which wears out after a limited number of writes: try\n"
               "          values with --ram, and write them to ROM once, with --yes to\n"
               "          confirm. It is sent once, never repeated. The V2.3 protocol has no\n"
               "          ROM write for acceleration.\n"
               "  --yes   confirm a ROM write\n"
               "  --json  one line: {\"command\":\"write_pid_ram\",\"id\":3,\"written\":{...},"
               "\"holds\":{...},\"match\":true}\n"
               "          (param: \"param\":NAME after \"id\")\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl write 3 pid 100 100 50 40 50 50 --ram --port /dev/ttyUSB0\n"
               "  lkctl write 3 pid 100 100 50 40 50 50 --rom --yes --port /dev/ttyUSB0\n"
               "  lkctl write 3 accel 5000 --ram --port ttyUSB0 --json\n"
               "  lkctl write 1 param speed_pid 50 20 0 --ram --port /dev/ttyUSB0\n"
               "  lkctl write 1 param max_angle_deg 720 --rom --yes --port /dev/ttyUSB0 --json\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(),
             exitStatusText(QStringLiteral(
                 "  4  refused: a ROM write without --yes (nothing was sent)\n"
                 "  5  the read-back differs from what was written: the drive holds other\n"
                 "     values (some firmware ignores write_accel_ram); both are printed\n"
                 "  (1 also: a V2.35 drive answered a parameter write with flag 1 = failure,\n"
                 "     or the drive's generation lacks the command)\n")),
             DriveParams::helpLines(QStringLiteral("  ")), ControlParamWrite::names());
}

std::optional<WriteCommand::Plan> WriteCommand::parse(const ArgParser &parser, Console &console,
                                                      int *status) const
{
    const auto fail = [&](const QString &message) {
        *status = usageError(console, message);
        return std::nullopt;
    };
    const QStringList &pos = parser.positionals();
    if (pos.size() < 2)
        return fail(QStringLiteral("expected ID and pid|accel|param with their values"));
    QString error;
    if (!parseId(pos.at(0), &error))
        return fail(error);
    Plan plan;
    const std::optional<bool> rom = romChosen(parser, &error);
    if (!rom)
        return fail(error);
    plan.rom = *rom;
    FieldValues values;
    values.insert(QStringLiteral("id"), pos.at(0));
    if (pos.at(1) == QLatin1String("pid")) {
        if (pos.size() != 2 + kPidFields.size())
            return fail(QStringLiteral("pid takes six gains: ANGLE_KP ANGLE_KI SPEED_KP SPEED_KI "
                                       "IQ_KP IQ_KI (got %1)")
                            .arg(pos.size() - 2));
        for (qsizetype i = 0; i < kPidFields.size(); ++i)
            values.insert(kPidFields.at(i), pos.at(2 + i));
        plan.command = plan.rom ? QStringLiteral("write_pid_rom") : QStringLiteral("write_pid_ram");
        plan.readBack = Command::ReadPid;
        plan.what = QStringLiteral("PID gains");
    } else if (pos.at(1) == QLatin1String("accel")) {
        if (plan.rom)
            return fail(QStringLiteral("acceleration has no ROM write in the protocol; use --ram"));
        if (pos.size() != 3)
            return fail(QStringLiteral("accel takes one value, DPS2"));
        values.insert(QStringLiteral("accel_dps2"), pos.at(2));
        plan.command = QStringLiteral("write_accel_ram");
        plan.readBack = Command::ReadAccel;
        plan.what = QStringLiteral("acceleration");
    } else {
        return fail(QStringLiteral("cannot write '%1'; write pid, accel or param").arg(pos.at(1)));
    }
    const FieldBuildResult built = RequestText::build(plan.command, values);
    if (!built.ok())
        return fail(built.message);
    plan.request = *built.request;
    plan.json = parser.isSet(QStringLiteral("json"));
    return plan;
}

int WriteCommand::readBack(LiveBus &bus, const Plan &plan, bool acknowledged)
{
    const int id = plan.request.id;
    const bus::RequestResult r = bus.request(plan.readBack, id);
    if (!r.ok() || !r.reply) {
        bus.error(acknowledged ? QStringLiteral("the write was acknowledged but the read-back "
                                                "failed:")
                               : QStringLiteral("the read-back failed too, so whether the write "
                                                "took effect is unknown:"));
        bus.reportFailure(r);
        return kExitFailure;
    }
    const QJsonObject written = FieldJson::requestFields(plan.request);
    const QJsonObject holds = FieldJson::replyFields(*r.reply);
    const bool same = written == holds;
    Console &console = bus.console();
    if (plan.json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), plan.command)
            .integer(QStringLiteral("id"), id)
            .fields(QStringLiteral("written"), written)
            .fields(QStringLiteral("holds"), holds)
            .boolean(QStringLiteral("match"), same);
        console.out(o.toJson() + '\n');
    } else {
        console.outLine(QStringLiteral("Drive %1 now holds (%2, read back with %3):")
                            .arg(id)
                            .arg(plan.rom ? QStringLiteral("in RAM; 0x32 wrote ROM too")
                                          : QStringLiteral("RAM"),
                                 protocol::CommandTable::name(plan.readBack)));
        for (const QString &line : ReplyText::lines(holds, QStringLiteral("  ")))
            console.outLine(line);
    }
    if (same)
        return kExitOk;
    const QString hint = plan.readBack == Command::ReadAccel
                             ? QStringLiteral(" Some firmware acknowledges write_accel_ram and "
                                              "ignores it (see docs/ERRATA.md).")
                             : QString();
    bus.error(QStringLiteral("read-back mismatch on drive %1: wrote %2 (%3) but the drive holds "
                             "%4.%5")
                  .arg(id)
                  .arg(plan.what, ReplyText::oneLine(written), ReplyText::oneLine(holds), hint));
    return kExitMismatch;
}

int WriteCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    parser.addOption(QStringLiteral("ram"), false);
    parser.addOption(QStringLiteral("rom"), false);
    parser.addOption(QStringLiteral("yes"), false);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const QStringList &pos = parser.positionals();
    if (pos.size() >= 2 && pos.at(1) == QLatin1String("param"))
        return runParam(parser, *busOptions, console);
    if (pos.size() >= 2 && pos.at(1) == QLatin1String("pid") &&
        declaresCan236(*busOptions, pos.at(0).toInt()))
        return runCan236Pid(parser, *busOptions, console);
    const std::optional<Plan> plan = parse(parser, console, &status);
    if (!plan)
        return status;
    if (plan->rom && !parser.isSet(QStringLiteral("yes")))
        return refuseRom(console, plan->what);
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    // The model first: a V2.35 drive has neither command, and is never sent one it lacks.
    const int id = plan->request.id;
    const QString lacks = protocol::CommandTable::name(plan->request.command);
    const std::optional<LiveBus::Identity> who = bus.identify(id);
    if (!who)
        return kExitFailure;
    const bool can236 =
        bus.link() == protocol::Link::Can && who->model.generation == protocol::Generation::V2_35;
    if (can236 && plan->readBack == Command::ReadPid) {
        // Its reply told V2.36 (no --drives): the gains are control parameters, RAM only.
        if (plan->rom) {
            bus.error(ControlParamWrite::romRefusal(id));
            return kExitFailure;
        }
        QString error;
        const auto control =
            ControlParamWrite::pidPlan(id, parser.positionals().mid(2), plan->json, &error);
        if (!control) {
            bus.error(error);
            return kExitFailure;
        }
        return ControlParamWrite::run(bus, *control);
    }
    if (who->model.generation != protocol::Generation::V2_3) {
        bus.error(
            (can236 ? QStringLiteral("drive %1 speaks CAN V2.36, which has no %2; nothing was "
                                     "sent. Its acceleration is the input speed ramp, a control "
                                     "parameter (RAM only): 'lkctl write %1 param "
                                     "speed_ramp_dps2 DPS2 --ram'")
                    : QStringLiteral("drive %1 runs firmware 2.35 or later (protocol V2.35), "
                                     "which has no %2; nothing was sent. Its gains and ramps are "
                                     "parameters: 'lkctl write %1 param angle_pid KP KI KD' "
                                     "(speed_pid, iq_pid), 'lkctl write %1 param "
                                     "speed_ramp_dps2 DPS2'"))
                .arg(id)
                .arg(lacks));
        return kExitFailure;
    }
    const bus::RequestResult w = bus.request(plan->request);
    if (w.ok())
        return readBack(bus, *plan, true);
    bus.reportFailure(w);
    // A lost or corrupt reply does not mean the drive did not act (and ROM writes are never
    // repeated): what it holds now is the answer the user needs.
    if (w.status != bus::RequestStatus::Timeout && w.status != bus::RequestStatus::Error)
        return kExitFailure;
    bus.error(QStringLiteral("reading back what drive %1 holds now (if it matches, the write "
                             "took effect and only its reply was lost):")
                  .arg(plan->request.id));
    return readBack(bus, *plan, false);
}

bool WriteCommand::speaks(LiveBus &bus, int id, protocol::Generation generation,
                          const QString &otherwise)
{
    const std::optional<LiveBus::Identity> who = bus.identify(id);
    if (!who)
        return false;
    if (who->model.generation == generation)
        return true;
    bus.error(otherwise);
    return false;
}

std::optional<bool> WriteCommand::romChosen(const ArgParser &parser, QString *error)
{
    const bool ram = parser.isSet(QStringLiteral("ram"));
    const bool rom = parser.isSet(QStringLiteral("rom"));
    if (ram != rom)
        return rom;
    *error = ram ? QStringLiteral("give --ram or --rom, not both")
                 : QStringLiteral("say where to write: --ram (until power-off) or --rom --yes "
                                  "(kept)");
    return std::nullopt;
}

int WriteCommand::refuseRom(Console &console, const QString &what) const
{
    console.errLine(
        QStringLiteral("lkctl write: refusing to write %1 to ROM without --yes. ROM is the "
                       "drive's flash memory, which wears out after a limited number of writes; "
                       "nothing was sent. Try the values with --ram first (they last until "
                       "power-off), then write them to ROM once with --rom --yes.")
            .arg(what));
    return kExitRefused;
}

int WriteCommand::runParam(const ArgParser &parser, const BusOptions &busOptions,
                           Console &console) const
{
    const QStringList &pos = parser.positionals();
    QString error;
    if (!parseId(pos.at(0), &error))
        return usageError(console, error);
    const std::optional<bool> rom = romChosen(parser, &error);
    if (!rom)
        return usageError(console, error);
    if (busOptions.isCan())
        return runCanParam(parser, busOptions, console, *rom);
    const std::optional<ParamWrite::Plan> plan =
        ParamWrite::plan(pos, *rom, parser.isSet(QStringLiteral("json")), &error);
    if (!plan)
        return usageError(console, error);
    if (*rom && !parser.isSet(QStringLiteral("yes")))
        return refuseRom(console, plan->param.name);
    LiveBus bus(console, name());
    if (!bus.open(busOptions))
        return kExitFailure;
    // The model first: only a V2.35 drive has the parameter table.
    if (!speaks(bus, plan->id, protocol::Generation::V2_35,
                DriveParams::noTableMessage(plan->id, QStringLiteral("write ") + plan->param.name)))
        return kExitFailure;
    return ParamWrite::run(bus, *plan);
}

int WriteCommand::runCan236Pid(const ArgParser &parser, const BusOptions &busOptions,
                               Console &console) const
{
    const QStringList &pos = parser.positionals();
    QString error;
    const std::optional<int> id = parseId(pos.at(0), &error);
    if (!id)
        return usageError(console, error);
    const std::optional<bool> rom = romChosen(parser, &error);
    if (!rom)
        return usageError(console, error);
    if (*rom) { // before --yes: there is no ROM to confirm
        console.errLine(
            QStringLiteral("lkctl %1: %2").arg(name(), ControlParamWrite::romRefusal(*id)));
        return kExitFailure;
    }
    if (pos.size() != 2 + kPidFields.size())
        return usageError(console, QStringLiteral("pid takes six gains: ANGLE_KP ANGLE_KI SPEED_KP "
                                                  "SPEED_KI IQ_KP IQ_KI (got %1)")
                                       .arg(pos.size() - 2));
    const auto plan =
        ControlParamWrite::pidPlan(*id, pos.mid(2), parser.isSet(QStringLiteral("json")), &error);
    if (!plan)
        return usageError(console, error);
    LiveBus bus(console, name());
    if (!bus.open(busOptions) || !bus.identify(*id)) // the drive answers, by the declared identity
        return kExitFailure;
    return ControlParamWrite::run(bus, *plan);
}

int WriteCommand::runCanParam(const ArgParser &parser, const BusOptions &busOptions,
                              Console &console, bool rom) const
{
    const QStringList &pos = parser.positionals();
    const int id = pos.at(0).toInt(); // checked by the caller
    if (rom) {
        // No CAN drive keeps a parameter in ROM: the old generation has no parameter table,
        // V2.36 keeps its control parameters in RAM only. Refused before --yes, nothing sent.
        console.errLine(QStringLiteral("lkctl %1: %2")
                            .arg(name(), declaresCan236(busOptions, id)
                                             ? ControlParamWrite::romRefusal(id)
                                             : QStringLiteral("no CAN drive writes a parameter "
                                                              "to ROM: CAN V2.36's control "
                                                              "parameters (0xC1) are RAM only "
                                                              "and the old CAN generation has "
                                                              "no parameter table; nothing was "
                                                              "sent. Use --ram.")));
        return kExitFailure;
    }
    QString error;
    const auto plan =
        ControlParamWrite::paramPlan(pos, parser.isSet(QStringLiteral("json")), &error);
    if (!plan)
        return usageError(console, error);
    LiveBus bus(console, name());
    if (!bus.open(busOptions))
        return kExitFailure;
    const std::optional<LiveBus::Identity> who = bus.identify(id);
    if (!who)
        return kExitFailure;
    if (who->model.generation != protocol::Generation::V2_35) {
        bus.error(QStringLiteral("drive %1 speaks the old CAN generation, which has no parameter "
                                 "table (0xC1 is CAN V2.36's); nothing was sent. Its gains and "
                                 "acceleration: 'lkctl write %1 pid ...', 'lkctl write %1 accel "
                                 "DPS2'")
                      .arg(id));
        return kExitFailure;
    }
    return ControlParamWrite::run(bus, *plan);
}

} // namespace lk::lkctl
