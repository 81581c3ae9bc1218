#include "DecodeCommand.h"

#include "Console.h"
#include "HexText.h"
#include "RecordingDecode.h"

#include "protocol/FieldJson.h"
#include "recording/CandumpLog.h"
#include "recording/RecordingReader.h"

#include <QtCore/QFile>
#include <QtCore/QFileInfo>

namespace lk::lkctl {

using protocol::FieldJson;
using protocol::ParseEvent;

QString DecodeCommand::name() const
{
    return QStringLiteral("decode");
}

QString DecodeCommand::summary() const
{
    return QStringLiteral("decode captured bus bytes into one JSON object per frame");
}

QString DecodeCommand::example() const
{
    return QStringLiteral("lkctl decode 3E 80 01 00 BF");
}

QString DecodeCommand::usage() const
{
    return QStringLiteral(
        "Usage: lkctl decode [--series MS|MF|MG|MH] [--generation v2.3|v2.35] HEX...\n"
        "       lkctl decode [--series S] [--generation G] -            hex text on stdin\n"
        "       lkctl decode [--series S] [--generation G] --binary -   raw bytes on stdin\n"
        "       lkctl decode FILE.lkrec                                  a recording\n"
        "       lkctl decode FILE.log                                    a candump log\n"
        "\n"
        "Decode LK RS485 bytes as captured on a bus: many frames, both directions, garbage\n"
        "between them. Prints one compact JSON object per line, in stream order:\n"
        "  {\"direction\":\"request\",\"command\":\"speed\",\"code\":\"0xA2\",\"id\":1,"
        "\"fields\":{\"speed_dps\":100.0,\"speed_raw\":10000}}\n"
        "  {\"direction\":\"echo\",\"command\":\"motor_off\",\"code\":\"0x80\",\"id\":1,"
        "\"fields\":{}}\n"
        "  {\"error\":\"bad_data_checksum\",\"bytes\":\"3E A4 01 07 EA 21 00 00 0A 00 2C 19 73\"}\n"
        "direction is request or reply where the frame's length tells them apart, echo where\n"
        "both directions carry the same bytes (an echo's fields are the values written).\n"
        "Field names and units follow CLI.md; scaled values also come as <field>_raw.\n"
        "Errors: bad_header_checksum, bad_data_checksum, bad_length, unknown_command,\n"
        "garbage (bytes skipped while resynchronising), truncated (input ended in a frame).\n"
        "\n"
        "Options:\n"
        "  --series S   drive series: MS replies carry power instead of iq (default MF)\n"
        "  --generation G\n"
        "               protocol generation of the drives, v2.3 (default) or v2.35 (firmware\n"
        "               2.35 and later): it decides the read_state1 layout (voltage, bus\n"
        "               current, motor state, error flags) and the current scales. A\n"
        "               read_model reply in the stream tells its drive's generation (42 data\n"
        "               bytes: v2.3, 58: v2.35), which then applies to that ID's later frames\n"
        "               whatever --generation says: it is what the drive itself reports.\n"
        "  --binary     standard input holds raw bytes, not hex text (implies -)\n"
        "  FILE         a recording (docs/RECORDING.md), told by its magic, as a file or on\n"
        "               standard input: every frame and fault as above with \"time_s\"\n"
        "               (session seconds to the microsecond, six decimals as monitor's) and\n"
        "               \"wire\" (tx: sent by the recording tool, rx: received), decoded with\n"
        "               the series and generation recorded for its moment; link events and\n"
        "               drops as {\"note\":...}. A truncated or damaged recording is decoded\n"
        "               up to the damage, whose byte offset is named on standard error (exit\n"
        "               status 3).\n"
        "               A candump log (can-utils: `candump -L` lines \"(1700000000.123456)\n"
        "               can0 141#9C00000000000000\", or candump's default \"can0  141   [8]\n"
        "               9C 00 ...\", with or without a time) is decoded the same way, as a\n"
        "               recording of received CAN frames: time_s from its first frame, a\n"
        "               frame on 0x180+ID or with a reply's layout a reply, one with a\n"
        "               request's layout on 0x140+ID told by order; a line that is no frame\n"
        "               is refused with its number.\n"
        "  -            read standard input; frames are printed as they arrive, so a live\n"
        "               pipe is decoded live\n"
        "  -h, --help   show this help\n"
        "\n"
        "Hex text (arguments and standard input):\n"
        "  Bytes are pairs of hex digits in either case; a group of digits may carry a 0x\n"
        "  prefix. Spaces, tabs, newlines, ',', ';' and ':' separate groups but are not\n"
        "  needed: \"3E800100BF\", \"3E 80 01 00 BF\" and \"0x3E,0x80,0x01,0x00,0xBF\" are\n"
        "  the same five bytes. '#' starts a comment that runs to the end of the line:\n"
        "  timestamps, directions and notes (as in the GUI's traffic export) go after '#'.\n"
        "  A group with an odd number of digits or any other character is refused with\n"
        "  its line (or argument) and column; on standard input the lines before it have\n"
        "  already been decoded and printed.\n"
        "\n"
        "Examples:\n"
        "  lkctl decode 3E 80 01 00 BF\n"
        "  lkctl decode --series MS 3E9C01 00DB 3E9C0107E2 1F F4 01 68 01 00 30 AD\n"
        "  lkctl decode --generation v2.35 3E 9A 01 07 E0 1E 60 09 EC FF 10 01 83\n"
        "  lkctl decode - < capture.txt\n"
        "  lkctl decode blackbox.lkrec\n"
        "  cat /dev/ttyUSB0 | lkctl decode --binary -\n"
        "\n"
        "Exit status:\n"
        "  0  every byte belonged to a valid frame\n"
        "  3  some bytes did not (each fault is printed as an error object)\n"
        "  2  unusable arguments or hex text (message on standard error)\n");
}

std::optional<DecodeCommand::Options> DecodeCommand::parseOptions(const QStringList &args,
                                                                  QString *problem)
{
    Options o;
    bool optionsEnded = false;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args.at(i);
        if (optionsEnded || !a.startsWith(QLatin1Char('-'))) {
            o.hex.append(a);
        } else if (a == QLatin1String("-")) {
            o.fromStdin = true;
        } else if (a == QLatin1String("--")) {
            optionsEnded = true;
        } else if (a == QLatin1String("--binary")) {
            o.binary = o.fromStdin = true;
        } else if (a == QLatin1String("--series") || a.startsWith(QLatin1String("--series="))) {
            QString value = a.mid(int(qstrlen("--series=")));
            if (!a.contains(QLatin1Char('='))) {
                if (i + 1 >= args.size()) {
                    *problem = QStringLiteral("--series needs a value: MS, MF, MG or MH");
                    return std::nullopt;
                }
                value = args.at(++i);
            }
            const auto series = protocol::seriesFromName(value);
            if (!series) {
                *problem = QStringLiteral("unknown series '%1' (MS, MF, MG or MH)").arg(value);
                return std::nullopt;
            }
            o.context.series = *series;
        } else if (a == QLatin1String("--generation") ||
                   a.startsWith(QLatin1String("--generation="))) {
            QString value = a.mid(int(qstrlen("--generation=")));
            if (!a.contains(QLatin1Char('='))) {
                if (i + 1 >= args.size()) {
                    *problem = QStringLiteral("--generation needs a value: v2.3 or v2.35");
                    return std::nullopt;
                }
                value = args.at(++i);
            }
            const auto generation = protocol::generationFromName(value);
            if (!generation) {
                *problem = QStringLiteral("unknown generation '%1' (v2.3 or v2.35)").arg(value);
                return std::nullopt;
            }
            o.context.generation = *generation;
        } else {
            *problem = QStringLiteral("unknown option '%1'").arg(a);
            return std::nullopt;
        }
    }
    if (o.fromStdin && !o.hex.isEmpty()) {
        *problem = QStringLiteral("give HEX arguments or read standard input, not both");
        return std::nullopt;
    }
    if (!o.fromStdin && o.hex.isEmpty()) {
        *problem = QStringLiteral("no input: give HEX bytes, or - to read standard input");
        return std::nullopt;
    }
    return o;
}

