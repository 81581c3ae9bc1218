#pragma once

#include "DriveView.h"

#include <bus/RequestResult.h>
#include <protocol/Values.h>

#include <QtCore/QHash>

#include <optional>

class QLabel;
class QPushButton;

namespace lk::ui {

class LoopPlot;
class ParameterTable;
class TelemetryStore;

/// Tuning of one drive: PID gains (angle, speed, iq; Kp/Ki 0..255) and acceleration. Reads
/// them from the drive, shows "at selection", "drive holds" and the pending edit side by side
/// with differences highlighted, writes to RAM (try) or ROM (keep, after a confirmation that
/// says why), and reads back after every write so that what the drive really holds is shown,
/// mismatches included. Undo restores the values read when the drive was first selected in
/// this session; parameters save to and load from JSON files. A live plot of the loop being
/// edited stays beside the table.
class TuningView : public DriveView {
    Q_OBJECT
public:
    explicit TuningView(QWidget *parent = nullptr);
    ~TuningView() override;

    /// lkstudio's shared telemetry (not owned); without one the plot records its own from
    /// the session's telemetryReceived.
    void setTelemetryStore(TelemetryStore *store);

    /// Reads PID and acceleration from the drive (read_pid, read_accel).
    void readFromDrive();
    /// Writes the pending edit to RAM (0x31, 0x34) and reads back.
    void writeToRam();
    /// Asks, then writes the gains to ROM (0x32, once, never retried) and acceleration to RAM
    /// (V2.3 has no ROM command for it), then reads back. Declining sends nothing.
    void writeToRom();
    /// Writes the values read when the drive was first selected back to RAM.
    void undoToSelection();
    /// Saves what the drive holds (last read) with its model, firmware and a timestamp.
    /// Returns an error text, empty on success.
    QString saveParameters(const QString &path);
    /// Loads a file into the pending edit (nothing is written). A file that cannot be read
    /// or parsed changes nothing. Returns an error text, empty on success.
    QString loadParameters(const QString &path);

    ParameterTable *table() const { return m_table; }
    LoopPlot *plot() const { return m_plot; }
    std::optional<protocol::PidGains> drivePid() const { return m_holdsPid; }
    std::optional<qint32> driveAccel() const { return m_holdsAccel; }
    /// The "RAM differs from ROM" warning is up (the RAM/ROM line shows it highlighted).
    bool romWarningShown() const;
    /// The read-back disagreed with what was written (empty when it agreed).
    QString mismatchText() const;
    QString statusText() const;
    bool isBusy() const;

signals:
    /// A read (or a write's read-back) of drive `id` completed.
    void parametersRead(int id);

protected:
    void contextChanged(Changes changes) override;
    void changeEvent(QEvent *event) override;

private:
    /// What the view remembers about a drive for the session.
    struct DriveMemory {
        bool originalRead = false;
        std::optional<protocol::PidGains> originalPid;
        std::optional<qint32> originalAccel;
        std::optional<protocol::PidGains> lastRomPid; ///< last 0x32 this session
        bool ramWritten = false; ///< RAM gains written this session after the last ROM write
    };
    /// What the last write asked for, compared with the read-back.
    struct Expected {
        bool rom = false;
        std::optional<protocol::PidGains> pid;
        std::optional<qint32> accel;
    };

    void buildUi();
    QWidget *buildButtons();
    void startRead(bool takePending);
    void onReadDone(int id);
    void writeParameters(bool rom);
    bool confirmRomWrite(int id);
    void sendWrite(const protocol::BuildResult &built, bool rom);
    void checkReadBack();
    void refreshWarnings();
    void refreshEnabled();
    void setStatus(const QString &text, bool error = false);
    void failed(const bus::RequestResult &result);

    ParameterTable *m_table = nullptr;
    LoopPlot *m_plot = nullptr;
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

    QHash<int, DriveMemory> m_memory; ///< per drive ID, for this session
    std::optional<protocol::PidGains> m_holdsPid;
    std::optional<qint32> m_holdsAccel;
    std::optional<Expected> m_expected; ///< what the last write asked for, until read back
    int m_readsOutstanding = 0;
    bool m_takePending = false;
    bool m_writeFailed = false;
    bool m_romWarningActive = false;
};

} // namespace lk::ui
