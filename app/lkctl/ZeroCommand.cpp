#include "ZeroCommand.h"

#include "Console.h"
#include "LiveBus.h"
#include "OrderedJson.h"
#include "ReplyText.h"

#include <cmath>

namespace lk::lkctl {

using protocol::Command;

QString ZeroCommand::name() const
{
    return m_kind == Kind::Zero ? QStringLiteral("zero") : QStringLiteral("clear-turns");
}

QString ZeroCommand::summary() const
{
    return m_kind == Kind::Zero
               ? QStringLiteral("make the present position zero: in RAM (clear_angle) or ROM "
                                "(write_zero_rom)")
               : QStringLiteral("clear a V2.35 drive's turn count (clear_turn_count)");
}

QString ZeroCommand::example() const
{
    return m_kind == Kind::Zero ? QStringLiteral("lkctl zero 3 --ram --yes --port /dev/ttyUSB0")
                                : QStringLiteral("lkctl clear-turns 1 --yes --port /dev/ttyUSB0");
}

QString ZeroCommand::usage() const
{
    if (m_kind == Kind::ClearTurns)
        return QStringLiteral(
                   "Usage: lkctl clear-turns ID --yes (--port DEV [--baud N] | --sim SPEC) "
                   "[--json]\n"
                   "\n"
                   "Set drive ID's turn count to 0 with clear_turn_count (0x93, firmware 2.35 and\n"
                   "later): the multi-turn angle keeps only the angle within the present turn,\n"
                   "so multi-turn position commands go elsewhere afterwards. The V2.35 document\n"
                   "does not say whether this survives a power cycle (RAM or ROM) or whether the\n"
                   "motor must be off: stop the motor first. The angle is read (read_multi_turn)\n"
                   "before and after; 0x93 is sent once. A V2.3 drive has no 0x93: refused after\n"
                   "read_model.\n"
                   "\n"
                   "Options:\n"
                   "  --yes    confirm (without it nothing is sent, exit 4)\n"
                   "  --json   one line: {\"command\":\"clear_turn_count\",\"id\":1,\"memory\":"
                   "\"undocumented\",\n"
                   "           \"before_deg\":1234.5,\"after_deg\":154.5,\"result\":\"cleared\"}\n"
                   "\n"
                   "%1"
                   "\n"
                   "Examples:\n"
                   "  lkctl clear-turns 1 --yes --port /dev/ttyUSB0\n"
                   "  lkctl clear-turns 1 --yes --sim 1:MS4015@2.35 --json\n"
                   "\n"
                   "%2")
            .arg(BusOptions::helpText(),
                 exitStatusText(QStringLiteral(
                     "     (also 1: the drive's generation has no clear_turn_count)\n"
                     "  4  refused: without --yes (nothing was sent)\n"
                     "  5  acknowledged, but the angle read after is still more than a turn\n")));
    return QStringLiteral(
               "Usage: lkctl zero ID (--ram | --rom) --yes (--port DEV [--baud N] | --sim SPEC) "
               "[--json]\n"
               "\n"
               "Make the present position of drive ID its zero; absolute position commands go\n"
               "elsewhere afterwards.\n"
               "  --ram   clear_angle (0x95): multi-turn and single-turn angle become 0 here,\n"
               "          until power-off. The angle is read (read_multi_turn) before and\n"
               "          after: some firmware acknowledges 0x95 and does nothing (exit 5).\n"
               "  --rom   write_zero_rom (0x19): the present encoder position becomes the zero\n"
               "          in the drive's flash, from the next power-on (nothing changes now).\n"
               "          Flash wears with every write: once, not as a routine. Sent exactly\n"
               "          once, never repeated, also when its reply is lost; V2.35 drives\n"
               "          answer with the new zero (encoder_zero).\n"
               "\n"
               "Options:\n"
               "  --ram, --rom   where the zero goes (one is required)\n"
               "  --yes          confirm (without it nothing is sent, exit 4)\n"
               "  --json         one line: {\"command\":\"clear_angle\",\"id\":3,\"memory\":"
               "\"ram\",\n"
               "                 \"before_deg\":123.45,\"after_deg\":0.0,\"result\":\"cleared\"}"
               ";\n"
               "                 --rom: {\"command\":\"write_zero_rom\",\"id\":3,\"memory\":"
               "\"rom\",\n"
               "                 \"acknowledged\":true,\"encoder_zero\":1244}\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl zero 3 --ram --yes --port /dev/ttyUSB0\n"
               "  lkctl zero 3 --rom --yes --port /dev/ttyUSB0 --json\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(),
             exitStatusText(
                 QStringLiteral("  4  refused: without --yes (nothing was sent)\n"
                                "  5  --ram: acknowledged, but the angle read after is not 0\n")));
}

std::optional<ZeroCommand::Plan> ZeroCommand::parse(const ArgParser &parser, Console &console,
                                                    int *status) const
{
    const auto fail = [&](const QString &message) {
        *status = usageError(console, message);
        return std::nullopt;
    };
    Plan plan;
    const std::optional<int> id = singleId(parser, console, status);
    if (!id)
        return std::nullopt;
    plan.id = *id;
    plan.json = parser.isSet(QStringLiteral("json"));
    if (m_kind == Kind::Zero) {
        const bool ram = parser.isSet(QStringLiteral("ram"));
        plan.rom = parser.isSet(QStringLiteral("rom"));
        if (ram == plan.rom)
            return fail(ram ? QStringLiteral("give --ram or --rom, not both")
                            : QStringLiteral("say where the zero goes: --ram (clear_angle, "
                                             "until power-off) or --rom (write_zero_rom, from "
                                             "the next power-on)"));
    }
    return plan;
}

int ZeroCommand::refuseWithoutYes(Console &console, const Plan &plan) const
{
    QString what;
    if (m_kind == Kind::ClearTurns)
        what = QStringLiteral("clearing the turn count of drive %1 (clear_turn_count, RAM or "
                              "ROM not documented)");
    else if (plan.rom)
        what = QStringLiteral("writing the present position of drive %1 to ROM as its zero "
                              "(write_zero_rom: the drive's flash, from the next power-on)");
    else
        what = QStringLiteral("making the present position of drive %1 angle 0 (clear_angle: "
                              "RAM, until power-off)");
    console.errLine(QStringLiteral("lkctl %1: refused without --yes: %2 moves the zero that "
                                   "every absolute position command goes by; nothing was sent. "
                                   "Add --yes to confirm.")
                        .arg(name(), what.arg(plan.id)));
    return kExitRefused;
}

std::optional<double> ZeroCommand::multiTurnDeg(LiveBus &bus, int id)
{
    const bus::RequestResult r = bus.request(Command::ReadMultiTurn, id);
    const auto *angle =
        r.ok() && r.reply ? std::get_if<protocol::MultiTurnAngle>(&r.reply->payload) : nullptr;
    if (!angle) {
        bus.reportFailure(r);
        return std::nullopt;
    }
    return angle->degrees();
}

void ZeroCommand::printAngles(LiveBus &bus, const Plan &plan, Command sent, double before,
                              double after, const QString &verdict) const
{
    const QString memory =
        sent == Command::ClearAngle ? QStringLiteral("ram") : QStringLiteral("undocumented");
    if (plan.json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), protocol::CommandTable::name(sent))
            .integer(QStringLiteral("id"), plan.id)
            .text(QStringLiteral("memory"), memory)
            .real(QStringLiteral("before_deg"), before)
            .real(QStringLiteral("after_deg"), after)
            .text(QStringLiteral("result"), verdict);
        bus.console().out(o.toJson() + '\n');
        return;
    }
    bus.console().outLine(
        QStringLiteral("Drive %1, %2 (%3):")
            .arg(plan.id)
            .arg(protocol::CommandTable::name(sent),
                 sent == Command::ClearAngle
                     ? QStringLiteral("RAM, until power-off")
                     : QStringLiteral("RAM or ROM: the V2.35 document does not say")));
    bus.console().outLine(
        QStringLiteral("  multi-turn angle before  %1 deg").arg(ReplyText::number(before, 2)));
    bus.console().outLine(
        QStringLiteral("  multi-turn angle after   %1 deg").arg(ReplyText::number(after, 2)));
    // The verdict as a person reads it; the reason of a failed check follows on stderr.
    const QString text =
        verdict == QLatin1String("cleared")
            ? (sent == Command::ClearAngle
                   ? QStringLiteral("verified: the angle reads 0 now, until power-off")
                   : QStringLiteral("verified: less than one output turn is left"))
        : verdict == QLatin1String("already_zero")
            ? QStringLiteral("not verifiable: the angle read 0 before already")
            : QStringLiteral("NOT verified: see the message below");
    bus.console().outLine(QStringLiteral("  %1").arg(text));
}

