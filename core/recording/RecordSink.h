#pragma once

#include "RecordingFormat.h"

#include <memory>
#include <vector>

namespace lk::recording {

/// Where a RecordingTransport hands what passed the link: the file writer, the black box's
/// ring, or both. append() is called on the bus thread, so it must be cheap and never block on
/// I/O.
class RecordSink {
public:
    virtual ~RecordSink() = default;
    virtual void append(RecordEvent event) = 0;
};

/// Hands every record to several sinks (a session recording and the black box at once).
class RecordFanout : public RecordSink {
public:
    explicit RecordFanout(std::vector<std::shared_ptr<RecordSink>> sinks)
        : m_sinks(std::move(sinks))
    {
    }
    void append(RecordEvent event) override
    {
        for (const auto &sink : m_sinks)
            sink->append(event);
    }

private:
    std::vector<std::shared_ptr<RecordSink>> m_sinks;
};

} // namespace lk::recording
