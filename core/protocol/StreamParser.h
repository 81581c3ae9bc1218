#pragma once

#include "FrameParser.h"

#include <QtCore/QByteArray>

namespace lk::protocol {

/// Incremental parser for a byte stream of LK RS485 frames (the RS485 FrameParser).
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
class StreamParser : public FrameParser {
public:
    using FrameParser::feed;
    void feed(const char *data, qsizetype size, const Sink &sink) override;
    /// A chunk that is exactly one frame, and holds no more memory than its bytes, gives that
    /// frame its bytes shared, without a copy (a replay's records, a quiet bus's reads).
    void feed(const QByteArray &bytes, const Sink &sink) override;
    /// End of stream: a pending partial frame is reported as Truncated.
    void finish(const Sink &sink) override;
    /// Drop pending bytes without reporting them (e.g. after reopening a port).
    void reset() override
    {
        m_buf.clear();
        m_garbage.clear();
    }
    qsizetype pendingBytes() const override { return m_buf.size() + m_garbage.size(); }

private:
    void process(const Sink &sink);
    qsizetype consumeBadHeader(qsizetype pos, ParseError error, const Sink &sink);
    void emitError(ParseError error, qsizetype from, qsizetype count, const Sink &sink);
    void addGarbage(qsizetype from, qsizetype count, const Sink &sink);
    void flushGarbage(const Sink &sink);

    QByteArray m_buf;     ///< unconsumed bytes: at most one partial frame plus one input slice
    QByteArray m_garbage; ///< the current run of garbage, reported when it ends (or per 4 KiB)
    /// While feed(QByteArray) runs: the chunk, when m_buf holds it and nothing before it.
    const QByteArray *m_chunk = nullptr;
};

/// The seam's name for it: the parser of the RS485 link.
using Rs485StreamParser = StreamParser;

} // namespace lk::protocol
