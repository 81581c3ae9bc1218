#pragma once

#include "DriveLimitSet.h"
#include "DriveView.h"

class QLabel;
class QPushButton;

namespace lk::ui {

class ParamExchange;
class ParameterTable;

/// The limits a V2.35 drive enforces itself (max torque current or power, max speed, max
/// angle, current and speed ramps; ParamIDs 0x99..0x9E): read with 0x40, written to RAM (0x42)
/// or, after a confirmation that says why, to ROM (0x44, each frame once), then read back.
/// Nothing is editable or writable until a complete read of the selected drive succeeded on
/// this connection; unknown values show as unknown. On a V2.3 drive it says that these
/// settings do not exist in that protocol generation and sends nothing. Separate from the
/// tool's soft limits, which only bound what this tool sends.
class DriveLimitsView : public DriveView {
    Q_OBJECT
public:
    explicit DriveLimitsView(QWidget *parent = nullptr);
    ~DriveLimitsView() override;

    /// Reads every limit from the drive (0x40 for 0x99..0x9E).
    void readFromDrive();
    /// Writes the changed limits to RAM (0x42; the max angle as a pair) and reads back.
    void writeToRam();
    /// Asks, then writes every limit to ROM (0x44, each once, never retried), and reads back.
    void writeToRom();

    ParameterTable *table() const { return m_table; }
    /// The selected drive speaks V2.35: it has these settings.
    bool isSupported() const;
    bool readComplete() const { return m_readComplete; }
    HeldValues driveValues() const;
    QString statusText() const;
    /// The read-back disagreed with what was written (empty when it agreed).
    QString mismatchText() const;
    bool isBusy() const;

signals:
    /// A read (or a write's read-back) of drive `id` completed.
    void parametersRead(int id);

protected:
    void contextChanged(Changes changes) override;

private:
    void onReadDone(int id);
    void write(bool rom);
    void refreshEnabled();
    void setStatus(const QString &text, bool error = false);

    DriveLimitSet m_currentLimits{false};
    DriveLimitSet m_powerLimits{true};
    const DriveLimitSet *m_spec = &m_currentLimits;
    ParamExchange *m_exchange = nullptr;
    ParameterTable *m_table = nullptr;
    QLabel *m_unsupported = nullptr;
    QLabel *m_mismatch = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_read = nullptr;
    QPushButton *m_writeRam = nullptr;
    QPushButton *m_writeRom = nullptr;
    QWidget *m_editor = nullptr;
    bool m_readComplete = false;
    bool m_shownSupported = false; ///< isSupported() when the table was last reset
    bool m_takePending = true;
    /// What the first complete read of this drive (on this connection) found: the table's
    /// "First read" column.
    std::optional<ParamValues> m_firstRead;
};

} // namespace lk::ui
