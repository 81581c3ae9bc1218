#include "ReplayTransport.h"

#include "RecordReadAhead.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QFileInfo>
#include <QtCore/QScopedValueRollback>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lk::recording {

namespace {

/// The recording's clock: the time of what the replay has played.
class RecordingClock final : public bus::BusClock {
public:
    explicit RecordingClock(const qint64 *position) : m_position(position) {}
    qint64 nowNs() const override { return *m_position; }

private:
    const qint64 *m_position;
};

/// "Load all" emits this many records per turn of the event loop.
constexpr int kFastForwardBatch = 4096;

} // namespace

ReplayTransport::ReplayTransport(const QString &path, Options options, QObject *parent)
    : Transport(parent), m_path(path), m_options(std::move(options)),
      m_recordingClock(std::make_shared<RecordingClock>(&m_positionNs))
{
    qRegisterMetaType<RecordEvent>();
    m_options.speed = std::clamp(m_options.speed, kMinSpeed, kMaxSpeed);
    m_timer = m_options.timers(
        this, [this] { tick(); }, Qt::PreciseTimer);
}

// The read-ahead is destroyed (its thread stopped) before the reader it reads: it is declared
// after it.
ReplayTransport::~ReplayTransport() = default;

QString ReplayTransport::description() const
{
    return QCoreApplication::translate("lk::recording::ReplayTransport", "Recording %1 (replay)")
        .arg(QFileInfo(m_path).fileName());
}

bool ReplayTransport::open()
{
    setReadAhead(false);
    m_ahead.clear();
    if (!m_reader.open(m_path)) {
        emit errorOccurred(transport::TransportError{transport::TransportError::Kind::IoError,
                                                     m_reader.error().message});
        return false;
    }
    m_blocks = m_reader.index();
    m_positionNs = 0;
    m_state = State::Open;
    emit stateChanged(m_state);
    advance();
    anchor(m_next ? m_next->timeNs : 0);
    m_positionNs = m_anchorRecordingNs;
    schedule();
    return true;
}

void ReplayTransport::close()
{
    m_timer->stop();
    setReadAhead(false);
    m_ahead.clear();
    if (m_state == State::Closed)
        return;
    m_state = State::Closed;
    m_next.reset();
    emit stateChanged(m_state);
}

void ReplayTransport::write(const QByteArray &bytes)
{
    m_refusedBytes += bytes.size();
    emit writeRefused(int(bytes.size()));
}

void ReplayTransport::setSpeed(double speed)
{
    const qint64 now = targetNs();
    m_options.speed = std::clamp(speed, kMinSpeed, kMaxSpeed);
    anchor(now);
    schedule();
}

void ReplayTransport::play()
{
    if (!m_paused)
        return;
    m_paused = false;
    anchor(m_positionNs);
    schedule();
}

void ReplayTransport::pause()
{
    m_paused = true;
    m_timer->stop();
}

qint64 ReplayTransport::targetNs() const
{
    const double elapsed = double(m_options.wallClock->nowNs() - m_anchorWallNs);
    return m_anchorRecordingNs + qint64(elapsed * m_options.speed);
}

void ReplayTransport::anchor(qint64 recordingNs)
{
    m_anchorWallNs = m_options.wallClock->nowNs();
    m_anchorRecordingNs = recordingNs;
}

void ReplayTransport::setReadAhead(bool on)
{
    if (on == bool(m_readAhead))
        return;
    if (on) {
        m_readAhead = std::make_unique<RecordReadAhead>(m_reader);
        m_readAhead->start();
        return;
    }
    // What it read and nobody played yet comes before what the reader reads next.
    std::deque<RecordEvent> left = m_readAhead->stop();
    m_readAhead.reset();
    for (RecordEvent &e : left)
        m_ahead.push_back(std::move(e));
}

void ReplayTransport::advance()
{
    RecordEvent e;
    bool got = false;
    if (!m_ahead.empty()) {
        e = std::move(m_ahead.front());
        m_ahead.pop_front();
        got = true;
    } else {
        got = m_readAhead ? m_readAhead->next(&e) : m_reader.next(&e);
    }
    if (got)
        m_next = std::move(e);
    else
        m_next.reset();
}

