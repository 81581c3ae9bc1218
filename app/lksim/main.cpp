// lksim: a simulated bus of LK drives served on a new pseudo-terminal (CLI.md "lksim").

#include "CanBusServer.h"
#include "PtyBusServer.h"
#include "PtyDevice.h"
#include "TapBusServer.h"

#include <bus/BusTiming.h>
#include <bus/LinkTiming.h>
#include <protocol/CanLayout.h>
#include <protocol/Command.h>
#include <sim/ControllerSpec.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <sim/SimParamsSeed.h>

#include <system/LocalTimeZone.h>

#include <QtCore/QCommandLineParser>
#include <QtCore/QCoreApplication>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <sys/prctl.h>

namespace {

std::atomic<bool> g_stop{false};
std::atomic<bool> g_dumpStats{false};

void onSignal(int)
{
    g_stop.store(true);
}

void onDumpSignal(int)
{
    g_dumpStats.store(true);
}

void installSignalHandlers()
{
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; // no SA_RESTART: ppoll must return EINTR so the loop sees the flag
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    sa.sa_handler = onDumpSignal;
    sigaction(SIGUSR1, &sa, nullptr);
    signal(SIGPIPE, SIG_IGN);
}

int fail(const QString &message)
{
    std::fprintf(stderr, "lksim: %s\n", qPrintable(message));
    return 2;
}

/// What --can adds to the drives: where, how fast, and a foreign master if any.
struct CanServe {
    QString where;
    QString rateText;
    QString baseText;
    bool wireTime = false;
    bool verbose = false;
    std::optional<lk::sim::ControllerSpec> controller;
    QString controllerLog;
};

/// A poll command of --controller that neither CAN generation has (read_model), named.
QString notOnCan(const lk::sim::ControllerSpec &spec)
{
    using lk::protocol::DecodeContext;
    using lk::protocol::Generation;
    for (const lk::protocol::Command c : spec.poll) {
        const bool onCan = lk::protocol::CommandTable::availableOn(
                               c, DecodeContext{{}, Generation::V2_3, lk::protocol::Link::Can}) ||
                           lk::protocol::CommandTable::availableOn(
                               c, DecodeContext{{}, Generation::V2_35, lk::protocol::Link::Can});
        if (!onCan)
            return lk::protocol::CommandTable::name(c);
    }
    return {};
}

/// lksim --can: the drives on a CAN interface until SIGINT/SIGTERM (CanBusServer).
int serveCan(lk::sim::SimBus &bus, const lk::sim::SimBusSpec &spec, const CanServe &serve)
{
    const QString &where = serve.where;
    const QString &rateText = serve.rateText;
    const QString &baseText = serve.baseText;
    const qsizetype colon = where.indexOf(QLatin1Char(':'));
    if (colon <= 0)
        return fail(QStringLiteral("--can takes PLUGIN:INTERFACE, e.g. virtualcan:can0"));
    bool ok = false;
    const int rate = rateText.toInt(&ok);
    if (!ok || !lk::bus::LinkTiming::isCanBitRate(rate))
        return fail(QStringLiteral("--bitrate must be 1000000, 500000, 250000, 125000 or 100000"));
    lk::app::CanBusServer::Options o;
    o.can.plugin = where.left(colon);
    o.can.interfaceName = where.mid(colon + 1);
    o.can.bitRate = rate;
    o.emulateWireTime = serve.wireTime;
    o.verbose = serve.verbose;
    o.controller = serve.controller;
    o.controllerLog = serve.controllerLog;
    lk::app::CanBusServer server(bus, o);
    if (baseText == QLatin1String("140"))
        server.front().setReplyBase(lk::protocol::can::IdBase::Base140);
    else if (baseText == QLatin1String("180"))
        server.front().setReplyBase(lk::protocol::can::IdBase::Base180);
    else if (!baseText.isEmpty())
        return fail(QStringLiteral("--can-reply-base is 140 or 180"));
    if (!server.open())
        return 2;
    installSignalHandlers();
    std::printf("%s\n", qPrintable(where));
    std::fflush(stdout);
    std::fprintf(
        stderr, "lksim: %s on CAN %s at %d bit/s%s\n", qPrintable(spec.toString()),
        qPrintable(where), rate,
        serve.controller
            ? qPrintable(QStringLiteral(", controller %1").arg(serve.controller->toString()))
            : "");
    const int rc = server.run(g_stop);
    std::fprintf(stderr, "%s\n", qPrintable(server.summary()));
    return rc;
}

bool isLkBaud(int baud)
{
    for (int b : lk::bus::BusTiming::standardBauds()) {
        if (b == baud)
            return true;
    }
    return false;
}

} // namespace

