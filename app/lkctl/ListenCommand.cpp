#include "ListenCommand.h"

#include "Console.h"
#include "ListenTable.h"
#include "LiveBus.h"
#include "StreamEnd.h"

#include <protocol/CanRecord.h>
#include <protocol/Command.h>

#include <csignal>

namespace lk::lkctl {

QString ListenCommand::summary() const
{
    return QStringLiteral("decode a bus another master drives, sending nothing");
}

QString ListenCommand::example() const
{
    return QStringLiteral("lkctl listen --port /dev/ttyUSB0 --baud 1000000 --json --duration 60");
}

QString ListenCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl listen --port DEV [--baud N] [--drives LIST] [--csv | --json]\n"
               "                    [--duration S]\n"
               "       lkctl listen --can PLUGIN:INTERFACE [--bitrate N] [--drives LIST] ...\n"
               "\n"
               "Watch a running machine's bus without taking part: another controller is the\n"
               "master, lkctl only listens. NOTHING is ever sent: the port is opened read-only,\n"
               "RTS and DTR are cleared where the driver allows (an adapter that switches its\n"
               "RS485 driver on RTS then never drives the bus), and the session refuses every\n"
               "transmission. Requests and replies arrive on one stream; each request is paired\n"
               "with its reply by order. Until Ctrl-C (SIGINT), SIGTERM or --duration, every\n"
               "reply that carries telemetry and every value the master commands (0xA0..0xA8)\n"
               "is printed as one row, in the long layout of `lkctl monitor`: time_s (when the\n"
               "frame arrived, seconds since the port opened), id, then every column; the\n"
               "commanded ones are commanded_iq_a, commanded_power, commanded_speed_dps,\n"
               "commanded_angle_deg (0xA3/0xA4), commanded_single_turn_deg and\n"
               "commanded_direction (0xA5/0xA6), commanded_increment_deg (0xA7/0xA8) and\n"
               "commanded_max_speed_dps (0xA4/0xA6/0xA8). Cells a frame does not carry are\n"
               "empty (JSON: no key).\n"
               "Then what the master did goes to standard error: requests and requests/s per\n"
               "drive and command, replies paired, requests left unanswered (its timeouts),\n"
               "echo frames that could be either way (counted, never guessed), checksum errors,\n"
               "bus load and reply latency per drive (approximate: frames are stamped when the\n"
               "adapter hands them over).\n"
               "\n"
               "Drives appear as they answer; their generation is learnt from a read_model\n"
               "reply or a command only one generation has, their series from a read_model\n"
               "reply. Until one passes, an MS drive's power reads as iq (iq_a): name its series\n"
               "with --drives. A V2.35 drive's read_state1 is read with V2.3's layout until a\n"
               "read_model reply or a V2.35-only command passes.\n"
               "\n"
               "On CAN (--can) the CAN transport sends nothing either. Requests travel on\n"
               "0x140+ID, replies on 0x140+ID (old generation) or 0x180+ID (V2.36): a frame on\n"
               "0x180+ID, or one whose bytes are no request's layout, is a reply; one with a\n"
               "request's layout on 0x140+ID is a request, unless it follows the open request\n"
               "of its command and ID within the reply window (an echo command's reply, the\n"
               "brake state after a read): told by order, as echo frames are on RS485. A reply\n"
               "on 0x180+ID, or a read_state1 reply whose layout only one generation has,\n"
               "names its drive's generation. The bus line counts frames, CAN error frames and\n"
               "frames on IDs that are no drive's (0x280 included).\n"
               "\n"
               "Options:\n"
               "  --csv               CSV, long layout (the default)\n"
               "  --json              JSON lines, the CSV's names as keys\n"
               "  --drives LIST       the series of drives until a read_model reply tells:\n"
               "                      ID:SERIES, comma-separated, e.g. 3:MG,17:MS\n"
               "  --duration S        stop after S seconds\n"
               "\n"
               "%1"
               "\n"
               "Examples:\n"
               "  lkctl listen --port /dev/ttyUSB0 --baud 1000000 > machine.csv   (Ctrl-C to "
               "stop)\n"
               "  lkctl listen --port ttyUSB0 --json --duration 60 | jq .speed_dps\n"
               "\n"
               "%2")
        .arg(BusOptions::helpText(false),
             exitStatusText(QStringLiteral("  A silent bus is no error: listen waits. --sim is "
                                           "refused (no other master there).\n")));
}

std::optional<ListenCommand::Plan> ListenCommand::parse(const ArgParser &parser, Console &console,
                                                        int *status) const
{
    const auto fail = [&](const QString &message) {
        *status = usageError(console, message);
        return std::nullopt;
    };
    Plan plan;
    QString error;
    if (!parser.positionals().isEmpty())
        return fail(QStringLiteral("listen takes no drive IDs: every drive that answers shows"));
    if (parser.isSet(QStringLiteral("duration"))) {
        plan.durationS = parser.numberValue(QStringLiteral("duration"), 0, &error);
        if (!plan.durationS)
            return fail(error);
    }
    const bool json = parser.isSet(QStringLiteral("json"));
    if (json && parser.isSet(QStringLiteral("csv")))
        return fail(QStringLiteral("--csv and --json exclude each other"));
    plan.format = json ? MonitorFormat::Json : MonitorFormat::CsvLong;
    if (parser.isSet(QStringLiteral("drives"))) {
        const std::optional<QVector<Drive>> drives =
            parseDrives(parser.value(QStringLiteral("drives")), &error);
        if (!drives)
            return fail(error);
        plan.drives = *drives;
    }
    return plan;
}

