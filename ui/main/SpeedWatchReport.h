#pragma once

#include <bus/RequestResult.h>
#include <bus/SpeedWatchTrip.h>

#include <QtCore/QMap>
#include <QtCore/QObject>
#include <QtCore/QPointer>

#include <optional>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class BusModel;
class MessageBanner;

/// The bus thread's speed watch (bus::SpeedWatch) in lkstudio: each stop of a drive under
/// torque or open loop past its speed limit becomes a banner entry for that drive (which
/// limit, the speed seen, whether the drive acknowledged the Motor Stop) and a log line, and
/// driveStopped() tells the Control view. On a V2.35 drive the entry offers to set the
/// drive's own Max Speed (ParamID 0x9A) to the soft limit: it is read first (0x40; a value
/// that could not be read is never replaced, nor one already at or below the limit), then
/// RAM-written (0x42, once) and read back (0x40), and the entry says what the read-back showed.
class SpeedWatchReport : public QObject {
    Q_OBJECT
public:
    static QString entryKey(int id) { return QStringLiteral("speedWatch/%1").arg(id); }
    /// The link of the entry that sets the drive's Max Speed.
    static QString maxSpeedLink() { return QStringLiteral("setMaxSpeed"); }

    /// None of the arguments is owned.
    SpeedWatchReport(bus::BusSession *session, BusModel *model, MessageBanner *banner,
                     QObject *parent = nullptr);

    /// What the entry and the log say about `trip` (translated, plain text).
    static QString describe(const bus::SpeedWatchTrip &trip);

public slots:
    void onTripped(const lk::bus::SpeedWatchTrip &trip);
    /// Read the Max Speed of drive `id`; above `dps`, RAM-write `dps` and read it back
    /// (V2.35 only; drive `id` must have tripped).
    void setDriveMaxSpeed(int id, double dps);

signals:
    /// Drive `id` was stopped by the watch; `why` for the Control view's status.
    void driveStopped(int id, const QString &why);

private:
    /// The entry of drive `id`: `trip` (describe()), then `detail`, both plain text.
    void showEntry(int id, const QString &trip, const QString &detail, bool offerMaxSpeed);
    void writeMaxSpeed(int id, double was, double dps);
    void finish(int id, const QString &result, bool offerAgain);
    static std::optional<double> maxSpeedOf(const bus::RequestResult &r);
    static QString readBackText(std::optional<double> readBack, double dps);

    QPointer<bus::BusSession> m_session;
    BusModel *m_model;
    MessageBanner *m_banner;
    QMap<int, bus::SpeedWatchTrip> m_trips; ///< the last trip per drive (its entry's text)
};

} // namespace lk::ui