std::optional<ZeroCommand::Angles> ZeroCommand::sendBetweenAngles(LiveBus &bus, int id,
                                                                  Command command)
{
    const QString name = protocol::CommandTable::name(command);
    const std::optional<double> before = multiTurnDeg(bus, id);
    if (!before) {
        bus.error(QStringLiteral("the angle could not be read, so %1 was not sent").arg(name));
        return std::nullopt;
    }
    // Sent once: 0x93 may write flash (undocumented), and a lost reply is answered by the
    // angle read after, not by sending again.
    const bus::RequestResult r = bus.request(command, id, bus::Priority::Operator, 0);
    if (!r.ok()) {
        bus.reportFailure(r);
        if (r.attempts == 0)
            return std::nullopt; // refused before the wire: the refusal said nothing was sent
        bus.error(QStringLiteral("whether drive %1 applied %2 is not known (it was not sent "
                                 "again): 'lkctl read %1 multi-turn' shows its angle")
                      .arg(id)
                      .arg(name));
        return std::nullopt;
    }
    const std::optional<double> after = multiTurnDeg(bus, id);
    if (!after) {
        bus.error(QStringLiteral("drive %1 acknowledged %2, but its angle could not be read "
                                 "back: whether it took is not known")
                      .arg(id)
                      .arg(name));
        return std::nullopt;
    }
    return Angles{*before, *after};
}

