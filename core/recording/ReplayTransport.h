#pragma once

#include "RecordingReader.h"

#include <bus/BusClock.h>
#include <bus/SingleShotTimer.h>
#include <transport/Transport.h>

#include <deque>
#include <functional>
#include <memory>
#include <optional>

namespace lk::recording {

class RecordReadAhead;

/// A Transport that plays a recording back: tx and rx chunks alike arrive as received bytes,
/// as a tap on the bus saw them, at their recorded times scaled by a speed (0.25x..20x), with
/// idle gaps longer than `skipIdleNs` shortened to that; seekable; or everything as fast as
/// the event loop takes it ("load all"). write() sends nothing: it reports a refusal.
/// Reading is block by block, so an hour-long recording plays in bounded memory.
class ReplayTransport : public transport::Transport {
    Q_OBJECT
public:
    static constexpr double kMinSpeed = 0.25;
    static constexpr double kMaxSpeed = 20.0;

    struct Options {
        double speed = 1.0;
        qint64 skipIdleNs = 1'000'000'000; ///< 0: play idle gaps at their length
        bool fastForward = false;
        /// The clock playback is paced by (tests hand a manual one) and its timers.
        std::shared_ptr<bus::BusClock> wallClock = bus::makeSteadyBusClock();
        bus::SingleShotTimerFactory timers = bus::makeQtSingleShotTimer;
    };

    ReplayTransport(const QString &path, Options options, QObject *parent = nullptr);
    ~ReplayTransport() override;

    /// Open the file, read its index and start playing from the first record. A file that
    /// cannot be read emits errorOccurred with the reader's message and stays Closed.
    bool open() override;
    void close() override;
    /// Sends nothing: a replay never transmits. Emits writeRefused.
    void write(const QByteArray &bytes) override;
    State state() const override { return m_state; }
    int baud() const override { return m_reader.header().baud; }
    QString description() const override;

    const RecordingHeader &header() const { return m_reader.header(); }
    /// Where reading the file stopped early (Kind::None for a whole file).
    const RecordingError &damage() const { return m_reader.indexDamage(); }
    qint64 durationNs() const { return m_reader.lastTimeNs(); }
    /// The recording time of the last record played.
    qint64 positionNs() const { return m_positionNs; }
    /// The recording's clock: what a session replaying it should stamp samples with.
    std::shared_ptr<bus::BusClock> recordingClock() const { return m_recordingClock; }
    qint64 refusedWriteBytes() const { return m_refusedBytes; }

    void setSpeed(double speed); ///< clamped to kMinSpeed..kMaxSpeed
    double speed() const { return m_options.speed; }
    void setSkipIdleNs(qint64 ns) { m_options.skipIdleNs = qMax<qint64>(0, ns); }
    /// Play the next batch of records at once, whatever their times, then batchPlayed (and
    /// finished at the end); false once nothing is left. It never touches the timer, so a
    /// worker thread may drive a paused transport through it (RecordingReplay's "Load all").
    bool playNextBatch();
    /// Read the file on a thread of its own, ahead of playNextBatch (Load all), until
    /// setReadAhead(false); playback goes on from the same record either way. Switch it only
    /// while no thread is playing records (Load all's worker joined): stopping it under a
    /// reader waiting for its next record would end that reader's playing early.
    void setReadAhead(bool on);
    /// A chunk of bytes played: `transmitted` when the recording tool sent them.
    using ChunkHandler = std::function<void(const QByteArray &bytes, bool transmitted)>;
    /// Who gets each chunk played (besides bytesReceived), called on the thread that plays:
    /// a reader that tells its own commands from another master's needs `transmitted`. Not a
    /// signal: one per chunk, for the millions of an hour, was a twelfth of Load all's thread.
    void setChunkHandler(ChunkHandler handler) { m_chunkHandler = std::move(handler); }
    /// Records are being played out (the chunk handler or a receiver of recordPlayed runs).
    bool isPlaying() const { return m_playing; }
    void play();
    void pause();
    bool isPaused() const { return m_paused; }
    bool isFinished() const { return !m_next; }
    /// Continue from recording time `ns`: nothing before it is emitted, except the decode
    /// context in force there (recordPlayed with the last Context record before it).
    bool seek(qint64 ns);

signals:
    /// A link, context or dropped record was reached (a context sets the decode context).
    void recordPlayed(const lk::recording::RecordEvent &record);
    /// The records due at this turn of the event loop were played (a reader that gathers
    /// what the chunks give hands it on here: once a batch, not once a chunk).
    void batchPlayed();
    void writeRefused(int bytes);
    /// The last record was played (or the damage that ends the file was reached).
    void finished();

private:
    qint64 targetNs() const;
    void anchor(qint64 recordingNs);
    void advance();
    void emitRecord(const RecordEvent &record);
    void tick();
    /// Play up to `max` records due by `targetNs`, then batchPlayed (and finished at the end).
    void playDue(qint64 targetNs, int max);
    void schedule();

    QString m_path;
    Options m_options;
    RecordingReader m_reader;
    std::unique_ptr<RecordReadAhead> m_readAhead; ///< owns m_reader while set
    std::deque<RecordEvent> m_ahead;              ///< read ahead, not yet played: next first
    QVector<RecordingReader::Block> m_blocks;
    std::optional<RecordEvent> m_next;
    std::unique_ptr<bus::SingleShotTimer> m_timer;
    std::shared_ptr<bus::BusClock> m_recordingClock;
    State m_state = State::Closed;
    bool m_paused = false;
    bool m_playing = false;
    ChunkHandler m_chunkHandler;
    qint64 m_anchorWallNs = 0;
    qint64 m_anchorRecordingNs = 0;
    qint64 m_positionNs = 0;
    qint64 m_refusedBytes = 0;
};

} // namespace lk::recording

Q_DECLARE_METATYPE(lk::recording::RecordEvent)
