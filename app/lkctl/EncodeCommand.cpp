#include "EncodeCommand.h"

#include "Console.h"
#include "RequestText.h"

#include "protocol/CanLayout.h"
#include "protocol/CanRecord.h"
#include "protocol/Command.h"
#include "protocol/FieldJson.h"
#include "protocol/ProtocolFields.h"
#include "protocol/RequestBuilder.h"

#include <cmath>
#include <optional>

namespace lk::lkctl {

using protocol::CommandTable;
using protocol::FieldJson;

namespace {

QString optionName(const QString &field)
{
    return QStringLiteral("--") + QString(field).replace(QLatin1Char('_'), QLatin1Char('-'));
}

QString fieldName(const QString &option)
{
    return QString(option).replace(QLatin1Char('-'), QLatin1Char('_'));
}

/// The command line after NAME: the command name and its fields, or why it was refused.
struct EncodeArgs {
    QString command;
    FieldValues values;
    QString problem;
};

EncodeArgs parseArgs(const QStringList &args)
{
    EncodeArgs r;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (!a.startsWith(QLatin1String("--"))) {
            if (!r.command.isEmpty()) {
                r.problem = QStringLiteral("unexpected argument '%1'").arg(a);
                return r;
            }
            r.command = a;
            continue;
        }
        QString option = a.mid(2);
        QString value;
        const auto eq = option.indexOf(QLatin1Char('='));
        if (eq >= 0) {
            value = option.mid(eq + 1);
            option.truncate(eq);
        } else if (i + 1 < args.size() && !args.at(i + 1).startsWith(QLatin1String("--"))) {
            value = args.at(++i); // may start with '-': "--angle-deg -90"
        } else {
            r.problem = QStringLiteral("%1 needs a value").arg(a);
            return r;
        }
        const QString field = fieldName(option);
        if (field.isEmpty() || r.values.contains(field)) {
            r.problem = field.isEmpty() ? QStringLiteral("empty option '%1'").arg(a)
                                        : QStringLiteral("%1 given twice").arg(optionName(field));
            return r;
        }
        r.values.insert(field, value);
    }
    if (r.command.isEmpty() && r.problem.isEmpty())
        r.problem = QStringLiteral("missing the command NAME (e.g. motor_off, speed)");
    return r;
}

/// Where the frame is for: `--link rs485|can|can236` and `--series`, taken out of the field
/// values. The series matters for the torque command's scale, which on V2.35/V2.36 differs
/// between MF and MG.
struct EncodeTarget {
    protocol::DecodeContext context;
    bool seriesGiven = false;
    std::optional<double> torqueLimitA; ///< V2.36's speed frame carries one (never 0)
    QString problem;
    bool onCan236() const
    {
        return context.link == protocol::Link::Can &&
               context.generation == protocol::Generation::V2_35;
    }
};

EncodeTarget takeTarget(FieldValues &values)
{
    EncodeTarget t;
    const QString link = values.take(QStringLiteral("link")).toLower();
    if (link == QLatin1String("can")) {
        t.context.link = protocol::Link::Can; // the old generation: V2.3's scales
    } else if (link == QLatin1String("can236")) {
        t.context.link = protocol::Link::Can;
        t.context.generation = protocol::Generation::V2_35; // V2.36 shares V2.35's
    } else if (!link.isEmpty() && link != QLatin1String("rs485")) {
        t.problem = QStringLiteral("--link must be rs485, can or can236, got '%1'").arg(link);
        return t;
    }
    if (values.contains(QStringLiteral("series"))) {
        const QString word = values.take(QStringLiteral("series"));
        const std::optional<protocol::Series> series = protocol::seriesFromName(word);
        if (!series) {
            t.problem = QStringLiteral("--series must be MS, MF, MG or MH, got '%1'").arg(word);
            return t;
        }
        t.context.series = *series;
        t.seriesGiven = true;
    }
    if (values.contains(QStringLiteral("torque_limit_a"))) {
        const QString text = values.take(QStringLiteral("torque_limit_a"));
        bool ok = false;
        const double a = text.toDouble(&ok);
        if (!ok || !std::isfinite(a)) {
            t.problem = QStringLiteral("--torque-limit-a must be a number, got '%1'").arg(text);
            return t;
        }
        t.torqueLimitA = a;
    }
    return t;
}

/// Why `command` cannot be encoded for `t`, or empty.
QString unavailable(const QString &commandName, const EncodeTarget &t)
{
    const std::optional<protocol::Command> command = CommandTable::fromName(commandName);
    if (!command)
        return {}; // RequestText names the unknown command
    const bool speedOn236 = *command == protocol::Command::Speed && t.onCan236();
    // Never printed without the limit it was given: only V2.36's speed frame carries one.
    if (t.torqueLimitA && !speedOn236)
        return QStringLiteral("--torque-limit-a belongs to speed on --link can236 only");
    if (t.context.link == protocol::Link::Rs485) {
        return CommandTable::info(*command).canOnly
                   ? QStringLiteral("%1 exists on CAN V2.36 only (--link can236)").arg(commandName)
                   : QString();
    }
    if (!CommandTable::availableOn(*command, t.context))
        return QStringLiteral("%1 does not exist on %2")
            .arg(commandName, protocol::dialectName(t.context));
    // On V2.36 the torque's scale is the series' own: without it the amps would be guessed.
    if (*command == protocol::Command::Torque && t.onCan236() && !t.seriesGiven)
        return QStringLiteral("torque on CAN V2.36 needs --series (its scale differs between "
                              "MF and MG)");
    if (speedOn236 && (!t.torqueLimitA || !t.seriesGiven))
        return QStringLiteral("speed on CAN V2.36 carries a torque limit, never 0: give "
                              "--torque-limit-a A and --series (the limit's scale)");
    return {};
}

} // namespace