int DecodeCommand::usageError(const QString &problem, Console &console) const
{
    console.errLine(QStringLiteral("lkctl decode: %1").arg(problem));
    return kExitUsage;
}

protocol::DecodeContext DecodeCommand::contextFor(int id) const
{
    protocol::DecodeContext c = m_context;
    c.generation = m_generationById.value(id, m_context.generation);
    return c;
}

void DecodeCommand::print(const ParseEvent &event, Console &console)
{
    const QJsonObject object = FieldJson::eventObject(event, contextFor(event.frame.id));
    m_sawFault = m_sawFault || FieldJson::isError(object);
    console.out(FieldJson::toJsonLine(object) + '\n');
    // A model reply's length tells its drive's generation (ERRATA "Generations").
    if (event.isFrame && event.direction == protocol::FrameDirection::Reply &&
        event.frame.command == quint8(protocol::Command::ReadModel)) {
        m_generationById.insert(event.frame.id, event.frame.data.size() == 42
                                                    ? protocol::Generation::V2_3
                                                    : protocol::Generation::V2_35);
    }
}

void DecodeCommand::feed(const QByteArray &bytes, Console &console)
{
    m_parser.feed(bytes, [this, &console](const ParseEvent &event) { print(event, console); });
}

int DecodeCommand::finish(Console &console)
{
    m_parser.finish([this, &console](const ParseEvent &event) { print(event, console); });
    console.flush();
    return m_sawFault ? kExitBadData : kExitOk;
}

int DecodeCommand::decodeArguments(const Options &options, Console &console)
{
    // Every argument is checked before anything is printed: bad hex yields no output at all.
    QByteArray bytes;
    for (qsizetype i = 0; i < options.hex.size(); ++i) {
        HexError error;
        const auto part = HexText::parse(options.hex.at(i).toUtf8(), &error);
        if (!part)
            return usageError(QStringLiteral("bad hex in argument %1, column %2: %3")
                                  .arg(i + 1)
                                  .arg(error.column)
                                  .arg(error.problem),
                              console);
        bytes += *part;
    }
    feed(bytes, console);
    return finish(console);
}

