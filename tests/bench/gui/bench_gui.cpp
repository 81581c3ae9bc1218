// lkstudio's own cost, run as a user runs it: lksim serves N drives on a pseudo-terminal with
// the wire time of the baud (default 4 drives at 1 Mbaud), and the real lkstudio binary
// (offscreen) connects to it, scans and polls at the bus's full rate with every signal of every
// drive plotted (--plot-all). The figures come from /proc: CPU time (user + system, every
// thread of the process) over the measured window, and the resident set at its end.
//
// Scenarios, each a fresh lkstudio:
//   plots      the Plots view shown, every signal of every drive
//   other_tab  the same plots exist but the Dashboard is shown
//   minimized  the Plots view, window minimised
//   views_cycling  every signal plotted, the next view shown every second (GUI actions)
//   plots_32   32 drives, Plots view, every signal (only with --drives32)
//
// With --can, on CAN at 1 Mbit/s instead, 4 drives (two old CAN, two V2.36), Plots view,
// every signal of every drive plotted:
//   can_sim     lkstudio --can sim: the built-in simulated CAN bus, as a user starts it; the
//               figure is the whole process: GUI, bus thread and the four simulated drives
//   can_virtual lksim --can on Qt's virtualcan (wire time, the V2.36 0.25 ms reply) and
//               lkstudio --can virtualcan:...: the GUI's own cost, no simulator inside it,
//               and the poll rate on the wire, counted by a listening node of this bench
//
// Prints one JSON line:
//   gui_cpu_pct_<scenario>   CPU time of lkstudio / wall time, % of one core
//   gui_thread_cpu_pct_<scenario>, bus_thread_cpu_pct_<scenario>   the same for its GUI
//                            (main) thread and its bus thread ("lk-bus") alone
//   gui_rss_mb_<scenario>    resident memory at the end of the window
//   bus_replies_per_s_<scenario>  replies lksim sent per second (what was being plotted)
//   bus_gaps_over_100ms_<scenario>  silences over 100 ms between requests in the window:
//                            the bus paused (a GUI action must not pause it)
//   bus_longest_gap_ms_<scenario>   the longest silence between requests of the whole run
//   gui_rss_mb_series        with --rss-minutes M: RSS every 30 s of an M-minute plots run,
//                            to show where memory levels off (the 10-minute window fills)
//   can_txn_per_s_can_virtual   request-reply pairs per second on the virtual CAN wire
//   can_limit_per_s          LinkTiming's CAN limit at the bit rate (8-byte frames with
//                            worst-case stuffing, 0.25 ms reply): a ratio of 1 is a full bus
//   can_poll_ratio_can_virtual  the two above divided
//
// Options: --seconds S (measured window, default 20), --warmup S (default 8), --drives32,
// --rss-minutes M, --baud N, --can, --only NAME (that scenario alone).

#include "BenchUtil.h"
#include "CanLksim.h"
#include "CanSniffer.h"
#include "LksimProcess.h"

#include <bus/LinkTiming.h>

#include <QtCore/QCommandLineParser>
#include <QtCore/QDir>
#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>

#include <unistd.h>

using namespace lk;