QString EncodeCommand::name() const
{
    return QStringLiteral("encode");
}

QString EncodeCommand::summary() const
{
    return QStringLiteral("print the request frame of a command as hex bytes");
}

QString EncodeCommand::example() const
{
    return QStringLiteral("lkctl encode speed --id 1 --speed-dps 100");
}

QString EncodeCommand::commandList()
{
    constexpr int kWidth = 34;
    QString text;
    for (const protocol::CommandInfo &info : CommandTable::all()) {
        QString head =
            QStringLiteral("  %1 (%2)")
                .arg(QLatin1String(info.name), CommandTable::codeText(quint8(info.command)));
        if (info.writesFlash)
            head += QStringLiteral(" ROM");
        if (info.canOnly)
            head += QStringLiteral(" can236");
        const QList<protocol::FieldSpec> specs = protocol::ProtocolFields::ofCommand(info.command);
        if (specs.isEmpty()) {
            text += head + QLatin1Char('\n');
            continue;
        }
        for (qsizetype i = 0; i < specs.size(); ++i) {
            const QString field =
                QStringLiteral("%1 <%2>").arg(optionName(specs.at(i).name), specs.at(i).range);
            if (i == 0 && head.size() < kWidth)
                text += head.leftJustified(kWidth) + field + QLatin1Char('\n');
            else if (i == 0)
                text += head + QLatin1Char('\n') + QString(kWidth, QLatin1Char(' ')) + field +
                        QLatin1Char('\n');
            else
                text += QString(kWidth, QLatin1Char(' ')) + field + QLatin1Char('\n');
        }
    }
    return text;
}

