#pragma once

#include <recording/BlackBox.h>
#include <recording/BlackBoxTriggers.h>

#include <bus/BusClock.h>
#include <bus/BusStatistics.h>
#include <bus/ConnectionStatus.h>
#include <bus/TelemetrySample.h>
#include <bus/TransportFactory.h>

#include <QtCore/QObject>

#include <memory>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class RingTrafficTap;

/// lkstudio's always-on black box: every connection's transports record into a BlackBox ring
/// (the last N minutes, active or listen-only), and the ring is saved to a timestamped file
/// on an emergency stop, a new drive fault flag, a link loss or a timeout burst
/// (BlackBoxTriggers), or when asked (save()). The Traffic view reads the same ring (tap()).
class BlackBoxRecorder : public QObject {
    Q_OBJECT
public:
    explicit BlackBoxRecorder(QObject *parent = nullptr);
    ~BlackBoxRecorder() override;

    /// Where saved recordings go: AppLocalDataLocation/recordings unless set.
    static QString defaultFolder();
    void setFolder(const QString &folder) { m_folder = folder; }
    QString folder() const { return m_folder; }
    /// The ring's length (default 10 minutes, at least 1): the current ring's from now on,
    /// and the next connection's.
    void setWindowMinutes(int minutes);
    int windowMinutes() const { return m_windowMinutes; }

    /// A fresh ring and clock for a new connection, and `inner` wrapped so that every
    /// transport it makes records into them.
    bus::TransportFactory wrap(bus::TransportFactory inner, recording::RecordingHeader header);
    /// Follow `session`: its decode context goes into the ring, its events trigger saves.
    void attach(bus::BusSession *session);

    /// The ring of the current connection (null before the first).
    std::shared_ptr<recording::BlackBox> box() const { return m_box; }
    RingTrafficTap *tap() const { return m_tap.get(); }
    /// The ring's clock now (ns): the time of a record appended at this moment.
    qint64 nowNs() const;

    /// Save the ring now, `why` naming the cause in the file name; emits saved or saveFailed.
    /// Returns the path, empty on failure (or when nothing was ever connected).
    QString save(const QString &why);

signals:
    /// wrap() made a fresh ring: what was shown of the last one is gone.
    void ringStarted();
    /// The ring was written to `path` because of `why` ("emergency stop", "on request").
    void saved(const QString &why, const QString &path);
    void saveFailed(const QString &why, const QString &error);

private:
    void trigger(std::optional<recording::BlackBoxTriggers::Reason> reason);
    void onConnection(const bus::ConnectionStatus &status);
    void onTelemetry(const bus::TelemetryBatch &batch);
    void onStatistics(const bus::BusStatistics &statistics);
    QString newPath(const QString &why) const;
    qint64 windowNs() const;

    QString m_folder;
    int m_windowMinutes = 10;
    std::shared_ptr<recording::BlackBox> m_box;
    std::shared_ptr<RingTrafficTap> m_tap;
    std::shared_ptr<bus::BusClock> m_clock;
    recording::BlackBoxTriggers m_triggers;
    bus::BusSession *m_session = nullptr;
    quint64 m_timeouts = 0; ///< the last statistics' timeout count
    bool m_wasOpen = false;
};

} // namespace lk::ui
