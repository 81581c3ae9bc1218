#pragma once

#include "RequestTracker.h"

#include <bus/KnownMotor.h>
#include <protocol/Values.h>

#include <QtWidgets/QGroupBox>

#include <functional>
#include <optional>

class QLabel;
class QPushButton;

namespace lk::ui {

/// The holding brake of a V2.35 drive (0x8C): read its state, engage it, release it. Release
/// asks first (a vertical axis drops its load), and while the motor is off (read with 0x9A
/// just before) it is refused unless the user also confirms a second, explicit warning. Every
/// change is followed by a read-back; the panel says what was sent and what the drive answered.
/// On a V2.3 drive (or one whose generation is unknown) it says why there is no brake command
/// and sends nothing; a CAN V2.36 drive has it (docs/CAN.md). It sends through the function the
/// Control view gives it.
class BrakePanel : public QGroupBox {
    Q_OBJECT
public:
    /// Queues a request on the Control view's path; returns the ticket (0: nothing sent).
    using Sender =
        std::function<quint64(const protocol::Request &, RequestTracker::Callback, int retries)>;

    explicit BrakePanel(QWidget *parent = nullptr);

    void setSender(Sender sender) { m_send = std::move(sender); }
    /// The drive acted on (0: none), whether anything can be sent, and the link (on CAN the
    /// generation is known without a model read); forgets the state read.
    void setDrive(int id, const bus::KnownMotor &motor, bool canSend,
                  protocol::Link link = protocol::Link::Rs485);

    void readState(); ///< 0x8C with 0x10 (read only)
    void engage();    ///< 0x8C 0x00, then read back
    void release();   ///< asks (twice while the motor is off), 0x8C 0x01, then read back

    /// Empty when the drive has the brake command; else the reason shown in its place.
    QString absence() const { return m_absence; }
    std::optional<protocol::BrakeState> lastState() const { return m_state; }
    QString statusText() const;

signals:
    /// A brake change was answered (`ok`) or failed; the read-back follows.
    void changeFinished(bool ok);
    /// The drive told its brake state (a read, a change's answer or its read-back).
    void stateRead(const lk::protocol::BrakeState &state);

private:
    bool usable() const;
    bool stillSame(int id) const;
    void releaseAfterMotorState(int id, const bus::RequestResult &state);
    void sendAction(int id, protocol::BrakeAction action);
    void showState(const protocol::BrakeState &state);
    void setStatus(const QString &text, bool error = false);
    void setBusy(bool busy);
    void refreshEnabled();
    static QString stateText(const protocol::BrakeState &state);

    Sender m_send;
    int m_id = 0;
    bus::KnownMotor m_motor;
    bool m_canSend = false;
    bool m_busy = false;
    QString m_absence;
    std::optional<protocol::BrakeState> m_state;
    QLabel *m_stateLabel = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_read = nullptr;
    QPushButton *m_engage = nullptr;
    QPushButton *m_release = nullptr;
};

} // namespace lk::ui
