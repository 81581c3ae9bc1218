#include "RecordingReader.h"

#include "Crc32.h"
#include "RecordTags.h"
#include "Varint.h"

#include <algorithm>

#include <QtCore/QBuffer>
#include <QtCore/QCoreApplication>
#include <QtCore/QFile>

namespace lk::recording {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("lk::recording::RecordingReader", text);
}

bool getString(const char *d, qsizetype end, qsizetype &pos, QString *out)
{
    quint64 n = 0;
    if (!varint::get(d, end, pos, n) || n > quint64(end - pos))
        return false;
    *out = QString::fromUtf8(d + pos, qsizetype(n));
    pos += qsizetype(n);
    return true;
}

bool getContext(const char *d, qsizetype end, qsizetype &pos, ContextSnapshot *out)
{
    quint64 n = 0;
    if (!varint::get(d, end, pos, n) || n > quint64(end - pos) / 3)
        return false;
    out->clear();
    for (quint64 i = 0; i < n; ++i, pos += 3) {
        DriveContext c;
        c.id = quint8(d[pos]);
        const quint8 series = quint8(d[pos + 1]);
        if (series > 4 || quint8(d[pos + 2]) > 1)
            return false;
        if (series > 0)
            c.series = protocol::Series(series - 1);
        c.generation = d[pos + 2] ? protocol::Generation::V2_35 : protocol::Generation::V2_3;
        out->append(c);
    }
    if (pos >= end)
        return true;
    // The drives the user chose (a later revision of version 1): varint count, then IDs, each
    // one of the entries above.
    quint64 m = 0;
    if (!varint::get(d, end, pos, m) || m > quint64(end - pos))
        return false;
    for (quint64 i = 0; i < m; ++i, ++pos) {
        const int id = quint8(d[pos]);
        const auto it = std::find_if(out->begin(), out->end(),
                                     [id](const DriveContext &c) { return c.id == id; });
        if (it == out->end())
            return false;
        it->chosen = true;
    }
    return true;
}

} // namespace

bool RecordingReader::hasMagic(const QByteArray &bytes)
{
    return bytes.startsWith(QByteArray::fromRawData(kMagic, sizeof kMagic));
}

bool RecordingReader::open(const QString &path)
{
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::ReadOnly))
        return fail(RecordingError::Kind::OpenFailed, -1,
                    tr("Cannot open the recording %1: %2.").arg(path, file->errorString()));
    return openDevice(std::move(file), path);
}

bool RecordingReader::openBytes(const QByteArray &bytes)
{
    auto buffer = std::make_unique<QBuffer>();
    buffer->setData(bytes);
    buffer->open(QIODevice::ReadOnly);
    return openDevice(std::move(buffer), tr("standard input"));
}

bool RecordingReader::openDevice(std::unique_ptr<QIODevice> device, const QString &name)
{
    m_device = std::move(device);
    m_name = name;
    m_error = {};
    m_block.clear();
    m_pos = 0;
    return readHeader();
}

bool RecordingReader::fail(RecordingError::Kind kind, qint64 offset, const QString &message)
{
    m_error = RecordingError{kind, offset, message};
    m_block.clear();
    m_pos = 0;
    return false;
}

qint64 RecordingReader::size() const
{
    return m_device ? m_device->size() : 0;
}

