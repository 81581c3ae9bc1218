#include "BusOptions.h"

#include "ArgParser.h"

#include <bus/BusTiming.h>
#include <sim/SimBusSpec.h>
#include <transport/SerialTransport.h>
#include <transport/SimTransport.h>

#include <QtCore/QDir>
#include <QtCore/QStringList>

namespace lk::lkctl {

void BusOptions::declare(ArgParser &parser)
{
    parser.addOption(QStringLiteral("port"), true);
    parser.addOption(QStringLiteral("baud"), true);
    parser.addOption(QStringLiteral("sim"), true);
    parser.addOption(QStringLiteral("sim-rom-dir"), true);
}

namespace {
/// The baud in `text` (from --baud or LKCTL_BAUD, named by `source`) when it is one of the
/// nine; nullopt with `error` naming the source otherwise.
std::optional<int> parseBaud(const QString &text, const QString &source, QString *error)
{
    bool ok = false;
    const int baud = text.toInt(&ok);
    if (ok && bus::BusTiming::isStandardBaud(baud))
        return baud;
    QStringList bauds;
    for (int b : bus::BusTiming::standardBauds())
        bauds << QString::number(b);
    *error = QStringLiteral("%1 must be one of %2 (got '%3')")
                 .arg(source, bauds.join(QStringLiteral(", ")), text);
    return std::nullopt;
}
} // namespace

std::optional<BusOptions> BusOptions::from(const ArgParser &parser, QString *error)
{
    BusOptions o;
    const bool sim = parser.isSet(QStringLiteral("sim"));
    // The command line wins over the environment: LKCTL_PORT only fills in a missing bus.
    const QString envPort = qEnvironmentVariable(kPortVariable);
    const bool port = parser.isSet(QStringLiteral("port")) || (!sim && !envPort.isEmpty());
    if (port == sim) {
        *error = port ? QStringLiteral("give --port or --sim, not both")
                      : QStringLiteral("no bus: give --port DEV (a serial adapter) or --sim "
                                       "ID:SERIES,... (the built-in simulator), or set %1")
                            .arg(QLatin1String(kPortVariable));
        return std::nullopt;
    }
    const bool baudOption = parser.isSet(QStringLiteral("baud"));
    if (baudOption || !qEnvironmentVariableIsEmpty(kBaudVariable)) {
        const std::optional<int> baud = baudOption ? parseBaud(parser.value(QStringLiteral("baud")),
                                                               QStringLiteral("--baud"), error)
                                                   : parseBaud(qEnvironmentVariable(kBaudVariable),
                                                               QLatin1String(kBaudVariable), error);
        if (!baud)
            return std::nullopt;
        o.baud = *baud;
    }
    if (parser.isSet(QStringLiteral("sim-rom-dir")) && !sim) {
        *error = QStringLiteral("--sim-rom-dir goes with --sim");
        return std::nullopt;
    }
    if (port) {
        o.port =
            parser.isSet(QStringLiteral("port")) ? parser.value(QStringLiteral("port")) : envPort;
        if (o.port.isEmpty()) {
            *error = QStringLiteral("--port needs a device, e.g. /dev/ttyUSB0");
            return std::nullopt;
        }
        o.port = portPath(o.port);
        return o;
    }
    o.simSpec = parser.value(QStringLiteral("sim"));
    o.simRomDir = parser.value(QStringLiteral("sim-rom-dir"));
    QString specError;
    if (!sim::SimBusSpec::parse(o.simSpec, &specError)) {
        *error = QStringLiteral("--sim: %1").arg(specError);
        return std::nullopt;
    }
    return o;
}

QString BusOptions::portPath(const QString &port)
{
    // A name with a slash is a path (./bus, ../lksim/bus, serial/by-id/...): relative to the
    // working directory, not to /dev, where only a bare name (ttyUSB0) is looked for.
    if (!port.contains(QLatin1Char('/')) || QDir::isAbsolutePath(port))
        return port;
    return QDir::cleanPath(QDir::current().absoluteFilePath(port));
}

bus::TransportFactory BusOptions::factory() const
{
    if (!isSimulated()) {
        transport::SerialSettings s;
        s.portName = port; // the baud is the session's (BusSession::open)
        return transport::SerialTransport::factory(s);
    }
    const std::optional<sim::SimBusSpec> parsed = sim::SimBusSpec::parse(simSpec);
    if (!parsed) // from() checked it; a hand-made BusOptions gets a link that does not open
        return [](int) -> std::unique_ptr<transport::Transport> { return nullptr; };
    transport::SimSettings s;
    s.spec = *parsed;
    s.romDirectory = simRomDir;
    return transport::SimTransport::factory(s);
}

QString BusOptions::helpText()
{
    return QStringLiteral(
        "Bus (one of --port and --sim is required, unless LKCTL_PORT names the port):\n"
        "  --port DEV         serial adapter, e.g. /dev/ttyUSB0 or ttyUSB0 (8N1); a name\n"
        "                     with a slash is a path (./bus: in this folder);\n"
        "                     default: the environment variable LKCTL_PORT\n"
        "  --baud N           9600, 19200, 38400, 57600, 115200, 230400, 460800, 1000000,\n"
        "                     2000000 or 4000000; default: LKCTL_BAUD, else 115200\n"
        "  --sim ID:SERIES,.. the built-in simulated bus instead, e.g. --sim 3:MF,17:MS\n"
        "                     (series MS, MF, MG, MH; it lives only as long as this command;\n"
        "                     1:MS4015@2.35 is a firmware-2.35 drive (protocol V2.35);\n"
        "                     3:MF+accel-ignored copies firmware that ignores 0x34, and\n"
        "                     +clear-angle-ignored firmware that ignores 0x95); every frame\n"
        "                     takes the wire time of --baud, as on a real bus\n"
        "  --sim-rom-dir DIR  keep the simulated drives' ROM in DIR between commands\n");
}

} // namespace lk::lkctl
