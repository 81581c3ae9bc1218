#include "StartupOptions.h"

#include "AppSettings.h"
#include "SettingsFile.h"

#include <bus/BusTiming.h>
#include <sim/FaultInjector.h>

#include <QtCore/QCommandLineParser>
#include <QtCore/QFileInfo>

#include <cstdio>

namespace lk::ui {

namespace {
constexpr int kMinId = 1;
constexpr int kMaxId = 32;
constexpr int kMinWindowSide = 200;

/// An ID 1..32 from text, or 0.
int idValue(const QString &text)
{
    bool ok = false;
    const int id = text.toInt(&ok);
    return ok && id >= kMinId && id <= kMaxId ? id : 0;
}

QCommandLineOption hidden(const QString &name, const QString &help, const QString &value = {})
{
    QCommandLineOption o(name, help, value);
    o.setFlags(QCommandLineOption::HiddenFromHelp);
    return o;
}

} // namespace

/// The options of the command line, defined once (names, help, value names).
struct StartupOptions::Definitions {
    QCommandLineOption port{QStringLiteral("port"),
                            tr("Open the serial port DEV (e.g. /dev/ttyUSB0, COM3)."),
                            QStringLiteral("DEV")};
    QCommandLineOption baud{QStringLiteral("baud"),
                            tr("Baud rate: 9600 ... 4000000 (default 115200)."),
                            QStringLiteral("N")};
    QCommandLineOption can{QStringLiteral("can"),
                           tr("Open a CAN interface through a Qt SerialBus plugin, e.g. "
                              "socketcan:can0 (see the README, \"Drives on CAN\"); \"sim\": "
                              "the built-in simulated bus on CAN (with --sim for its drives)."),
                           QStringLiteral("PLUGIN:INTERFACE")};
    QCommandLineOption bitRate{QStringLiteral("bitrate"),
                               tr("CAN bit rate: 1000000, 500000, 250000, 125000 or 100000 "
                                  "(default 1000000)."),
                               QStringLiteral("N")};
    QCommandLineOption listen{QStringLiteral("listen"),
                              tr("Listen only: watch a bus another controller runs and transmit "
                                 "nothing, not even an emergency stop.")};
    QCommandLineOption noListen{QStringLiteral("no-listen"),
                                tr("Open the bus as its master (the default unless the last "
                                   "connection listened).")};
    QCommandLineOption sim{QStringLiteral("sim"),
                           tr("Open the built-in simulated bus with these drives, e.g. "
                              "1:MF,2:MG,3:MS,4:MH or 5:MG5010E-i36."),
                           QStringLiteral("ID:SERIES,...")};
    QCommandLineOption simFaults{
        QStringLiteral("sim-faults"),
        tr("Inject faults into the simulated bus, e.g. corrupt=0.01,garbage=0.01,drop=0.005 "
           "(also length=P, delay=P, delay_ms=N, silent=ID, seed=N)."),
        QStringLiteral("SPEC")};
    QCommandLineOption settings{QStringLiteral("settings"),
                                tr("Read and write settings in FILE (INI) instead of the user's "
                                   "settings."),
                                QStringLiteral("FILE")};
    QCommandLineOption noScan{QStringLiteral("no-scan"),
                              tr("Do not scan the bus after connecting.")};
    QCommandLineOption view{QStringLiteral("view"),
                            tr("Start on a view: dashboard, overview, plots, traffic, tuning, "
                               "control, encoder, info."),
                            QStringLiteral("NAME")};
    QCommandLineOption select{QStringLiteral("select"), tr("Select drive ID once it is found."),
                              QStringLiteral("ID")};
    // For demos and the documentation's screenshots: not part of the user interface.
    QCommandLineOption shot =
        hidden(QStringLiteral("screenshot"),
               QStringLiteral("Save the window to FILE (PNG) and quit."), QStringLiteral("FILE"));
    QCommandLineOption delay =
        hidden(QStringLiteral("screenshot-delay-ms"),
               QStringLiteral("Wait N ms before the screenshot."), QStringLiteral("N"));
    QCommandLineOption motion =
        hidden(QStringLiteral("sim-motion"), QStringLiteral("Simulator only: move the drives."));
    QCommandLineOption lowVoltage =
        hidden(QStringLiteral("sim-low-voltage"),
               QStringLiteral("Simulator only: drive ID's supply sags below its series minimum."),
               QStringLiteral("ID"));
    QCommandLineOption plotAll =
        hidden(QStringLiteral("plot-all"),
               QStringLiteral("Plot every signal of every drive found (benchmarks)."));
    QCommandLineOption minimized =
        hidden(QStringLiteral("minimized"), QStringLiteral("Start with the window minimised."));
    QCommandLineOption cycleViews =
        hidden(QStringLiteral("cycle-views"),
               QStringLiteral("Show the next view every MS milliseconds (benchmarks)."),
               QStringLiteral("MS"));
    QCommandLineOption size =
        hidden(QStringLiteral("window-size"),
               QStringLiteral("Window size in pixels, e.g. 1600x1000."), QStringLiteral("WxH"));