bool RecordingReader::readHeader()
{
    const QByteArray fixed = m_device->read(sizeof kMagic + 6);
    if (!hasMagic(fixed))
        return fail(RecordingError::Kind::NotARecording, 0,
                    tr("%1 is not an LK Servo Studio recording (no recording magic).").arg(m_name));
    if (fixed.size() < qsizetype(sizeof kMagic + 6))
        return fail(RecordingError::Kind::Truncated, fixed.size(),
                    tr("The recording %1 ends inside its header, at byte offset %2.")
                        .arg(m_name)
                        .arg(fixed.size()));
    m_header = {};
    m_header.version = varint::getFixed<quint16>(fixed.constData() + 8);
    if (m_header.version != kFormatVersion)
        return fail(RecordingError::Kind::UnsupportedVersion, 8,
                    tr("The recording %1 has format version %2; this build reads version %3.")
                        .arg(m_name)
                        .arg(m_header.version)
                        .arg(kFormatVersion));
    const quint32 length = varint::getFixed<quint32>(fixed.constData() + 10);
    const QByteArray rest = length > kMaxBlockPayload ? QByteArray() : m_device->read(length + 4);
    if (length > kMaxBlockPayload || rest.size() < qsizetype(length) + 4)
        return fail(RecordingError::Kind::Truncated, fixed.size() + rest.size(),
                    tr("The recording %1 ends inside its header, at byte offset %2.")
                        .arg(m_name)
                        .arg(fixed.size() + rest.size()));
    quint32 crc = crc32(fixed.constData(), fixed.size());
    crc = crc32(rest.constData(), length, crc);
    const char *d = rest.constData();
    qsizetype pos = 0;
    quint8 kind = 0;
    bool ok = crc == varint::getFixed<quint32>(d + length) &&
              getString(d, length, pos, &m_header.toolVersion) && pos < qsizetype(length);
    if (ok) {
        kind = quint8(d[pos++]);
        ok = getString(d, length, pos, &m_header.linkDescription) && pos + 12 <= qsizetype(length);
    }
    if (ok) {
        m_header.linkKind = LinkKind(kind);
        m_header.baud = int(varint::getFixed<quint32>(d + pos));
        m_header.wallClockStartMs = varint::getFixed<qint64>(d + pos + 4);
        pos += 12;
        ok = getContext(d, length, pos, &m_header.context);
    }
    if (!ok)
        return fail(
            RecordingError::Kind::DamagedHeader, 0,
            tr("The header of the recording %1 is damaged (checksum or layout).").arg(m_name));
    m_firstBlockOffset = m_device->pos();
    return true;
}

bool RecordingReader::readBlock()
{
    m_blockOffset = m_device->pos();
    const QByteArray head = m_device->read(kBlockHeaderSize);
    if (head.isEmpty())
        return false; // a clean end
    const auto truncated = [this](qint64 at) {
        return fail(RecordingError::Kind::Truncated, at,
                    tr("The recording %1 ends inside a block at byte offset %2 (the writer "
                       "stopped there); it was read up to that point.")
                        .arg(m_name)
                        .arg(at));
    };
    const auto damaged = [this](qint64 at, const QString &why) {
        return fail(RecordingError::Kind::Damaged, at,
                    tr("The recording %1 is damaged at byte offset %2 (%3); it was read up to "
                       "that point.")
                        .arg(m_name)
                        .arg(at)
                        .arg(why));
    };
    if (head.size() < kBlockHeaderSize)
        return truncated(m_blockOffset);
    if (!head.startsWith(QByteArray::fromRawData(kBlockSync, sizeof kBlockSync)))
        return damaged(m_blockOffset, tr("no block starts there"));
    const quint32 length = varint::getFixed<quint32>(head.constData() + 4);
    if (length == 0 || length > kMaxBlockPayload)
        return damaged(m_blockOffset, tr("impossible block length"));
    QByteArray payload = m_device->read(length);
    if (payload.size() < qsizetype(length))
        return truncated(m_blockOffset);
    quint32 crc = crc32(head.constData() + 4, 12);
    crc = crc32(payload.constData(), payload.size(), crc);
    if (crc != varint::getFixed<quint32>(head.constData() + 16))
        return damaged(m_blockOffset, tr("block checksum mismatch"));
    m_block = std::move(payload);
    m_pos = 0;
    m_timeNs = varint::getFixed<qint64>(head.constData() + 8);
    return true;
}

