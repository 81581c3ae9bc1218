#include "SessionRecorder.h"

#include <QtCore/QCoreApplication>

namespace lk::recording {

namespace {

/// What a queued record costs in memory, roughly: its bytes and the record itself.
qsizetype queuedSize(const RecordEvent &e)
{
    return e.bytes.size() + qsizetype(sizeof(RecordEvent));
}

} // namespace

SessionRecorder::SessionRecorder(Limits limits) : m_limits(limits)
{
    qRegisterMetaType<RecordingError>();
}

SessionRecorder::~SessionRecorder()
{
    stop();
}

std::optional<RecordingError> SessionRecorder::start(const QString &path,
                                                     const RecordingHeader &header)
{
    stop();
    m_path = path;
    m_failure.reset();
    if (auto error = m_file.create(path))
        return error;
    m_encoder = RecordEncoder{};
    if (auto error = m_file.write(RecordEncoder::encodeHeader(header))) {
        m_file.close();
        return error;
    }
    m_stopRequested = false;
    m_running = true;
    m_thread = std::thread([this] { writerLoop(); });
    return std::nullopt;
}

void SessionRecorder::stop()
{
    if (!m_thread.joinable())
        return;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_stopRequested = true;
    }
    m_wake.notify_all();
    m_thread.join();
    m_running = false;
    m_file.close();
}

std::optional<RecordingError> SessionRecorder::failure() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_failure;
}

void SessionRecorder::holdWriter(bool hold)
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_hold = hold;
    }
    m_wake.notify_all();
}

void SessionRecorder::append(RecordEvent event)
{
    if (!m_running.load(std::memory_order_relaxed))
        return;
    const qsizetype size = queuedSize(event);
    bool wake = false;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_queuedBytes + size > m_limits.maxQueuedBytes ||
            qsizetype(m_queue.size()) >= m_limits.maxQueuedRecords) {
            if (m_droppedChunks == 0)
                m_dropTimeNs = event.timeNs;
            m_droppedBytes += quint64(event.bytes.size());
            ++m_droppedChunks;
            return;
        }
        m_queuedBytes += size;
        m_queue.push_back(std::move(event));
        wake = m_queuedBytes >= m_limits.blockBytes && m_queuedBytes - size < m_limits.blockBytes;
    }
    if (wake)
        m_wake.notify_one();
}

bool SessionRecorder::writeBytes(const QByteArray &bytes)
{
    auto error = m_file.write(bytes);
    if (!error)
        return true;
    error->message +=
        QLatin1Char(' ') + QCoreApplication::translate("lk::recording::SessionRecorder",
                                                       "The session goes on without recording.");
    std::lock_guard<std::mutex> lock(m_mutex);
    m_failure = std::move(error);
    return false;
}

void SessionRecorder::encodeBatch(std::deque<RecordEvent> &batch, quint64 droppedBytes,
                                  quint64 droppedChunks, qint64 dropTimeNs)
{
    for (RecordEvent &e : batch) {
        m_encoder.append(e);
        if (m_encoder.pendingBytes() >= m_limits.blockBytes && !writeBytes(m_encoder.takeBlock()))
            return;
    }
    if (droppedChunks > 0) {
        // The drops happened after every record of this batch (the queue was full of them).
        RecordEvent dropped;
        dropped.kind = RecordEvent::Kind::Dropped;
        dropped.timeNs = dropTimeNs;
        dropped.droppedBytes = droppedBytes;
        dropped.droppedChunks = droppedChunks;
        m_encoder.append(dropped);
        m_totalDroppedBytes += droppedBytes;
    }
    if (!m_encoder.isEmpty())
        writeBytes(m_encoder.takeBlock());
}

void SessionRecorder::writerLoop()
{
    const auto interval = std::chrono::milliseconds(m_limits.flushIntervalMs);
    std::unique_lock<std::mutex> lock(m_mutex);
    auto deadline = std::chrono::steady_clock::now() + interval;
    for (;;) {
        m_wake.wait_until(lock, deadline, [this] {
            return m_stopRequested || (!m_hold && m_queuedBytes >= m_limits.blockBytes);
        });
        if (std::chrono::steady_clock::now() >= deadline)
            deadline = std::chrono::steady_clock::now() + interval;
        if (m_hold && !m_stopRequested)
            continue;
        std::deque<RecordEvent> batch;
        batch.swap(m_queue);
        const quint64 droppedBytes = std::exchange(m_droppedBytes, 0);
        const quint64 droppedChunks = std::exchange(m_droppedChunks, 0);
        const qint64 dropTimeNs = m_dropTimeNs;
        m_queuedBytes = 0;
        const bool stopping = m_stopRequested;
        lock.unlock();
        encodeBatch(batch, droppedBytes, droppedChunks, dropTimeNs);
        batch.clear(); // free the bytes outside the lock
        lock.lock();
        if (m_failure) {
            m_running = false;
            const RecordingError error = *m_failure;
            lock.unlock();
            emit recordingFailed(error);
            return;
        }
        if (stopping)
            return;
    }
}

} // namespace lk::recording
