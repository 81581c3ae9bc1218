#pragma once

#include "ReplayStatistics.h"
#include "ReplayTransport.h"

#include <bus/KnownMotor.h>
#include <bus/ListenStatistics.h>
#include <bus/TelemetrySample.h>
#include <bus/TrafficBacklog.h>
#include <bus/TrafficEvent.h>
#include <protocol/FrameParser.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QObject>

#include <array>
#include <atomic>
#include <memory>

class QThreadPool;

namespace lk::recording {

/// Decodes a recording into what the live views read (ui::RecordingReplay puts it in front of
/// them, and runs its "Load all" on a worker thread): its frames as traffic rows and its
/// replies as telemetry samples on the recording's clock (seconds since it started), decoded
/// with the decode context the recording carries at each moment. Built on ReplayTransport,
/// which never transmits; no bus session is involved, so nothing can be sent while it plays.
/// A recording made on CAN plays as CAN frames, each one's direction told as a listener tells
/// it (bus::PassivePairing::canDirections).
///
/// As live listening does, it also gives the statistics of the traffic (ListenStatistics on
/// the recording's clock, every half second of it and at the end; a seek starts them afresh)
/// and what is known of each drive (series and generation from the recording's decode
/// context, model and firmware from the read_model replies that pass).
///
/// Its signals go out on the thread that plays: the event loop's while it plays on its timer,
/// a worker's while that worker calls playNextBatch (the transport's signals reach this object
/// directly either way); endLoadAll's on the thread that calls it.
class ReplayDecoder : public QObject {
    Q_OBJECT
public:
    explicit ReplayDecoder(QObject *parent = nullptr);
    ~ReplayDecoder() override;

    /// Open `path` and start playing at `options.speed` (paused when `options` says so).
    /// False with the reader's message (naming the offset of damage) when it cannot be read;
    /// a file damaged later opens up to the damage and damage() says where.
    bool open(const QString &path, ReplayTransport::Options options, QString *error);
    void close();
    bool isOpen() const { return m_transport != nullptr; }
    QString path() const { return m_path; }

    const RecordingHeader &header() const { return m_transport->header(); }
    /// The link of the stream being replayed (a recording may change it at a Link record).
    protocol::Link link() const { return m_link; }
    /// Where the file stops being readable; Kind::None for a whole file.
    RecordingError damage() const;
    double durationSeconds() const;
    double positionSeconds() const;
    bool isPaused() const;
    bool isFinished() const;
    double speed() const;

