#pragma once

#include "RecordEncoder.h"
#include "RecordSink.h"

#include <deque>
#include <mutex>
#include <optional>

namespace lk::recording {

/// The always-on recorder: the last `window` (default 10 minutes) of the link in memory,
/// bounded in bytes too, kept encoded (about 1.5x the wire bytes) in one-second blocks; saved
/// on demand as a recording file. append() comes from the bus thread, saveLast() and events()
/// from any other.
class BlackBox : public RecordSink {
public:
    struct Limits {
        qint64 windowNs = 10LL * 60 * 1'000'000'000;
        qsizetype maxBytes = 128 * 1024 * 1024;
        qint64 blockNs = 1'000'000'000; ///< a block spans at most this (eviction granularity)
        qsizetype blockBytes = 64 * 1024;
    };

    /// `header`: the link and tool the saved files name; its context is the one in force
    /// before the first record.
    explicit BlackBox(RecordingHeader header) : BlackBox(std::move(header), Limits{}) {}
    BlackBox(RecordingHeader header, Limits limits);

    void append(RecordEvent event) override;
    /// The link and tool the ring was made on (its context: the one at the start).
    const RecordingHeader &header() const { return m_header; }

    /// Write what the ring holds to `path`; the path, or the error that stopped it.
    struct SaveResult {
        QString path;
        std::optional<RecordingError> error;
    };
    SaveResult saveLast(const QString &path) const;

    /// The ring as records, oldest first (for the Traffic view), and the decode context in
    /// force before the first of them.
    QVector<RecordEvent> events(ContextSnapshot *contextBefore = nullptr) const;
    /// How much the ring keeps from now on (the oldest blocks go with the next record).
    void setWindowNs(qint64 windowNs);
    qint64 windowNs() const;
    /// Bytes the ring holds (encoded) and the time it spans.
    qsizetype bytes() const;
    qint64 spanNs() const;

private:
    struct Block {
        QByteArray bytes;
        qint64 firstNs = 0;
        qint64 lastNs = 0;
        ContextSnapshot contextBefore;
        int baudBefore = 0;
    };
    QByteArray snapshot(RecordingHeader *header) const;
    void closeBlock();
    void evict(qint64 newestNs);

    RecordingHeader m_header;
    Limits m_limits;
    mutable std::mutex m_mutex;
    std::deque<Block> m_blocks;
    qsizetype m_blockBytes = 0; ///< in m_blocks
    RecordEncoder m_current;
    Block m_open; ///< the current block's times and context (bytes in m_current)
    bool m_hasOpen = false;
    ContextSnapshot m_context; ///< in force after the last record
    int m_baud = 0;
};

} // namespace lk::recording
