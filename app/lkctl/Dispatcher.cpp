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
                                  "       %1 help [COMMAND] | %1 --help | %1 --version\n\n"
                                  "Command-line tool for LK-TECH MS/MF/MG/MH servo drives on RS485 "
                                  "(protocol V2.3).\n\nCommands:\n")
                       .arg(m_program);
    for (const auto &c : m_commands)
        text += QStringLiteral("  %1  %2\n").arg(c->name().leftJustified(width), c->summary());
    text += QStringLiteral("\nRun '%1 COMMAND --help' for the options and examples of a "
                           "command.\n\nExamples:\n")
                .arg(m_program);
    for (const auto &c : m_commands)
        text += QStringLiteral("  %1\n").arg(c->example());
    text += QStringLiteral("\nExit status: 0 success, 2 unusable arguments; each command's help "
                           "lists the others.\n");
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
    if (first == QLatin1String("--version")) {
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