QString EncodeCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl encode NAME --id N [--link rs485|can|can236] [--series S]\n"
               "                    [--FIELD VALUE ...]\n"
               "\n"
               "Print the request frame of command NAME for drive ID N (1..32) as upper-case\n"
               "hex bytes separated by spaces, on one line. Nothing is sent to any drive.\n"
               "Fields are the CLI.md field names with '-' for '_' (--speed-dps 100,\n"
               "--direction ccw); --FIELD=VALUE works too, and a value may be negative\n"
               "(--angle-deg -90). Values are physical units (A, dps, deg, dps/s) rounded to\n"
               "the nearest wire unit; a value out of range is refused, never clamped.\n"
               "Every field a command takes is required; angle_deg of increment_position* is\n"
               "signed (the sign gives the direction). ROM marks commands that write the\n"
               "drive's flash.\n"
               "\n"
               "On CAN (--link can for the old generation, can236 for V2.36) the frame is\n"
               "printed in candump's notation, ID#DATA (141#A200000010270000), with that\n"
               "generation's layouts; a command the generation lacks is refused. Commands\n"
               "marked can236 exist on CAN V2.36 only.\n"
               "\n"
               "Options:\n"
               "  --id N            drive ID, 1..32 (required)\n"
               "  --link LINK       rs485 (default), can or can236\n"
               "  --series SERIES   MS, MF, MG or MH: the torque's scale (required for torque\n"
               "                    and speed on can236, where MF and MG differ)\n"
               "  --torque-limit-a A  speed on can236 only: the torque limit its frame\n"
               "                    carries (required; rounded down to iq units, never 0)\n"
               "  -h, --help        show this help\n"
               "\n"
               "Commands and their fields:\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl encode motor_off --id 1\n"
               "      3E 80 01 00 BF\n"
               "  lkctl encode speed --id 1 --speed-dps 100\n"
               "      3E A2 01 04 E5 10 27 00 00 37\n"
               "  lkctl encode speed --id 1 --speed-dps 100 --link can\n"
               "      141#A200000010270000\n"
               "  lkctl encode single_position --id 2 --direction ccw --angle-deg 90\n"
               "  lkctl encode increment_position_limited --id 3 --angle-deg -45 "
               "--max-speed-dps 360\n"
               "  lkctl encode write_pid_ram --id 1 --angle-kp 100 --angle-ki 100 "
               "--speed-kp 50 \\\n"
               "      --speed-ki 40 --iq-kp 50 --iq-ki 50\n"
               "\n"
               "Exit status:\n"
               "  0  the frame was printed\n"
               "  2  unknown command, missing or unknown field, value not a number or out of\n"
               "     range (the message names the field and its range)\n")
        .arg(commandList());
}

int EncodeCommand::run(const QStringList &args, Console &console)
{
    const EncodeArgs parsed = parseArgs(args);
    if (!parsed.problem.isEmpty()) {
        console.errLine(
            QStringLiteral("lkctl encode: %1 (see lkctl encode --help)").arg(parsed.problem));
        return kExitUsage;
    }
    FieldValues values = parsed.values;
    const EncodeTarget target = takeTarget(values);
    QString problem = target.problem;
    if (problem.isEmpty())
        problem = unavailable(parsed.command, target);
    if (!problem.isEmpty()) {
        console.errLine(QStringLiteral("lkctl encode: %1 (see lkctl encode --help)").arg(problem));
        return kExitUsage;
    }
    const FieldBuildResult built = RequestText::build(parsed.command, values, target.context);
    if (!built.ok()) {
        // A refused value's message already names the field and its range; a wrong name
        // is best answered by the list in the help.
        const QString hint =
            built.fieldError ? QString() : QStringLiteral(" (see lkctl encode --help)");
        console.errLine(QStringLiteral("lkctl encode: %1%2").arg(built.message, hint));
        return kExitUsage;
    }
    if (target.context.link == protocol::Link::Rs485) {
        console.outLine(FieldJson::hexText(built.request->encode()));
        return kExitOk;
    }
    protocol::Request request = *built.request;
    if (request.command == protocol::Command::Speed && target.onCan236()) {
        // The speed was checked above; the builder adds the limit at the series' scale.
        const protocol::BuildResult b =
            protocol::build::speed(request.id, values.value(QStringLiteral("speed_dps")).toDouble(),
                                   target.context, *target.torqueLimitA);
        if (!b.ok()) {
            console.errLine(QStringLiteral("lkctl encode: %1").arg(b.error.message()));
            return kExitUsage;
        }
        request = *b.request;
    }
    // CAN: the layouts of the generation chosen, in candump's notation.
    const protocol::can::CanEncodeResult can =
        protocol::can::encodeRequest(request, target.context);
    if (!can.ok()) {
        console.errLine(QStringLiteral("lkctl encode: %1").arg(can.error.message()));
        return kExitUsage;
    }
    console.outLine(protocol::CanRecord::of(*can.data).candumpText());
    return kExitOk;
}

} // namespace lk::lkctl
