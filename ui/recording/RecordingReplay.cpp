#include "RecordingReplay.h"

#include <QtCore/QCoreApplication>
#include <QtCore/QSemaphore>
#include <QtCore/QThread>

#include <utility>

namespace lk::ui {

namespace {

/// Load all's worker stays at most this many batches ahead of the views: the queue between
/// them stays a few megabytes however long the recording and however slow the drawing.
constexpr int kBatchesAhead = 8;

} // namespace

RecordingReplay::RecordingReplay(QObject *parent)
    : QObject(parent), m_decoder(std::make_unique<recording::ReplayDecoder>())
{
    using D = recording::ReplayDecoder;
    // Signal to signal: direct while the decoder plays on this thread, queued (in order)
    // while Load all's worker plays it.
    connect(m_decoder.get(), &D::telemetryReceived, this, &RecordingReplay::telemetryReceived);
    connect(m_decoder.get(), &D::trafficCaptured, this, &RecordingReplay::trafficCaptured);
    connect(m_decoder.get(), &D::trafficDropped, this, &RecordingReplay::trafficDropped);
    connect(m_decoder.get(), &D::drivesChanged, this, &RecordingReplay::drivesChanged);
    connect(m_decoder.get(), &D::driveSeen, this, &RecordingReplay::driveSeen);
    connect(m_decoder.get(), &D::knownMotorsChanged, this, &RecordingReplay::knownMotorsChanged);
    connect(m_decoder.get(), &D::listenStatisticsUpdated, this,
            &RecordingReplay::listenStatisticsUpdated);
    connect(m_decoder.get(), &D::positionChanged, this, [this](double seconds) {
        m_loadingPosition = seconds;
        emit positionChanged(seconds);
    });
    connect(m_decoder.get(), &D::finished, this, [this] {
        joinLoader(); // the worker ends right after the last batch
        m_decoder->endLoadAll();
        emit finished();
    });
}

RecordingReplay::~RecordingReplay()
{
    abandonLoading(); // nothing delivered: the views may be gone already
}

bool RecordingReplay::open(const QString &path, recording::ReplayTransport::Options options,
                           QString *error)
{
    stopLoading();
    return m_decoder->open(path, std::move(options), error);
}

void RecordingReplay::close()
{
    stopLoading();
    m_decoder->close();
}

double RecordingReplay::positionSeconds() const
{
    return m_loader ? m_loadingPosition : m_decoder->positionSeconds();
}

bool RecordingReplay::isPaused() const
{
    return !m_loader && m_decoder->isPaused();
}

bool RecordingReplay::isFinished() const
{
    return !m_loader && m_decoder->isFinished();
}

void RecordingReplay::play()
{
    if (!m_loader)
        m_decoder->play();
}

void RecordingReplay::pause()
{
    stopLoading();
    m_decoder->pause();
}

void RecordingReplay::setSpeed(double speed)
{
    if (m_loader)
        m_speedAfterLoading = speed; // the worker owns the transport until it is done
    else
        m_decoder->setSpeed(speed);
}

void RecordingReplay::seek(double seconds)
{
    stopLoading();
    m_decoder->seek(seconds);
}

void RecordingReplay::loadAll()
{
    if (m_loader || !m_decoder->isOpen() || m_decoder->isFinished())
        return;
    if (m_draining > 0 || m_decoder->isPlaying()) {
        // Rows are being handed on from this thread: the worker would play the transport
        // while it is still being played here. Start once that is over.
        QMetaObject::invokeMethod(this, &RecordingReplay::loadAll, Qt::QueuedConnection);
        return;
    }
    // The event loop's timer stays still while the worker plays the rest.
    m_decoder->pause();
    m_loadingPosition = m_decoder->positionSeconds();
    m_stopLoading = false;
    m_decoder->beginLoadAll(m_trafficRowsKept); // the tail handed on when the worker is done
    auto room = std::make_shared<QSemaphore>(kBatchesAhead);
    m_queueRoom = room;
    recording::ReplayDecoder *decoder = m_decoder.get();
    m_loader = QThread::create([this, decoder, room] {
        while (!m_stopLoading.load() && decoder->playNextBatch()) {
            // Given back behind the batch's rows: the views have taken it when this runs.
            QMetaObject::invokeMethod(
                this, [room] { room->release(); }, Qt::QueuedConnection);
            while (!room->tryAcquire(1, 20) && !m_stopLoading.load()) {
            }
        }
    });
    m_loader->setObjectName(QStringLiteral("lk-replay-load-all"));
    m_loader->start();
}

void RecordingReplay::stopLoading()
{
    const bool wasLoading = m_loader != nullptr;
    if (wasLoading) {
        m_stopLoading = true;
        joinLoader();
    }
    // What the worker handed on reaches the views before whatever the caller does next; a
    // slot that calls back in (a seek from a slot of these signals) waits for the rest too.
    if (wasLoading || m_draining > 0) {
        ++m_draining;
        QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
        --m_draining;
    }
    if (wasLoading)
        m_decoder->endLoadAll(); // the newest rows it decoded, after the rest
}

void RecordingReplay::abandonLoading()
{
    m_stopLoading = true;
    joinLoader();
}

void RecordingReplay::joinLoader()
{
    if (!m_loader)
        return;
    m_loader->wait();
    delete m_loader;
    m_loader = nullptr;
    if (m_speedAfterLoading)
        m_decoder->setSpeed(*std::exchange(m_speedAfterLoading, std::nullopt));
}

} // namespace lk::ui
