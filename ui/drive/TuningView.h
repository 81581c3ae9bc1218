#pragma once

#include "DriveView.h"
#include "ParamSetSpec.h"
#include "ParameterTable.h"
#include "TuningSetCan236.h"
#include "TuningSetV23.h"
#include "TuningSetV235.h"

#include <safety/MotionGuard.h>
#include <safety/SoftLimits.h>

#include <QtCore/QJsonObject>

#include <functional>
#include <optional>

class QGroupBox;
class QLabel;
class QPushButton;
class QTabWidget;

namespace lk::ui {

class FrequencyTuningView;

class DriveLimitsView;
class LoopPlot;
class StepRunList;
class StepRunsView;
class StepTestPanel;
class TelemetryStore;
class TuningSetCycle;

/// Tuning of one drive, in the set its protocol generation has: on V2.3 PID gains (angle, speed,
/// iq; Kp/Ki 0..255) and acceleration, on V2.35 Kp/Ki/Kd (0..65535) of the three loops
/// (ParamIDs 0x96..0x98; the ramps are drive limits there). Reads them from the drive, shows "first
/// read", "drive holds" and the pending edit side by side with differences highlighted, writes to
/// RAM (try) or ROM (keep, after a confirmation that says why), and reads back after every write so
/// that what the drive really holds is shown, mismatches included.
///
/// Never writes what was not read (TuningSetCycle runs the read / write / read-back cycle and
/// keeps that rule): edits, writes, restores and file loads stay disabled until
/// a complete read (every value of the set answered) of the selected drive succeeded on
/// the current connection; another drive, another session or a reconnection starts over, and
/// unknown values show as unknown. Unsent edits stay with their drive (kept while another
/// drive is selected, dropped with the connection). "Restore values read at ..." writes the
/// values of the first complete read back to RAM after asking. Parameters save to and load
/// from JSON files. A live plot of the loop being edited stays beside the table. A second tab
/// holds the drive's own limits (DriveLimitsView, V2.35 only).
class TuningView : public DriveView {
    Q_OBJECT
public:
    explicit TuningView(QWidget *parent = nullptr);
    ~TuningView() override;

    /// lkstudio's shared telemetry (not owned); without one the plot records its own from
    /// the session's telemetryReceived.
    void setTelemetryStore(TelemetryStore *store);

    /// Reads the set from the drive (V2.3: read_pid, read_accel; V2.35: 0x40 per loop).
    void readFromDrive();
    /// Writes the pending edit to RAM (V2.3: 0x31, 0x34; V2.35: 0x42) and reads back.
    void writeToRam();
    /// Asks, then writes the gains to ROM (V2.3: 0x32 and acceleration to RAM, which V2.3
    /// cannot store; V2.35: 0x44 per loop), each frame once and never retried, then reads
    /// back. Declining sends nothing.
    void writeToRom();
    /// Asks, then writes the values of this drive's first complete read on this connection
    /// back to RAM, and reads back. Declining sends nothing.
    void restoreFirstRead();
    /// Saves what the drive holds (last read) with its model, firmware and a timestamp.
    /// Returns an error text, empty on success.
    QString saveParameters(const QString &path);
    /// Loads a file into the pending edit (nothing is written); needs a complete read of the
    /// drive first. A file that cannot be read or is not a valid parameter file changes
    /// nothing, and so does a file of the other protocol generation. Returns an error text
    /// naming the key and range (or the generations), empty on success.
    QString loadParameters(const QString &path);

