#include "ExportCommand.h"

#include "Console.h"

#include <bus/TelemetrySample.h>
#include <protocol/Reply.h>
#include <record/TelemetryColumns.h>
#include <record/TelemetryCsv.h>
#include <recording/CandumpLog.h>
#include <recording/PcapExport.h>
#include <recording/RecordedFrameParser.h>
#include <recording/RecordingReader.h>

#include <QtCore/QSaveFile>

#include <numeric>

namespace lk::lkctl {

using recording::RecordingReader;

QString ExportCommand::name() const
{
    return QStringLiteral("export");
}

QString ExportCommand::summary() const
{
    return QStringLiteral("export a recording as pcap (Wireshark), a candump log or telemetry CSV");
}

QString ExportCommand::example() const
{
    return QStringLiteral("lkctl export blackbox.lkrec --pcap blackbox.pcap");
}

QString ExportCommand::usage() const
{
    return QStringLiteral(
        "Usage: lkctl export FILE --pcap OUT\n"
        "       lkctl export FILE --candump OUT\n"
        "       lkctl export FILE --csv OUT\n"
        "\n"
        "Export a recording (docs/RECORDING.md; lkstudio's session recording or black box).\n"
        "\n"
        "  --pcap OUT   one pcap packet per frame (link type USER0, 147), both directions,\n"
        "               behind a 2-byte pseudo-header (wire direction, frame direction).\n"
        "               Wireshark decodes it with the dissector shipped in the package\n"
        "               (lkservo.lua): every command of both generations, request and reply,\n"
        "               fields and values. Without the installed package:\n"
        "                 wireshark -X lua_script:lkservo.lua OUT\n"
        "               A recording made on CAN is written with the SocketCAN link type\n"
        "               (LINKTYPE_CAN_SOCKETCAN, 227), one packet per CAN frame, which\n"
        "               Wireshark's own CAN dissector reads.\n"
        "  --candump OUT\n"
        "               a recording made on CAN as a `candump -L` log, which can-utils\n"
        "               (canplayer, log2asc), python-can and SavvyCAN read: one line per frame,\n"
        "               \"(1700000000.123456) can0 141#9C00000000000000\", at the wall-clock\n"
        "               time it passed; what the tool sent and what it received (its own\n"
        "               frames looped back by the adapter once); error frames with the\n"
        "               CAN_ERR_FLAG in their 8-digit ID, as candump writes them. Link events\n"
        "               and drops have no candump form and are left out. A recording made on\n"
        "               RS485 is refused (exit status 2).\n"
        "  --csv OUT    the telemetry of every reply (docs/CSV.md, long layout: time_s, id,\n"
        "               then every column); each reply is a row of its own at its own time,\n"
        "               decoded with the series and generation recorded for its moment.\n"
        "  -h, --help   show this help\n"
        "\n"
        "OUT is written whole or not at all. A truncated or damaged recording is exported up\n"
        "to the damage, whose byte offset is named on standard error (exit status 3).\n"
        "\n"
        "Exit status:\n"
        "  0  done\n"
        "  1  OUT cannot be written\n"
        "  2  unusable arguments, or FILE is no recording (--candump: no CAN recording)\n"
        "  3  the recording is damaged (what came before the damage was exported)\n");
}

namespace {

int finishExport(QSaveFile &out, const RecordingReader &reader, const QString &what,
                 Console &console)
{
    if (!out.commit()) {
        console.errLine(QStringLiteral("lkctl export: cannot write %1: %2")
                            .arg(out.fileName(), out.errorString()));
        return kExitFailure;
    }
    console.errLine(QStringLiteral("lkctl export: %1 written to %2").arg(what, out.fileName()));
    if (reader.error().isError()) {
        console.errLine(QStringLiteral("lkctl export: %1").arg(reader.error().message));
        return kExitBadData;
    }
    return kExitOk;
}

} // namespace

QString ExportCommand::writePcap(RecordingReader &reader, QIODevice &out)
{
    return QStringLiteral("%1 packets").arg(recording::PcapExport::write(reader, out));
}

QString ExportCommand::writeCsv(RecordingReader &reader, QIODevice &file)
{
    QVector<int> columns(record::TelemetryColumns::all().size());
    std::iota(columns.begin(), columns.end(), 0);
    const record::TelemetryCsv csv = record::TelemetryCsv::longLayout(columns);
    file.write(csv.header());
    qint64 rows = 0;
    recording::RecordedFrameParser parser(reader.header().context,
                                          recording::linkOf(reader.header()));
    const auto sink = [&](const recording::RecordedFrame &f) {
        if (!f.event.isFrame || f.event.direction != protocol::FrameDirection::Reply)
            return;
        const auto reply = protocol::decodeReply(f.event.frame, f.context);
        if (!reply.reply)
            return;
        const double time = double(f.timeNs) * 1e-9;
        const auto sample = bus::TelemetrySample::fromReply(*reply.reply, time);
        if (!sample)
            return;
        record::CycleValues row;
        row.time = time;
        row.drives[sample->id] = record::TelemetryColumns::values(*sample);
        for (const QByteArray &line : csv.rows(row)) {
            file.write(line);
            ++rows;
        }
    };
    recording::RecordEvent e;
    while (reader.next(&e))
        parser.feed(e, sink);
    parser.finish(sink);
    return QStringLiteral("%1 rows").arg(rows);
}

int ExportCommand::run(const QStringList &args, Console &console)
{
    QString input;
    QString pcap;
    QString csv;
    QString candump;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (a == QLatin1String("--pcap") || a == QLatin1String("--csv") ||
            a == QLatin1String("--candump")) {
            if (i + 1 >= args.size()) {
                console.errLine(QStringLiteral("lkctl export: %1 needs a file name").arg(a));
                return kExitUsage;
            }
            (a == QLatin1String("--pcap")  ? pcap
             : a == QLatin1String("--csv") ? csv
                                           : candump) = args.at(++i);
        } else if (!a.startsWith(QLatin1Char('-')) && input.isEmpty()) {
            input = a;
        } else {
            console.errLine(QStringLiteral("lkctl export: unexpected argument '%1' (see lkctl "
                                           "export --help)")
                                .arg(a));
            return kExitUsage;
        }
    }
    const int outputs = int(!pcap.isEmpty()) + int(!csv.isEmpty()) + int(!candump.isEmpty());
    if (input.isEmpty() || outputs != 1) {
        console.errLine(QStringLiteral("lkctl export: give a recording and one of --pcap OUT, "
                                       "--candump OUT or --csv OUT (see lkctl export --help)"));
        return kExitUsage;
    }
    RecordingReader reader;
    if (!reader.open(input)) {
        console.errLine(QStringLiteral("lkctl export: %1").arg(reader.error().message));
        return kExitUsage;
    }
    if (!candump.isEmpty() && recording::linkOf(reader.header()) != protocol::Link::Can) {
        console.errLine(QStringLiteral("lkctl export: %1 was recorded on %2, not CAN: a candump "
                                       "log holds CAN frames only")
                            .arg(input, reader.header().linkDescription));
        return kExitUsage;
    }
    QSaveFile file(!pcap.isEmpty() ? pcap : !csv.isEmpty() ? csv : candump);
    if (!file.open(QIODevice::WriteOnly)) {
        console.errLine(QStringLiteral("lkctl export: cannot write %1: %2")
                            .arg(file.fileName(), file.errorString()));
        return kExitFailure;
    }
    const QString what =
        !pcap.isEmpty() ? writePcap(reader, file)
        : !csv.isEmpty()
            ? writeCsv(reader, file)
            : QStringLiteral("%1 frames").arg(recording::CandumpLog::write(reader, file));
    return finishExport(file, reader, what, console);
}

} // namespace lk::lkctl
