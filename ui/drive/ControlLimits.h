#pragma once

#include "RequestTracker.h"

#include <bus/KnownMotor.h>
#include <protocol/Request.h>
#include <safety/DriveLimits.h>
#include <safety/SoftLimits.h>

#include <QtCore/QObject>
#include <QtCore/QString>

#include <functional>
#include <memory>
#include <optional>

namespace lk::ui {

class DriveSettingsStore;

/// The limits the Control view bounds its drive's motion by. The soft limits are kept per
/// drive in a DriveSettingsStore: stored ones that are damaged refuse motion until the user
/// applies limits again (the ones in force stay when they break under a drive already shown).
/// On a V2.35 drive the limits it holds itself (DriveLimits: Max Speed, max torque current or
/// Max Power, Max Angle) are read when it is selected; every bound is then the lower of both.
class ControlLimits : public QObject {
    Q_OBJECT
public:
    /// Queues a read on the view's path; returns the ticket (0: nothing sent).
    using Sender = std::function<quint64(const protocol::Request &, RequestTracker::Callback)>;

    explicit ControlLimits(Sender sender, QObject *parent = nullptr);
    ~ControlLimits() override;

    /// Where soft limits persist (not owned; nullptr: kept for this process).
    void setStore(DriveSettingsStore *store);
    /// Loads the soft limits of drive `id` (0: none; the series' defaults). Returns a status
    /// to show when stored limits broke under the drive shown (its limits in force stay).
    QString load(int id, const bus::KnownMotor &motor, std::optional<protocol::Series> series,
                 const QString &driveTitle);
    /// The soft limits stored for drive `id` in `store` as load() takes them (the series'
    /// defaults when none are stored); nullopt with load()'s refusal in `why` when they are
    /// damaged. For a drive the view does not show (the multi-motor torque panel's others).
    static std::optional<safety::SoftLimits> stored(DriveSettingsStore &store, int id,
                                                    const bus::KnownMotor &motor,
                                                    const QString &driveTitle, QString *why);
    /// Applies and persists the soft limits of drive `id`.
    void apply(int id, const bus::KnownMotor &motor, const safety::SoftLimits &limits);

    const safety::SoftLimits &soft() const { return m_soft; }
    /// Why motion is refused (the stored limits are damaged); empty when it is not.
    QString problem() const { return m_problem; }

    /// Reads the drive's own limits on a V2.35 drive (nothing on V2.3); forgets those of
    /// another drive at once. driveLimitsChanged() follows each change.
    void readDriveLimits(int id, const bus::KnownMotor &motor,
                         std::optional<protocol::Series> series);
    const safety::DriveLimits &drive() const { return m_drive; }
    /// The soft limits narrowed to the drive's own: what each setpoint is checked against.
    safety::SoftLimits inForce() const { return m_drive.narrow(m_soft); }
    /// The drive's own limits in one line (empty when none were read).
    QString driveText() const;

signals:
    void driveLimitsChanged();

private:
    /// The refusal while the stored limits of `driveTitle` are damaged (`error` says how).
    static QString damaged(const QString &driveTitle, const QString &error);

    Sender m_send;
    std::unique_ptr<DriveSettingsStore> m_ownStore;
    DriveSettingsStore *m_store;
    safety::SoftLimits m_soft;
    QString m_key;     ///< the drive key m_soft belongs to
    QString m_problem; ///< the stored limits are damaged: motion is refused until applied
    safety::DriveLimits m_drive;
    int m_driveId = 0;   ///< the drive m_drive was read from
    quint64 m_reads = 0; ///< readDriveLimits() calls: answers to an older one are dropped
};

} // namespace lk::ui
