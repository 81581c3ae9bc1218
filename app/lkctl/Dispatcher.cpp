#include "Dispatcher.h"

#include "Console.h"

#include <algorithm>

namespace lk::lkctl {

Dispatcher::Dispatcher(QString program, QString version)
    : m_program(std::move(program)), m_version(std::move(version))
{
}

void Dispatcher::add(std::unique_ptr<Subcommand> command)
{
    Q_ASSERT(command && !find(command->name()));
    m_commands.push_back(std::move(command));
}

const Subcommand *Dispatcher::find(const QString &name) const
{
    for (const auto &c : m_commands) {
        if (c->name() == name)
            return c.get();
    }
    return nullptr;
}

QString Dispatcher::usage() const
{
    qsizetype width = 0;
    for (const auto &c : m_commands)
        width = std::max(width, c->name().size());
    QString text = QStringLiteral("Usage: %1 COMMAND [OPTIONS]\n"
                                  "       %1 help [COMMAND] | %1 --help | %1 --version (-v)\n\n"
                                  "Command-line tool for LK-TECH MS/MF/MG/MH servo drives on RS485 "
                                  "(protocols V2.3 and V2.35).\n\nCommands:\n")
                       .arg(m_program);
    for (const auto &c : m_commands)
        text += QStringLiteral("  %1  %2\n").arg(c->name().leftJustified(width), c->summary());
    text += QStringLiteral("\nRun '%1 COMMAND --help' for the options and examples of a "
                           "command.\nEvery JSON shape, CSV column and exit status is in CLI.md "
                           "(/usr/share/doc/lkstudio/CLI.md,\nor docs/CLI.md in the source); "
                           "see also man %1.\n\nExamples:\n")
                .arg(m_program);
    for (const auto &c : m_commands)
        text += QStringLiteral("  %1\n").arg(c->example());
    text += QStringLiteral(
        "\nBus options of the live commands (scan ... monitor):\n"
        "  --port DEV [--baud N]   a serial adapter (default 115200 baud)\n"
        "  --sim ID:SERIES,...     the built-in simulated bus, e.g. --sim 3:MF,17:MS\n"
        "\nEnvironment (the command line wins):\n"
        "  LKCTL_PORT   the port when neither --port nor --sim is given\n"
        "  LKCTL_BAUD   the baud when --baud is not given (else 115200)\n"
        "\nExit status (each command's help says which apply to it):\n"
        "  0  success\n"
        "  1  the operation failed: the port could not be opened (the message says why and how\n"
        "     to fix it), a drive did not answer (the message names the ID and the command),\n"
        "     or the bus went away\n"
        "  2  unusable arguments or input text; nothing was sent\n"
        "  3  decode: the input held bytes that were not valid frames\n"
        "  4  refused for safety, nothing was sent: a control command over a series or soft\n"
        "     limit, a ROM write without --yes, a brake release without --yes (or with\n"
        "     the motor off, without --motor-off-ok), a zero or turn-count clear\n"
        "     without --yes, or a restore or clone with a refused target\n"
        "  5  write, restore, clone: the value read back differs from the value written;\n"
        "     diff: some value differs; brake: the drive\n"
        "     reports another brake state than the one asked for; clear-errors, zero,\n"
        "     clear-turns: the drive read back does not show the change\n");
    return text;
}

bool Dispatcher::asksForHelp(const QStringList &args)
{
    for (const QString &a : args) {
        if (a == QLatin1String("--"))
            return false; // what follows is data, not options
        if (a == QLatin1String("--help") || a == QLatin1String("-h"))
            return true;
    }
    return false;
}

int Dispatcher::help(const QStringList &args, Console &console) const
{
    if (args.isEmpty()) {
        console.out(usage().toUtf8());
        return kExitOk;
    }
    const Subcommand *c = find(args.first());
    if (!c) {
        console.errLine(QStringLiteral("%1: no command '%2'; run '%1 --help' for the list")
                            .arg(m_program, args.first()));
        return kExitUsage;
    }
    console.out(c->usage().toUtf8());
    return kExitOk;
}

int Dispatcher::run(const QStringList &args, Console &console)
{
    if (args.isEmpty()) {
        console.errLine(usage().trimmed());
        return kExitUsage;
    }
    const QString &first = args.first();
    if (first == QLatin1String("--help") || first == QLatin1String("-h"))
        return help({}, console);
    if (first == QLatin1String("help"))
        return help(args.mid(1), console);
    if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
        console.outLine(QStringLiteral("%1 %2").arg(m_program, m_version));
        return kExitOk;
    }
    Subcommand *c = nullptr;
    for (const auto &candidate : m_commands) {
        if (candidate->name() == first)
            c = candidate.get();
    }
    if (!c) {
        const QString what = first.startsWith(QLatin1Char('-')) ? QStringLiteral("option")
                                                                : QStringLiteral("command");
        console.errLine(QStringLiteral("%1: unknown %2 '%3'; run '%1 --help' for the list")
                            .arg(m_program, what, first));
        return kExitUsage;
    }
    const QStringList rest = args.mid(1);
    if (asksForHelp(rest))
        return help({first}, console);
    const int status = c->run(rest, console);
    console.flush();
    return status;
}

} // namespace lk::lkctl
