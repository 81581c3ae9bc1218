#pragma once

#include <recording/RecordSink.h>
#include <recording/RecordedFrameParser.h>

#include <bus/TrafficEvent.h>

#include <mutex>

namespace lk::ui {

/// A copy of the records that reach the black box, kept while the Traffic view looks (bus
/// thread in, GUI thread out), and turned into traffic rows with a parser that carries a frame
/// split across chunks from one take() to the next. Bounded: past `maxPending` records it
/// stops copying and says so (overflowed()), and the view reloads the ring instead.
class RingTrafficTap : public recording::RecordSink {
public:
    explicit RingTrafficTap(qsizetype maxPending = 200000) : m_maxPending(maxPending) {}

    void append(recording::RecordEvent event) override;

    /// Start copying (dropping what was pending) or stop.
    void setEnabled(bool on);
    bool isEnabled() const;
    /// The records copied since the last take(); `overflowed` is set when some were not.
    QVector<recording::RecordEvent> take(bool *overflowed = nullptr);

private:
    mutable std::mutex m_mutex;
    QVector<recording::RecordEvent> m_pending;
    qsizetype m_maxPending;
    bool m_enabled = false;
    bool m_overflowed = false;
};

/// Records to traffic rows, one stream at a time (the ring first, then what the tap copies):
/// tx frames as Sent, rx frames as Frame (direction by LEN), bytes that form no frame as
/// Fault, link events and drops as Notes; each frame with the decode context of its moment.
class RecordTrafficConverter {
public:
    explicit RecordTrafficConverter(recording::ContextSnapshot context = {},
                                    protocol::Link link = protocol::Link::Rs485)
        : m_parser(std::move(context), link)
    {
    }
    bus::TrafficBatch convert(const QVector<recording::RecordEvent> &records);

private:
    recording::RecordedFrameParser m_parser;
};

} // namespace lk::ui
