#pragma once

#include <panels/DriveHealth.h>

#include <bus/TelemetrySample.h>
#include <protocol/Request.h>

#include <QtCore/QDateTime>
#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QStringList>

#include <optional>

namespace lk::ui {

class BusModel;
class CommandedMotion;
class MessageBanner;

/// Faults and trips do not pass unnoticed. For every drive on the bus it follows what the
/// polls read: a fault flag that appears, a temperature at or above DriveHealth's threshold, a
/// supply outside the series' range, and a drive that stops by itself (commanded to move, not
/// stopped by lkstudio, and now reading a fault, motor off, 0 dps under a speed command or no
/// current under a torque or open-loop command). Each raises the drive's banner entry (its
/// problems now, and what happened when) and a log line with the time and the flags by name;
/// driveStopped() tells the Control view. A drive back in range says so in its entry, which
/// stays until dismissed.
class DriveFaultWatch : public QObject {
    Q_OBJECT
public:
    /// A drive is judged "stopped by itself" from the readings only this long after its
    /// command was first followed by a reading (it needs time to start), and only when they
    /// agree for kStoppedForS (one poll may catch a speed reversal's zero crossing).
    static constexpr double kStartGraceS = 1.0;
    static constexpr double kStoppedForS = 0.5;

    static QString entryKey(int id) { return QStringLiteral("driveHealth/%1").arg(id); }

    /// None of the arguments is owned.
    DriveFaultWatch(BusModel *model, CommandedMotion *motion, MessageBanner *banner,
                    QObject *parent = nullptr);

    /// What the drive's entry and the log said last (tests, bug reports).
    QStringList events(int id) const { return m_drives.value(id).events; }

public slots:
    /// Telemetry from the bus, after BusModel has merged it.
    void onTelemetry(const lk::bus::TelemetryBatch &batch);

signals:
    /// Drive `id` stopped by itself; `why` for the Control view's status.
    void driveStopped(int id, const QString &why);

private:
    struct Drive {
        DriveHealth health;
        bus::TelemetryFields polled; ///< the fields read so far
        int errorState = 0;
        QDateTime commandAt;       ///< the CommandedMotion entry it follows (its sentAt)
        double firstReadingS = -1; ///< session time of the first reading after that command
        double stillSinceS = -1;   ///< readings have said "not moving" since then; -1: no
        bool stopReported = false;
        QStringList events; ///< "12:03:04 over-temperature (0x08)", newest last
    };
    /// `judged`: the fields read in an earlier batch (the others are not judged yet).
    void judgeHealth(int id, Drive &d, bus::TelemetryFields judged);
    void judgeStopped(const bus::TelemetrySample &s, Drive &d);
    /// Why reading `s` says the drive is not following `command`; empty: it is following it;
    /// nullopt: the reading says nothing about it (another command's fields).
    std::optional<QString> notMovingReason(const bus::TelemetrySample &s,
                                           const protocol::Request &command) const;
    void note(int id, Drive &d, const QString &event, bool warning);
    void show(int id, const Drive &d);

    BusModel *m_model;
    CommandedMotion *m_motion;
    MessageBanner *m_banner;
    QMap<int, Drive> m_drives;
};

} // namespace lk::ui
