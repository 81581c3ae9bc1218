// lkstudio: parse the command line, build the main window, connect, and (for the
// documentation) optionally save a screenshot and quit.

#include "DemoMotion.h"
#include "LeaveHooks.h"

#include <main/AppSettings.h>
#include <main/BusController.h>
#include <main/LanguageLoader.h>
#include <main/MainWindow.h>
#include <main/SettingsFile.h>
#include <main/StartupOptions.h>
#include <main/ThemePalette.h>
#include <panels/BusModel.h>
#include <panels/FileDialogs.h>
#include <panels/MessageBanner.h>
#include <plot/PlotPanel.h>
#include <recording/RecordingController.h>

#include <motor/SeriesLimits.h>
#include <sim/SimBus.h>
#include <system/LocalTimeZone.h>
#include <system/LogFile.h>
#include <system/SignalWatcher.h>
#include <transport/CanTransport.h>
#include <transport/SerialTransport.h>
#include <transport/SimBusHandle.h>

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QLibraryInfo>
#include <QtCore/QLocale>
#include <QtCore/QLoggingCategory>
#include <QtCore/QTimer>
#include <QtCore/QVersionNumber>
#include <QtWidgets/QApplication>

#include <cstdio>
#include <cstdlib>
#include <optional>

Q_LOGGING_CATEGORY(lcStudio, "lk.studio")

namespace {

// The installed .desktop file's base name (packaging/linux): on Wayland the compositor
// matches the window to its menu entry and icon by this app ID.
const char kDesktopFileName[] = "org.lkservostudio.lkstudio";

/// After the first scan, select the drive asked for with --select.
void selectWhenFound(lk::ui::MainWindow &window, int id)
{
    auto *model = window.busModel();
    QObject::connect(model, &lk::ui::BusModel::drivesChanged, &window, [model, id] {
        if (model->drive(id))
            model->setCurrentId(id);
    });
}

/// --plot-all: every drive the scan finds is selected and every signal shown on the Plots
/// view, the heaviest load a user can put on the GUI (tests/bench/gui measures it).
void plotEverythingFound(lk::ui::MainWindow &window)
{
    auto *model = window.busModel();
    auto *plots = window.plots();
    for (const auto channel : lk::ui::PlotPanel::pickableChannels())
        plots->setChannelVisible(channel, true);
    QObject::connect(model, &lk::ui::BusModel::drivesChanged, &window,
                     [model] { model->setSelectedIds(model->ids()); });
}

/// --cycle-views: the next view every `periodMs`, as a user clicking through them, so that a
/// benchmark can see whether GUI work (building and drawing a view) pauses the bus.
void cycleViews(lk::ui::MainWindow &window, int periodMs)
{
    auto *timer = new QTimer(&window);
    QObject::connect(timer, &QTimer::timeout, &window, [&window, next = 0]() mutable {
        const QStringList names = window.viewNames();
        if (!names.isEmpty())
            window.showView(names.at(next++ % names.size()));
    });
    timer->start(periodMs);
}

/// --sim-low-voltage: once drive `id` is found on the simulator, its supply sags below the
/// series minimum, so that the low-voltage warning can be seen (demos, documentation).
void lowerSupplyWhenFound(lk::ui::MainWindow &window, int id)
{
    auto *model = window.busModel();
    auto *controller = window.controller();
    QObject::connect(model, &lk::ui::BusModel::drivesChanged, &window, [model, controller, id] {
        const auto *d = model->drive(id);
        const auto sim = controller->simulator();
        if (!d || !d->series || !sim)
            return;
        const double volts = lk::motor::seriesLimits(*d->series).minSupplyV * 0.75;
        sim->withBus([id, volts](lk::sim::SimBus &bus) {
            if (auto *drive = bus.drive(id))
                drive->setSupplyVoltage(volts);
        });
    });
}

/// The built-in bus moves on its own (a first run shows live plots), and the banner says so
/// for as long as it does.
void startDemo(lk::ui::MainWindow &window, DemoMotion &demo)
{
    const QString key = QStringLiteral("demo-motion");
    window.banner()->setEntry(
        key, lk::ui::MessageBanner::Level::Info,
        QApplication::translate("main", "The simulated drives move on their own (a demo) so that "
                                        "the plots show live values. Command any drive, or "
                                        "press Esc, and the demo stops.")
            .toHtmlEscaped());
    QObject::connect(&demo, &DemoMotion::stopped, window.banner(),
                     [&window, key] { window.banner()->clearEntry(key); });
    demo.start();
}

/// Save the window to `file` after `delayMs`, then quit (exit code 1 if it could not).
void screenshotLater(lk::ui::MainWindow &window, const QString &file, int delayMs)
{
    QTimer::singleShot(delayMs, &window, [&window, file] {
        const bool ok = window.grab().save(file, "PNG");
        if (!ok)
            std::fprintf(stderr, "lkstudio: cannot write %s\n", qPrintable(file));
        QCoreApplication::exit(ok ? 0 : 1);
    });
}

/// --help and --version print text only: they must work without a display (man pages, SSH).
bool wantsTextOnly(int argc, char *argv[])
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "-h" || a == "--help" || a == "--help-all" || a == "-v" || a == "--version")
            return true;
    }
    return false;
}

