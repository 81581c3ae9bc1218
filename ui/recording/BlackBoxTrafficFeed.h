#pragma once

#include "RingTrafficTap.h"

#include <QtCore/QObject>

class QTimer;

namespace lk::ui {

class BlackBoxRecorder;
class TrafficPanel;

/// Feeds the Traffic view from the black box: when the view opens (captureWanted) it shows
/// the whole ring, so the traffic of the minutes it was closed is there, then follows what
/// the ring receives at 10 Hz until the view closes.
class BlackBoxTrafficFeed : public QObject {
    Q_OBJECT
public:
    BlackBoxTrafficFeed(BlackBoxRecorder *recorder, TrafficPanel *panel, QObject *parent = nullptr);

    /// Read the whole ring into the view again.
    void reload();
    /// Move what the ring received since the last call into the view (the timer does it).
    void follow();
    /// While suspended (a recording plays in the view) the ring is not shown; resuming
    /// shows it again if the view is open.
    void setSuspended(bool on);

private:
    void setLooking(bool on);

    BlackBoxRecorder *m_recorder;
    TrafficPanel *m_panel;
    QTimer *m_timer;
    RecordTrafficConverter m_converter;
    qint64 m_shownUntilNs = -1; ///< records up to this time came with the ring's snapshot
    bool m_looking = false;     ///< the view wants traffic
    bool m_suspended = false;
};

} // namespace lk::ui
