#pragma once

#include <QtCore/QString>
#include <QtCore/QStringList>

namespace lk::lkctl {

class Console;

// Exit statuses shared by every subcommand (CLI.md); a subcommand may add its own above 3.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  ///< the operation itself failed (e.g. no reply on the bus)
constexpr int kExitUsage = 2;    ///< unusable arguments or input text; message on stderr
constexpr int kExitBadData = 3;  ///< input held bytes that were not valid frames
constexpr int kExitRefused = 4;  ///< refused for safety (a limit, a ROM write without --yes)
constexpr int kExitMismatch = 5; ///< a write's read-back differs from what was written

/// One `lkctl NAME ...` subcommand. To add one: derive, then register an instance with
/// Dispatcher::add() in main.cpp; help, `lkctl help NAME` and `NAME --help` come for free.
class Subcommand {
public:
    virtual ~Subcommand() = default;

    virtual QString name() const = 0;    ///< "decode": the word after lkctl
    virtual QString summary() const = 0; ///< one line for the command list of `lkctl --help`
    virtual QString example() const = 0; ///< one typical invocation for `lkctl --help`
    virtual QString usage() const = 0;   ///< full text of `lkctl NAME --help`, with examples

    /// Runs with the arguments after NAME and returns the exit status. The dispatcher has
    /// already answered --help/-h. A QCoreApplication exists: a long-running subcommand
    /// (monitor) may run its own event loop here and return when it ends.
    virtual int run(const QStringList &args, Console &console) = 0;
};

} // namespace lk::lkctl