void setNames()
{
    QCoreApplication::setApplicationName(QStringLiteral("lkstudio"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LK_STUDIO_VERSION));
    QCoreApplication::setOrganizationName(QStringLiteral("lkstudio"));
}

/// QT_QPA_PLATFORM=wayland without Qt's Wayland plugin (package qt6-wayland) makes Qt abort
/// with a message that does not name the package: say what is missing and use X11 (XWayland).
void checkWaylandPlugin()
{
    if (qgetenv("QT_QPA_PLATFORM") != "wayland")
        return;
    const QDir platforms(QLibraryInfo::path(QLibraryInfo::PluginsPath) +
                         QStringLiteral("/platforms"));
    if (!platforms.entryList({QStringLiteral("libqwayland*")}, QDir::Files).isEmpty())
        return;
    std::fprintf(stderr, "lkstudio: QT_QPA_PLATFORM=wayland, but Qt's Wayland plugin is not "
                         "installed (Debian: sudo apt install qt6-wayland); using xcb instead\n");
    qputenv("QT_QPA_PLATFORM", "xcb");
}

/// The log in the XDG state directory (rotated) gets every Qt message; stderr still does.
void startLog(lk::system::LogFile &log)
{
    QString error;
    if (!log.open(&error))
        std::fprintf(stderr, "lkstudio: no log file (%s)\n", qPrintable(error));
    log.install();
}

/// A serial port, or "can:PLUGIN:INTERFACE" (StartupOptions::initialChoice), is there now.
bool portPresent(const QString &port)
{
    if (port.startsWith(QLatin1String("can:"))) {
        const QString plugin = port.section(QLatin1Char(':'), 1, 1);
        // virtualcan's bus is a server lkstudio starts itself: nothing to look for.
        return plugin == QLatin1String("virtualcan") ||
               lk::transport::CanTransport::interfaces(plugin).contains(
                   port.section(QLatin1Char(':'), 2));
    }
    return QFile::exists(lk::transport::SerialTransport::systemPath(port));
}

/// "/dev/ttyUSB0", "socketcan:can0" or "the simulated bus", for the log and the banner.
QString linkText(const lk::ui::ConnectionChoice &choice)
{
    if (choice.isCan())
        return QStringLiteral("%1:%2").arg(choice.canPlugin, choice.canInterface);
    return choice.isSimulator() ? QStringLiteral("the simulated bus") : choice.port;
}

/// What the banner says goes to the log too, so that a bug report has the recent errors.
void logMessages(lk::ui::BusController *controller)
{
    using Level = lk::ui::MessageBanner::Level;
    QObject::connect(controller, &lk::ui::BusController::message, controller,
                     [](Level level, const QString &text) {
                         if (level == Level::Info)
                             qCInfo(lcStudio).noquote() << text;
                         else
                             qCWarning(lcStudio).noquote() << text;
                     });
}

/// Remember the folder of each kind of file in the settings.
void rememberFolders(lk::ui::AppSettings &settings)
{
    lk::ui::FileDialogs::setFolderMemory(
        {[&settings](const QString &purpose) { return settings.lastFolder(purpose); },
         [&settings](const QString &purpose, const QString &folder) {
             settings.setLastFolder(purpose, folder);
         }});
}

std::optional<lk::ui::StartupOptions> parseOptions()
{
    QString error;
    auto options = lk::ui::StartupOptions::parse(QCoreApplication::arguments(), &error);
    if (!options)
        std::fprintf(stderr, "lkstudio: %s\n", qPrintable(error));
    return options;
}

/// Qt 6.4's Wayland plugin destroys its event queues after it has disconnected (and freed)
/// the display, in ~QWaylandDisplay: a use after free that valgrind shows on every exit and
/// that sometimes crashes (qt/qtwayland pull request 5). Such a crash at exit would hide a clean
/// shutdown from the desktop and fill crash reports, so lkstudio leaves without Qt's teardown.
bool waylandTeardownCrashes()
{
    return QGuiApplication::platformName().startsWith(QLatin1String("wayland")) &&
           QLibraryInfo::version() < QVersionNumber(6, 5);
}

