#pragma once

#include <bus/KnownMotor.h>
#include <bus/MultiTorque.h>
#include <protocol/Series.h>
#include <safety/MultiTorqueGuard.h>
#include <safety/SoftLimits.h>

#include <QtCore/QMap>
#include <QtCore/QPointer>
#include <QtWidgets/QGroupBox>

#include <functional>
#include <optional>

class QCheckBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QPushButton;

namespace lk::bus {
class BusSession;
}

namespace lk::ui {

class RequestTracker;

/// The old CAN generation's multi-motor torque frame (0x280, docs/CAN.md section 4.2): one row
/// per drive of ID 1..4 on the bus (a tick, its torque in A bounded by its soft limits, its
/// last reply), Send and Stop. Send builds one torque request per ticked drive and passes them
/// through safety::MultiTorqueGuard with the link, each drive's series, generation and limits
/// and the IDs on the bus: one refusal names the drive and the limit and sends nothing to any
/// drive, and so does a known drive of ID 1..4 left unticked (the frame would give it 0 A).
/// Nothing is ticked at first, nothing is ever sent on a timer, and an emergency stop or a
/// connection change unticks everything and forgets the last frame. Off CAN, without an old
/// CAN drive at IDs 1..4, or while the link may not transmit (listen-only, replay), the panel
/// says why in one line and sends nothing. lkstudio places it in the Control view.
class MultiTorquePanel : public QGroupBox {
    Q_OBJECT
public:
    /// The limits drive `id` is bounded by; nullopt with the refusal in `why` while its stored
    /// limits are damaged.
    using LimitsLookup = std::function<std::optional<safety::SoftLimits>(
        int id, const bus::KnownMotor &motor, QString *why)>;

    explicit MultiTorquePanel(QWidget *parent = nullptr);
    ~MultiTorquePanel() override;

    /// The bus (not owned): its drives make the rows, its emergency stop resets the panel.
    void setSession(bus::BusSession *session);
    /// Where each drive's limits come from (default: its series' defaults).
    void setLimitsLookup(LimitsLookup lookup);
    /// The link of the connection: the frame exists on CAN only. A change resets the panel.
    void setLink(protocol::Link link);
    /// Whether the link may transmit (BusModel::canSend); `whyNot` is said while it may not
    /// (listen-only). A change resets the panel.
    void setConnected(bool canSend, const QString &whyNot = {});

    /// The Send button: one frame with the ticked drives' torques, or a refusal.
    void send();
    /// The Stop button: Motor Stop (0x81) to every drive of the last frame.
    void stop();
    /// Unticks every drive, sets every torque back to 0 A, forgets the last frame and its
    /// replies (results of a frame sent before are dropped); `why` is shown.
    void reset(const QString &why);

    /// The drive title the panel uses: "Drive 3" or "Drive 3 (MG4010)".
    static QString driveTitle(int id, const bus::KnownMotor &motor);
    /// Empty when the panel can be used on this link and bus; else the one-line reason.
    QString absence() const { return m_absence; }
    /// The IDs that have a row, ascending.
    QVector<int> rowIds() const { return m_rows.keys().toVector(); }
    /// Why drive `id` cannot be ticked (empty: it can).
    QString rowRefusal(int id) const;
    QString replyText(int id) const;
    QString statusText() const;
    /// The drives Stop reaches: those of the last frame, and of one still awaited.
    QVector<int> stopTargets() const;

signals:
    /// Send was refused before anything went out (the reason, translated).
    void refused(const QString &reason);
    /// A frame handed to the bus ended (sent and answered or not, or refused there).
    void frameFinished(const lk::bus::MultiTorqueResult &result);

private:
    struct Row {
        bus::KnownMotor motor;
        QString refusal; ///< why it cannot be ticked; empty: it can
        QCheckBox *tick = nullptr;
        QDoubleSpinBox *iq = nullptr;
        QLabel *reply = nullptr;
    };

    void setDrives(const bus::KnownMotors &motors);
    void buildRow(int id, const bus::KnownMotor &motor);
    void removeRow(int id);
    /// The rows' limits and refusals again (limits may have changed since); a row refused
    /// is unticked. Bounds the torque to the limits (a value beyond is brought to them).
    void refreshRows();
    void refreshRow(int id, Row &row);
    void refreshAbsence();
    void refreshEnabled();
    bool canUse() const;
    /// Why a drive of this identity cannot be in the frame; empty when it can. `bound`: the
    /// largest torque its limits allow (0 when refused).
    QString refusalOf(int id, const bus::KnownMotor &motor, double *bound) const;
    std::optional<safety::SoftLimits> limitsOf(int id, const bus::KnownMotor &motor,
                                               QString *why) const;
    /// The guard's refusal in the panel's words.
    QString refusalText(const safety::MultiTorqueVerdict &verdict,
                        const QMap<int, safety::MultiTorqueDrive> &drives) const;
    void refuse(const QString &why);
    void onFrameEnded(const bus::MultiTorqueResult &result);
    void setStatus(const QString &text, bool error = false);

    QPointer<bus::BusSession> m_session;
    QMetaObject::Connection m_motorsConnection;
    QMetaObject::Connection m_stopConnection;
    RequestTracker *m_tracker;
    LimitsLookup m_limits;
    protocol::Link m_link = protocol::Link::Rs485;
    bool m_canSend = false;
    QString m_whyNot;
    QString m_absence;
    bus::KnownMotors m_motors; ///< what the session knows, all IDs
    QMap<int, Row> m_rows;     ///< IDs 1..4 on the bus
    QVector<int> m_lastFrame;  ///< the drives of the last frame that went on the wire
    QVector<int> m_awaited;    ///< the drives of a frame handed to the bus, not ended yet
    quint64 m_epoch = 0;       ///< reset() count: a frame's end from before it is dropped
    QLabel *m_reason = nullptr;
    QWidget *m_rowBox = nullptr;
    QGridLayout *m_grid = nullptr;
    QPushButton *m_send = nullptr;
    QPushButton *m_stop = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace lk::ui
