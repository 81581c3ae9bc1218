#include "MonitorCommand.h"

#include "Console.h"
#include "LiveBus.h"
#include "MonitorTable.h"
#include "ReadCommand.h"
#include "StreamEnd.h"

#include <bus/LinkTiming.h>
#include <motor/SeriesLimits.h>
#include <record/TelemetryColumns.h>

#include <QtCore/QTimer>

#include <algorithm>
#include <csignal>

namespace lk::lkctl {

using protocol::Command;

namespace {
const QStringList kPollable{"state1", "state2", "state3", "multi-turn", "single-turn", "encoder"};
const char kDefaultWhat[] = "state2,state1,multi-turn";

/// The telemetry column names (TelemetryColumns), wrapped for the help text.
QString columnList()
{
    QString text = QStringLiteral("  ");
    int lineStart = 0;
    const QVector<record::TelemetryColumn> &columns = record::TelemetryColumns::all();
    for (int i = 0; i < columns.size(); ++i) {
        const QString item = QLatin1String(columns.at(i).key) +
                             (i + 1 < columns.size() ? QStringLiteral(",") : QString());
        if (text.size() - lineStart + item.size() + 1 > 80) {
            text += QStringLiteral("\n  ");
            lineStart = int(text.size()) - 2;
        } else if (i > 0) {
            text += QLatin1Char(' ');
        }
        text += item;
    }
    return text;
}
} // namespace

QString MonitorCommand::summary() const
{
    return QStringLiteral("stream live values of drives as CSV or JSON lines");
}

QString MonitorCommand::example() const
{
    return QStringLiteral("lkctl monitor 3 17 --port /dev/ttyUSB0 --rate 50 --duration 10");
}

QString MonitorCommand::usage() const
{
    return QStringLiteral(
               "Usage: lkctl monitor ID... (--port DEV [--baud N] | --sim SPEC) [--what LIST]\n"
               "                     [--rate HZ] [--duration S] [--count N]\n"
               "                     [--csv [--csv-layout wide|long] | --json]\n"
               "\n"
               "Poll the drives round robin and print what each poll round read, until Ctrl-C\n"
               "(SIGINT) or SIGTERM, --duration or --count. Then the achieved rate and the bus\n"
               "statistics go to standard error; the rate is given as a share of what the wire\n"
               "carries for the command mix at the baud (the frames' wire time alone, which no\n"
               "rate can pass), beside the rate drives that take the full 0.5 ms they may to\n"
               "answer would allow.\n"
               "\n"
               "Options:\n"
               "  --what LIST         what to poll, comma-separated from %1\n"
               "                      (default %2)\n"
               "  --rate HZ           poll rounds per second (default %3); 0 = as fast as the\n"
               "                      bus allows\n"
               "  --duration S        stop after S seconds\n"
               "  --count N           stop after N rows\n"
               "  --csv               CSV (the default)\n"
               "  --csv-layout L      wide (default): one row per poll round, time_s then one\n"
               "                      column id<N>_<name> per drive and signal, e.g.\n"
               "                      id3_speed_dps; long: one row per drive and round,\n"
               "                      time_s,id,<name>...\n"
               "  --json              JSON lines: one object per drive and round, the long\n"
               "                      layout's names as keys\n"
               "\n"
               "A row holds the values of one poll round only, and time_s is when that round\n"
               "began (host clock, seconds since the bus opened). The columns of what is\n"
               "polled follow, in this order (names carry the unit; power instead of iq_a on\n"
               "MS):\n"
               "%6\n"
               "A value the round did not bring (a lost reply) is an empty cell (JSON: no key),\n"
               "never 0. CSV.md (in /usr/share/doc/lkstudio, docs/ in the sources) describes\n"
               "both layouts, every column and how to load the files in pandas and PlotJuggler.\n"
               "JSON example:\n"
               "  {\"time_s\":1.234567,\"id\":3,\"temperature_c\":31,\"iq_a\":0.1611,"
               "\"speed_dps\":360,\"encoder\":1234}\n"
               "\n"
               "%4"
               "\n"
               "Examples:\n"
               "  lkctl monitor 3 --port /dev/ttyUSB0 > run.csv          (Ctrl-C to stop)\n"
               "  lkctl monitor 3 17 32 --port ttyUSB0 --rate 0 --duration 5 --json\n"
               "  lkctl monitor 3 17 --port ttyUSB0 --csv-layout long --count 100\n"
               "  lkctl monitor 3 --port ttyUSB0 --what state2,state3 --count 100\n"
               "\n"
               "%5")
        .arg(kPollable.join(QStringLiteral(", ")), QLatin1String(kDefaultWhat))
        .arg(kDefaultRateHz)
        .arg(BusOptions::helpText(),
             exitStatusText(QStringLiteral(
                 "  An interrupt ends monitoring normally (status 0); losing the bus, or no\n"
                 "  reply from any drive for 5 s (three poll periods and a second at a slow\n"
                 "  --rate), gives 1. A --what set no drive's series has, or a drive with\n"
                 "  none of the sets (--what state3 on MS), is refused after read_model\n"
                 "  with 2, before anything is polled.\n")))
        .arg(columnList());
}

std::optional<MonitorCommand::Plan> MonitorCommand::parse(const ArgParser &parser, Console &console,
                                                          int *status) const
{
    const auto fail = [&](const QString &message) {
        *status = usageError(console, message);
        return std::nullopt;
    };
    Plan plan;
    QString error;
    if (parser.positionals().isEmpty())
        return fail(QStringLiteral("missing the drive ID(s)"));
    for (const QString &p : parser.positionals()) {
        const std::optional<int> id = parseId(p, &error);
        if (!id)
            return fail(error);
        if (plan.ids.contains(*id))
            return fail(QStringLiteral("ID %1 given twice").arg(*id));
        plan.ids.append(*id);
    }
    const QString what = parser.isSet(QStringLiteral("what")) ? parser.value(QStringLiteral("what"))
                                                              : QLatin1String(kDefaultWhat);
    for (const QString &w : what.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString name = w.trimmed();
        if (!kPollable.contains(name))
            return fail(QStringLiteral("cannot poll '%1'; --what takes %2")
                            .arg(name, kPollable.join(QStringLiteral(", "))));
        const Command c = *ReadCommand::commandFor(name);
        if (!plan.commands.contains(c))
            plan.commands.append(c);
    }
    if (plan.commands.isEmpty())
        return fail(QStringLiteral("--what names nothing to poll"));
    if (parser.isSet(QStringLiteral("rate"))) {
        const auto r = parser.numberValue(QStringLiteral("rate"), 0, &error);
        if (!r)
            return fail(error);
        plan.rateHz = *r;
    }
    if (parser.isSet(QStringLiteral("duration"))) {
        plan.durationS = parser.numberValue(QStringLiteral("duration"), 0, &error);
        if (!plan.durationS)
            return fail(error);
    }
    if (parser.isSet(QStringLiteral("count"))) {
        plan.count = parser.intValue(QStringLiteral("count"), 1, qint64(1) << 53, &error);
        if (!plan.count)
            return fail(error);
    }
    const std::optional<MonitorFormat> format = parseFormat(parser, &error);
    if (!format)
        return fail(error);
    plan.format = *format;
    return plan;
}

std::optional<MonitorFormat> MonitorCommand::parseFormat(const ArgParser &parser, QString *error)
{
    const bool json = parser.isSet(QStringLiteral("json"));
    if (json && parser.isSet(QStringLiteral("csv"))) {
        *error = QStringLiteral("--csv and --json exclude each other");
        return std::nullopt;
    }
    if (!parser.isSet(QStringLiteral("csv-layout")))
        return json ? MonitorFormat::Json : MonitorFormat::CsvWide;
    if (json) {
        *error = QStringLiteral("--csv-layout is for CSV, not --json");
        return std::nullopt;
    }
    const QString name = parser.value(QStringLiteral("csv-layout"));
    const std::optional<record::CsvLayout> layout = record::TelemetryCsv::layoutFromName(name);
    if (!layout) {
        *error = QStringLiteral("--csv-layout takes wide or long, not '%1'").arg(name);
        return std::nullopt;
    }
    return *layout == record::CsvLayout::Long ? MonitorFormat::CsvLong : MonitorFormat::CsvWide;
}

QString MonitorCommand::lackingSet(const Plan &plan,
                                   const QMap<int, std::optional<protocol::Series>> &series)
{
    const auto answers = [&series](int id, Command c) {
        const std::optional<protocol::Series> s = series.value(id);
        return !s || motor::supports(*s, c);
    };
    const auto refusal = [&series](int id, Command c) {
        QString what;
        for (const QString &w : kPollable) {
            if (ReadCommand::commandFor(w) == c)
                what = w;
        }
        const QString name = protocol::seriesName(*series.value(id));
        return QStringLiteral("drive %1 is %2, and the %2 series has no %3 (--what %4): "
                              "nothing was polled; leave %4 out for this drive")
            .arg(id)
            .arg(name, protocol::CommandTable::name(c), what);
    };
    // Drives of several series may share a set some of them lack (state3 for an MF beside
    // an MS: the MS's columns go without it). What cannot be is a set no drive has, or a
    // drive with nothing to poll: its rows would never come.
    for (Command c : plan.commands) {
        if (std::none_of(plan.ids.cbegin(), plan.ids.cend(),
                         [&](int id) { return answers(id, c); }))
            return refusal(plan.ids.first(), c);
    }
    for (int id : plan.ids) {
        if (std::none_of(plan.commands.cbegin(), plan.commands.cend(),
                         [&](Command c) { return answers(id, c); }))
            return refusal(id, plan.commands.first());
    }
    return {};
}

double MonitorCommand::silenceLimitS(const Plan &plan)
{
    // Long enough for a few poll periods at a slow rate and for a loaded machine; short
    // enough that a bus gone quiet ends monitoring instead of holding it forever.
    return std::max(kSilenceS, plan.rateHz > 0 ? 3 / plan.rateHz + 1 : 0.0);
}

int MonitorCommand::stream(LiveBus &bus, const Plan &plan, MonitorTable &table)
{
    Console &console = bus.console();
    bus::BusSession &session = bus.session();
    StreamEnd end(bus, plan.durationS);
    qint64 samples = 0;
    qint64 rows = 0; // printed
    double firstSample = -1, lastSample = -1;
    bus::BusStatistics stats;
    QObject context; // every connection below ends with it
    // No reply from any drive for silenceLimitS(): the drives went quiet (unplugged, powered
    // off); say so and end, rather than wait for rows that cannot come.
    QTimer silence;
    silence.setSingleShot(true);
    silence.setInterval(int(silenceLimitS(plan) * 1000));
    QObject::connect(&silence, &QTimer::timeout, &context, [&] {
        if (end.stopped())
            return;
        end.lose();
        QStringList ids;
        for (int id : plan.ids)
            ids << QString::number(id);
        bus.error(QStringLiteral("no reply from drive %1 for %2 s: check the power, the wiring "
                                 "and the baud (--baud)")
                      .arg(ids.join(QStringLiteral(", ")))
                      .arg(silenceLimitS(plan), 0, 'f', 1));
    });
    QObject::connect(&session, &bus::BusSession::statisticsUpdated, &context,
                     [&stats](const bus::BusStatistics &s) { stats = s; });
    QObject::connect(&session, &bus::BusSession::telemetryReceived, &context,
                     [&](const bus::TelemetryBatch &batch) {
                         for (const bus::TelemetrySample &s : batch) {
                             if (end.stopped() || !plan.ids.contains(s.id))
                                 continue;
                             ++samples;
                             silence.start();
                             firstSample = firstSample < 0 ? s.time : firstSample;
                             lastSample = s.time;
                             for (const QByteArray &row : table.add(s)) {
                                 console.out(row);
                                 ++rows;
                                 if (plan.count && rows >= *plan.count) {
                                     end.stop();
                                     break;
                                 }
                             }
                         }
                         console.flush();
                         if (console.outputFailed()) // e.g. `| head` closed the pipe
                             end.stop();
                     });
    console.out(table.header());
    console.flush();
    bus::PollPlan poll;
    poll.ids = plan.ids;
    poll.commands = plan.commands;
    poll.rateHz = plan.rateHz;
    session.resetStatistics();
    session.startPolling(poll);
    silence.start();
    end.startClock();
    end.wait();
    session.stopPolling();
    // Rows still being merged when a signal, the duration or a lost bus ended the run carry
    // real values: print them (with --count the count is the contract, so not then).
    if (!plan.count) {
        for (const QByteArray &row : table.flush()) {
            console.out(row);
            ++rows;
        }
        console.flush();
    }
    // One more statistics snapshot, so that the figures cover the whole run.
    const int before = int(stats.time * 1000);
    bus.waitUntil([&] { return end.lost() || int(stats.time * 1000) != before; }, 2000);
    report(bus, plan, table, rows, samples, lastSample - firstSample, stats);
    return end.lost() ? kExitFailure : kExitOk;
}

void MonitorCommand::report(LiveBus &bus, const Plan &plan, const MonitorTable &table, qint64 rows,
                            qint64 samples, double samplesSpanS,
                            const bus::BusStatistics &stats) const
{
    const double repliesPerS = samples > 1 && samplesSpanS > 0 ? (samples - 1) / samplesSpanS : 0;
    QString limit;
    if (plan.simulated)
        limit = QStringLiteral(" (simulated bus: no wire time, no bus limit)");
    else if (plan.wireLimit > 0)
        // The wire time is the one true ceiling. The 0.5 ms turnaround is the most a drive may
        // take to answer, not what it takes (lksim 0.2 ms, real drives often less): a rate
        // measured against it can pass 100 %, so it is given as what slow drives would allow.
        limit = QStringLiteral(", %1% of the %2/s the wire carries for this mix at %3 "
                               "(%4/s if every drive took the %5 ms it may to answer)")
                    .arg(100 * repliesPerS / plan.wireLimit, 0, 'f', 0)
                    .arg(plan.wireLimit, 0, 'f', 0)
                    .arg(plan.linkRate)
                    .arg(plan.slowDriveLimit, 0, 'f', 0)
                    .arg(plan.turnaroundMs);
    bus.error(QStringLiteral("%1 rows in %2 s, %3 Hz per drive (%4); %5 replies/s%6")
                  .arg(rows)
                  .arg(table.elapsedS(), 0, 'f', 2)
                  .arg(table.cyclesPerSecond(), 0, 'f', 1)
                  .arg(plan.rateHz > 0 ? QStringLiteral("%1 Hz asked").arg(plan.rateHz)
                                       : QStringLiteral("as fast as the bus allows"))
                  .arg(repliesPerS, 0, 'f', 0)
                  .arg(limit));
    const bus::LinkStatistics &b = stats.bus;
    bus.error(QStringLiteral("bus: requests %1, replies %2, timeouts %3, retries %4, checksum "
                             "errors %5, garbage bytes %6, parse errors %7, late replies %8; "
                             "latency min/median/p95/max %9 ms")
                  .arg(b.requests)
                  .arg(b.replies)
                  .arg(b.timeouts)
                  .arg(b.retries)
                  .arg(b.checksumErrors)
                  .arg(b.garbageBytes)
                  .arg(b.parseErrors)
                  .arg(b.lateReplies)
                  .arg(QStringLiteral("%1/%2/%3/%4")
                           .arg(b.latency.minMs, 0, 'f', 2)
                           .arg(b.latency.medianMs, 0, 'f', 2)
                           .arg(b.latency.p95Ms, 0, 'f', 2)
                           .arg(b.latency.maxMs, 0, 'f', 2)));
}

int MonitorCommand::run(const QStringList &args, Console &console)
{
    ArgParser parser = makeParser();
    for (const char *o : {"what", "rate", "duration", "count", "csv-layout"})
        parser.addOption(QLatin1String(o), true);
    parser.addOption(QStringLiteral("csv"), false);
    int status = kExitOk;
    const std::optional<BusOptions> busOptions = parseBus(parser, args, console, &status);
    if (!busOptions)
        return status;
    std::optional<Plan> plan = parse(parser, console, &status);
    if (!plan)
        return status;
    plan->simulated = busOptions->isSimulated();
    LiveBus bus(console, name());
    if (!bus.open(*busOptions))
        return kExitFailure;
    QMap<int, std::optional<protocol::Series>> series;
    QSet<int> v235;
    for (int id : plan->ids) {
        const std::optional<LiveBus::Identity> who = bus.identify(id);
        if (!who)
            return kExitFailure;
        series.insert(id, who->series);
        if (who->model.generation == protocol::Generation::V2_35)
            v235.insert(id);
    }
    // A set a drive's series lacks would never be polled, and its rows never complete:
    // refused here, before the first poll, rather than waited for.
    if (const QString lacking = lackingSet(*plan, series); !lacking.isEmpty()) {
        bus.error(lacking);
        return kExitUsage;
    }
    // A reader that goes away (`| head`) must end the loop, not kill the process silently.
    std::signal(SIGPIPE, SIG_IGN);
    // The bus limits of the mix (docs/ARCHITECTURE.md), without what a series never answers.
    QVector<Command> mix;
    for (int id : plan->ids) {
        for (Command c : plan->commands) {
            if (!series.value(id) || motor::supports(*series.value(id), c))
                mix.append(c);
        }
    }
    // The link's own timing: a CAN frame's bits at the bit rate and its 0.25 ms reply time,
    // or RS485 bytes at the baud and its 0.5 ms turnaround.
    const bus::LinkTiming timing = busOptions->isCan() ? bus::LinkTiming::can(busOptions->bitRate)
                                                       : bus::LinkTiming::rs485(busOptions->baud);
    plan->linkRate = busOptions->isCan()
                         ? QStringLiteral("%1 bit/s on CAN").arg(busOptions->bitRate)
                         : QStringLiteral("%1 baud").arg(busOptions->baud);
    plan->turnaroundMs = timing.turnaroundS() * 1e3;
    plan->wireLimit = timing.transactionsPerSecond(mix, 0.0);
    plan->slowDriveLimit = timing.transactionsPerSecond(mix);
    MonitorTable table(plan->commands, series, plan->format, v235);
    return stream(bus, *plan, table);
}

} // namespace lk::lkctl