std::optional<QVector<ListenCommand::Drive>> ListenCommand::parseDrives(const QString &text,
                                                                        QString *error)
{
    QVector<Drive> drives;
    for (const QString &item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QStringList parts = item.split(QLatin1Char(':'));
        QString idError;
        const std::optional<int> id = parseId(parts.value(0), &idError);
        const std::optional<protocol::Series> series = protocol::seriesFromName(parts.value(1));
        if (parts.size() != 2 || !id || !series) {
            *error = QStringLiteral("--drives takes ID:SERIES, comma-separated (e.g. 3:MG,17:MS), "
                                    "not '%1'")
                         .arg(item);
            return std::nullopt;
        }
        drives.append(Drive{*id, *series});
    }
    return drives;
}

int ListenCommand::stream(LiveBus &bus, const Plan &plan, ListenTable &table)
{
    Console &console = bus.console();
    bus::BusSession &session = bus.session();
    StreamEnd end(bus, plan.durationS);
    qint64 rows = 0;
    bus::ListenStatistics stats;
    // The report gives the first snapshot that comes after the end, and no row is printed
    // after it: a batch emitted after that snapshot may hold replies it has not counted, and
    // one pass of the event loop can deliver both.
    bool reported = false;
    QObject context; // every connection below ends with it
    QObject::connect(&session, &bus::BusSession::listenStatisticsUpdated, &context,
                     [&](const bus::ListenStatistics &s) {
                         if (reported)
                             return;
                         stats = s;
                         reported = end.stopped();
                     });
    QObject::connect(&session, &bus::BusSession::telemetryReceived, &context,
                     [&](const bus::TelemetryBatch &batch) {
                         if (reported)
                             return;
                         for (const bus::TelemetrySample &s : batch) {
                             for (const QByteArray &row : table.add(s)) {
                                 console.out(row);
                                 ++rows;
                             }
                         }
                         console.flush();
                         if (console.outputFailed()) // e.g. `| head` closed the pipe
                             end.stop();
                     });
    console.out(table.header());
    console.flush();
    end.startClock();
    end.wait();
    // One more statistics snapshot, so that the figures cover the whole run and every row.
    bus.waitUntil([&] { return end.lost() || reported; }, 2000);
    report(bus, rows, stats);
    return end.lost() ? kExitFailure : kExitOk;
}

void ListenCommand::report(LiveBus &bus, qint64 rows, const bus::ListenStatistics &s)
{
    bus.error(QStringLiteral("%1 rows in %2 s; nothing was sent").arg(rows).arg(s.time, 0, 'f', 2));
    bus.error(QStringLiteral("the other master: requests %1 (%2/s), replies %3, paired %4, "
                             "unanswered %5, replies without their request %6, ambiguous echo "
                             "frames %7, corrupt replies %8, pairs broken by lost bytes %9")
                  .arg(s.requests)
                  .arg(s.requestsPerSecond, 0, 'f', 1)
                  .arg(s.replies)
                  .arg(s.paired)
                  .arg(s.unanswered)
                  .arg(s.orphanReplies)
                  .arg(s.ambiguous)
                  .arg(s.corruptReplies)
                  .arg(s.brokenPairs));
    if (bus.session().connection().link == protocol::Link::Can)
        bus.error(QStringLiteral("bus: %1 frames, load %2%, CAN error frames %3, frames on other "
                                 "IDs %4")
                      .arg(s.bytes / protocol::CanRecord::kSize)
                      .arg(100 * s.busLoad, 0, 'f', 1)
                      .arg(s.canErrorFrames)
                      .arg(s.otherFrames));
    else
        bus.error(QStringLiteral("bus: %1 bytes, load %2%, checksum errors %3, garbage bytes %4")
                      .arg(s.bytes)
                      .arg(100 * s.busLoad, 0, 'f', 1)
                      .arg(s.checksumErrors)
                      .arg(s.garbageBytes));
    for (auto it = s.perDrive.cbegin(); it != s.perDrive.cend(); ++it) {
        const bus::ListenDriveStatistics &d = it.value();
        bus.error(QStringLiteral("drive %1: requests %2 (%3/s), replies %4, unanswered %5, "
                                 "latency median/max %6/%7 ms")
                      .arg(it.key())
                      .arg(d.requests)
                      .arg(d.requestsPerSecond, 0, 'f', 1)
                      .arg(d.replies)
                      .arg(d.unanswered)
                      .arg(d.latency.medianMs, 0, 'f', 2)
                      .arg(d.latency.maxMs, 0, 'f', 2));
    }
    for (auto it = s.perCommand.cbegin(); it != s.perCommand.cend(); ++it)
        bus.error(QStringLiteral("command %1: requests %2 (%3/s)")
                      .arg(protocol::CommandTable::name(static_cast<protocol::Command>(it.key())))
                      .arg(it->requests)
                      .arg(it->requestsPerSecond, 0, 'f', 1));
}

int ListenCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    parser.addOption(QStringLiteral("duration"), true);
    parser.addOption(QStringLiteral("drives"), true);
    parser.addOption(QStringLiteral("csv"), false);
    int status = kExitOk;
    std::optional<BusOptions> busOptions =
        parseBus(parser, args, console, &status, /*listenDrives=*/true);
    if (!busOptions)
        return status;
    if (busOptions->isSimulated())
        return usageError(console, QStringLiteral("--sim has no other master to listen to; "
                                                  "give --port (lksim --controller serves one)"));
    const std::optional<Plan> plan = parse(parser, console, &status);
    if (!plan)
        return status;
    busOptions->mode = bus::LinkMode::ListenOnly;
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    for (const Drive &d : plan->drives)
        bus.session().setSeries(d.id, d.series);
    // A reader that goes away (`| head`) must end the loop, not kill the process silently.
    std::signal(SIGPIPE, SIG_IGN);
    ListenTable table(plan->format);
    return stream(bus, *plan, table);
}

} // namespace lk::lkctl
