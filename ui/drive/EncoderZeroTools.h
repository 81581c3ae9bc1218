#pragma once

#include "AngleCheck.h"
#include "RequestTracker.h"

#include <bus/KnownMotor.h>
#include <protocol/Request.h>

#include <QtWidgets/QGroupBox>

#include <functional>
#include <optional>

class QLabel;
class QPushButton;

namespace lk::ui {

struct ConfirmRequest;

/// The zero tools of the Encoder view, each asked first and checked after: clear motor angle
/// (0x95) verified with read_multi_turn before and after (firmware that acknowledges and
/// ignores it is named); current position to ROM as zero (0x19, sent once, never retried:
/// power cycle, flash wear); on V2.35 drives clear turn count (0x93) with a read-back of the
/// multi-turn angle. One sequence at a time; it sends through the function the view gives it
/// and reports what it did with statusChanged().
class EncoderZeroTools : public QGroupBox {
    Q_OBJECT
public:
    /// Queues a request on the view's path; returns the ticket (0: nothing sent).
    using Sender =
        std::function<quint64(const protocol::Request &, RequestTracker::Callback, int retries)>;

    explicit EncoderZeroTools(QWidget *parent = nullptr);

    void setSender(Sender sender) { m_send = std::move(sender); }
    /// The drive acted on (0: none), whether anything can be sent, and the link (CAN has no
    /// 0x93: GenerationNote).
    void setDrive(int id, const bus::KnownMotor &motor, bool canSend,
                  protocol::Link link = protocol::Link::Rs485);
    /// The requests of a running sequence were dropped (another session or drive, nothing
    /// pending any more): it ends without a result. `forgetCheck`: the last check goes too.
    void abandon(bool forgetCheck);
    /// Rotor degrees per output turn / 360 (the turn-count read-back allows one output turn).
    void setGearRatio(double ratio) { m_ratio = ratio; }
    /// Another sequence of the view (an offset write) runs: none starts here meanwhile.
    void setBlocked(bool blocked);
    bool isBusy() const { return m_busy; }

    void clearAngle();     ///< asks, then 0x95 checked with 0x92 before and after
    void writeZeroToRom(); ///< asks, then 0x19 once
    void clearTurnCount(); ///< V2.35: asks, then 0x93 and the multi-turn angle read back
    /// Empty when the drive's generation has clear turn count (0x93); else why not.
    QString turnCountAbsence() const;
    std::optional<AngleCheck> lastAngleCheck() const { return m_angleCheck; }

signals:
    void statusChanged(const QString &text, bool error);
    /// A multi-turn angle read by a sequence (rotor degrees).
    void multiTurnRead(double deg);
    void busyChanged(bool busy);
    void angleCheckFinished(const lk::ui::AngleCheck &check);
    void zeroWriteFinished(bool ok);
    void turnCountCleared(bool ok);

private:
    bool canStart() const { return m_canSend && !m_busy && !m_blocked && m_id > 0; }
    bool confirm(const ConfirmRequest &request);
    void setBusy(bool busy);
    void fail(const bus::RequestResult &result);
    void readMultiTurn(std::function<void(double)> then);
    void onClearAcknowledged(int id, double before);
    void onTurnsCleared(int id, double before);
    void showAngleCheck(const AngleCheck &check);
    void refreshEnabled();

    Sender m_send;
    int m_id = 0;
    bus::KnownMotor m_motor;
    protocol::Link m_link = protocol::Link::Rs485;
    bool m_canSend = false;
    bool m_busy = false;
    bool m_blocked = false;
    double m_ratio = 1.0;
    std::optional<AngleCheck> m_angleCheck;
    QPushButton *m_clearAngle = nullptr;
    QPushButton *m_zeroRom = nullptr;
    QPushButton *m_clearTurns = nullptr;
    QLabel *m_clearTurnsNote = nullptr;
};

} // namespace lk::ui