RecordingReader::Decoded RecordingReader::decodeRecord(RecordEvent *event)
{
    const char *d = m_block.constData();
    const qsizetype end = m_block.size();
    const qsizetype start = m_pos;
    const quint8 tag = quint8(d[m_pos++]);
    quint64 delta = 0;
    quint64 n = 0;
    bool ok = true;
    if (!(tag & tags::kMeta)) {
        n = tag & tags::kLengthMask;
        if (n == 0)
            ok = varint::get(d, end, m_pos, n);
        ok = ok && varint::get(d, end, m_pos, delta) && n <= quint64(end - m_pos);
        if (ok) {
            *event = RecordEvent::data((tag & tags::kTxBit) ? RecordEvent::Kind::Tx
                                                            : RecordEvent::Kind::Rx,
                                       0, QByteArray(d + m_pos, qsizetype(n)));
            m_pos += qsizetype(n);
        }
    } else {
        ok = varint::get(d, end, m_pos, delta) && varint::get(d, end, m_pos, n) &&
             n <= quint64(end - m_pos);
        const qsizetype payloadEnd = ok ? m_pos + qsizetype(n) : 0;
        qsizetype p = m_pos;
        *event = RecordEvent{};
        switch (tag & ~tags::kMeta) {
        case tags::kLink:
            ok = ok && p + 5 <= payloadEnd;
            if (ok) {
                event->kind = RecordEvent::Kind::Link;
                event->link = LinkEventKind(quint8(d[p]));
                event->baud = int(varint::getFixed<quint32>(d + p + 1));
                p += 5;
                ok = getString(d, payloadEnd, p, &event->text);
            }
            break;
        case tags::kContext:
            event->kind = RecordEvent::Kind::Context;
            ok = ok && getContext(d, payloadEnd, p, &event->context);
            break;
        case tags::kDropped:
            event->kind = RecordEvent::Kind::Dropped;
            ok = ok && varint::get(d, payloadEnd, p, event->droppedBytes) &&
                 varint::get(d, payloadEnd, p, event->droppedChunks);
            break;
        default:
            // A meta record of a later minor revision: its length lets us step over it.
            if (!ok)
                break;
            m_pos = payloadEnd;
            m_timeNs += qint64(delta);
            return Decoded::Skipped;
        }
        m_pos = payloadEnd;
    }
    if (!ok) {
        fail(RecordingError::Kind::Damaged, m_blockOffset + kBlockHeaderSize + start,
             tr("The recording %1 is damaged at byte offset %2 (a record's layout is wrong); it "
                "was read up to that point.")
                 .arg(m_name)
                 .arg(m_blockOffset + kBlockHeaderSize + start));
        return Decoded::Failed;
    }
    m_timeNs += qint64(delta);
    event->timeNs = m_timeNs;
    return Decoded::Record;
}

bool RecordingReader::next(RecordEvent *event)
{
    if (!m_device || m_error.isError())
        return false;
    for (;;) {
        while (m_pos >= m_block.size()) {
            if (!readBlock())
                return false;
        }
        switch (decodeRecord(event)) {
        case Decoded::Record:
            return true;
        case Decoded::Failed:
            return false;
        case Decoded::Skipped:
            break;
        }
    }
}

QVector<RecordingReader::Block> RecordingReader::index()
{
    QVector<Block> blocks;
    if (!m_device || !seek(Block{m_firstBlockOffset, 0}))
        return blocks;
    while (readBlock()) {
        blocks.append(Block{m_blockOffset, m_timeNs});
        m_lastTimeNs = m_timeNs;
    }
    m_indexDamage = m_error;
    if (!blocks.isEmpty() && seek(blocks.last()) && readBlock()) {
        // The last record's time: decode the last good block once.
        RecordEvent e;
        while (m_pos < m_block.size() && decodeRecord(&e) != Decoded::Failed)
            m_lastTimeNs = m_timeNs;
    }
    // Reading starts again at the first block; next() meets the damage where it is.
    seek(Block{m_firstBlockOffset, 0});
    return blocks;
}

bool RecordingReader::seek(const Block &block)
{
    if (!m_device || !m_device->seek(block.offset))
        return false;
    m_error = {};
    m_block.clear();
    m_pos = 0;
    return true;
}

} // namespace lk::recording