    void play();
    void pause();
    void setSpeed(double speed);
    /// Continue from `seconds` into the recording (what was shown stays; later rows follow).
    void seek(double seconds);
    /// The next batch of records at once, whatever their times, on the calling thread (a
    /// worker driving "Load all" while playback is paused); false once nothing is left.
    bool playNextBatch();
    /// Inside the transport's playing of records (one of this object's signals is running).
    bool isPlaying() const { return m_transport && m_transport->isPlaying(); }
    /// Load all is about to call playNextBatch on a worker: read the file ahead on a thread of
    /// its own, and keep the traffic rows here instead of handing them on, at most the newest
    /// `trafficRowsKept` of them (the rest only counted; 0: hand every row on). Load all keeps
    /// what the Traffic view can hold: building, queueing and freeing the millions of rows of
    /// an hour that it would drop took a tenth of the load's time, most of it on the GUI thread.
    void beginLoadAll(qsizetype trafficRowsKept);
    /// Load all's worker is done (joined): stop reading ahead, and hand on the rows kept
    /// (trafficDropped with the counts of those it did not keep, then trafficCaptured) and
    /// the statistics where it got to. While it runs, the statistics go out at most every
    /// kLoadAllStatisticsMs of wall time, not every half second of the recording: an hour
    /// loads in seconds, and 7200 snapshots refilled the statistics view as many times.
    void endLoadAll();

signals:
    void telemetryReceived(const lk::bus::TelemetryBatch &batch);
    void trafficCaptured(const lk::bus::TrafficBatch &batch);
    /// Rows of the traffic that were not kept (keepTrafficTail), counted by kind.
    void trafficDropped(const lk::bus::TrafficCounts &counts);
    /// The decode context changed: these drives are on the recorded bus.
    void drivesChanged(const lk::recording::ContextSnapshot &drives);
    /// A drive not in the context replied (its series is unknown: decoded as MF).
    void driveSeen(int id);
    /// What the drives are, as far as the recording tells so far (knownMotors of a session).
    void knownMotorsChanged(const lk::bus::KnownMotors &motors);
    /// The traffic's figures so far (since the last seek).
    void listenStatisticsUpdated(const lk::bus::ListenStatistics &statistics);
    void positionChanged(double seconds);
    void finished();

private:
    void onBytes(const QByteArray &bytes, bool transmitted);
    void onRecord(const RecordEvent &record);
    /// One parsed frame or fault of the chunk being played: its rows and samples go to
    /// m_traffic and m_telemetry, at m_chunkTime.
    void onFrame(const protocol::ParseEvent &event);
    protocol::DecodeContext contextOf(int id) const;
    void setContext(const ContextSnapshot &context);
    void learnModel(const protocol::Reply &reply);
    /// What another master's request commands, as the live listener samples it.
    void takeCommand(const protocol::Frame &frame);
    void takeCommand(const protocol::Request &request);
    /// A frame on no drive's ID: a multi-motor torque frame (CAN 0x280) is a traffic row, a
    /// request to each drive it names (statistics) and, another master's, its commands.
    void takeOtherFrame(const protocol::CanRecord &record);
    void emitStatistics();
    static constexpr int kLoadAllStatisticsMs = 100;
    /// The rows and samples gathered so far go to the views: at the end of each batch the
    /// transport plays, and before a drive or context signal, so the views see them in order.
    void handOnRows();
    void keepTrafficTail(qsizetype rows);
    void releaseTrafficTail();
    void addRow(bus::TrafficEvent &&row); ///< to m_traffic, counted while the tail is kept
    void handOnBatch();
    qint64 positionNs() const;

    std::unique_ptr<ReplayTransport> m_transport;
    QString m_path;
    /// A new stream of the recording's link: RS485 bytes or CAN records.
    void restartParser();

    std::unique_ptr<protocol::FrameParser> m_parser;
    protocol::Link m_link = protocol::Link::Rs485;
    ContextSnapshot m_context;
    /// contextOf() by drive ID, built from m_context and m_link when first asked after a change.
    mutable std::array<protocol::DecodeContext, 256> m_contexts;
    mutable bool m_contextsValid = false;
    QVector<int> m_seen; ///< every drive reported (context or reply)
    ReplayStatistics m_statistics;
    bus::KnownMotors m_known;
    bool m_transmitted = false; ///< the chunk being parsed is one the recording tool sent
    // What the chunks of the batch being played give, emitted when it is done.
    double m_chunkTime = 0;
    bus::TrafficBatch m_traffic;
    bus::TrafficCounts m_trafficCounts; ///< of m_traffic, while m_keepTail
    bus::TelemetryBatch m_telemetry;
    bool m_keepTail = false;
    bool m_loadingAll = false;       ///< between beginLoadAll and endLoadAll
    bool m_statisticsHeld = false;   ///< a snapshot was due and not sent (Load all's rate)
    QElapsedTimer m_statisticsClock; ///< since the last snapshot sent during Load all
    bus::TrafficBacklog m_tail;      ///< the rows kept while m_keepTail
    /// Batches handed to m_disposal and not freed yet; past kDisposalsQueued the decoding
    /// thread frees them itself, so that memory stays bounded if the disposal lags.
    std::atomic<int> m_disposalsQueued{0};
    static constexpr int kDisposalsQueued = 8;
    /// Frees the rows m_tail drops during Load all, off the thread that decodes (a thread
    /// of its own, started with the first of them). Declared last: destroyed first, it waits
    /// for its work, which counts in m_disposalsQueued.
    std::unique_ptr<QThreadPool> m_disposal;
};

} // namespace lk::recording
