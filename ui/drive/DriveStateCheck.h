#pragma once

#include "RequestTracker.h"

#include <bus/KnownMotor.h>
#include <bus/TelemetrySample.h>
#include <protocol/Request.h>
#include <protocol/Values.h>

#include <QtCore/QObject>

#include <functional>
#include <optional>

namespace lk::ui {

/// What a V2.35 drive's own state says about motion before the Control view sends any: its
/// motor-on flag (0x9A motorState) and its holding brake (0x8C). After Motor Off (0x80) or a
/// protection trip a V2.35 drive stays off until Motor On (0x88), and a control command is
/// answered but not acted on (docs/V2.35.md sections 3 and 11): motion to a drive that reads
/// off is refused with what to do. An engaged brake holds the shaft: motion is sent with a
/// warning. A V2.3 drive has neither flag: nothing is checked. The state comes from reads
/// (refresh()), the poll's telemetry and the brake panel's reads.
class DriveStateCheck : public QObject {
    Q_OBJECT
public:
    /// Queues a read on the view's path; returns the ticket (0: nothing sent).
    using Sender = std::function<quint64(const protocol::Request &, RequestTracker::Callback)>;

    explicit DriveStateCheck(Sender sender, QObject *parent = nullptr);

    /// The drive checked (0: none); forgets the state read for another.
    void setDrive(int id, const bus::KnownMotor &motor);
    /// True for a V2.35 drive: its motor state and brake decide.
    bool applies() const;
    /// True when `request` is motion this check stands before: not Motor On itself, and not
    /// a command that holds the drive still (speed, torque or power 0), which is never held
    /// back.
    bool gates(const protocol::Request &request) const;
    std::optional<bool> motorOn() const { return m_motorOn; }
    std::optional<bool> brakeReleased() const { return m_brakeReleased; }

    /// Reads the motor state (0x9A) and, unless `motorOnly`, the brake (0x8C); `then(ok)` runs
    /// once the motor state has answered (ok: it was read).
    void refresh(std::function<void(bool ok)> then = {}, bool motorOnly = false);
    /// Reads the motor state, then runs `known` when it tells on or off, or `unknown` with
    /// the refusal (translated) when it could not be told. Nothing runs for another drive.
    void whenKnown(std::function<void()> known, std::function<void(const QString &)> unknown);
    void noteTelemetry(const bus::TelemetryBatch &batch);
    void noteBrake(const protocol::BrakeState &state);

    /// Why motion must not be sent now (translated); empty when it may.
    QString refusal() const;
    /// What to say with motion that is sent (the brake reads engaged); empty when nothing.
    QString warning() const;
    /// The drive's state in one line for the command box; empty for a V2.3 drive.
    QString stateText() const;

signals:
    /// The motor state or the brake state changed (or became unknown).
    void changed();

private:
    void setMotorOn(std::optional<bool> on);

    Sender m_send;
    int m_id = 0;
    bool m_v235 = false;
    std::optional<bool> m_motorOn;
    std::optional<bool> m_brakeReleased;
};

} // namespace lk::ui