void ReplayTransport::emitRecord(const RecordEvent &record)
{
    m_positionNs = qMax(m_positionNs, record.timeNs);
    if (record.kind == RecordEvent::Kind::Rx || record.kind == RecordEvent::Kind::Tx) {
        if (m_chunkHandler)
            m_chunkHandler(record.bytes, record.kind == RecordEvent::Kind::Tx);
        emit bytesReceived(record.bytes);
    } else
        emit recordPlayed(record);
}

void ReplayTransport::schedule()
{
    if (m_state != State::Open || m_paused)
        return;
    if (!m_next) {
        m_timer->stop();
        return;
    }
    if (m_options.fastForward) {
        m_timer->start(0);
        return;
    }
    const qint64 target = targetNs();
    if (m_options.skipIdleNs > 0 &&
        m_next->timeNs - qMax(target, m_positionNs) > m_options.skipIdleNs) {
        // A long silence plays as skipIdleNs of recording time.
        anchor(m_next->timeNs - m_options.skipIdleNs);
    }
    const double waitNs = double(m_next->timeNs - targetNs()) / m_options.speed;
    m_timer->start(waitNs <= 0 ? 0 : int(std::ceil(waitNs / 1e6)));
}

void ReplayTransport::tick()
{
    if (m_state != State::Open || m_paused)
        return;
    // Load all: a batch per turn of the event loop; else what is due by now.
    if (m_options.fastForward)
        playDue(std::numeric_limits<qint64>::max(), kFastForwardBatch);
    else
        playDue(targetNs(), std::numeric_limits<int>::max());
    if (m_next && m_state == State::Open)
        schedule();
}

bool ReplayTransport::playNextBatch()
{
    if (m_state != State::Open || !m_next)
        return false;
    playDue(std::numeric_limits<qint64>::max(), kFastForwardBatch);
    return m_next && m_state == State::Open;
}

void ReplayTransport::playDue(qint64 targetNs, int max)
{
    const QScopedValueRollback<bool> playing(m_playing, true);
    for (int i = 0; i < max && m_next && m_next->timeNs <= targetNs && m_state == State::Open;
         ++i) {
        const RecordEvent record = std::move(*m_next);
        advance();
        emitRecord(record);
    }
    if (m_state != State::Open)
        return;
    emit batchPlayed();
    if (!m_next)
        emit finished();
}

bool ReplayTransport::seek(qint64 ns)
{
    if (m_state != State::Open || m_blocks.isEmpty())
        return false;
    // The last block that starts at or before ns (or the first).
    auto it = std::upper_bound(
        m_blocks.cbegin(), m_blocks.cend(), ns,
        [](qint64 t, const RecordingReader::Block &b) { return t < b.baseTimeNs; });
    if (it != m_blocks.cbegin())
        --it;
    setReadAhead(false);
    if (!m_reader.seek(*it))
        return false; // where it was: the records read ahead still play next
    m_ahead.clear();
    std::optional<RecordEvent> context;
    advance();
    while (m_next && m_next->timeNs < ns) {
        if (m_next->kind == RecordEvent::Kind::Context)
            context = m_next;
        advance();
    }
    // The context in force at ns: the last one before it in this block, else the one that
    // came before the block (the seek reads back to the file's start only when needed).
    if (!context && it != m_blocks.cbegin()) {
        RecordingReader earlier;
        if (earlier.open(m_path)) {
            RecordEvent e;
            while (earlier.next(&e) && e.timeNs < it->baseTimeNs)
                if (e.kind == RecordEvent::Kind::Context)
                    context = e;
        }
    }
    if (!context) {
        RecordEvent initial;
        initial.kind = RecordEvent::Kind::Context;
        initial.context = m_reader.header().context;
        context = initial;
    }
    context->timeNs = ns;
    m_positionNs = ns;
    emit recordPlayed(*context);
    anchor(ns);
    schedule();
    return true;
}

} // namespace lk::recording
