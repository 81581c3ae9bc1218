#include "LiveCommand.h"

#include "Console.h"

#include <protocol/Checksum.h>

namespace lk::lkctl {

int LiveCommand::usageError(Console &console, const QString &message) const
{
    console.errLine(QStringLiteral("lkctl %1: %2 (see lkctl %1 --help)").arg(name(), message));
    return kExitUsage;
}

std::optional<int> LiveCommand::parseId(const QString &text, QString *error, const QString &what)
{
    bool ok = false;
    const int id = text.toInt(&ok);
    if (!ok || id < protocol::kMinId || id > protocol::kMaxId) {
        *error = QStringLiteral("%1 must be 1..32 (got '%2')").arg(what, text);
        return std::nullopt;
    }
    return id;
}

std::optional<int> LiveCommand::singleId(const ArgParser &parser, Console &console,
                                         int *status) const
{
    const QStringList &pos = parser.positionals();
    QString error;
    std::optional<int> id;
    if (pos.size() != 1)
        error = pos.isEmpty() ? QStringLiteral("missing the drive ID")
                              : QStringLiteral("unexpected argument '%1'").arg(pos.at(1));
    else
        id = parseId(pos.at(0), &error);
    if (!id)
        *status = usageError(console, error);
    return id;
}

ArgParser LiveCommand::makeParser(bool json)
{
    ArgParser p;
    BusOptions::declare(p);
    if (json)
        p.addOption(QStringLiteral("json"), false);
    return p;
}

std::optional<BusOptions> LiveCommand::parseBus(ArgParser &parser, const QStringList &args,
                                                Console &console, int *status,
                                                bool listenDrives) const
{
    QString error;
    if (!parser.parse(args, &error)) {
        *status = usageError(console, error);
        return std::nullopt;
    }
    std::optional<BusOptions> bus = BusOptions::from(parser, &error, listenDrives);
    if (!bus)
        *status = usageError(console, error);
    return bus;
}

QString LiveCommand::exitStatusText(const QString &extra)
{
    return QStringLiteral("Exit status:\n"
                          "  0  done\n"
                          "  1  the bus could not be opened (the message says why and how to "
                          "fix it),\n"
                          "     a drive did not answer (the message names the ID and the "
                          "command), or\n"
                          "     the bus went away\n"
                          "  2  unusable arguments (nothing was sent)\n") +
           extra;
}

} // namespace lk::lkctl