int ZeroCommand::clearAngle(LiveBus &bus, const Plan &plan) const
{
    const std::optional<Angles> angles = sendBetweenAngles(bus, plan.id, Command::ClearAngle);
    if (!angles)
        return kExitFailure;
    const double before = angles->before;
    const double after = angles->after;
    const bool zeroAfter = std::fabs(after) <= kZeroToleranceDeg;
    if (zeroAfter) {
        const bool already = std::fabs(before) <= kZeroToleranceDeg;
        printAngles(bus, plan, Command::ClearAngle, before, after,
                    already ? QStringLiteral("already_zero") : QStringLiteral("cleared"));
        if (already)
            bus.error(QStringLiteral("the angle read %1 deg before already: whether the drive "
                                     "applied clear_angle cannot be told")
                          .arg(ReplyText::number(before, 2)));
        return kExitOk;
    }
    const bool unchanged = std::fabs(after - before) <= kZeroToleranceDeg;
    printAngles(bus, plan, Command::ClearAngle, before, after,
                unchanged ? QStringLiteral("unchanged") : QStringLiteral("changed_not_zero"));
    if (unchanged)
        bus.error(QStringLiteral("drive %1 acknowledged clear_angle (0x95) but its angle did not "
                                 "change (%2 deg): this firmware ignores clear_angle; 'lkctl "
                                 "zero %1 --rom --yes' (0x19) sets a zero from the next "
                                 "power-on instead")
                      .arg(plan.id)
                      .arg(ReplyText::number(after, 2)));
    else
        bus.error(QStringLiteral("the angle of drive %1 changed from %2 deg to %3 deg but is "
                                 "not 0: was the motor turning? Stop it and clear again")
                      .arg(plan.id)
                      .arg(ReplyText::number(before, 2), ReplyText::number(after, 2)));
    return kExitMismatch;
}

