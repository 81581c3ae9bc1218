#pragma once

#include "TrafficEvent.h"

namespace lk::bus {

/// Bounded buffer of traffic events between two deliveries of the traffic view. Records
/// nothing while disabled; past the bound it drops events and says how many in a Note.
class TrafficRecorder {
public:
    static constexpr int kMaxPending = 4096;

    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    void record(TrafficEvent event);
    /// A timeout or a note (events without a frame).
    void record(TrafficEvent::Kind kind, double time, const QByteArray &bytes, int id,
                quint8 command, const QString &text = {});
    /// A request as written: `bytes` is one frame the host encoded itself, so it is taken
    /// apart without a parser. `context` is how its ID decodes now.
    void recordSent(double time, const QByteArray &bytes, const protocol::DecodeContext &context);
    /// A frame or a fault from the stream parser; `context` is how the frame's ID decodes now.
    void recordParseEvent(const protocol::ParseEvent &event, double time,
                          const protocol::DecodeContext &context);
    bool hasPending() const { return !m_pending.isEmpty() || m_dropped > 0; }
    /// The events since the last take (with a Note for drops); empties the buffer.
    TrafficBatch take(double now);

private:
    /// Whether an event may be kept now; counts it as dropped when the buffer is full.
    bool admit();

    bool m_enabled = false;
    TrafficBatch m_pending;
    quint64 m_dropped = 0;
};

} // namespace lk::bus