int DecodeCommand::decodeStdinText(Console &console)
{
    // Line by line as input arrives: positions are exact, output is live, and the lines before
    // a bad one are decoded and printed before the refusal.
    QByteArray pending = m_firstInput;
    int line = 1;
    for (;;) {
        const QByteArray chunk = console.readSome();
        pending += chunk;
        qsizetype start = 0;
        for (;;) {
            qsizetype end = pending.indexOf('\n', start);
            if (end < 0 && (!chunk.isEmpty() || start >= pending.size()))
                break; // wait for the rest of the line (or nothing is left at the end)
            end = end < 0 ? pending.size() : end + 1;
            HexError error;
            const auto bytes = HexText::parse(pending.mid(start, end - start), &error, line);
            if (!bytes) {
                console.flush();
                return usageError(QStringLiteral("bad hex on standard input, line %1, column "
                                                 "%2: %3")
                                      .arg(error.line)
                                      .arg(error.column)
                                      .arg(error.problem),
                                  console);
            }
            feed(*bytes, console);
            ++line;
            start = end;
        }
        pending.remove(0, start);
        console.flush();
        if (chunk.isEmpty())
            break;
    }
    if (console.inputFailed())
        return usageError(QStringLiteral("cannot read standard input"), console);
    return finish(console);
}

int DecodeCommand::decodeStdinBinary(Console &console)
{
    if (!m_firstInput.isEmpty())
        feed(m_firstInput, console);
    for (QByteArray chunk = console.readSome(); !chunk.isEmpty(); chunk = console.readSome()) {
        feed(chunk, console);
        console.flush();
    }
    if (console.inputFailed())
        return usageError(QStringLiteral("cannot read standard input"), console);
    return finish(console);
}

int DecodeCommand::decodeRecordingFile(const QString &path, Console &console)
{
    if (!isRecordingFile(path)) {
        QFile f(path);
        const QByteArray text = f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        if (recording::CandumpLog::looksLikeLog(text))
            return decodeCandump(text, console);
    }
    recording::RecordingReader reader;
    if (!reader.open(path))
        return usageError(reader.error().message, console);
    return decodeRecording(reader, console);
}

int DecodeCommand::decodeCandump(const QByteArray &text, Console &console)
{
    int badLine = 0;
    const std::optional<QByteArray> asRecording =
        recording::CandumpLog::toRecording(text, &badLine);
    recording::RecordingReader reader;
    if (!asRecording)
        return usageError(QStringLiteral("line %1 of the candump log is no CAN frame").arg(badLine),
                          console);
    if (!reader.openBytes(*asRecording))
        return usageError(reader.error().message, console);
    return decodeRecording(reader, console);
}

int DecodeCommand::run(const QStringList &args, Console &console)
{
    QString problem;
    const std::optional<Options> options = parseOptions(args, &problem);
    if (!options)
        return usageError(problem + QStringLiteral(" (see lkctl decode --help)"), console);
    m_parser.reset();
    m_context = options->context;
    m_generationById.clear();
    m_sawFault = false;
    if (!options->fromStdin && options->hex.size() == 1 && QFileInfo(options->hex.first()).isFile())
        return decodeRecordingFile(options->hex.first(), console);
    if (!options->fromStdin)
        return decodeArguments(*options, console);
    // A recording on standard input is told by its magic in the first bytes.
    m_firstInput.clear();
    for (QByteArray chunk = console.readSome(); !chunk.isEmpty(); chunk = console.readSome()) {
        m_firstInput += chunk;
        const QByteArray magic(recording::kMagic, sizeof recording::kMagic);
        if (m_firstInput.size() >= magic.size() || !magic.startsWith(m_firstInput))
            break; // enough to tell: live input is not held back
    }
    if (recording::RecordingReader::hasMagic(m_firstInput)) {
        for (QByteArray chunk = console.readSome(); !chunk.isEmpty(); chunk = console.readSome())
            m_firstInput += chunk;
        recording::RecordingReader reader;
        if (!reader.openBytes(m_firstInput))
            return usageError(reader.error().message, console);
        return decodeRecording(reader, console);
    }
    // A candump log is told by its first line: hex text is read by lines anyway.
    while (!options->binary && !m_firstInput.contains('\n')) {
        const QByteArray chunk = console.readSome();
        if (chunk.isEmpty())
            break;
        m_firstInput += chunk;
    }
    if (!options->binary && recording::CandumpLog::looksLikeLog(m_firstInput)) {
        for (QByteArray chunk = console.readSome(); !chunk.isEmpty(); chunk = console.readSome())
            m_firstInput += chunk;
        return decodeCandump(m_firstInput, console);
    }
    return options->binary ? decodeStdinBinary(console) : decodeStdinText(console);
}

} // namespace lk::lkctl
