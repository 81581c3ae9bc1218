#pragma once

#include "RecordEncoder.h"
#include "RecordFile.h"
#include "RecordSink.h"

#include <QtCore/QObject>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

namespace lk::recording {

/// Writes a recording file on a thread of its own. append() (bus thread) only queues the record
/// in a bounded queue; the writer thread encodes and writes a block at least every
/// `flushIntervalMs` (so a killed process loses at most that), and sooner when a block fills.
/// A full queue is counted and written as an explicit Dropped record, never a silent gap. A
/// write error (disk full) stops the recording with a typed error; the session goes on.
class SessionRecorder : public QObject, public RecordSink {
    Q_OBJECT
public:
    struct Limits {
        qsizetype maxQueuedBytes = 32 * 1024 * 1024;
        qsizetype maxQueuedRecords = 1 << 20;
        int flushIntervalMs = 1000;
        qsizetype blockBytes = 64 * 1024;
    };

    SessionRecorder() : SessionRecorder(Limits{}) {}
    explicit SessionRecorder(Limits limits);
    ~SessionRecorder() override;

    /// Create `path`, write the header and start the writer thread. An error (cannot create,
    /// disk full already) is returned and nothing runs.
    std::optional<RecordingError> start(const QString &path, const RecordingHeader &header);
    /// Write what is queued, close the file and end the thread.
    void stop();

    void append(RecordEvent event) override;

    bool isRecording() const { return m_running.load(); }
    QString path() const { return m_path; }
    /// The error that stopped the recording, if one did.
    std::optional<RecordingError> failure() const;
    quint64 droppedBytes() const { return m_totalDroppedBytes.load(); }
    /// Test hook: while held, the writer thread takes nothing from the queue (a stalled disk).
    void holdWriter(bool hold);

signals:
    /// The recording stopped on a write error; emitted from the writer thread.
    void recordingFailed(const lk::recording::RecordingError &error);

private:
    void writerLoop();
    bool writeBytes(const QByteArray &bytes);
    void encodeBatch(std::deque<RecordEvent> &batch, quint64 droppedBytes, quint64 droppedChunks,
                     qint64 dropTimeNs);

    Limits m_limits;
    QString m_path;
    RecordFile m_file;
    RecordEncoder m_encoder;
    std::thread m_thread;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<RecordEvent> m_queue;
    qsizetype m_queuedBytes = 0;
    quint64 m_droppedBytes = 0;
    quint64 m_droppedChunks = 0;
    qint64 m_dropTimeNs = 0;
    bool m_stopRequested = false;
    bool m_hold = false;
    std::optional<RecordingError> m_failure;
    std::atomic<bool> m_running{false};
    std::atomic<quint64> m_totalDroppedBytes{0};
};

} // namespace lk::recording
