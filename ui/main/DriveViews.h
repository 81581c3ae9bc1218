#pragma once

#include <protocol/Series.h>

#include <QtCore/QObject>
#include <QtCore/QString>

#include <memory>
#include <optional>
#include <tuple>

namespace lk::ui {

class BusController;
class BusModel;
class ControlView;
class DriveInfoView;
class DriveSettingsStore;
class EncoderResolutions;
class EncoderView;
class MultiTorquePanel;
class SettingsFile;
class TelemetryStore;
class TuningView;

/// The views that change a drive (Tuning, Control, Encoder, Info), kept pointed at the
/// current session, the selected drive and the connection state, so that MainWindow only
/// places them.
class DriveViews : public QObject {
    Q_OBJECT
public:
    /// `settingsFile`: where per-drive soft limits, encoder resolution and gear ratio persist
    /// (the application's settings file, shared with AppSettings); it outlives the views.
    DriveViews(BusModel *model, BusController *controller, TelemetryStore *store,
               SettingsFile &settingsFile, QWidget *parentWidget);
    ~DriveViews() override;

    TuningView *tuning() const { return m_tuning; }
    ControlView *control() const { return m_control; }
    EncoderView *encoder() const { return m_encoder; }
    DriveInfoView *info() const { return m_info; }
    /// The multi-motor torque frame (0x280) of old CAN drives 1..4, in the Control view.
    MultiTorquePanel *multiTorque() const { return m_multiTorque; }
    /// Where per-drive soft limits, encoder resolutions and gear ratios are kept.
    DriveSettingsStore *settingsStore() const { return m_settings.get(); }
    /// The encoder resolutions the Encoder view uses; the dashboard shares them.
    EncoderResolutions *encoderResolutions() const { return m_resolutions; }

    /// Stop what the views send by themselves (jog, setpoint generator) at once, before the
    /// emergency stop reaches the bus: a generator tick must not restart a motor after it.
    /// The multi-motor torque panel unticks everything (it never sends on its own).
    void haltLocalMotion(const QString &reason);

signals:
    /// A view's own stop button (a running step test): the emergency stop's job.
    void emergencyStopRequested();

private:
    void syncDrive();
    void syncConnection();

    BusModel *m_model;
    BusController *m_controller;
    std::unique_ptr<DriveSettingsStore> m_settings;
    EncoderResolutions *m_resolutions;
    TuningView *m_tuning;
    ControlView *m_control;
    EncoderView *m_encoder;
    DriveInfoView *m_info;
    MultiTorquePanel *m_multiTorque;
    int m_shownId = 0;
    QString m_shownKey; ///< DriveSettingsStore::driveKey of the drive the views show
    /// What the views were last told of that drive's protocol: on CAN (no model, so the same
    /// key) the generation comes later, chosen or seen in a reply, and must still reach them.
    std::tuple<std::optional<protocol::Series>, protocol::Generation, bool> m_shownProtocol;
};

} // namespace lk::ui
