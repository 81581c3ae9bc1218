#include "BusOptions.h"

#include "ArgParser.h"

#include <bus/BusTiming.h>
#include <bus/LinkTiming.h>
#include <sim/SimBusSpec.h>
#include <transport/CanTransport.h>
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
    parser.addOption(QStringLiteral("can"), true);
    parser.addOption(QStringLiteral("bitrate"), true);
    parser.addOption(QStringLiteral("drives"), true);
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

/// `--can PLUGIN:INTERFACE` (or LKCTL_CAN, named by `source`) and `--bitrate` into `o`.
bool readCan(const ArgParser &parser, const QString &text, const QString &source, BusOptions &o,
             QString *error)
{
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    if (colon <= 0 || colon == text.size() - 1) {
        *error = QStringLiteral("%1 \"%2\": write PLUGIN:INTERFACE, e.g. socketcan:can0 or "
                                "virtualcan:can0")
                     .arg(source, text);
        return false;
    }
    o.canPlugin = text.left(colon);
    o.canInterface = text.mid(colon + 1);
    const QStringList plugins = transport::CanTransport::plugins();
    if (!plugins.contains(o.canPlugin)) {
        *error = QStringLiteral("%1: Qt has no CAN plugin \"%2\" here (it has: %3)")
                     .arg(source, o.canPlugin,
                          plugins.isEmpty() ? QStringLiteral("none") : plugins.join(", "));
        return false;
    }
    if (parser.isSet(QStringLiteral("bitrate"))) {
        bool ok = false;
        const int rate = parser.value(QStringLiteral("bitrate")).toInt(&ok);
        if (!ok || !bus::LinkTiming::isCanBitRate(rate)) {
            *error = QStringLiteral("--bitrate must be 1000000, 500000, 250000, 125000 or "
                                    "100000 (the rates LK drives take on CAN), got \"%1\"")
                         .arg(parser.value(QStringLiteral("bitrate")));
            return false;
        }
        o.bitRate = rate;
    }
    return true;
}
} // namespace

std::optional<BusOptions> BusOptions::from(const ArgParser &parser, QString *error,
                                           bool listenDrives)
{
    BusOptions o;
    if (!listenDrives && parser.isSet(QStringLiteral("drives"))) {
        const auto drives =
            bus::DriveIdentity::parseList(parser.value(QStringLiteral("drives")), error);
        if (!drives) {
            *error = QStringLiteral("--drives: %1").arg(*error);
            return std::nullopt;
        }
        o.drives = *drives;
    }
    const bool canOption = parser.isSet(QStringLiteral("can"));
    const bool sim = parser.isSet(QStringLiteral("sim"));
    if (canOption && (sim || parser.isSet(QStringLiteral("port")))) {
        *error = QStringLiteral("give one bus: --can, --port or --sim");
        return std::nullopt;
    }
    const QString envCan = qEnvironmentVariable(kCanVariable);
    const bool portGiven = parser.isSet(QStringLiteral("port")) || sim;
    if (canOption || (!portGiven && !envCan.isEmpty())) {
        if (parser.isSet(QStringLiteral("baud"))) {
            *error = QStringLiteral("--baud is for RS485; on CAN give --bitrate");
            return std::nullopt;
        }
        const bool ok = canOption ? readCan(parser, parser.value(QStringLiteral("can")),
                                            QStringLiteral("--can"), o, error)
                                  : readCan(parser, envCan, QLatin1String(kCanVariable), o, error);
        return ok ? std::optional<BusOptions>(o) : std::nullopt;
    }
    if (parser.isSet(QStringLiteral("bitrate"))) {
        *error = QStringLiteral("--bitrate goes with --can (RS485 takes --baud)");
        return std::nullopt;
    }
    // The command line wins over the environment: LKCTL_PORT only fills in a missing bus.
    const QString envPort = qEnvironmentVariable(kPortVariable);
    const bool port = parser.isSet(QStringLiteral("port")) || (!sim && !envPort.isEmpty());
    if (port == sim) {
        *error = port ? QStringLiteral("give --port or --sim, not both")
                      : QStringLiteral("no bus: give --port DEV (a serial adapter), --can "
                                       "PLUGIN:INTERFACE (a CAN adapter) or --sim ID:SERIES,... "
                                       "(the built-in simulator), or set %1 or %2")
                            .arg(QLatin1String(kPortVariable), QLatin1String(kCanVariable));
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
    if (isCan()) {
        transport::CanSettings s;
        s.plugin = canPlugin;
        s.interfaceName = canInterface;
        s.bitRate = bitRate;
        return transport::CanTransport::factory(s);
    }
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

QString BusOptions::helpText(bool withDrives)
{
    const QString common = QStringLiteral(
        "Bus (one of --port, --can and --sim is required, unless LKCTL_PORT or LKCTL_CAN\n"
        "names it):\n"
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
        "  --sim-rom-dir DIR  keep the simulated drives' ROM in DIR between commands\n"
        "  --can PLUGIN:IF    a CAN adapter through Qt SerialBus: socketcan:can0 (candleLight,\n"
        "                     PCAN-USB, CANable via slcand), peakcan:usb0, or\n"
        "                     virtualcan:can0 (tcp://HOST:PORT/can0 for a server of one's\n"
        "                     own); default: the environment variable LKCTL_CAN\n"
        "  --bitrate N        CAN bit rate: 1000000 (default), 500000, 250000, 125000 or\n"
        "                     100000; it must be the drives'. Where Qt cannot set it, the\n"
        "                     message gives the `ip link` command to run as root\n");
    if (!withDrives)
        return common;
    return common +
           QStringLiteral(
               "  --drives LIST      what each drive is, where no model read tells it (every "
               "drive\n"
               "                     on CAN): ID:SERIES@GEN[/GEAR],... e.g. 3:MG@2.35, "
               "1:MF@can236,\n"
               "                     2:MS@can; GEN is 2.3 or 2.35 (RS485), can (old CAN) or "
               "can236\n"
               "                     (CAN V2.36). Until a drive's series is known, torque, power\n"
               "                     and open loop are refused\n");
}

} // namespace lk::lkctl
