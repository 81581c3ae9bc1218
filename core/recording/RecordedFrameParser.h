#pragma once

#include "RecordingFormat.h"

#include <protocol/StreamParser.h>

#include <functional>

namespace lk::recording {

/// One frame or fault of a recording, with when and which way it passed.
struct RecordedFrame {
    qint64 timeNs = 0;
    bool transmitted = false; ///< sent by the recording tool (tx); else received (rx)
    protocol::ParseEvent event;
    protocol::DecodeContext context; ///< how its ID decoded at that moment
};

/// Parses a recording's data records into frames: tx and rx are separate streams (each its
/// own StreamParser), a link that closes or reopens ends both, context records change how
/// later frames decode.
class RecordedFrameParser {
public:
    using Sink = std::function<void(const RecordedFrame &)>;

    explicit RecordedFrameParser(ContextSnapshot context) : m_context(std::move(context)) {}

    void feed(const RecordEvent &record, const Sink &sink);
    /// End of the recording: a partial frame or garbage left is reported.
    void finish(const Sink &sink);
    const ContextSnapshot &context() const { return m_context; }

private:
    void parse(bool transmitted, const QByteArray &bytes, const Sink &sink);
    void finishStream(bool transmitted, const Sink &sink);

    ContextSnapshot m_context;
    protocol::StreamParser m_rx;
    protocol::StreamParser m_tx;
    qint64 m_timeNs = 0;
};

/// The decode context of `id` in a snapshot (unknown series decodes as MF).
protocol::DecodeContext decodeContextOf(const ContextSnapshot &snapshot, int id);

} // namespace lk::recording
