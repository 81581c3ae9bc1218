#pragma once

#include "Subcommand.h"

#include <QtCore/QString>
#include <QtCore/QStringList>

#include <memory>
#include <vector>

namespace lk::lkctl {

class Console;

/// Picks the subcommand named by the first argument and runs it; answers --help, help,
/// --version and unknown names itself, so that a subcommand only parses its own options.
class Dispatcher {
public:
    Dispatcher(QString program, QString version);

    /// Register a subcommand; `lkctl --help` lists them in registration order.
    void add(std::unique_ptr<Subcommand> command);
    const Subcommand *find(const QString &name) const;

    /// `lkctl --help`: usage, the command list with summaries, examples.
    QString usage() const;
    /// args: the command line without the program name. Returns the exit status.
    int run(const QStringList &args, Console &console);

private:
    int help(const QStringList &args, Console &console) const;
    static bool asksForHelp(const QStringList &args);

    QString m_program;
    QString m_version;
    std::vector<std::unique_ptr<Subcommand>> m_commands;
};

} // namespace lk::lkctl
