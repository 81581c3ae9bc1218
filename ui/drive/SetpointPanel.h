#pragma once

#include <bus/SetpointWaveform.h>
#include <protocol/Series.h>

#include <QtWidgets/QGroupBox>

#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace lk::ui {

class SetpointGenerator;

/// The setpoint generator's settings and Start/Stop. Torque is offered only where the
/// series has a torque loop. Start emits startRequested; the control view runs the generator.
class SetpointPanel : public QGroupBox {
    Q_OBJECT
public:
    explicit SetpointPanel(QWidget *parent = nullptr);

    void setSeries(std::optional<protocol::Series> series);
    bus::SetpointWaveform::Settings settings() const;
    void setSettings(const bus::SetpointWaveform::Settings &settings);
    /// Shows running/stopped and the last message.
    void setRunning(bool running, const QString &message = {});
    /// Shows whether `generator` runs, and why it stopped, from now on.
    void follow(SetpointGenerator *generator);
    void setStartEnabled(bool enabled);
    /// The drive's multi-turn angle (nullopt: another drive, not read yet). A position
    /// waveform is centred on it: the offset follows it until the user edits the offset.
    void setDriveAngle(std::optional<double> deg);

signals:
    void startRequested(const lk::bus::SetpointWaveform::Settings &settings);
    void stopRequested();

private:
    void refreshUnits();
    void fillOffsetFromDrive();

    QComboBox *m_waveform;
    QComboBox *m_target;
    QDoubleSpinBox *m_amplitude;
    QDoubleSpinBox *m_offset;
    QDoubleSpinBox *m_period;
    QDoubleSpinBox *m_rate;
    QPushButton *m_start;
    QPushButton *m_stop;
    QLabel *m_state;
    std::optional<double> m_driveAngle;
    bool m_offsetEdited = false; ///< the user typed an offset for this drive
};

} // namespace lk::ui
