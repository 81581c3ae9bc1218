#pragma once

#include "ArgParser.h"
#include "BusOptions.h"
#include "Subcommand.h"

#include <QtCore/QString>

#include <optional>

namespace lk::lkctl {

/// Shared plumbing of the subcommands that talk to a bus (scan, info, read, write, control,
/// off/stop/run, monitor): the bus options, argument errors, ID parsing and help sections.
class LiveCommand : public Subcommand {
public:
    /// `lkctl NAME: message (see lkctl NAME --help)` on standard error; returns kExitUsage.
    int usageError(Console &console, const QString &message) const;
    /// The one positional argument, a drive ID; nullopt after the usage error (missing, two
    /// arguments, not 1..32), with `status` set.
    std::optional<int> singleId(const ArgParser &parser, Console &console, int *status) const;
    /// "3" -> 3; nullopt with `error` naming `what` unless it is 1..32.
    static std::optional<int> parseId(const QString &text, QString *error,
                                      const QString &what = QStringLiteral("ID"));

protected:
    /// A parser with the bus options (and --json when `json`) declared.
    static ArgParser makeParser(bool json = true);
    /// Parse and read the bus options; on failure prints and returns nullopt. `listenDrives`:
    /// --drives is the command's own (BusOptions::from).
    std::optional<BusOptions> parseBus(ArgParser &parser, const QStringList &args, Console &console,
                                       int *status, bool listenDrives = false) const;
    /// The exit status section shared by every live command's help.
    static QString exitStatusText(const QString &extra = QString());
};

} // namespace lk::lkctl
