#pragma once

#include "Frame.h"

#include <QtCore/QByteArray>

#include <functional>

namespace lk::protocol {

/// What went wrong with some bytes of a stream (names as in CLI.md).
enum class ParseError {
    BadHeaderChecksum,
    BadDataChecksum,
    BadLength,      ///< LEN over 60, or a LEN the command never carries (checksums were fine)
    UnknownCommand, ///< checksums fine, command code not in the table
    Garbage,        ///< bytes skipped while looking for the next 0x3E
    Truncated,      ///< the stream ended inside a frame
};
const char *parseErrorName(ParseError e); ///< "bad_header_checksum", ...

/// One result of parsing: a valid frame, or a fault with the bytes it covers.
struct ParseEvent {
    bool isFrame = false;
    Frame frame; ///< set for frames, and for UnknownCommand/BadLength (checksums were valid)
    FrameDirection direction = FrameDirection::Request; ///< meaningful when isFrame
    ParseError error = ParseError::Garbage;             ///< meaningful when !isFrame
    QByteArray bytes;                                   ///< the raw bytes this event consumed
};

/// Incremental parser for a byte stream of LK frames.
///
/// Feed it chunks of any size; it calls the sink for every frame or fault, in stream order,
/// and resynchronises on the next 0x3E after any fault. Every input byte is reported exactly
/// once (in a frame or in an error). Between calls it holds at most one partial frame (fewer
/// than kMaxFrameSize bytes) and one run of garbage (fewer than 4096 bytes: a run that reaches
/// 4 KiB is reported), so pendingBytes() stays below kMaxFrameSize + 4096; it never reads past
/// its buffer and never decodes a short frame.
/// A run of garbage is reported when the next 0x3E ends it (or at 4 KiB, or at finish()), so
/// the events do not depend on how the input was chunked. Events for BadLength,
/// UnknownCommand and BadDataChecksum carry the frame's command and ID.
class StreamParser {
public:
    using Sink = std::function<void(const ParseEvent &)>;

    void feed(const char *data, qsizetype size, const Sink &sink);
    void feed(const QByteArray &bytes, const Sink &sink)
    {
        feed(bytes.constData(), bytes.size(), sink);
    }
    /// End of stream: a pending partial frame is reported as Truncated.
    void finish(const Sink &sink);
    /// Drop pending bytes without reporting them (e.g. after reopening a port).
    void reset()
    {
        m_buf.clear();
        m_garbage.clear();
    }
    qsizetype pendingBytes() const { return m_buf.size() + m_garbage.size(); }

private:
    void process(const Sink &sink);
    qsizetype consumeBadHeader(qsizetype pos, ParseError error, const Sink &sink);
    void emitError(ParseError error, qsizetype from, qsizetype count, const Sink &sink);
    void addGarbage(qsizetype from, qsizetype count, const Sink &sink);
    void flushGarbage(const Sink &sink);

    QByteArray m_buf;     ///< unconsumed bytes: at most one partial frame plus one input slice
    QByteArray m_garbage; ///< the current run of garbage, reported when it ends (or per 4 KiB)
};

} // namespace lk::protocol
