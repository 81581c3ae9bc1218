#pragma once

#include <bus/TelemetrySample.h>

#include <QtCore/QObject>
#include <QtCore/QSet>
#include <QtCore/QVector>

namespace lk::ui {

class BusModel;
class CommandedMotion;
class MessageBanner;

/// Says which drives may still be moving when the link drops: a drive keeps executing its
/// last command until its own input-timeout protection (if set) stops it. Each drive
/// lkstudio had commanded to move gets one banner entry ("Drive 2 may still be moving: last
/// command speed 360 dps at 12:03:04; ..."), which stays until a state read after the link is
/// back shows the drive at speed 0, or until the user dismisses it.
class LinkLossWatch : public QObject {
    Q_OBJECT
public:
    /// None of the arguments is owned.
    LinkLossWatch(BusModel *model, CommandedMotion *motion, MessageBanner *banner,
                  QObject *parent = nullptr);

    static QString entryKey(int id) { return QStringLiteral("mayBeMoving/%1").arg(id); }
    /// Drives with a warning shown, ascending.
    QVector<int> warnedIds() const;

public slots:
    /// Telemetry from the bus: a zero speed read after the reconnect clears a warning.
    void onTelemetry(const lk::bus::TelemetryBatch &batch);

private:
    void onConnectionChanged();
    void warn(int id);
    void clear(int id);

    BusModel *m_model;
    CommandedMotion *m_motion;
    MessageBanner *m_banner;
    QSet<int> m_warned;
    bool m_wasOpen = false;
};

} // namespace lk::ui