/// Builds the window, connects and runs the event loop; returns the exit code. Every object
/// of ours (settings, bus thread, log of the session) is saved and destroyed when it returns.
int runStudio(const lk::ui::StartupOptions &options)
{
    if (!options.palette.isEmpty())
        lk::ui::ThemePalette::apply(options.palette); // else the system's, untouched
    // One QSettings on the file for the whole window: AppSettings and the drive views' store
    // both keep their keys in it.
    lk::ui::SettingsFile settingsFile(options.settingsFile);
    lk::ui::AppSettings settings(settingsFile);
    // Before any widget exists: texts are translated when the widgets are built.
    const QString preferred = options.language.isEmpty() ? settings.language() : options.language;
    lk::ui::LanguageLoader::install(
        lk::ui::LanguageLoader::resolve(preferred, QLocale::system().uiLanguages()));
    rememberFolders(settings);
    lk::ui::MainWindow window(&settings);
    logMessages(window.controller());
    // SIGTERM (logout, systemd, kill) and Ctrl-C close the window as its close button does,
    // so that the geometry and settings are saved and the bus thread ends cleanly; drives
    // commanded to move are stopped first, without asking. A logout asks when it may.
    lk::system::SignalWatcher terminationSignals;
    LeaveHooks::closeOnTermination(window, terminationSignals);
    LeaveHooks::askBeforeLogout(window);
    if (options.sim)
        window.controller()->setSimulatorSpec(*options.sim);
    window.controller()->setSimulatorFaults(options.simFaults);
    window.controller()->setScanOnConnect(options.scan);
    if (!options.view.isEmpty() && !window.showView(options.view)) {
        std::fprintf(stderr, "lkstudio: no view named %s (%s)\n", qPrintable(options.view),
                     qPrintable(window.viewNames().join(QStringLiteral(", "))));
        return 2;
    }
    if (options.selectId > 0)
        selectWhenFound(window, options.selectId);
    if (options.simLowVoltageId > 0)
        lowerSupplyWhenFound(window, options.simLowVoltageId);
    if (options.plotAll)
        plotEverythingFound(window);
    if (options.cycleViewsMs > 0)
        cycleViews(window, options.cycleViewsMs);
    if (options.windowSize.isValid())
        window.resize(options.windowSize);
    if (options.minimized)
        window.showMinimized();
    else
        window.show();

    if (!options.recording.isEmpty()) {
        // `lkstudio FILE`: replay, no bus (the banner says why a file cannot be read).
        window.recording()->openRecording(options.recording);
        if (!options.screenshotFile.isEmpty())
            screenshotLater(window, options.screenshotFile, options.screenshotDelayMs);
        return QApplication::exec();
    }
    const lk::ui::ConnectionChoice choice = options.initialChoice(settings, &portPresent);
    const bool fellBack = options.fellBackToSimulator(settings, &portPresent);
    const QString rememberedPort = linkText(settings.connection());
    qCInfo(lcStudio).noquote() << "connecting to" << linkText(choice);
    // A fallback to the simulator must not overwrite the port the user chose last time.
    window.connectTo(choice, !fellBack);
    if (fellBack) {
        window.banner()->showMessage(
            lk::ui::MessageBanner::Level::Info,
            QApplication::translate("main", "%1 is not plugged in: showing the built-in simulated "
                                            "bus. Pick the port and press Connect when the "
                                            "adapter is in.")
                .arg(rememberedPort));
    }
    DemoMotion demo(window.controller());
    LeaveHooks::followDemo(window, demo);
    if (options.simMotion && !choice.isSimulator()) {
        std::fprintf(stderr, "lkstudio: --sim-motion works only on the simulated bus\n");
        return 2;
    }
    if (DemoMotion::startsOnItsOwn(options, choice))
        startDemo(window, demo);
    if (!options.screenshotFile.isEmpty())
        screenshotLater(window, options.screenshotFile, options.screenshotDelayMs);
    return QApplication::exec();
}

} // namespace

int main(int argc, char *argv[])
{
    lk::system::LocalTimeZone::readOnce(); // before any thread: Qt's CAN plugins stamp frames
    if (wantsTextOnly(argc, argv)) {
        QCoreApplication app(argc, argv);
        setNames();
        return parseOptions() ? 0 : 2;
    }
    lk::system::LogFile log(lk::system::LogFile::defaultPath(QStringLiteral("lkstudio")));
    startLog(log);
    checkWaylandPlugin();
    QApplication app(argc, argv);
    setNames();
    QApplication::setApplicationDisplayName(QStringLiteral("LK Servo Studio"));
    QGuiApplication::setDesktopFileName(QString::fromLatin1(kDesktopFileName));
    const auto options = parseOptions();
    if (!options)
        return 2;
    qCInfo(lcStudio, "lkstudio %s, Qt %s, platform %s", LK_STUDIO_VERSION, qVersion(),
           qPrintable(QGuiApplication::platformName()));
    const int code = runStudio(*options);
    if (waylandTeardownCrashes()) {
        // Everything of ours is saved and destroyed; only Qt's own teardown is left.
        std::fflush(nullptr);
        std::_Exit(code);
    }
    return code;
}
