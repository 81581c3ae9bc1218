#pragma once

#include "RecordingFormat.h"

#include <protocol/FrameParser.h>

#include <functional>
#include <memory>

namespace lk::recording {

/// One frame or fault of a recording, with when and which way it passed.
struct RecordedFrame {
    qint64 timeNs = 0;
    bool transmitted = false; ///< sent by the recording tool (tx); else received (rx)
    protocol::ParseEvent event;
    protocol::DecodeContext context; ///< how its ID decoded at that moment (its link included)
};

/// Parses a recording's data records into frames: tx and rx are separate streams (each its
/// own frame parser of the recording's link: RS485 bytes, or CAN records), a link that closes
/// or reopens ends both, context records change how later frames decode. On CAN a received
/// frame's direction is the one a listener tells (bus::PassivePairing::canDirections): the
/// tool's own frames are requests, what it heard a reply unless it has a request's layout on
/// 0x140+ID. A multi-motor torque frame (0x280), the tool's own or another master's, is a
/// request of no drive: event.frame is empty (ID 0, command 0), event.canId says 0x280, its
/// bytes the slots.
class RecordedFrameParser {
public:
    using Sink = std::function<void(const RecordedFrame &)>;

    explicit RecordedFrameParser(ContextSnapshot context,
                                 protocol::Link link = protocol::Link::Rs485);

    void feed(const RecordEvent &record, const Sink &sink);
    /// End of the recording: a partial frame or garbage left is reported.
    void finish(const Sink &sink);
    const ContextSnapshot &context() const { return m_context; }
    protocol::Link link() const { return m_link; }

private:
    void parse(bool transmitted, const QByteArray &bytes, const Sink &sink);
    void finishStream(bool transmitted, const Sink &sink);
    void emitEvent(bool transmitted, protocol::ParseEvent event, const Sink &sink);

    ContextSnapshot m_context;
    protocol::Link m_link;
    std::unique_ptr<protocol::FrameParser> m_rx;
    std::unique_ptr<protocol::FrameParser> m_tx;
    qint64 m_timeNs = 0;
};

/// What a received CAN reply says of its drive's generation (a reply on 0x180+ID, a 0x9A
/// layout: protocol::can::generationHint), put into `context` as the live engine learns it
/// before it decodes that reply, unless the user chose the drive's generation
/// (DriveContext::chosen); true when the context changed.
bool learnCanGeneration(ContextSnapshot &context, const protocol::ParseEvent &reply);

/// The decode context of `id` in a snapshot (unknown series decodes as MF) on `link`.
protocol::DecodeContext decodeContextOf(const ContextSnapshot &snapshot, int id,
                                        protocol::Link link = protocol::Link::Rs485);

} // namespace lk::recording
