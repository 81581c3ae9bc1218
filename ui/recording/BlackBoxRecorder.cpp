#include "BlackBoxRecorder.h"

#include "RingTrafficTap.h"

#include <recording/KnownMotorsContext.h>
#include <recording/RecordingTransport.h>

#include <bus/BusSession.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QDateTime>
#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QStandardPaths>

namespace lk::ui {

using recording::BlackBoxTriggers;

BlackBoxRecorder::BlackBoxRecorder(QObject *parent)
    : QObject(parent), m_folder(defaultFolder()), m_tap(std::make_shared<RingTrafficTap>()),
      m_clock(bus::makeSteadyBusClock())
{
}

BlackBoxRecorder::~BlackBoxRecorder() = default;

QString BlackBoxRecorder::defaultFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
           QStringLiteral("/recordings");
}

void BlackBoxRecorder::setWindowMinutes(int minutes)
{
    m_windowMinutes = qMax(1, minutes);
    if (m_box)
        m_box->setWindowNs(windowNs());
}

qint64 BlackBoxRecorder::windowNs() const
{
    return qint64(m_windowMinutes) * 60 * 1'000'000'000;
}

bus::TransportFactory BlackBoxRecorder::wrap(bus::TransportFactory inner,
                                             recording::RecordingHeader header)
{
    m_clock = bus::makeSteadyBusClock(); // time 0: this connection's start
    header.wallClockStartMs = QDateTime::currentMSecsSinceEpoch();
    if (header.toolVersion.isEmpty())
        header.toolVersion = QCoreApplication::applicationVersion();
    recording::BlackBox::Limits limits;
    limits.windowNs = windowNs();
    m_box = std::make_shared<recording::BlackBox>(std::move(header), limits);
    m_triggers = BlackBoxTriggers{};
    m_timeouts = 0;
    m_wasOpen = false;
    m_tap->setEnabled(m_tap->isEnabled()); // what it held was the last connection's
    auto fanout = std::make_shared<recording::RecordFanout>(
        std::vector<std::shared_ptr<recording::RecordSink>>{m_box, m_tap});
    emit ringStarted();
    return recording::recordingFactory(std::move(inner), std::move(fanout), m_clock);
}

void BlackBoxRecorder::attach(bus::BusSession *session)
{
    using S = bus::BusSession;
    m_session = session;
    connect(session, &S::knownMotorsChanged, this, [this](const bus::KnownMotors &motors) {
        if (!m_box)
            return;
        // The ring and the tap both: a replay and the Traffic view decode as the session does.
        const auto record = recording::contextRecord(nowNs(), motors);
        m_box->append(record);
        m_tap->append(record);
    });
    connect(session, &S::emergencyStopFinished, this,
            [this] { trigger(m_triggers.emergencyStop(nowNs())); });
    connect(session, &S::connectionChanged, this, &BlackBoxRecorder::onConnection);
    connect(session, &S::telemetryReceived, this, &BlackBoxRecorder::onTelemetry);
    connect(session, &S::statisticsUpdated, this, &BlackBoxRecorder::onStatistics);
}

qint64 BlackBoxRecorder::nowNs() const
{
    return m_clock->nowNs();
}

void BlackBoxRecorder::onConnection(const bus::ConnectionStatus &status)
{
    using St = transport::Transport::State;
    if (status.state == St::Open)
        m_wasOpen = true;
    else if (status.state == St::Disconnected && m_wasOpen) {
        m_wasOpen = false;
        trigger(m_triggers.linkLost(nowNs()));
    }
}

void BlackBoxRecorder::onTelemetry(const bus::TelemetryBatch &batch)
{
    for (const bus::TelemetrySample &s : batch) {
        if (s.has(bus::TelemetryField::ErrorState))
            trigger(m_triggers.faultFlags(s.id, quint32(s.errorState), nowNs()));
    }
}

void BlackBoxRecorder::onStatistics(const bus::BusStatistics &statistics)
{
    const quint64 timeouts = statistics.bus.timeouts;
    if (timeouts < m_timeouts) // the figures were reset
        m_timeouts = 0;
    // Statistics come at about 2 Hz: each new timeout counts at this moment (a burst spans
    // seconds, so the half second of blur does not matter).
    const qint64 now = nowNs();
    for (quint64 i = m_timeouts; i < timeouts; ++i) {
        const auto reason = m_triggers.timeout(now);
        if (reason) {
            trigger(reason);
            break;
        }
    }
    m_timeouts = timeouts;
}

void BlackBoxRecorder::trigger(std::optional<BlackBoxTriggers::Reason> reason)
{
    if (reason)
        save(QString::fromLatin1(recording::blackBoxReasonName(*reason)));
}

QString BlackBoxRecorder::newPath(const QString &why) const
{
    QString slug = why;
    slug.replace(QLatin1Char(' '), QLatin1Char('-'));
    const QString stem =
        QStringLiteral("%1/blackbox-%2-%3")
            .arg(m_folder, QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")),
                 slug);
    QString path = stem + QStringLiteral(".lkrec");
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = QStringLiteral("%1-%2.lkrec").arg(stem).arg(n);
    return path;
}

QString BlackBoxRecorder::save(const QString &why)
{
    if (!m_box) {
        emit saveFailed(why, tr("Nothing to save: no connection has been opened yet."));
        return {};
    }
    if (!QDir().mkpath(m_folder)) {
        emit saveFailed(why, tr("Cannot create the folder %1.").arg(m_folder));
        return {};
    }
    const auto result = m_box->saveLast(newPath(why));
    if (result.error) {
        emit saveFailed(why, result.error->message);
        return {};
    }
    emit saved(why, result.path);
    return result.path;
}

} // namespace lk::ui
