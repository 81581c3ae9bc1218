#include "BlackBox.h"

#include "RecordFile.h"
#include "RecordingReader.h"

namespace lk::recording {

BlackBox::BlackBox(RecordingHeader header, Limits limits)
    : m_header(std::move(header)), m_limits(limits), m_context(m_header.context),
      m_baud(m_header.baud)
{
}

void BlackBox::closeBlock()
{
    m_open.bytes = m_current.takeBlock();
    m_blockBytes += m_open.bytes.size();
    m_blocks.push_back(std::move(m_open));
    m_open = Block{};
    m_hasOpen = false;
}

void BlackBox::evict(qint64 newestNs)
{
    while (!m_blocks.empty() && (m_blocks.front().lastNs < newestNs - m_limits.windowNs ||
                                 m_blockBytes + m_current.pendingBytes() > m_limits.maxBytes)) {
        m_blockBytes -= m_blocks.front().bytes.size();
        m_blocks.pop_front();
    }
}

void BlackBox::append(RecordEvent event)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_hasOpen && (event.timeNs - m_open.firstNs >= m_limits.blockNs ||
                      m_current.pendingBytes() >= m_limits.blockBytes))
        closeBlock();
    if (!m_hasOpen) {
        m_open.firstNs = event.timeNs;
        m_open.contextBefore = m_context;
        m_open.baudBefore = m_baud;
        m_hasOpen = true;
    }
    m_open.lastNs = qMax(m_open.lastNs, event.timeNs);
    if (event.kind == RecordEvent::Kind::Context)
        m_context = event.context;
    if (event.kind == RecordEvent::Kind::Link && event.baud > 0)
        m_baud = event.baud;
    m_current.append(event);
    evict(event.timeNs);
}

QByteArray BlackBox::snapshot(RecordingHeader *header) const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    *header = m_header;
    const Block *first = !m_blocks.empty() ? &m_blocks.front() : m_hasOpen ? &m_open : nullptr;
    if (first) {
        header->context = first->contextBefore;
        header->baud = first->baudBefore;
    }
    QByteArray out = RecordEncoder::encodeHeader(*header);
    for (const Block &b : m_blocks)
        out += b.bytes;
    RecordEncoder open = m_current; // a copy: the ring goes on
    out += open.takeBlock();
    return out;
}

BlackBox::SaveResult BlackBox::saveLast(const QString &path) const
{
    RecordingHeader header;
    const QByteArray bytes = snapshot(&header);
    RecordFile file;
    auto error = file.create(path);
    if (!error)
        error = file.write(bytes);
    file.close();
    return SaveResult{error ? QString() : path, error};
}

QVector<RecordEvent> BlackBox::events(ContextSnapshot *contextBefore) const
{
    RecordingHeader header;
    RecordingReader reader;
    QVector<RecordEvent> out;
    if (!reader.openBytes(snapshot(&header)))
        return out;
    if (contextBefore)
        *contextBefore = header.context;
    RecordEvent e;
    while (reader.next(&e))
        out.append(e);
    return out;
}

void BlackBox::setWindowNs(qint64 windowNs)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_limits.windowNs = windowNs;
}

qint64 BlackBox::windowNs() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_limits.windowNs;
}

qsizetype BlackBox::bytes() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_blockBytes + m_current.pendingBytes();
}

qint64 BlackBox::spanNs() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    const Block *first = !m_blocks.empty() ? &m_blocks.front() : m_hasOpen ? &m_open : nullptr;
    if (!first)
        return 0;
    const qint64 last = m_hasOpen ? m_open.lastNs : m_blocks.back().lastNs;
    return last - first->firstNs;
}

} // namespace lk::recording