namespace {

struct Usage {
    double cpuSeconds = 0; ///< user + system of every thread
    double rssMb = 0;
    double guiThreadSeconds = 0; ///< of the main thread (the GUI's)
    double busThreadSeconds = 0; ///< of the thread named "lk-bus" (the bus engine's)
};

/// utime + stime of a /proc stat line (fields 14, 15, after the parenthesised name).
std::optional<double> cpuSecondsOf(const QString &statPath)
{
    QFile stat(statPath);
    if (!stat.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QByteArray line = stat.readAll();
    const QList<QByteArray> f = line.mid(line.lastIndexOf(')') + 2).split(' ');
    if (f.size() < 13)
        return std::nullopt;
    return (f[11].toLongLong() + f[12].toLongLong()) / double(sysconf(_SC_CLK_TCK));
}

/// The process's CPU time (every thread), its GUI and bus threads' and its VmRSS.
std::optional<Usage> usageOf(qint64 pid)
{
    const QString proc = QStringLiteral("/proc/%1").arg(pid);
    QFile status(proc + QStringLiteral("/status"));
    const auto all = cpuSecondsOf(proc + QStringLiteral("/stat"));
    if (!all || !status.open(QIODevice::ReadOnly))
        return std::nullopt;
    Usage u;
    u.cpuSeconds = *all;
    for (const QByteArray &l : status.readAll().split('\n')) {
        if (l.startsWith("VmRSS:"))
            u.rssMb = l.mid(6).trimmed().split(' ').value(0).toDouble() / 1024.0;
    }
    const QString tasks = proc + QStringLiteral("/task/");
    for (const QString &tid : QDir(tasks).entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile comm(tasks + tid + QStringLiteral("/comm"));
        const QByteArray name = comm.open(QIODevice::ReadOnly) ? comm.readAll().trimmed() : "";
        const double t = cpuSecondsOf(tasks + tid + QStringLiteral("/stat")).value_or(0);
        if (tid.toLongLong() == pid)
            u.guiThreadSeconds = t;
        else if (name == "lk-bus")
            u.busThreadSeconds += t;
    }
    return u;
}

QString motors(int count)
{
    static const char *const kSeries[] = {"MF", "MG", "MS", "MH"};
    QStringList list;
    for (int id = 1; id <= count; ++id)
        list << QStringLiteral("%1:%2").arg(id).arg(QLatin1String(kSeries[(id - 1) % 4]));
    return list.join(QLatin1Char(','));
}

enum class Bus {
    Rs485Pty,   ///< lksim on a pseudo-terminal, lkstudio --port
    CanSim,     ///< lkstudio --can sim: the simulated drives inside lkstudio
    CanVirtual, ///< lksim --can on virtualcan, lkstudio --can virtualcan:...
};

struct Scenario {
    QString name;
    int drives = 4;
    QString view = QStringLiteral("plots");
    bool minimized = false;
    int cycleViewsMs = 0; ///< lkstudio --cycle-views: GUI actions beside the polling
    Bus bus = Bus::Rs485Pty;
};

/// Two drives of each CAN generation (docs/CAN.md): lksim's words and the built-in spec's.
const char kCanMotors[] = "1:MG@can,2:MF@can,3:MG@can236,4:MF@can236";
const char kCanSimSpec[] = "1:MG,2:MF,3:MG@2.35,4:MF@2.35";
constexpr int kCanBitRate = 1000000;

struct Options {
    int seconds = 20;
    int warmup = 8;
    int baud = 1000000;
};

/// The bus of `sc` started and lkstudio's arguments for it; false (said why) if it failed.
bool startBus(const Scenario &sc, const Options &o, e2e::LksimProcess &sim, e2e::CanLksim &canSim,
              e2e::CanSniffer &wire, QStringList *args)
{
    switch (sc.bus) {
    case Bus::Rs485Pty:
        if (!sim.start({QStringLiteral("--motors"), motors(sc.drives),
                        QStringLiteral("--wire-time"), QStringLiteral("--baud"),
                        QString::number(o.baud)})) {
            std::fprintf(stderr, "bench_gui: lksim: %s\n", qPrintable(sim.errorString()));
            return false;
        }
        *args << QStringLiteral("--port") << sim.devicePath() << QStringLiteral("--baud")
              << QString::number(o.baud);
        return true;
    case Bus::CanSim:
        *args << QStringLiteral("--can") << QStringLiteral("sim") << QStringLiteral("--bitrate")
              << QString::number(kCanBitRate) << QStringLiteral("--sim")
              << QString::fromLatin1(kCanSimSpec);
        return true;
    case Bus::CanVirtual: {
        const QString failed =
            canSim.start(QString::fromLatin1(kCanMotors),
                         {QStringLiteral("--wire-time"), QStringLiteral("--bitrate"),
                          QString::number(kCanBitRate), QStringLiteral("--reply-delay-us"),
                          QString::number(qRound(bus::LinkTiming::kCanReplyTimeS * 1e6))});
        if (!failed.isEmpty()) {
            std::fprintf(stderr, "bench_gui: lksim --can: %s\n", qPrintable(failed));
            return false;
        }
        if (!wire.open(canSim.url().mid(QStringLiteral("virtualcan:").size()))) {
            std::fprintf(stderr, "bench_gui: cannot listen on %s\n", qPrintable(canSim.url()));
            return false;
        }
        *args << canSim.can() << QStringLiteral("--bitrate") << QString::number(kCanBitRate);
        return true;
    }
    }
    return false;
}

/// One lkstudio on one bus: CPU and RSS over the window. `each30s` gets the RSS every 30 s.
bool measure(const Scenario &sc, const Options &o, bench::JsonLine &json,
             const std::function<void(double)> &each30s = {})
{
    e2e::LksimProcess sim(QStringLiteral(LKSIM_PATH));
    e2e::CanLksim canSim;
    e2e::CanSniffer wire; // a third node on the virtual bus: what the wire carried
    QTemporaryDir dir;
    QStringList args{QStringLiteral("--settings"), dir.filePath(QStringLiteral("lkstudio.ini"))};
    if (!startBus(sc, o, sim, canSim, wire, &args))
        return false;
    args << QStringLiteral("--view") << sc.view << QStringLiteral("--plot-all")
         << QStringLiteral("--window-size") << QStringLiteral("1400x900");
    if (sc.minimized)
        args << QStringLiteral("--minimized");
    if (sc.cycleViewsMs > 0)
        args << QStringLiteral("--cycle-views") << QString::number(sc.cycleViewsMs);
    QProcess studio;
    auto env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("XDG_STATE_HOME"), dir.path());
    studio.setProcessEnvironment(env);
    studio.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    studio.setStandardOutputFile(QProcess::nullDevice());
    studio.start(QStringLiteral(LKSTUDIO_PATH), args);
    if (!studio.waitForStarted()) {
        std::fprintf(stderr, "bench_gui: lkstudio did not start\n");
        return false;
    }
    bench::spin(o.warmup * 1000);
    const qint64 pid = studio.processId();
    const bool rs485 = sc.bus == Bus::Rs485Pty;
    const auto countsBefore = rs485 ? sim.currentCounters() : std::nullopt;
    wire.clear(); // the window starts now
    const auto before = usageOf(pid);
    QElapsedTimer wall;
    wall.start();
    for (int left = o.seconds; left > 0; left -= 30) {
        bench::spin(std::min(left, 30) * 1000);
        if (each30s) {
            if (const auto u = usageOf(pid))
                each30s(u->rssMb);
        }
    }
    const auto after = usageOf(pid);
    const double seconds = wall.elapsed() / 1e3;
    const auto countsAfter = rs485 ? sim.currentCounters() : std::nullopt;
    const qint64 frames = wire.frames().size();
    studio.terminate();
    studio.waitForFinished(10000);
    sim.stop();
    canSim.stop();
    if (!before || !after) {
        std::fprintf(stderr, "bench_gui: lkstudio ended during the measurement\n");
        return false;
    }
    json.add(QStringLiteral("gui_cpu_pct_") + sc.name,
             100.0 * (after->cpuSeconds - before->cpuSeconds) / seconds, 1);
    json.add(QStringLiteral("gui_thread_cpu_pct_") + sc.name,
             100.0 * (after->guiThreadSeconds - before->guiThreadSeconds) / seconds, 1);
    json.add(QStringLiteral("bus_thread_cpu_pct_") + sc.name,
             100.0 * (after->busThreadSeconds - before->busThreadSeconds) / seconds, 1);
    json.add(QStringLiteral("gui_rss_mb_") + sc.name, after->rssMb, 1);
    if (countsBefore && countsAfter) {
        json.add(QStringLiteral("bus_replies_per_s_") + sc.name,
                 (countsAfter->replies - countsBefore->replies) / seconds, 1);
        // Pauses of the bus as lksim saw them: silences over 100 ms between requests in the
        // window, and the longest silence of the whole run (warm-up and scan included).
        json.addInt(QStringLiteral("bus_gaps_over_100ms_") + sc.name,
                    countsAfter->requestGapsOver100ms - countsBefore->requestGapsOver100ms);
        json.add(QStringLiteral("bus_longest_gap_ms_") + sc.name, countsAfter->longestRequestGapMs,
                 1);
    }
    if (sc.bus == Bus::CanVirtual) {
        // Every request is answered by one frame: a transaction is two frames on the wire.
        const double txn = frames / 2.0 / seconds;
        const double limit = bus::LinkTiming::can(kCanBitRate)
                                 .transactionsPerSecond({protocol::Command::ReadState2});
        json.add(QStringLiteral("can_txn_per_s_") + sc.name, txn, 1);
        json.add(QStringLiteral("can_limit_per_s"), limit, 0);
        json.add(QStringLiteral("can_poll_ratio_") + sc.name, txn / limit, 3);
    }
    return true;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCommandLineParser p;
    const QCommandLineOption seconds(QStringLiteral("seconds"), QStringLiteral("window"),
                                     QStringLiteral("S"), QStringLiteral("20"));
    const QCommandLineOption warmup(QStringLiteral("warmup"), QStringLiteral("warm-up"),
                                    QStringLiteral("S"), QStringLiteral("8"));
    const QCommandLineOption baud(QStringLiteral("baud"), QStringLiteral("baud"),
                                  QStringLiteral("N"), QStringLiteral("1000000"));
    const QCommandLineOption drives32(QStringLiteral("drives32"), QStringLiteral("32 drives"));
    const QCommandLineOption rss(QStringLiteral("rss-minutes"), QStringLiteral("long run"),
                                 QStringLiteral("M"));
    const QCommandLineOption can(QStringLiteral("can"), QStringLiteral("CAN at 1 Mbit/s"));
    const QCommandLineOption only(QStringLiteral("only"), QStringLiteral("one scenario"),
                                  QStringLiteral("NAME"));
    p.addOptions({seconds, warmup, baud, drives32, rss, can, only});
    p.process(app);
    Options o;
    o.seconds = std::max(1, p.value(seconds).toInt());
    o.warmup = std::max(0, p.value(warmup).toInt());
    o.baud = p.value(baud).toInt();

    bench::JsonLine json;
    if (p.isSet(can)) {
        json.addInt(QStringLiteral("can_bit_rate"), kCanBitRate);
        Scenario builtIn{QStringLiteral("can_sim")};
        builtIn.bus = Bus::CanSim;
        Scenario virtualBus{QStringLiteral("can_virtual")};
        virtualBus.bus = Bus::CanVirtual;
        for (const Scenario &sc : {builtIn, virtualBus}) {
            if (p.isSet(only) && sc.name != p.value(only))
                continue;
            if (!measure(sc, o, json))
                return 1;
        }
        json.print();
        return 0;
    }
    json.addInt(QStringLiteral("baud"), o.baud);
    if (p.isSet(rss)) {
        Options longRun = o;
        longRun.seconds = std::max(1, p.value(rss).toInt()) * 60;
        QStringList series;
        if (!measure({QStringLiteral("plots_long")}, longRun, json,
                     [&series](double mb) { series << QString::number(mb, 'f', 1); }))
            return 1;
        json.addRaw(QStringLiteral("gui_rss_mb_series"),
                    QLatin1Char('[') + series.join(QLatin1Char(',')) + QLatin1Char(']'));
        json.print();
        return 0;
    }
    QVector<Scenario> scenarios{
        {QStringLiteral("plots")},
        {QStringLiteral("other_tab"), 4, QStringLiteral("dashboard")},
        {QStringLiteral("minimized"), 4, QStringLiteral("plots"), true},
        {QStringLiteral("views_cycling"), 4, QStringLiteral("plots"), false, 1000}};
    if (p.isSet(drives32))
        scenarios.append({QStringLiteral("plots_32"), 32});
    for (const Scenario &sc : scenarios) {
        if (p.isSet(only) && sc.name != p.value(only))
            continue;
        if (!measure(sc, o, json))
            return 1;
    }
    json.print();
    return 0;
}