    QCommandLineOption language =
        hidden(QStringLiteral("language"),
               QStringLiteral("User interface language, e.g. zh_CN or en (not saved)."),
               QStringLiteral("NAME"));
    QCommandLineOption palette =
        hidden(QStringLiteral("palette"),
               QStringLiteral("Use a dark or light Fusion palette instead of the system's."),
               QStringLiteral("dark|light"));

    QList<QCommandLineOption> all() const
    {
        return {port,     baud,    can,       bitRate,    listen,   noListen, sim,    simFaults,
                settings, noScan,  view,      select,     shot,     delay,    motion, lowVoltage,
                size,     plotAll, minimized, cycleViews, language, palette};
    }
};

std::optional<StartupOptions> StartupOptions::parse(const QStringList &arguments, QString *error)
{
    QCommandLineParser p;
    p.setApplicationDescription(
        tr("LK Servo Studio: connect, scan, watch, plot and diagnose LK-TECH servo drives on an "
           "RS485 or CAN bus. With no options it opens the last port used if it is plugged in, "
           "else the built-in simulated bus."));
    p.addPositionalArgument(QStringLiteral("file"),
                            tr("A recording (.lkrec) to replay instead of connecting."),
                            QStringLiteral("[FILE]"));
    const auto help = p.addHelpOption();
    const auto version = p.addVersionOption();
    const Definitions d;
    p.addOptions(d.all());
    StartupOptions o;
    QString why;
    if (!p.parse(arguments)) {
        why = p.errorText();
    } else if (p.isSet(help) || p.isSet(version)) {
        const QString text =
            p.isSet(help) ? p.helpText()
                          : QStringLiteral("%1 %2\n").arg(QCoreApplication::applicationName(),
                                                          QCoreApplication::applicationVersion());
        std::fputs(qPrintable(text), stdout);
        o.helpShown = true;
        return o;
    } else if (p.positionalArguments().size() > 1 ||
               (p.positionalArguments().size() == 1 &&
                !QFileInfo(p.positionalArguments().constFirst()).isFile())) {
        why = tr("Unexpected argument: %1").arg(p.positionalArguments().constLast());
    } else {
        o.recording = p.positionalArguments().value(0);
        why = o.readBus(p, d);
        if (why.isEmpty())
            why = o.readCan(p, d);
        if (why.isEmpty())
            why = o.readDisplay(p, d);
    }
    if (why.isEmpty())
        return o;
    if (error)
        *error = why;
    return std::nullopt;
}

QString StartupOptions::readBus(const QCommandLineParser &p, const Definitions &d)
{
    if (p.isSet(d.port) && p.isSet(d.sim))
        return tr("--port and --sim exclude each other: pick one bus.");
    if (p.isSet(d.port))
        port = p.value(d.port);
    if (p.isSet(d.baud)) {
        bool ok = false;
        baud = p.value(d.baud).toInt(&ok);
        if (!ok || !bus::BusTiming::isStandardBaud(baud))
            return tr("--baud %1 is not an LK baud (9600, 19200, 38400, 57600, 115200, 230400, "
                      "460800, 1000000, 2000000, 4000000).")
                .arg(p.value(d.baud));
        baudGiven = true;
    }
    if (p.isSet(d.listen) && p.isSet(d.noListen))
        return tr("--listen and --no-listen exclude each other.");
    if (p.isSet(d.listen) || p.isSet(d.noListen))
        listenOnly = p.isSet(d.listen);
    if (p.isSet(d.sim)) {
        QString why;
        sim = sim::SimBusSpec::parse(p.value(d.sim), &why);
        if (!sim)
            return tr("--sim: %1").arg(why);
    }
    if (p.isSet(d.simFaults)) {
        if (port)
            return tr("--sim-faults works on the simulated bus only, not with --port.");
        QString why;
        sim::FaultInjector probe;
        if (!probe.configure(p.value(d.simFaults), &why))
            return tr("--sim-faults: %1").arg(why);
        simFaults = p.value(d.simFaults);
    }
    settingsFile = p.value(d.settings);
    if (p.isSet(d.settings)) {
        // Refused here, where the user typed it; the default file is checked by SettingsFile.
        if (const std::optional<system::FileReadError> problem = SettingsFile::check(settingsFile))
            return tr("--settings %1: %2").arg(settingsFile, problem->reason());
    }
    scan = !p.isSet(d.noScan);
    simMotion = p.isSet(d.motion);
    if (simMotion && port)
        return tr("--sim-motion moves simulated drives only; it cannot go with --port.");
    if (p.isSet(d.select)) {
        selectId = idValue(p.value(d.select));
        if (selectId == 0)
            return tr("--select takes an ID from 1 to 32.");
    }
    if (p.isSet(d.lowVoltage)) {
        simLowVoltageId = idValue(p.value(d.lowVoltage));
        if (simLowVoltageId == 0 || port)
            return tr("--sim-low-voltage takes a simulated drive's ID from 1 to 32.");
    }
    return {};
}

QString StartupOptions::readCan(const QCommandLineParser &p, const Definitions &d)
{
    const QString value = p.value(d.can).trimmed();
    simCan = p.isSet(d.can) && value == QLatin1String("sim");
    if (simCan) {
        if (p.isSet(d.port))
            return tr("--can sim is the simulated bus: it cannot go with --port.");
    } else if (p.isSet(d.can)) {
        if (p.isSet(d.port) || p.isSet(d.sim))
            return tr("--can, --port and --sim exclude each other: pick one bus.");
        // The first colon only: a virtualcan interface is a URL ("tcp://127.0.0.1:35468/can0").
        canPlugin = value.section(QLatin1Char(':'), 0, 0).trimmed();
        canInterface = value.section(QLatin1Char(':'), 1).trimmed();
        if (canPlugin.isEmpty() || canInterface.isEmpty())
            return tr("--can takes PLUGIN:INTERFACE, e.g. socketcan:can0 (found \"%1\").")
                .arg(value);
    }
    if (p.isSet(d.bitRate)) {
        if (p.isSet(d.port) || (p.isSet(d.sim) && !simCan))
            return tr("--bitrate is the bit rate of a CAN bus; it cannot go with --port or "
                      "--sim (their rate is --baud).");
        bool ok = false;
        bitRate = p.value(d.bitRate).toInt(&ok);
        if (!ok || !ConnectionChoice::isCanBitRate(bitRate))
            return tr("--bitrate %1 is not a CAN bit rate of LK drives (1000000, 500000, "
                      "250000, 125000, 100000).")
                .arg(p.value(d.bitRate));
        bitRateGiven = true;
    }
    return {};
}

QString StartupOptions::readDisplay(const QCommandLineParser &p, const Definitions &d)
{
    view = p.value(d.view);
    plotAll = p.isSet(d.plotAll);
    minimized = p.isSet(d.minimized);
    if (p.isSet(d.cycleViews)) {
        bool ok = false;
        cycleViewsMs = p.value(d.cycleViews).toInt(&ok);
        if (!ok || cycleViewsMs < 100)
            return tr("--cycle-views takes a period of at least 100 ms.");
    }
    if (p.isSet(d.size)) {
        const QStringList wh = p.value(d.size).split(QLatin1Char('x'));
        const int w = wh.value(0).toInt();
        const int h = wh.value(1).toInt();
        if (wh.size() != 2 || w < kMinWindowSide || h < kMinWindowSide)
            return tr("--window-size takes WIDTHxHEIGHT, e.g. 1600x1000.");
        windowSize = QSize(w, h);
    }
    language = p.value(d.language);
    palette = p.value(d.palette);
    if (!palette.isEmpty() && palette != QLatin1String("dark") && palette != QLatin1String("light"))
        return tr("--palette takes dark or light.");
    screenshotFile = p.value(d.shot);
    if (p.isSet(d.delay)) {
        bool ok = false;
        screenshotDelayMs = p.value(d.delay).toInt(&ok);
        if (!ok || screenshotDelayMs < 0)
            return tr("--screenshot-delay-ms takes a number of milliseconds.");
    }
    return {};
}

ConnectionChoice
StartupOptions::initialChoice(const AppSettings &settings,
                              const std::function<bool(const QString &)> &portExists) const
{
    ConnectionChoice c = settings.connection();
    const QString canKey = QStringLiteral("can:%1:%2").arg(c.canPlugin, c.canInterface);
    if (port) {
        c.kind = ConnectionChoice::Kind::Serial;
        c.port = *port;
    } else if (!canPlugin.isEmpty()) {
        c.kind = ConnectionChoice::Kind::Can;
        c.canPlugin = canPlugin;
        c.canInterface = canInterface;
    } else if (sim || simCan) {
        c.kind = ConnectionChoice::Kind::Simulator;
        c.simulatedCan = simCan; // --sim alone: the simulated RS485 bus
    } else if (c.isCan() ? !portExists(canKey)
                         : !c.isSimulator() && (c.port.isEmpty() || !portExists(c.port))) {
        c.simulatedCan = c.isCan(); // without the CAN adapter: the simulated CAN bus
        c.kind = ConnectionChoice::Kind::Simulator;
        c.listenOnly = false; // the built-in bus has no other master to listen to
    }
    if (baudGiven)
        c.baud = baud;
    if (bitRateGiven)
        c.bitRate = bitRate;
    if (listenOnly)
        c.listenOnly = *listenOnly;
    return c;
}

bool StartupOptions::fellBackToSimulator(
    const AppSettings &settings, const std::function<bool(const QString &)> &portExists) const
{
    const ConnectionChoice remembered = settings.connection();
    return !port && !sim && !simCan && canPlugin.isEmpty() && !remembered.isSimulator() &&
           initialChoice(settings, portExists).isSimulator();
}

} // namespace lk::ui
