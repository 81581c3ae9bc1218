#include "RecordEncoder.h"

#include "Crc32.h"
#include "RecordTags.h"
#include "Varint.h"

#include <protocol/Checksum.h>

namespace lk::recording {

namespace {

void putString(QByteArray &out, const QString &s)
{
    const QByteArray utf8 = s.toUtf8();
    varint::put(out, quint64(utf8.size()));
    out.append(utf8);
}

} // namespace

void RecordEncoder::putContext(QByteArray &out, const ContextSnapshot &context)
{
    varint::put(out, quint64(context.size()));
    for (const DriveContext &d : context) {
        out.append(char(quint8(d.id)));
        out.append(char(d.series ? quint8(int(*d.series) + 1) : quint8(0)));
        out.append(char(quint8(d.generation == protocol::Generation::V2_35 ? 1 : 0)));
    }
    // The drives the user chose follow, only when there are any: a context without a choice
    // is byte for byte what readers before this revision wrote, and those readers step over
    // the list (it lies past the entries they know, inside the record's or header's length).
    QByteArray chosen;
    for (const DriveContext &d : context) {
        if (d.chosen)
            chosen.append(char(quint8(d.id)));
    }
    if (chosen.isEmpty())
        return;
    varint::put(out, quint64(chosen.size()));
    out.append(chosen);
}

QByteArray RecordEncoder::encodeHeader(const RecordingHeader &header)
{
    QByteArray body;
    putString(body, header.toolVersion);
    body.append(char(quint8(header.linkKind)));
    putString(body, header.linkDescription);
    varint::putFixed<quint32>(body, quint32(header.baud));
    varint::putFixed<qint64>(body, header.wallClockStartMs);
    putContext(body, header.context);

    QByteArray out(kMagic, sizeof kMagic);
    varint::putFixed<quint16>(out, header.version);
    varint::putFixed<quint32>(out, quint32(body.size()));
    out.append(body);
    varint::putFixed<quint32>(out, crc32(out.constData(), out.size()));
    return out;
}

qint64 RecordEncoder::deltaFor(qint64 timeNs)
{
    if (m_payload.isEmpty())
        m_baseNs = m_lastNs = timeNs;
    // The session clock never goes back; a record made out of order is stamped with its
    // predecessor's time rather than given a negative delta.
    const qint64 delta = qMax<qint64>(0, timeNs - m_lastNs);
    m_lastNs += delta;
    return delta;
}

qsizetype RecordEncoder::pendingBytes() const
{
    // A pending chunk costs its bytes and a few of tag, length and delta.
    return m_payload.size() + (m_data ? m_data->bytes.size() + 4 : 0);
}

void RecordEncoder::appendMeta(quint8 type, qint64 delta, const QByteArray &payload)
{
    m_payload.append(char(tags::kMeta | type));
    varint::put(m_payload, quint64(delta));
    varint::put(m_payload, quint64(payload.size()));
    m_payload.append(payload);
}

void RecordEncoder::appendData(const RecordEvent &event)
{
    protocol::StreamParser &frames = event.kind == RecordEvent::Kind::Tx ? m_txFrames : m_rxFrames;
    bool ended = false; // a frame or a fault ended inside this chunk
    frames.feed(event.bytes, [&ended](const protocol::ParseEvent &) { ended = true; });
    // Only a frame's start and what continues it, at most a frame's length: bytes that form
    // no frame (garbage, a stream joined mid-frame) stay in records of their own chunks.
    const bool continues = m_data && m_data->kind == event.kind && m_data->insideFrame &&
                           m_data->bytes.startsWith(char(protocol::kFrameHead)) &&
                           event.timeNs >= m_data->timeNs &&
                           event.timeNs - m_data->timeNs <= kMergeGapNs &&
                           m_data->bytes.size() + event.bytes.size() <= protocol::kMaxFrameSize;
    if (continues) {
        m_data->bytes += event.bytes;
        m_data->timeNs = event.timeNs;
        m_data->insideFrame = !ended;
        return;
    }
    writePendingData();
    m_data = PendingData{event.kind, event.timeNs, event.bytes, !ended};
}

void RecordEncoder::writePendingData()
{
    if (!m_data)
        return;
    const PendingData data = std::move(*m_data);
    m_data.reset();
    const qint64 delta = deltaFor(data.timeNs);
    const quint8 dir = data.kind == RecordEvent::Kind::Tx ? tags::kTxBit : 0;
    const qsizetype n = data.bytes.size();
    if (n >= 1 && n <= tags::kMaxInlineLength) {
        m_payload.append(char(dir | quint8(n)));
    } else {
        m_payload.append(char(dir));
        varint::put(m_payload, quint64(n));
    }
    varint::put(m_payload, quint64(delta));
    m_payload.append(data.bytes);
}

void RecordEncoder::append(const RecordEvent &event)
{
    if (event.kind == RecordEvent::Kind::Rx || event.kind == RecordEvent::Kind::Tx) {
        appendData(event);
        return;
    }
    writePendingData();
    const qint64 delta = deltaFor(event.timeNs);
    QByteArray payload;
    switch (event.kind) {
    case RecordEvent::Kind::Rx:
    case RecordEvent::Kind::Tx:
        return; // above
    case RecordEvent::Kind::Link:
        // A link that opens, closes or changes baud starts new streams, for a reader too
        // (RecordedFrameParser); an error leaves them.
        if (event.link != LinkEventKind::Error) {
            m_rxFrames.reset();
            m_txFrames.reset();
        }
        payload.append(char(quint8(event.link)));
        varint::putFixed<quint32>(payload, quint32(event.baud));
        putString(payload, event.text);
        appendMeta(tags::kLink, delta, payload);
        return;
    case RecordEvent::Kind::Context:
        putContext(payload, event.context);
        appendMeta(tags::kContext, delta, payload);
        return;
    case RecordEvent::Kind::Dropped:
        varint::put(payload, event.droppedBytes);
        varint::put(payload, event.droppedChunks);
        appendMeta(tags::kDropped, delta, payload);
        return;
    }
}

QByteArray RecordEncoder::takeBlock()
{
    writePendingData();
    if (m_payload.isEmpty())
        return {};
    QByteArray block(kBlockSync, sizeof kBlockSync);
    block.reserve(kBlockHeaderSize + m_payload.size());
    varint::putFixed<quint32>(block, quint32(m_payload.size()));
    varint::putFixed<qint64>(block, m_baseNs);
    // The CRC covers length, base time and payload: a flipped length is found too.
    quint32 crc = crc32(block.constData() + 4, 12);
    crc = crc32(m_payload.constData(), m_payload.size(), crc);
    varint::putFixed<quint32>(block, crc);
    block.append(m_payload);
    m_payload.clear();
    return block;
}

} // namespace lk::recording
