#pragma once

#include <recording/ReplayDecoder.h>

#include <QtCore/QObject>

#include <atomic>
#include <memory>
#include <optional>

class QSemaphore;
class QThread;

namespace lk::ui {

/// A recording played into the views (recording::ReplayDecoder does the decoding): at its
/// pace on the event loop, or all of what is left at once ("Load all"), decoded on a worker
/// thread while the views take each batch on this one, so an hour's recording loads in
/// seconds. Nothing here can transmit.
///
/// While Load all runs, the worker owns the decoder: pause, seek and close stop it first (what
/// it decoded reaches the views before they return), and the position is the last one it
/// handed on.
///
/// Pause, seek and close are meant for user input. Called from a slot of telemetryReceived or
/// trafficCaptured while Load all runs, they deliver the later batches to that slot before the
/// receivers connected after it have the current one.
class RecordingReplay : public QObject {
    Q_OBJECT
public:
    explicit RecordingReplay(QObject *parent = nullptr);
    ~RecordingReplay() override;

    /// Open `path` and start playing at `options.speed` (paused when `options` says so).
    /// False with the reader's message (naming the offset of damage) when it cannot be read;
    /// a file damaged later opens up to the damage and damage() says where.
    bool open(const QString &path, recording::ReplayTransport::Options options, QString *error);
    void close();
    bool isOpen() const { return m_decoder->isOpen(); }
    QString path() const { return m_decoder->path(); }

    const recording::RecordingHeader &header() const { return m_decoder->header(); }
    /// The link of the stream being replayed (a recording may change it at a Link record).
    protocol::Link link() const { return m_decoder->link(); }
    /// Where the file stops being readable; Kind::None for a whole file. It and the duration
    /// come from the file's index, read at open: the worker never changes them.
    recording::RecordingError damage() const { return m_decoder->damage(); }
    double durationSeconds() const { return m_decoder->durationSeconds(); }
    double positionSeconds() const;
    bool isPaused() const;
    bool isFinished() const;
    double speed() const { return m_decoder->speed(); }
    /// Load all is running on its worker.
    bool isLoadingAll() const { return m_loader != nullptr; }
    /// Stop Load all without delivering what it decoded (the window's teardown, when the
    /// views that would take it are going).
    void abandonLoading();

    void play();
    /// Pause (and stop Load all where it got to).
    void pause();
    void setSpeed(double speed);
    /// Continue from `seconds` into the recording (what was shown stays; later rows follow);
    /// stops Load all, paused there.
    void seek(double seconds);
    /// Everything left at once, decoded on a worker thread ("Load all"); finished at the end.
    /// Called while the replay is handing rows on (from a slot of its signals), it starts when
    /// that is over.
    void loadAll();
    /// Load all hands on only the newest `rows` traffic rows (in whole batches: up to a batch
    /// more), when it ends or stops, and the counts of the others (trafficDropped): what the
    /// Traffic view keeps. 0 (the default): every row, batch by batch.
    void setTrafficRowsKept(qsizetype rows) { m_trafficRowsKept = rows; }

signals:
    void telemetryReceived(const lk::bus::TelemetryBatch &batch);
    void trafficCaptured(const lk::bus::TrafficBatch &batch);
    /// Traffic rows Load all did not hand on (setTrafficRowsKept), counted by kind.
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
    /// Stop the Load all worker where it got to and wait for it; what it handed on is
    /// delivered before this returns.
    void stopLoading();
    /// The worker is done (or told to stop): join it.
    void joinLoader();

    std::unique_ptr<recording::ReplayDecoder> m_decoder;
    QThread *m_loader = nullptr;
    std::atomic<bool> m_stopLoading{false};
    /// Free places in the queue to the views: the worker takes one a batch, the views give it
    /// back when they took the batch. A new one for each Load all.
    std::shared_ptr<QSemaphore> m_queueRoom;
    /// stopLoading is delivering what the worker handed on (a slot may call back in).
    int m_draining = 0;
    /// What positionSeconds answers while the worker owns the decoder (the last it handed on).
    double m_loadingPosition = 0;
    std::optional<double> m_speedAfterLoading;
    qsizetype m_trafficRowsKept = 0;
};

} // namespace lk::ui