int ZeroCommand::writeZeroRom(LiveBus &bus, const Plan &plan) const
{
    // Exactly once: a lost reply does not mean the flash was not written.
    const bus::RequestResult r =
        bus.request(Command::WriteZeroRom, plan.id, bus::Priority::Operator, 0);
    const auto *zero =
        r.ok() && r.reply ? std::get_if<protocol::ZeroWritten>(&r.reply->payload) : nullptr;
    if (!zero) {
        bus.reportFailure(r);
        if (r.attempts == 0)
            return kExitFailure; // refused before the wire: nothing was written
        bus.error(QStringLiteral("whether drive %1 wrote the zero to its flash is not known; "
                                 "write_zero_rom was NOT sent again (a ROM write is never "
                                 "repeated). After a power cycle, 'lkctl read %1 multi-turn' "
                                 "shows where the zero is")
                      .arg(plan.id));
        return kExitFailure;
    }
    if (plan.json) {
        OrderedJson o;
        o.text(QStringLiteral("command"), protocol::CommandTable::name(Command::WriteZeroRom))
            .integer(QStringLiteral("id"), plan.id)
            .text(QStringLiteral("memory"), QStringLiteral("rom"))
            .boolean(QStringLiteral("acknowledged"), true);
        if (zero->encoderOffset)
            o.integer(QStringLiteral("encoder_zero"), *zero->encoderOffset);
        else
            o.null(QStringLiteral("encoder_zero"));
        bus.console().out(o.toJson() + '\n');
        return kExitOk;
    }
    bus.console().outLine(
        QStringLiteral("Drive %1, write_zero_rom (ROM, from the next power-on):").arg(plan.id));
    bus.console().outLine(
        zero->encoderOffset
            ? QStringLiteral("  acknowledged; the drive reports the new zero as encoder %1")
                  .arg(*zero->encoderOffset)
            : QStringLiteral("  acknowledged (this firmware does not report the new zero)"));
    bus.console().outLine(QStringLiteral("  nothing changes until the drive is powered off and "
                                         "on; the angle is not verified before then"));
    return kExitOk;
}

int ZeroCommand::clearTurns(LiveBus &bus, const Plan &plan, double gearRatio) const
{
    const std::optional<Angles> angles = sendBetweenAngles(bus, plan.id, Command::ClearTurnCount);
    if (!angles)
        return kExitFailure;
    const double before = angles->before;
    const double after = angles->after;
    // Within one output turn (360 deg x the gear ratio of rotor angle) means no whole turns.
    const bool cleared = std::fabs(after) < 360.0 * gearRatio;
    printAngles(bus, plan, Command::ClearTurnCount, before, after,
                cleared ? QStringLiteral("cleared") : QStringLiteral("not_cleared"));
    if (cleared)
        return kExitOk;
    bus.error(QStringLiteral("drive %1 acknowledged clear_turn_count (0x93), but its multi-turn "
                             "angle reads %2 deg (was %3 deg): more than one turn, so the turn "
                             "count was not cleared")
                  .arg(plan.id)
                  .arg(ReplyText::number(after, 2), ReplyText::number(before, 2)));
    return kExitMismatch;
}

int ZeroCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    if (m_kind == Kind::Zero) {
        parser.addOption(QStringLiteral("ram"), false);
        parser.addOption(QStringLiteral("rom"), false);
    }
    parser.addOption(QStringLiteral("yes"), false);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    const std::optional<Plan> plan = parse(parser, console, &status);
    if (!plan)
        return status;
    if (!parser.isSet(QStringLiteral("yes")))
        return refuseWithoutYes(console, *plan);
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    // The model first: the generation decides what the drive has.
    const std::optional<LiveBus::Identity> who = bus.identify(plan->id);
    if (!who)
        return kExitFailure;
    const Command command = m_kind == Kind::ClearTurns ? Command::ClearTurnCount
                            : plan->rom                ? Command::WriteZeroRom
                                                       : Command::ClearAngle;
    if (!protocol::CommandTable::availableOn(command, who->model.generation)) {
        bus.error(QStringLiteral("drive %1 speaks protocol V2.3 (firmware before 2.35), which "
                                 "has no %2 (0x93); nothing was sent. 'lkctl zero %1 --ram "
                                 "--yes' (clear_angle) clears its multi-turn angle")
                      .arg(plan->id)
                      .arg(protocol::CommandTable::name(command)));
        return kExitFailure;
    }
    if (command == Command::ClearTurnCount)
        return clearTurns(bus, *plan, who->gear());
    return command == Command::WriteZeroRom ? writeZeroRom(bus, *plan) : clearAngle(bus, *plan);
}

} // namespace lk::lkctl