    ParameterTable *table() const { return m_table; }
    LoopPlot *plot() const { return m_plot; }
    /// The drive limits editor (the "Drive limits" tab; V2.35 only).
    DriveLimitsView *limits() const { return m_limits; }
    /// The step test beside the gains, and the runs it kept (the "Step response" tab).
    StepTestPanel *stepTest() const { return m_stepTest; }
    StepRunsView *stepRuns() const { return m_stepRuns; }
    StepRunList *runList() const { return m_runs; }
    /// Where step tests get their soft limits (the Control view's, nullopt with the reason
    /// when they cannot be used).
    void setStepTestLimits(std::function<std::optional<safety::SoftLimits>(QString *why)> limits);
    /// Shows the live plot (false) or the step response (true) beside the table.
    void showStepResponse(bool show);
    /// Stops a running step test from sending (the emergency stop's first step).
    void haltLocalMotion(const QString &reason);
    /// The set of the selected drive's generation.
    const ParamSetSpec &spec() const { return *m_spec; }
    /// The link the drives are reached over. A V2.36 drive on CAN keeps its control
    /// parameters in RAM only: they are read with 0xC0 and written with 0xC1 (TuningSetCan236),
    /// no ROM write is offered, and a label says why; an old CAN drive keeps V2.3's 0x30..0x34
    /// with RAM and ROM.
    void setLink(protocol::Link link);
    /// The selected drive is a V2.36 drive on CAN: its parameters are RAM only.
    bool isRamOnly() const { return m_ramOnly; }
    /// What the drive holds (last read), one per field of spec(); nullopt while unknown.
    HeldValues driveValues() const;
    /// Every value of the selected drive's set was read on this connection: edits and writes
    /// are possible.
    bool readComplete() const;
    /// The "RAM differs from ROM" warning is up (the RAM/ROM line shows it highlighted).
    bool romWarningShown() const;
    /// The read-back disagreed with what was written (empty when it agreed).
    QString mismatchText() const;
    QString statusText() const;
    bool isBusy() const;

signals:
    /// A read (or a write's read-back) of drive `id` completed.
    void parametersRead(int id);
    /// The running step test's Stop button: the emergency stop's job.
    void emergencyStopRequested();

protected:
    void contextChanged(Changes changes) override;
    void changeEvent(QEvent *event) override;

private:
    void buildUi();
    QWidget *buildButtons();
    QWidget *buildStepTab();
    /// What the drive holds (last complete read), under lkctl's names: the gains, or the
    /// ramps (accel_dps2, current_ramp, speed_ramp_dps2).
    QJsonObject heldObject(bool ramps) const;
    void updateStepDrive();
    const ParamSetSpec *specFor(protocol::Generation generation) const;
    /// Shows the set of the selected drive's generation.
    void selectSpec();
    /// Keeps the drive limits tab on the same session, drive and connection.
    void forwardContext(Changes changes);
    void wireCycle();
    void refreshWarnings();
    void refreshEnabled();
    /// A V2.36 drive on CAN: m_ramOnly follows; true when that changed.
    bool updateRamOnly();
    void refreshRestoreButton();
    void setStatus(const QString &text, bool error = false);

    TuningSetV23 m_v23;
    TuningSetV235 m_v235;
    TuningSetCan236 m_can236;
    const ParamSetSpec *m_spec = &m_v23;
    TuningSetCycle *m_cycle = nullptr;
    ParameterTable *m_table = nullptr;
    QGroupBox *m_box = nullptr;
    QTabWidget *m_tabs = nullptr;
    DriveLimitsView *m_limits = nullptr;
    QLabel *m_note = nullptr;
    QLabel *m_ramOnlyNote = nullptr; ///< why a CAN V2.36 drive has no ROM button
    LoopPlot *m_plot = nullptr;
    QTabWidget *m_side = nullptr; ///< live plot | step response | frequency response
    FrequencyTuningView *m_frequency = nullptr;
    StepRunList *m_runs = nullptr;
    StepTestPanel *m_stepTest = nullptr;
    StepRunsView *m_stepRuns = nullptr;
    QPushButton *m_repeatStep = nullptr;
    QLabel *m_title = nullptr;
    QLabel *m_romWarning = nullptr;
    QLabel *m_mismatch = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_read = nullptr;
    QPushButton *m_writeRam = nullptr;
    QPushButton *m_writeRom = nullptr;
    QPushButton *m_undo = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_load = nullptr;
    QMetaObject::Connection m_telemetry;

    bool m_romWarningActive = false;
    protocol::Link m_link = protocol::Link::Rs485;
    bool m_ramOnly = false; ///< the drive shown is a V2.36 drive on CAN
};

} // namespace lk::ui
