#pragma once

#include <drive/DriveSettingsStore.h>

#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QPointer>

#include <memory>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

/// Brings the user's soft limits to the bus thread's speed watch (bus::SpeedWatch), which
/// bounds drives under torque and open loop: the drive views' settings store, wrapped. Every
/// drive the session knows gets its stored limits (the series' defaults when none are
/// stored, or when they are damaged: the views refuse motion then anyway) when the drives
/// change, and again when the user applies new ones (setSoftLimits).
class SoftLimitsFeed : public QObject, public DriveSettingsStore {
    Q_OBJECT
public:
    SoftLimitsFeed(std::unique_ptr<DriveSettingsStore> store, bus::BusSession *session,
                   QObject *parent = nullptr);

    std::optional<safety::SoftLimits> softLimits(const QString &driveKey,
                                                 const safety::SoftLimits &fallback,
                                                 QString *error = nullptr) override;
    void setSoftLimits(const QString &driveKey, const safety::SoftLimits &limits) override;
    std::optional<int> encoderBits(const QString &driveKey) override;
    void setEncoderBits(const QString &driveKey, int bits) override;
    std::optional<double> gearRatio(const QString &driveKey) override;
    void setGearRatio(const QString &driveKey, double ratio) override;

    /// The limits last given to the session for drive `id`; nullopt: none yet.
    std::optional<safety::SoftLimits> fed(int id) const;

private:
    void feedAll();

    std::unique_ptr<DriveSettingsStore> m_store;
    QPointer<bus::BusSession> m_session;
    QMap<int, safety::SoftLimits> m_fed;
};

} // namespace lk::ui
