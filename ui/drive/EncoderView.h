#pragma once

#include "AngleCheck.h"
#include "DriveView.h"

#include <bus/PollExtrasLease.h>
#include <bus/RequestResult.h>
#include <bus/TelemetrySample.h>
#include <protocol/Values.h>

#include <memory>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;

namespace lk::ui {

class DriveSettingsStore;
class EncoderLiveBox;
class EncoderResolutions;
class EncoderZeroTools;
struct ConfirmRequest;

/// Encoder and zero tools of one drive: encoder, raw encoder, offset and angles read live
/// while the view is visible (extra commands of the session's poll plan, read back from its
/// telemetry); encoder offset write (0x91); the zero tools (EncoderZeroTools: clear motor
/// angle 0x95, zero to ROM 0x19, V2.35 clear turn count 0x93). The encoder
/// resolution is the one EncoderResolutions believes (name, series, data, user); the gear
/// ratio is inferred from the model name; both are editable and kept per drive.
class EncoderView : public DriveView {
    Q_OBJECT
public:
    static const QList<int> &resolutions(); ///< 12, 14, 15, 16, 18 bit

    explicit EncoderView(QWidget *parent = nullptr);
    ~EncoderView() override;

    /// Where resolution and gear ratio persist per drive (not owned; default: this process).
    void setSettingsStore(DriveSettingsStore *store);
    /// The resolutions shared with the dashboard (not owned); without, the view keeps its own
    /// over its session and settings store.
    void setEncoderResolutions(EncoderResolutions *resolutions);
    int encoderBits() const;
    void setEncoderBits(int bits); ///< one of resolutions(); persisted for the drive
    double gearRatio() const { return m_ratio; }
    void setGearRatio(double ratio); ///< >= 1; persisted for the drive
    /// Counts per turn on the wire for the chosen resolution (18-bit reports 16 bits).
    int countsPerTurn() const;
    /// The reads the view adds to the poll plan for its drive while it is shown.
    static const QVector<protocol::Command> &liveCommands();
    /// The handle of those reads in the session (0: none added now).
    quint64 pollExtrasHandle() const { return m_extras.handle(); }

    /// Asks, then writes `offset` (0..countsPerTurn()-1) with 0x91 and reads it back.
    void writeOffset(int offset);
    /// Asks, then clears the angle (0x95) and checks it with read_multi_turn before/after.
    void clearAngle();
    /// Asks, then writes the current position to ROM as zero (0x19, once, never retried).
    void writeZeroToRom();
    /// V2.35: asks, then clears the turn count (0x93) and reads the multi-turn angle back.
    void clearTurnCount();
    /// Why clear turn count is not offered for the drive (empty: it is).
    /// Empty when the drive's generation has `command`; else why it is absent.
    QString absenceOf(protocol::Command command) const;

    std::optional<protocol::EncoderReading> lastEncoder() const { return m_encoder; }
    std::optional<double> lastMultiTurnDeg() const { return m_multiTurnDeg; }
    std::optional<AngleCheck> lastAngleCheck() const;
    QString statusText() const;

signals:
    void angleCheckFinished(const lk::ui::AngleCheck &check);
    void offsetWriteFinished(bool ok);
    void zeroWriteFinished(bool ok);
    void turnCountCleared(bool ok);

protected:
    void contextChanged(Changes changes) override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    QWidget *buildSetupBox();
    QWidget *buildOffsetBox();
    void wireZeroTools();
    void loadDriveSettings();
    /// Adds the live reads to the poll plan while shown with a drive to talk to, else takes
    /// them out (from the session they went to).
    void syncPollExtras();
    void onTelemetry(const bus::TelemetryBatch &batch);
    quint64 readEncoder(bus::Priority priority);
    quint64 readMultiTurn(bus::Priority priority);
    void readBackOffset(int offset);
    void refreshReadouts();
    void refreshEnabled();
    void setStatus(const QString &text, bool error = false);
    bool confirm(const ConfirmRequest &request);

    std::unique_ptr<DriveSettingsStore> m_ownStore;
    DriveSettingsStore *m_store;
    std::unique_ptr<EncoderResolutions> m_ownResolutions;
    EncoderResolutions *m_resolutions;
    double m_ratio = 1.0;
    QString m_ratioSource;
    std::optional<protocol::EncoderReading> m_encoder;
    std::optional<double> m_multiTurnDeg;
    std::optional<double> m_singleTurnDeg;
    bus::PollExtrasLease m_extras; ///< the live reads, while shown for its drive
    bool m_shown = false;
    QMetaObject::Connection m_telemetry;
    bool m_busy = false; ///< an offset write is running (the zero tools keep their own)

    QLabel *m_title = nullptr;
    EncoderLiveBox *m_live = nullptr;
    QComboBox *m_bitsCombo = nullptr;
    QLabel *m_bitsNote = nullptr;
    QDoubleSpinBox *m_ratioSpin = nullptr;
    QLabel *m_ratioNote = nullptr;
    QSpinBox *m_offsetSpin = nullptr;
    QPushButton *m_useRaw = nullptr;
    QPushButton *m_writeOffset = nullptr;
    EncoderZeroTools *m_zero = nullptr;
    QLabel *m_offsetNote = nullptr; // what 0x91 does, or why this drive has none
    QLabel *m_status = nullptr;
    QPlainTextEdit *m_log = nullptr;
};

} // namespace lk::ui
