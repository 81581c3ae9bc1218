#pragma once

#include "DriveView.h"
#include "MotionGate.h"
#include "SetpointGenerator.h"

#include <bus/RequestResult.h>
#include <bus/SetpointWaveform.h>
#include <bus/TelemetrySample.h>
#include <safety/SoftLimits.h>

#include <QtWidgets/QBoxLayout>

#include <functional>

class QLabel;

namespace lk::ui {

class BrakePanel;
class ControlCommandBox;
class ControlLimits;
class DriveStateCheck;
class ControlModePanel;
class DriveSettingsStore;
class JogKeys;
class JogPanel;
class LoopPlot;
class SetpointPanel;
class SoftLimitsEditor;
class TelemetryStore;

/// Commands a drive in every control mode of protocol V2.3 (modes the series lacks are not
/// offered), with Motor Off / Stop / Run, jog (hold-to-run speed, step moves, optional arrow
/// keys) and a setpoint generator for tuning. Every motion command passes the protocol
/// builders and MotionGuard (series and the drive's soft limits, editable and persisted)
/// before it is sent; a refusal sends nothing and says which limit stopped it. The generator's
/// setpoints are paced and checked the same way on the bus thread (bus::SetpointStream), with
/// the limits and the angle this view hands it at the start. A V2.35 drive's
/// holding brake (0x8C) is in its own BrakePanel, which sends through this view's path.
///
/// An emergency stop on the session, a drive or connection change and Motor Off/Stop all halt
/// the generator and the jog. Esc belongs to lkstudio's emergency stop (EmergencyStopControl),
/// which calls haltLocalMotion() before it sends anything.
class ControlView : public DriveView {
    Q_OBJECT
public:
    explicit ControlView(QWidget *parent = nullptr);
    ~ControlView() override;

    /// lkstudio's shared telemetry for the live plot (not owned); without one the plot
    /// records its own from the session.
    void setTelemetryStore(TelemetryStore *store);
    /// Where soft limits persist, per drive (not owned; default: kept for this process).
    void setSettingsStore(DriveSettingsStore *store);
    safety::SoftLimits softLimits() const;
    /// The limits every motion of the selected drive is bounded by (the soft limits, lowered
    /// to the drive's own where a V2.35 drive's were read), or nullopt with the refusal
    /// (`why`) while the stored limits are damaged and none were applied.
    std::optional<safety::SoftLimits> limitsInForce(QString *why) const;
    /// Applies and persists the drive's soft limits.
    void setSoftLimits(const safety::SoftLimits &limits);

    /// Sends the command of the current mode and inputs through the gate.
    MotionOutcome sendCommand();
    /// Any motion request through the gate (builder error, MotionPlanner, then the bus). A
    /// move that needs the drive's angle reads it (0x92) first, and motion to a V2.35 drive
    /// reads its motor state (0x9A) first: the outcome is then pending and lastOutcome()
    /// tells the result once the reads have answered. A V2.35 drive that reads off is
    /// refused (Motor On first, DriveStateCheck).
    MotionOutcome sendMotion(const protocol::BuildResult &built);
    /// The multi-turn angle last read from the drive (0x92 or telemetry); nullopt: not yet.
    std::optional<double> currentAngle() const { return m_angleDeg; }
    /// The drives selected in lkstudio: with several, the view says which one it acts on.
    void setSelectedDrives(const QVector<int> &ids);
    void motorOff();              ///< 0x80, ahead of queued work; halts generator and jog
    void motorStop();             ///< 0x81, ahead of queued work; halts generator and jog
    void motorRun();              ///< 0x88 through the gate (V2.35: Motor On)
    void startJog(int direction); ///< speed command at the jog speed, sign = direction
    void endJog();                ///< speed 0 when a jog is running
    void step(int direction);     ///< one incremental move of the jog step
    void startGenerator(const bus::SetpointWaveform::Settings &settings);
    /// Stops the generator and sends motor_stop (the last setpoint must not stay active).
    void stopGenerator();
    /// Stops generator and jog without sending anything (emergency stop is under way).
    /// lkstudio's emergency stop (button or Esc) should call it before stopping the bus, so
    /// that no setpoint can follow the emergency motor_off.
    void haltLocalMotion(const QString &reason);
    /// Drive `id` stopped without this view stopping it (a fault trip, the speed watch): the
    /// status says `why` instead of the command last sent; its generator and jog halt.
    void showDriveStopped(int id, const QString &why)
    {
        if (id == driveId()) { // (here: ControlView.cpp is at its 600 lines)
            haltLocalMotion(why);
            setStatus(why, true);
        }
    }

