#pragma once

#include <panels/ConnectionChoice.h>
#include <sim/SimBusSpec.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QSize>
#include <QtCore/QString>
#include <QtCore/QStringList>

#include <functional>

class QCommandLineParser;
#include <optional>

namespace lk::ui {

class AppSettings;

/// lkstudio's command line: what to connect to at start, which settings file to use, and
/// the hidden screenshot options used to make the documentation images.
struct StartupOptions {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::StartupOptions)
public:
    std::optional<QString> port; ///< --port DEV: a real serial port
    int baud = 115200;           ///< --baud N (one of the nine LK bauds)
    bool baudGiven = false;
    /// --can PLUGIN:INTERFACE: a CAN interface through a Qt SerialBus plugin ("socketcan",
    /// "can0"); empty plugin: not given.
    QString canPlugin;
    QString canInterface;
    /// --can sim: the built-in simulated bus with its drives on CAN (old and V2.36 drives, CAN
    /// wire time at --bitrate); goes with --sim for the drives.
    bool simCan = false;
    int bitRate = ConnectionChoice::kDefaultBitRate; ///< --bitrate N (a CAN bit rate)
    bool bitRateGiven = false;
    /// --listen: the bus opens listen-only (transmits nothing); --no-listen: as bus master.
    /// nullopt: as last time.
    std::optional<bool> listenOnly;
    std::optional<sim::SimBusSpec> sim; ///< --sim ID:SERIES,...
    QString simFaults;                  ///< --sim-faults SPEC: faults the simulated bus injects
    QString settingsFile;               ///< --settings FILE (tests); empty: the user's file
    bool scan = true;                   ///< --no-scan turns the scan on connect off
    QString view;                       ///< --view NAME: dashboard, overview, plots, traffic
    int selectId = 0;                   ///< --select ID: the drive selected after the scan
    bool simMotion = false;             ///< --sim-motion (hidden): simulated drives move, for demos
    int simLowVoltageId = 0;            ///< --sim-low-voltage ID (hidden): that drive's supply sags
    QSize windowSize;                   ///< --window-size WxH (hidden); invalid: saved or default
    bool plotAll = false;   ///< --plot-all (hidden): every drive and signal plotted (benchmarks)
    bool minimized = false; ///< --minimized (hidden): the window starts minimised (benchmarks)
    /// --cycle-views MS (hidden): show the next view every MS ms, as a user clicking through
    /// them (benchmarks: do GUI actions pause the bus?); 0: off
    int cycleViewsMs = 0;
    QString screenshotFile;       ///< --screenshot FILE (hidden)
    int screenshotDelayMs = 3000; ///< --screenshot-delay-ms N (hidden)
    QString language;             ///< --language NAME (hidden): e.g. zh_CN, en; empty: setting
    QString palette;              ///< --palette dark|light (hidden): a Fusion palette
    bool helpShown = false;       ///< --help or --version printed; exit 0
    QString recording; ///< FILE (the one positional argument): replay it instead of connecting

    /// Parse `arguments` (argv, program name first). nullopt with a message on bad input.
    static std::optional<StartupOptions> parse(const QStringList &arguments, QString *error);

    /// What to connect to at start: --port, --can or --sim when given; else the last choice
    /// when it is the simulator or a port that is plugged in now; else the built-in simulated
    /// bus (so that a first run, and a run without the adapter, shows live motors). A CAN
    /// interface is asked of `portExists` as "can:PLUGIN:INTERFACE" (BusController::portKey).
    ConnectionChoice initialChoice(const AppSettings &settings,
                                   const std::function<bool(const QString &)> &portExists) const;
    /// True when initialChoice fell back to the simulator although a port was remembered.
    bool fellBackToSimulator(const AppSettings &settings,
                             const std::function<bool(const QString &)> &portExists) const;

private:
    struct Definitions;
    /// Read one group of options; an error message, or empty when fine.
    QString readBus(const QCommandLineParser &parser, const Definitions &definitions);
    QString readDisplay(const QCommandLineParser &parser, const Definitions &definitions);
    QString readCan(const QCommandLineParser &parser, const Definitions &definitions);
};

} // namespace lk::ui
