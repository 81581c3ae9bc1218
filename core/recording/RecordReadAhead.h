#pragma once

#include "RecordingFormat.h"

#include <QtCore/QtGlobal>

#include <condition_variable>
#include <deque>
#include <mutex>
#include <vector>

class QThread;

namespace lk::recording {

class RecordingReader;

/// Reads the records of a RecordingReader on a thread of its own, a bounded number ahead of
/// the thread that plays them: Load all's worker then spends its time decoding, not reading,
/// checking and unpacking the file (a fifth of its work on an hour's recording). Owns the
/// reader from start() until stop(); what it read that nobody took stays with it.
class RecordReadAhead {
public:
    /// Records per hand-over, and hand-overs kept ready (a few megabytes at most).
    static constexpr int kChunkRecords = 2048;
    static constexpr int kChunksAhead = 8;

    explicit RecordReadAhead(RecordingReader &reader);
    ~RecordReadAhead(); ///< stops the thread
    RecordReadAhead(const RecordReadAhead &) = delete;
    RecordReadAhead &operator=(const RecordReadAhead &) = delete;

    void start();
    /// The next record (waits for the thread to read it); false at the end of the file or at
    /// damage (the reader's error() tells which, once stopped).
    bool next(RecordEvent *event);
    /// Stop and join the thread: the reader is the caller's again, positioned after the last
    /// record read. The records read but not taken are returned, oldest first. Call it from
    /// the thread that takes the records, or once that thread is joined: a next() waiting
    /// when it stops returns false as at the end.
    std::deque<RecordEvent> stop();

private:
    void run();

    RecordingReader &m_reader;
    QThread *m_thread = nullptr;
    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::deque<std::vector<RecordEvent>> m_ready; ///< read, not yet taken (under m_mutex)
    bool m_done = false;                          ///< the reader has nothing more (m_mutex)
    bool m_stop = false;                          ///< asked to stop (m_mutex)
    std::vector<RecordEvent> m_taking;            ///< the chunk next() takes from
    size_t m_taken = 0;                           ///< of m_taking
};

} // namespace lk::recording
