#pragma once

#include <bus/KnownMotor.h>
#include <bus/TelemetrySample.h>
#include <motor/EncoderResolution.h>

#include <QtCore/QHash>
#include <QtCore/QObject>
#include <QtCore/QPointer>

#include <memory>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class DriveSettingsStore;

/// The encoder resolution lkstudio believes for every drive, one motor::EncoderResolution per
/// drive identity (DriveSettingsStore::driveKey), fed by the telemetry the session already
/// receives (no bus traffic of its own). The Encoder view and the dashboard both read it, so
/// they never disagree; the user's choice is kept in the DriveSettingsStore.
class EncoderResolutions : public QObject {
    Q_OBJECT
public:
    explicit EncoderResolutions(QObject *parent = nullptr);
    ~EncoderResolutions() override;

    /// The session whose telemetry raises the resolutions (not owned). Another session
    /// forgets what the previous one's data showed.
    void setSession(bus::BusSession *session);
    /// Where user choices persist (not owned; default: kept for this process).
    void setSettingsStore(DriveSettingsStore *store);

    /// The resolution of drive `id` as `motor` describes it; the description is remembered
    /// for the telemetry of that ID when the session does not know the drive.
    motor::EncoderResolution of(int id, const bus::KnownMotor &motor);
    /// The user's choice for the drive (one of EncoderResolution::choices()), persisted.
    void setUserBits(int id, const bus::KnownMotor &motor, int bits);
    /// Feeds the encoder values of a batch (the session's telemetryReceived does this).
    void observe(const bus::TelemetryBatch &batch);
    /// One encoder value a view read itself, ahead of the batch that carries it too.
    void observe(int id, const bus::KnownMotor &motor, int encoder);

    /// "6437 of 65536 (16-bit, from data)": an encoder value with the resolution it is read with.
    static QString readoutText(int value, const motor::EncoderResolution &resolution);
    /// "from data: the drive reported 43388", "the MS series default", ...
    static QString sourceText(const motor::EncoderResolution &resolution, const QString &motorName,
                              std::optional<protocol::Series> series);

signals:
    /// The resolution of drive `id` changed (data raised it, or the user chose one).
    void changed(int id);

private:
    motor::EncoderResolution &entry(int id, const bus::KnownMotor &motor);
    bus::KnownMotor motorOf(int id) const;

    std::unique_ptr<DriveSettingsStore> m_ownStore;
    DriveSettingsStore *m_store;
    QPointer<bus::BusSession> m_session;
    QMetaObject::Connection m_telemetry;
    QHash<QString, motor::EncoderResolution> m_byKey;
    QHash<int, bus::KnownMotor> m_described; ///< what of() was told, by ID
};

} // namespace lk::ui
