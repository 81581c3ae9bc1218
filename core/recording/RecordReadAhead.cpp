#include "RecordReadAhead.h"

#include "RecordingReader.h"

#include <QtCore/QThread>

#include <utility>

namespace lk::recording {

RecordReadAhead::RecordReadAhead(RecordingReader &reader) : m_reader(reader) {}

RecordReadAhead::~RecordReadAhead()
{
    stop();
}

void RecordReadAhead::start()
{
    if (m_thread)
        return;
    m_stop = false;
    m_done = false;
    m_thread = QThread::create([this] { run(); });
    m_thread->setObjectName(QStringLiteral("lk-replay-read"));
    m_thread->start();
}

void RecordReadAhead::run()
{
    for (;;) {
        std::vector<RecordEvent> chunk;
        chunk.reserve(kChunkRecords);
        RecordEvent e;
        bool more = true;
        while (chunk.size() < size_t(kChunkRecords) && (more = m_reader.next(&e)))
            chunk.push_back(std::move(e));
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [this] { return m_stop || m_ready.size() < size_t(kChunksAhead); });
        if (!chunk.empty())
            m_ready.push_back(std::move(chunk)); // kept even when stopping: it was read
        if (!more)
            m_done = true;
        m_changed.notify_all();
        if (m_stop || m_done)
            return;
    }
}

bool RecordReadAhead::next(RecordEvent *event)
{
    if (m_taken == m_taking.size()) {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [this] { return !m_ready.empty() || m_done || m_stop; });
        if (m_ready.empty())
            return false;
        m_taking = std::move(m_ready.front());
        m_ready.pop_front();
        m_taken = 0;
        m_changed.notify_all(); // room for the reader
    }
    *event = std::move(m_taking[m_taken++]);
    return true;
}

std::deque<RecordEvent> RecordReadAhead::stop()
{
    if (m_thread) {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_changed.notify_all();
        m_thread->wait();
        delete m_thread;
        m_thread = nullptr;
    }
    std::deque<RecordEvent> left;
    for (size_t i = m_taken; i < m_taking.size(); ++i)
        left.push_back(std::move(m_taking[i]));
    m_taking.clear();
    m_taken = 0;
    for (std::vector<RecordEvent> &chunk : m_ready)
        for (RecordEvent &e : chunk)
            left.push_back(std::move(e));
    m_ready.clear();
    return left;
}

} // namespace lk::recording
