#include "ReplayCommand.h"

#include "Console.h"
#include "ListenTable.h"

#include <bus/BusDiagnostics.h>
#include <bus/ListenMonitor.h>
#include <bus/MotorRegistry.h>
#include <bus/TelemetryBatcher.h>
#include <recording/RecordingReader.h>

namespace lk::lkctl {

using recording::RecordEvent;

namespace {

/// The recording's clock: the time of the record being replayed.
class RecordTimeClock final : public bus::BusClock {
public:
    qint64 nowNs() const override { return m_ns; }
    void set(qint64 ns) { m_ns = ns; }

private:
    qint64 m_ns = 0;
};

void applyContext(bus::MotorRegistry &motors, const recording::ContextSnapshot &context)
{
    for (const recording::DriveContext &d : context) {
        if (d.series)
            motors.setSeries(d.id, *d.series);
        motors.learnGeneration(d.id, d.generation);
    }
}

} // namespace

QString ReplayCommand::name() const
{
    return QStringLiteral("replay");
}

QString ReplayCommand::summary() const
{
    return QStringLiteral("decode a recording as lkctl listen decodes a live bus");
}

QString ReplayCommand::example() const
{
    return QStringLiteral("lkctl replay blackbox.lkrec --json");
}

QString ReplayCommand::usage() const
{
    return QStringLiteral(
        "Usage: lkctl replay FILE [--csv | --json]\n"
        "\n"
        "Decode a recording (docs/RECORDING.md: lkstudio's session recording or black box)\n"
        "as `lkctl listen` decodes a live bus: both directions on one stream, each request\n"
        "paired with its reply by order, every reply that carries telemetry and every value\n"
        "another master's request commands printed as one row in the long layout of\n"
        "`lkctl monitor` (time_s: the recording's session seconds, id, then every column),\n"
        "decoded with the series and generation recorded for its moment. The recording\n"
        "tool's own requests are paired and counted, but give no commanded-value rows.\n"
        "The whole file is read at once.\n"
        "A recording made on CAN is read as CAN frames: a frame on 0x180+ID, or with a\n"
        "reply's layout, is a reply; one with a request's layout on the shared 0x140+ID is\n"
        "told by order.\n"
        "Then the traffic's statistics go to standard error: requests, replies paired,\n"
        "requests left unanswered, ambiguous echo frames, checksum errors.\n"
        "\n"
        "Options:\n"
        "  --csv               CSV, long layout (the default)\n"
        "  --json              JSON lines, the CSV's names as keys\n"
        "  -h, --help          show this help\n"
        "\n"
        "Exit status:\n"
        "  0  done\n"
        "  2  unusable arguments, or FILE is no recording\n"
        "  3  the recording is damaged (what came before the damage was replayed; the byte\n"
        "     offset is on standard error)\n");
}

int ReplayCommand::run(const QStringList &args, Console &console)
{
    QString path;
    MonitorFormat format = MonitorFormat::CsvLong;
    for (const QString &a : args) {
        if (a == QLatin1String("--csv")) {
            format = MonitorFormat::CsvLong;
        } else if (a == QLatin1String("--json")) {
            format = MonitorFormat::Json;
        } else if (!a.startsWith(QLatin1Char('-')) && path.isEmpty()) {
            path = a;
        } else {
            console.errLine(
                QStringLiteral("lkctl replay: unexpected argument '%1' (see lkctl replay --help)")
                    .arg(a));
            return kExitUsage;
        }
    }
    if (path.isEmpty()) {
        console.errLine(QStringLiteral("lkctl replay: give a recording (see lkctl replay --help)"));
        return kExitUsage;
    }
    recording::RecordingReader reader;
    if (!reader.open(path)) {
        console.errLine(QStringLiteral("lkctl replay: %1").arg(reader.error().message));
        return kExitUsage;
    }

    // The passive path of a listen-only session, fed from the file on the file's clock.
    auto clock = std::make_shared<RecordTimeClock>();
    bus::MotorRegistry motors;
    bus::TelemetryBatcher batcher;
    bus::BusDiagnostics diagnostics(motors, clock, bus::makeQtSingleShotTimer);
    bus::ListenMonitor monitor(motors, batcher, diagnostics, clock);
    ListenTable table(format);
    qint64 rows = 0;
    QObject::connect(&batcher, &bus::TelemetryBatcher::batchReady,
                     [&](const bus::TelemetryBatch &batch) {
                         for (const bus::TelemetrySample &s : batch)
                             for (const QByteArray &row : table.add(s)) {
                                 console.out(row);
                                 ++rows;
                             }
                     });
    console.out(table.header());
    const protocol::Link link = recording::linkOf(reader.header());
    motors.setLink(link);
    monitor.restart(link);
    applyContext(motors, reader.header().context);
    int baud = reader.header().baud > 0 ? reader.header().baud : 115200;
    RecordEvent e;
    while (reader.next(&e)) {
        clock->set(e.timeNs);
        switch (e.kind) {
        case RecordEvent::Kind::Rx:
        case RecordEvent::Kind::Tx:
            monitor.feed(e.bytes, baud, e.kind == RecordEvent::Kind::Tx);
            batcher.flush();
            break;
        case RecordEvent::Kind::Context:
            applyContext(motors, e.context);
            break;
        case RecordEvent::Kind::Link:
            if (e.baud > 0)
                baud = e.baud;
            if (e.link != recording::LinkEventKind::Error)
                monitor.restart(link); // a new stream: no partial frame, no open request
            break;
        case RecordEvent::Kind::Dropped:
            monitor.restart(link); // bytes are missing: pair nothing across the gap
            break;
        }
    }
    const bus::ListenStatistics s = monitor.snapshot(baud);
    batcher.flush();
    console.flush();
    console.errLine(QStringLiteral("lkctl replay: %1 rows; requests %2, replies %3, paired %4, "
                                   "unanswered %5, replies without their request %6, ambiguous "
                                   "echo frames %7, corrupt replies %8, checksum errors %9%10")
                        .arg(rows)
                        .arg(s.requests)
                        .arg(s.replies)
                        .arg(s.paired)
                        .arg(s.unanswered)
                        .arg(s.orphanReplies)
                        .arg(s.ambiguous)
                        .arg(s.corruptReplies)
                        .arg(s.checksumErrors)
                        .arg(link == protocol::Link::Can
                                 ? QStringLiteral(", CAN error frames %1").arg(s.canErrorFrames)
                                 : QString()));
    if (reader.error().isError()) {
        console.errLine(QStringLiteral("lkctl replay: %1").arg(reader.error().message));
        return kExitBadData;
    }
    return kExitOk;
}

} // namespace lk::lkctl