    ControlModePanel *modePanel() const { return m_modes; }
    JogPanel *jogPanel() const { return m_jog; }
    SetpointPanel *setpointPanel() const { return m_setpointPanel; }
    BrakePanel *brakePanel() const { return m_brake; }
    /// Places `panel` in the right column under the brake (lkstudio's multi-motor torque).
    void addSidePanel(QWidget *panel) { m_side->insertWidget(m_side->count() - 1, panel); }
    DriveStateCheck *driveState() const { return m_driveState; }
    ControlLimits *limits() const { return m_limitSet; }
    SetpointGenerator *generator() const { return m_generator; }
    LoopPlot *plot() const { return m_plot; }
    bool isJogging() const { return m_jogging; }
    QString statusText() const;
    MotionOutcome lastOutcome() const { return m_last; }

signals:
    /// A command was refused before sending (reason translated).
    void commandRefused(const QString &reason);

protected:
    void contextChanged(Changes changes) override;

private:
    void wire();
    void loadLimits();
    void readDriveState();
    void showDriveState();
    /// sendMotion() once the motor state allows it: reads the angle first where needed.
    MotionOutcome moveFromWhereTheDriveIs(const protocol::BuildResult &built);
    void startGeneratorNow(const bus::SetpointWaveform::Settings &settings);
    /// Stops the generator (and the drive) when the limits or series it runs under changed.
    void keepGeneratorWithinLimits();
    void readAngle(std::function<void()> then = {});
    void onAngle(int id, double deg);
    MotionOutcome submitMotion(const protocol::BuildResult &built);
    safety::DrivePosition drivePosition() const;
    void refreshSelectionNote();
    void onMotionResult(const bus::RequestResult &result);
    void sendRunState(protocol::Command command);
    void onTelemetry(const bus::TelemetryBatch &batch);
    void report(const MotionOutcome &outcome, const QString &sentText);
    /// Says why nothing was sent (as report()) and returns that outcome.
    MotionOutcome refuse(const QString &why, safety::LimitKind limit = safety::LimitKind::None);
    /// A motion that waits for a read: the outcome is pending, `status` says what is read.
    MotionOutcome pendingOn(const QString &status);
    void setStatus(const QString &text, bool error = false);
    void refreshEnabled();

    ControlLimits *m_limitSet;     ///< soft limits (stored per drive) and the drive's own
    DriveStateCheck *m_driveState; ///< V2.35: motor on and brake before motion
    std::optional<double> m_angleDeg;
    QVector<int> m_selected;
    ControlCommandBox *m_commandBox = nullptr;
    ControlModePanel *m_modes = nullptr; ///< the command box's
    SoftLimitsEditor *m_limitsEditor = nullptr;
    JogPanel *m_jog = nullptr;
    JogKeys *m_keys = nullptr; ///< the arrow keys as jog controls
    SetpointPanel *m_setpointPanel = nullptr;
    BrakePanel *m_brake = nullptr;
    QVBoxLayout *m_side = nullptr; ///< the right column, its stretch last
    SetpointGenerator *m_generator = nullptr;
    LoopPlot *m_plot = nullptr;
    QLabel *m_title = nullptr;
    QLabel *m_readout = nullptr;
    QLabel *m_status = nullptr;
    QString m_offlineShown; ///< the "cannot send" status last shown, cleared when it ends
    QMetaObject::Connection m_telemetryConnection;
    QMetaObject::Connection m_stopConnection;
    MotionOutcome m_last;
    int m_motionId = 0;     ///< drive the generator or jog commands
    quint64 m_halts = 0;    ///< haltLocalMotion() calls: a start waiting on a read checks it
    bool m_jogging = false; ///< a hold-to-run speed command is active
};

} // namespace lk::ui