int main(int argc, char *argv[])
{
    lk::system::LocalTimeZone::readOnce(); // before any thread: Qt's CAN plugins stamp frames
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("lksim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LK_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Serves a simulated RS485 bus of LK-TECH drives on a new pseudo-terminal.\n"
        "The device path is printed as the first line of standard output; open it with\n"
        "lkctl --port PATH, lkstudio --port PATH or any serial program. Runs until SIGINT or\n"
        "SIGTERM.\n\n"
        "Collisions: RS485 is half duplex. A request that arrives while a drive is about to\n"
        "answer (after it was asked) or while its reply is still on the wire would corrupt\n"
        "both frames on a real bus. lksim counts each such request as a collision, logs it\n"
        "on standard error (\"lksim: collision: request ... arrived ...\"), prints a summary\n"
        "line on exit (\"lksim: N requests, N replies, N collisions ...\") and keeps the\n"
        "counts in --stats-file. A request that overlaps a reply only because lksim may have\n"
        "read the request that asked for it late (a loaded machine; with --measure-pty-lag\n"
        "also when the kernel held the host's bytes in the pty), or that came in one read\n"
        "with the request the reply answers, is logged as an\n"
        "\"unjudged overlap\" and counted apart. Without --wire-time a reply is on the wire\n"
        "for an instant, --reply-delay-us after its request.\n\n"
        "Example:\n"
        "  lksim --motors 3:MF,17:MS,32:MG --link /tmp/lkbus --wire-time --baud 115200\n"
        "  lkctl scan --port /tmp/lkbus"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption motors(
        QStringLiteral("motors"),
        QStringLiteral("Drives on the bus: ID:SERIES[,ID:SERIES...], ID 1..32, series MS, MF, "
                       "MG or MH; a motor name may stand for the series (5:MG5010E-i36). "
                       "@2.35 after the model makes a firmware-2.35 drive speaking protocol "
                       "V2.35 (1:MS4015@2.35). Firmware quirks seen on real drives may follow: "
                       "3:MF+accel-ignored "
                       "(0x34 acknowledged, not applied, 0x33 reads 0), "
                       "+clear-angle-ignored (0x95 acknowledged, angle unchanged); for tests, "
                       "+param-write-refused (a V2.35 drive answers 0x42/0x44 with the "
                       "failure flag and changes nothing)."),
        QStringLiteral("spec"));
    const QCommandLineOption link(QStringLiteral("link"),
                                  QStringLiteral("Also make PATH a symlink to the device."),
                                  QStringLiteral("path"));
    const QCommandLineOption baud(QStringLiteral("baud"),
                                  QStringLiteral("Baud for wire-time emulation (default 115200)."),
                                  QStringLiteral("n"), QStringLiteral("115200"));
    const QCommandLineOption wireTime(
        QStringLiteral("wire-time"),
        QStringLiteral("Delay replies by the time request and reply take on a real 8N1 wire "
                       "at --baud, so that timing resembles a real bus."));
    const QCommandLineOption replyDelay(
        QStringLiteral("reply-delay-us"),
        QStringLiteral("The drives' turnaround before replying, microseconds (default 200; "
                       "real drives answer within 500)."),
        QStringLiteral("us"), QStringLiteral("200"));
    const QCommandLineOption romDir(
        QStringLiteral("rom-dir"),
        QStringLiteral("Persist each drive's ROM (PID, zero) in DIR, so ROM writes survive a "
                       "restart of lksim. Without it ROM lives in memory only."),
        QStringLiteral("dir"));
    // Distinct parameters per drive, so that a bus has something to compare and restore.
    const QCommandLineOption paramSeed(
        QStringLiteral("param-seed"),
        QStringLiteral("Give each drive distinct PID gains, acceleration, encoder zero and "
                       "(V2.35) limits, derived from N and its ID (the same N gives the same "
                       "values). A drive whose ROM is stored in --rom-dir keeps it; the seeded "
                       "values are stored there, so they persist."),
        QStringLiteral("n"));
    parser.addOption(paramSeed);
    const QCommandLineOption faults(
        QStringLiteral("faults"),
        QStringLiteral("Inject faults: comma-separated drop=P, corrupt=P, length=P, garbage=P, "
                       "delay=P (P = probability 0..1 per reply), drop_next=N (and corrupt_next, "
                       "...: exactly the next N replies), delay_ms=N, silent=ID (repeatable), "
                       "seed=N. Example: drop=0.01,corrupt=0.01,silent=17"),
        QStringLiteral("spec"));
    const QCommandLineOption fault(
        QStringLiteral("fault"),
        QStringLiteral(
            "A drive raises a protection fault by itself: ID:FAULT[@START[-END]], "
            "comma-separated, repeatable. FAULT is an error flag of the drive's generation: "
            "V2.3 low_voltage, over_temperature; V2.35 low_voltage, over_voltage, "
            "driver_over_temperature, motor_over_temperature (or over_temperature), "
            "over_current, short_circuit, stall, input_timeout. START and END are seconds "
            "after lksim started (\"5s\" or \"5\"): the cause appears at START (default "
            "0) and goes at END (default: never). The flag latches in 0x9A, the drive stops "
            "as a real one does (motion ends; a V2.35 drive's motor state reads off until "
            "0x88), and 0x9B clears the flag once its cause has gone. Low and over voltage "
            "show in the supply voltage, over-temperature in the motor temperature. "
            "In --motors and in lkctl/lkstudio --sim the same is written "
            "ID:MODEL+fault=FAULT[@START[-END]]. Example: --fault 1:over_temperature@5s,"
            "2:stall@2-4s"),
        QStringLiteral("spec"));
    const QCommandLineOption badChecksumPct(
        QStringLiteral("bad-checksum-pct"),
        QStringLiteral("Copy firmware 2.35's bug: about P % (0..100, default 0) of the 0xA4 "
                       "replies of @2.35 drives carry a data checksum off by 3 (the header is "
                       "good); real drives do it to ~1 %. Counted as bad_checksum_replies in "
                       "--stats-file; deterministic for a --faults seed=N (default 1)."),
        QStringLiteral("p"), QStringLiteral("0"));
    const QCommandLineOption verbose(QStringLiteral("verbose"),
                                     QStringLiteral("Log every frame in and out on stderr."));
    const QCommandLineOption busyPoll(
        QStringLiteral("busy-poll"),
        QStringLiteral("Spin instead of sleeping while the host is polling (for benchmarks at "
                       "high baud: a sleeping process wakes 30-100 us late). Uses one CPU core "
                       "while requests keep coming."));
    const QCommandLineOption measurePtyLag(
        QStringLiteral("measure-pty-lag"),
        QStringLiteral("Time how long the kernel holds the host's bytes before lksim can read "
                       "them, with a canary byte through a second pseudo-terminal every "
                       "0.5 ms: on a loaded machine that hold reaches milliseconds, and a "
                       "request overlapping a reply within it is an unjudged overlap, not a "
                       "collision. For tests on busy machines; wakes lksim 2000 times a "
                       "second."));
    const QCommandLineOption adapterLatency(
        QStringLiteral("adapter-latency-us"),
        QStringLiteral("The host receives each reply this many microseconds after its last "
                       "byte left the wire, as behind a USB adapter's latency timer (FTDI: "
                       "up to 16000). The wire is free meanwhile. Default 0."),
        QStringLiteral("us"), QStringLiteral("0"));
    const QCommandLineOption statsFile(
        QStringLiteral("stats-file"),
        QStringLiteral("Keep the counters in PATH as one line of JSON: {\"requests\":N,"
                       "\"replies\":N,\"collisions\":N,\"collisions_before_reply\":N,"
                       "\"collisions_during_reply\":N,\"overlaps_unjudged\":N,"
                       "\"longest_request_gap_ms\":X,\"request_gaps_over_100ms\":N,"
                       "\"bad_checksum_replies\":N,"
                       "\"running\":true}. Rewritten whole at "
                       "start, after every collision (the collision count is always current), "
                       "on SIGUSR1 (all counters current) and at exit (\"running\":false)."),
        QStringLiteral("path"));
    parser.addOptions({motors, fault, link, baud, wireTime, replyDelay, adapterLatency, romDir,
                       faults, badChecksumPct, busyPoll, measurePtyLag, statsFile, verbose});
    // --controller: a simulated foreign master drives the bus; the pty is a tap (TapBusServer).
    const QCommandLineOption controller(
        QStringLiteral("controller"),
        QStringLiteral("A simulated foreign master drives the bus, and the device carries what "
                       "an RS485 tap sees: its requests and the drives' replies in bus order, "
                       "timed at --baud (wire time implied). SPEC: comma-separated rate=HZ|max "
                       "(requests per second, default 100), ids=LIST (1-4:17; default every "
                       "drive), poll=LIST|none (reads by code or name, 9c:9a:92; default 9c), "
                       "speed=sine:AMPdps:FREQHz (a speed setpoint per drive and round), "
                       "move=every:PERIODs[:STEPdeg][:MAXdps] (an incremental move of +STEP, "
                       "then -STEP; default 90deg, 360dps), timeout=Nms (default 5ms). The "
                       "tool on the device should only listen: bytes it writes are a second "
                       "master (a collision over the controller's frames, logged). --faults "
                       "and --fault apply. With --can the master is a node of the CAN bus: its "
                       "requests go on 0x140+ID in each drive's CAN layout, and its frames and the "
                       "drives' replies (a corrupted one never comes) go on the bus in order "
                       "(wire time at --bitrate), for a listener there; a V2.36 "
                       "drive's speed setpoint carries the torque limit 2048; read_model "
                       "cannot be polled. Example: rate=200,ids=1-4,poll=9c:9a:92,"
                       "speed=sine:300dps:0.5Hz,move=every:5s"),
        QStringLiteral("spec"));
    const QCommandLineOption controllerLog(
        QStringLiteral("controller-log"),
        QStringLiteral("With --controller: write each of its requests, when it is done, as one "
                       "JSON line to PATH: {\"time_s\",\"id\",\"command\",\"code\","
                       "\"request\":{fields},\"outcome\":answered|unanswered|dropped|garbled|"
                       "collided[,\"reply_s\"][,\"noise_bytes\"][,\"reply\":{fields}]}, "
                       "fields as lkctl decode writes them."),
        QStringLiteral("path"));
    parser.addOption(controller);
    parser.addOption(controllerLog);
    // --can: the drives on a CAN interface instead of a pty (CanBusServer).
    const QCommandLineOption can(
        QStringLiteral("can"),
        QStringLiteral("Serve the drives on CAN through Qt SerialBus instead of a pty: "
                       "virtualcan:tcp://127.0.0.1:PORT/can0 (a port of one's own), "
                       "socketcan:vcan0. In --motors, @can makes an old CAN drive, @can236 a "
                       "V2.36 one (replies on 0x180+ID)."),
        QStringLiteral("PLUGIN:INTERFACE"));
    const QCommandLineOption bitRate(QStringLiteral("bitrate"),
                                     QStringLiteral("CAN bit rate (default 1000000)."),
                                     QStringLiteral("N"), QStringLiteral("1000000"));
    const QCommandLineOption replyBase(
        QStringLiteral("can-reply-base"),
        QStringLiteral("Answer on 0x140+ID or 0x180+ID whatever the generation (140 or 180); "
                       "default: as each generation's document says."),
        QStringLiteral("BASE"));
    parser.addOptions({can, bitRate, replyBase});
    parser.process(app);

    if (!parser.isSet(motors))
        return fail(QStringLiteral("--motors is required, e.g. --motors 1:MF,2:MS"));
    QString error;
    std::optional<lk::sim::SimBusSpec> spec =
        lk::sim::SimBusSpec::parse(parser.value(motors), &error);
    if (!spec)
        return fail(error);
    for (const QString &faultSpec : parser.values(fault)) {
        if (!spec->addFaults(faultSpec, &error))
            return fail(QStringLiteral("--fault: %1").arg(error));
    }
    bool ok = false;
    const int baudValue = parser.value(baud).toInt(&ok);
    if (!ok || !isLkBaud(baudValue))
        return fail(QStringLiteral("--baud must be one of 9600, 19200, 38400, 57600, 115200, "
                                   "230400, 460800, 1000000, 2000000, 4000000"));
    const int delayUs = parser.value(replyDelay).toInt(&ok);
    if (!ok || delayUs < 0 || delayUs > 1000000)
        return fail(QStringLiteral("--reply-delay-us must be 0..1000000"));
    const int latencyUs = parser.value(adapterLatency).toInt(&ok);
    if (!ok || latencyUs < 0 || latencyUs > 1000000)
        return fail(QStringLiteral("--adapter-latency-us must be 0..1000000"));

    std::optional<lk::sim::ControllerSpec> controllerSpec;
    if (parser.isSet(controller)) {
        controllerSpec = lk::sim::ControllerSpec::parse(parser.value(controller), &error);
        if (!controllerSpec)
            return fail(error);
        if (parser.isSet(busyPoll) || parser.isSet(measurePtyLag))
            return fail(QStringLiteral("--busy-poll and --measure-pty-lag time a host's "
                                       "requests; with --controller nobody asks on the pty"));
    } else if (parser.isSet(controllerLog)) {
        return fail(QStringLiteral("--controller-log needs --controller"));
    }

    std::unique_ptr<lk::sim::SimBus> bus = lk::sim::SimBus::fromSpec(*spec, parser.value(romDir));
    bus->setReplyDelay(delayUs * 1e-6);
    for (const QString &e : bus->romStore().errors())
        std::fprintf(stderr, "lksim: %s\n", qPrintable(e));
    if (parser.isSet(paramSeed)) {
        const uint seed = parser.value(paramSeed).toUInt(&ok);
        if (!ok)
            return fail(QStringLiteral("--param-seed must be a number 0..4294967295"));
        lk::sim::SimParamsSeed::apply(*bus, seed);
    }
    if (parser.isSet(faults) && !bus->faults().configure(parser.value(faults), &error))
        return fail(QStringLiteral("--faults: %1").arg(error));
    const double badChecksum = parser.value(badChecksumPct).toDouble(&ok);
    if (!ok || !(badChecksum >= 0 && badChecksum <= 100))
        return fail(QStringLiteral("--bad-checksum-pct must be a percentage 0..100, got '%1'")
                        .arg(parser.value(badChecksumPct)));
    bus->faults().setProbability(lk::sim::Fault::FirmwareChecksum, badChecksum / 100.0);

    if (parser.isSet(can)) {
        if (controllerSpec && !notOnCan(*controllerSpec).isEmpty())
            return fail(QStringLiteral("--controller poll=%1: CAN has no such read")
                            .arg(notOnCan(*controllerSpec)));
        CanServe serve;
        serve.where = parser.value(can);
        serve.rateText = parser.value(bitRate);
        serve.baseText = parser.value(replyBase);
        serve.wireTime = parser.isSet(wireTime);
        serve.verbose = parser.isSet(verbose);
        serve.controller = controllerSpec;
        serve.controllerLog = parser.value(controllerLog);
        return serveCan(*bus, *spec, serve);
    }

    lk::app::PtyDevice pty;
    if (!pty.open())
        return fail(pty.errorString());
    if (parser.isSet(link) && !pty.linkTo(parser.value(link)))
        return fail(pty.errorString());

    installSignalHandlers();
    prctl(PR_SET_TIMERSLACK, 1UL); // sub-millisecond reply timing needs a tight timer slack

    if (controllerSpec) {
        lk::app::TapBusServer::Options tapOptions;
        tapOptions.baud = baudValue;
        tapOptions.adapterLatencyS = latencyUs * 1e-6;
        tapOptions.verbose = parser.isSet(verbose);
        tapOptions.statsFile = parser.value(statsFile);
        tapOptions.logFile = parser.value(controllerLog);
        lk::app::TapBusServer tap(pty, *bus, *controllerSpec, tapOptions);
        if (!tap.open())
            return 2;
        std::printf("%s\n", qPrintable(pty.slavePath()));
        std::fflush(stdout);
        std::fprintf(stderr, "lksim: %s on %s, controller %s at %d baud\n",
                     qPrintable(spec->toString()), qPrintable(pty.slavePath()),
                     qPrintable(controllerSpec->toString()), baudValue);
        const int rc = tap.run(g_stop, g_dumpStats);
        pty.close();
        std::fprintf(stderr, "%s\n", qPrintable(tap.summary()));
        return rc;
    }

    lk::app::PtyBusServer::Options options;
    options.baud = baudValue;
    options.emulateWireTime = parser.isSet(wireTime);
    options.verbose = parser.isSet(verbose);
    options.busyPoll = parser.isSet(busyPoll);
    options.adapterLatencyS = latencyUs * 1e-6;
    options.ptyLagProbePeriodS = parser.isSet(measurePtyLag) ? 0.0005 : 0;
    options.statsFile = parser.value(statsFile);
    lk::app::PtyBusServer server(pty, *bus, options);
    if (!server.writeStats(true))
        return 2; // before the path is printed: a test never waits on a file that is not there
    std::printf("%s\n", qPrintable(pty.slavePath()));
    std::fflush(stdout);
    std::fprintf(
        stderr, "lksim: %s on %s%s\n", qPrintable(spec->toString()), qPrintable(pty.slavePath()),
        parser.isSet(wireTime) ? qPrintable(QStringLiteral(", wire time at %1 baud").arg(baudValue))
                               : "");

    const int rc = server.run(g_stop, g_dumpStats);
    pty.close();
    const lk::app::WireCounters &c = server.counters();
    std::fprintf(stderr,
                 "lksim: %lld requests, %lld replies, %lld collisions (%lld before a reply "
                 "began, %lld during one), %lld unjudged overlaps, longest silence between "
                 "requests %.1f ms (%lld over 100 ms), %lld bad-checksum 0xA4 replies\n",
                 c.requests, c.replies, c.collisions(), c.collisionsBefore, c.collisionsDuring,
                 c.overlapsUnjudged, c.longestRequestGapS * 1e3, c.requestGapsOver100ms,
                 server.badChecksumReplies());
    return rc;
}
