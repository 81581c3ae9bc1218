#include "EncodeCommand.h"

#include "Console.h"
#include "RequestText.h"

#include "protocol/Command.h"
#include "protocol/FieldJson.h"
#include "protocol/ProtocolFields.h"

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
        if (info.canOnly) // encode writes RS485 frames: 0xC0/0xC1 exist only on CAN V2.36
            continue;
        QString head =
            QStringLiteral("  %1 (%2)")
                .arg(QLatin1String(info.name), CommandTable::codeText(quint8(info.command)));
        if (info.writesFlash)
            head += QStringLiteral(" ROM");
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
               "Usage: lkctl encode NAME --id N [--FIELD VALUE ...]\n"
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
               "Options:\n"
               "  --id N       drive ID, 1..32 (required)\n"
               "  -h, --help   show this help\n"
               "\n"
               "Commands and their fields:\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl encode motor_off --id 1\n"
               "      3E 80 01 00 BF\n"
               "  lkctl encode speed --id 1 --speed-dps 100\n"
               "      3E A2 01 04 E5 10 27 00 00 37\n"
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
    const FieldBuildResult built = RequestText::build(parsed.command, parsed.values);
    if (!built.ok()) {
        // A refused value's message already names the field and its range; a wrong name
        // is best answered by the list in the help.
        const QString hint =
            built.fieldError ? QString() : QStringLiteral(" (see lkctl encode --help)");
        console.errLine(QStringLiteral("lkctl encode: %1%2").arg(built.message, hint));
        return kExitUsage;
    }
    console.outLine(FieldJson::hexText(built.request->encode()));
    return kExitOk;
}

} // namespace lk::lkctl
