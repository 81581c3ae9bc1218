#include "CandumpLog.h"

#include "RecordEncoder.h"
#include "RecordingReader.h"

#include <QtCore/QRegularExpression>

namespace lk::recording {

using protocol::CanRecord;

QString CandumpLog::interfaceOf(const RecordingHeader &header)
{
    // "PLUGIN:INTERFACE @ RATE" as the GUI and lkctl describe a CAN link.
    static const QRegularExpression re(QStringLiteral(R"(^[^:\s]+:(\S+?)(?:\s+@.*)?$)"));
    const QRegularExpressionMatch m = re.match(header.linkDescription);
    if (!m.hasMatch())
        return QStringLiteral("can0");
    const QString name = m.captured(1);
    // virtualcan's "tcp://127.0.0.1:35468/can0": the last part.
    return name.section(QLatin1Char('/'), -1);
}

void CandumpLog::forEachFrame(RecordingReader &reader,
                              const std::function<void(qint64, const CanRecord &)> &frame)
{
    RecordEvent e;
    while (reader.next(&e)) {
        if (e.kind != RecordEvent::Kind::Rx && e.kind != RecordEvent::Kind::Tx)
            continue;
        for (qsizetype at = 0; at + CanRecord::kSize <= e.bytes.size(); at += CanRecord::kSize) {
            const std::optional<CanRecord> r = CanRecord::decode(e.bytes.constData() + at);
            if (r && !(e.kind == RecordEvent::Kind::Rx && r->isEcho()))
                frame(e.timeNs, *r); // a looped-back frame: its transmitted copy is the one
        }
    }
}

qint64 CandumpLog::write(RecordingReader &reader, QIODevice &out)
{
    if (linkOf(reader.header()) != protocol::Link::Can)
        return -1;
    const QString iface = interfaceOf(reader.header());
    const qint64 startUs = reader.header().wallClockStartMs * 1000;
    qint64 frames = 0;
    forEachFrame(reader, [&](qint64 timeNs, const CanRecord &record) {
        CanRecord r = record;
        r.timestampUs = startUs + timeNs / 1000;
        out.write(r.candumpLogLine(iface).toLatin1() + '\n');
        ++frames;
    });
    return frames;
}

std::optional<CanRecord> CandumpLog::parseLine(const QString &line)
{
    if (std::optional<CanRecord> r = CanRecord::fromCandump(line))
        return r;
    // candump's default form, "(time) " when asked for: "can0  141   [8]  9C 00 00 00 ...",
    // error frames with a trailing "ERRORFRAME" and the flag in their 8-digit ID.
    static const QRegularExpression re(QStringLiteral(
        R"(^\s*(\(\d+\.\d+\)\s+)?\S+\s+([0-9A-Fa-f]{3}|[0-9A-Fa-f]{8})\s+\[(\d)\]((?:\s+[0-9A-Fa-f]{2})*)(?:\s+ERRORFRAME.*)?\s*$)"));
    const QRegularExpressionMatch m = re.match(line);
    if (!m.hasMatch())
        return std::nullopt;
    const QString data = m.captured(4).simplified().remove(QLatin1Char(' '));
    if (data.size() != 2 * m.captured(3).toInt())
        return std::nullopt;
    const QString prefix =
        m.captured(1).isEmpty() ? QString() : m.captured(1).trimmed() + QStringLiteral(" can ");
    return CanRecord::fromCandump(prefix + m.captured(2) + QLatin1Char('#') + data);
}

bool CandumpLog::looksLikeLog(const QByteArray &text)
{
    for (const QByteArray &line : text.split('\n')) {
        if (line.trimmed().isEmpty())
            continue;
        return parseLine(QString::fromLatin1(line)).has_value();
    }
    return false;
}

std::optional<QByteArray> CandumpLog::toRecording(const QByteArray &text, int *badLine)
{
    RecordingHeader header;
    header.linkKind = LinkKind::Can;
    header.linkDescription = QStringLiteral("candump log");
    RecordEncoder encoder;
    QByteArray body;
    std::optional<qint64> firstUs;
    int lineNo = 0;
    for (const QByteArray &line : text.split('\n')) {
        ++lineNo;
        if (line.trimmed().isEmpty())
            continue;
        const std::optional<CanRecord> r = parseLine(QString::fromLatin1(line));
        if (!r) {
            if (badLine)
                *badLine = lineNo;
            return std::nullopt;
        }
        if (!firstUs) {
            firstUs = r->timestampUs;
            header.wallClockStartMs = r->timestampUs / 1000;
        }
        const qint64 timeNs = std::max<qint64>(0, r->timestampUs - *firstUs) * 1000;
        encoder.append(RecordEvent::data(RecordEvent::Kind::Rx, timeNs, r->encode()));
        if (encoder.pendingBytes() >= 64 * 1024)
            body += encoder.takeBlock();
    }
    body += encoder.takeBlock();
    return RecordEncoder::encodeHeader(header) + body;
}

} // namespace lk::recording
