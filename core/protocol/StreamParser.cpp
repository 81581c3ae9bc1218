#include "StreamParser.h"

#include "Checksum.h"
#include "Command.h"

#include <algorithm>

namespace lk::protocol {

namespace {
/// `count` bytes of `buf` from `from`, in an allocation of their own. QByteArray::mid() returns
/// the whole buffer, shared, when the range covers it (a chunk holding one frame): an event
/// kept by a view (a Traffic row of the black box) then held the parser's reserved buffer,
/// about 4 KiB a frame, hundreds of MB for a ring of traffic.
QByteArray copyOf(const QByteArray &buf, qsizetype from, qsizetype count)
{
    return QByteArray(buf.constData() + from, count);
}

// Input is taken in slices so that the internal buffer stays bounded whatever the chunk size.
constexpr qsizetype kSlice = 4096;

quint8 at(const QByteArray &b, qsizetype i)
{
    return static_cast<quint8>(b.constData()[i]);
}
} // namespace

const char *parseErrorName(ParseError e)
{
    switch (e) {
    case ParseError::BadHeaderChecksum:
        return "bad_header_checksum";
    case ParseError::BadDataChecksum:
        return "bad_data_checksum";
    case ParseError::BadLength:
        return "bad_length";
    case ParseError::UnknownCommand:
        return "unknown_command";
    case ParseError::Garbage:
        return "garbage";
    case ParseError::Truncated:
        return "truncated";
    }
    return "?";
}

void StreamParser::feed(const char *data, qsizetype size, const Sink &sink)
{
    if (m_buf.capacity() < kMaxFrameSize + kSlice)
        m_buf.reserve(kMaxFrameSize + kSlice);
    for (qsizetype off = 0; off < size; off += kSlice) {
        m_buf.append(data + off, std::min(kSlice, size - off));
        process(sink);
    }
}

void StreamParser::feed(const QByteArray &bytes, const Sink &sink)
{
    // Shared only when the chunk's allocation is its bytes (not a reserved read buffer: see
    // copyOf) and it lands alone at the start of the buffer.
    constexpr qsizetype kSlack = 32;
    const bool shareable = m_buf.isEmpty() && m_garbage.isEmpty() && bytes.size() <= kSlice &&
                           bytes.capacity() >= bytes.size() && // not fromRawData
                           bytes.capacity() <= bytes.size() + kSlack;
    m_chunk = shareable ? &bytes : nullptr;
    feed(bytes.constData(), bytes.size(), sink);
    m_chunk = nullptr;
}

void StreamParser::finish(const Sink &sink)
{
    process(sink);
    while (!m_buf.isEmpty()) {
        // process() leaves only a partial frame starting at 0x3E behind. Its header may have
        // promised more than ever came, so only the bytes up to the next 0x3E are truncated:
        // a complete frame after them is still found.
        const auto next = m_buf.indexOf(static_cast<char>(kFrameHead), 1);
        const qsizetype cut = next < 0 ? m_buf.size() : next;
        emitError(ParseError::Truncated, 0, cut, sink);
        m_buf.remove(0, cut);
        process(sink);
    }
    flushGarbage(sink);
}

void StreamParser::addGarbage(qsizetype from, qsizetype count, const Sink &sink)
{
    m_garbage.append(m_buf.constData() + from, count);
    while (m_garbage.size() >= kSlice) {
        ParseEvent ev;
        ev.error = ParseError::Garbage;
        ev.bytes = m_garbage.left(kSlice);
        m_garbage.remove(0, kSlice);
        sink(ev);
    }
}

void StreamParser::flushGarbage(const Sink &sink)
{
    if (m_garbage.isEmpty())
        return;
    ParseEvent ev;
    ev.error = ParseError::Garbage;
    ev.bytes = m_garbage;
    m_garbage.clear();
    sink(ev);
}

void StreamParser::emitError(ParseError error, qsizetype from, qsizetype count, const Sink &sink)
{
    flushGarbage(sink); // keep stream order: the garbage run came first
    ParseEvent ev;
    ev.isFrame = false;
    ev.error = error;
    ev.bytes = copyOf(m_buf, from, count);
    sink(ev);
}

// A header that cannot start a frame: consume its 0x3E and the bytes after it up to (not
// including) the next 0x3E inside the header, so that a real frame starting there is found.
qsizetype StreamParser::consumeBadHeader(qsizetype pos, ParseError error, const Sink &sink)
{
    qsizetype k = 1;
    while (k < kHeaderSize && at(m_buf, pos + k) != kFrameHead)
        ++k;
    flushGarbage(sink);
    ParseEvent ev;
    ev.error = error;
    ev.bytes = copyOf(m_buf, pos, k);
    if (error == ParseError::BadLength) { // the header checksum held: its fields are real
        ev.frame.command = at(m_buf, pos + 1);
        ev.frame.id = at(m_buf, pos + 2);
    }
    sink(ev);
    return pos + k;
}

void StreamParser::process(const Sink &sink)
{
    qsizetype pos = 0;
    const auto n = [this] { return m_buf.size(); };
    while (pos < n()) {
        // Skip to the next frame head; what lies before it is garbage.
        if (at(m_buf, pos) != kFrameHead) {
            const char *start = m_buf.constData() + pos;
            const void *head = memchr(start, kFrameHead, static_cast<size_t>(n() - pos));
            const qsizetype end = head ? static_cast<const char *>(head) - m_buf.constData() : n();
            addGarbage(pos, end - pos, sink);
            pos = end;
            continue;
        }
        flushGarbage(sink); // a frame head ends the garbage run
        if (n() - pos < kHeaderSize)
            break; // wait for the rest of the header
        const quint8 cmd = at(m_buf, pos + 1);
        const quint8 id = at(m_buf, pos + 2);
        const quint8 len = at(m_buf, pos + 3);
        if (at(m_buf, pos + 4) != headerChecksum(cmd, id, len)) {
            pos = consumeBadHeader(pos, ParseError::BadHeaderChecksum, sink);
            continue;
        }
        if (len > kMaxDataLength) {
            pos = consumeBadHeader(pos, ParseError::BadLength, sink);
            continue;
        }
        const qsizetype frameSize = kHeaderSize + len + (len > 0 ? 1 : 0);
        if (n() - pos < frameSize)
            break; // wait for the rest of the frame
        ParseEvent ev;
        ev.bytes = m_chunk && pos == 0 && frameSize == m_chunk->size()
                       ? *m_chunk
                       : copyOf(m_buf, pos, frameSize);
        ev.frame.command = cmd;
        ev.frame.id = id;
        ev.frame.data = copyOf(m_buf, pos + kHeaderSize, len);
        pos += frameSize;
        if (len > 0 && at(ev.bytes, frameSize - 1) != byteSum(ev.frame.data.constData(), len)) {
            // The header is trusted (its checksum is good), so the whole frame is consumed.
            ev.error = ParseError::BadDataChecksum;
            sink(ev);
            continue;
        }
        const std::optional<FrameDirection> dir = ev.frame.direction();
        if (!CommandTable::findOnRs485(cmd)) {
            ev.error = ParseError::UnknownCommand;
        } else if (!dir) {
            ev.error = ParseError::BadLength;
        } else {
            ev.isFrame = true;
            ev.direction = *dir;
        }
        sink(ev);
    }
    m_buf.remove(0, pos);
}

} // namespace lk::protocol
