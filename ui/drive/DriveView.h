#pragma once

#include <bus/KnownMotor.h>
#include <protocol/Series.h>

#include <QtCore/QFlags>
#include <QtCore/QPointer>
#include <QtWidgets/QWidget>

#include <optional>

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class RequestTracker;

/// Common face of the drive views (tuning, control, encoder, info) towards the main window:
/// a session, the selected drive (or none) and whether the link may transmit. Everything that
/// sends is disabled unless all three are there (canSendToDrive()); while the link is open
/// but may not transmit (listen-only), every disabled button says why in its tooltip.
class DriveView : public QWidget {
    Q_OBJECT
public:
    enum class Change {
        Session = 0x1,    ///< another session (or none)
        Drive = 0x2,      ///< another drive ID (or none)
        MotorInfo = 0x4,  ///< same ID, new model or series information
        Connection = 0x8, ///< the link came up or went down
    };
    Q_DECLARE_FLAGS(Changes, Change)

    explicit DriveView(QWidget *parent = nullptr);

    /// The bus to talk to; not owned. Pending requests of the previous one are forgotten.
    void setSession(lk::bus::BusSession *session);
    lk::bus::BusSession *session() const;
    /// Select a drive by ID with what the bus knows about it (series, model).
    void setDrive(int id, const lk::bus::KnownMotor &motor);
    /// No drive selected: the view shows nothing to act on.
    void clearDrive();
    /// Whether the link may transmit (BusModel::canSend: open, and not listen-only); sending
    /// controls are disabled while it may not. `whyNot`: what the disabled buttons' tooltips
    /// and the views' status say (empty: the plain "disconnected" wording).
    void setConnected(bool connected, const QString &whyNot = {});
    /// The link's kind (RS485 or CAN): on CAN the generation is known without a model read and
    /// the link decides which commands exist (GenerationNote). A change is MotorInfo news.
    void setLink(protocol::Link link);
    protocol::Link link() const { return m_link; }

    int driveId() const { return m_id; } ///< 0 when no drive is selected
    bool hasDrive() const { return m_id > 0; }
    const lk::bus::KnownMotor &motor() const { return m_motor; }
    /// The link may transmit (open and not listen-only).
    bool isConnected() const { return m_connected; }
    /// What a view says instead of `disconnected` while it cannot send: the reason given to
    /// setConnected (listen-only), else `disconnected` itself.
    QString cannotSendText(const QString &disconnected) const;
    /// The drive's series: from the KnownMotor given, else what the session knows.
    std::optional<protocol::Series> series() const;
    /// A session, a connected link and a selected drive: this view can send to its drive.
    /// More than the link being open (BusModel::connection().isOpen()).
    bool canSendToDrive() const;
    /// "Drive 3 (MF4015)" or "no drive selected".
    QString driveTitle() const;

protected:
    RequestTracker *tracker() const { return m_tracker; }
    /// Called after any change of session, drive or connection; refresh and enable here.
    virtual void contextChanged(Changes changes) = 0;

private:
    void notify(Changes changes);

    QPointer<lk::bus::BusSession> m_session;
    RequestTracker *m_tracker;
    int m_id = 0;
    lk::bus::KnownMotor m_motor;
    bool m_connected = false;
    QString m_whyNot;
    protocol::Link m_link = protocol::Link::Rs485;
};

} // namespace lk::ui

Q_DECLARE_OPERATORS_FOR_FLAGS(lk::ui::DriveView::Changes)
