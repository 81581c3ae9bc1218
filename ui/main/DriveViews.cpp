#include "DriveViews.h"

#include "BusController.h"
#include "SettingsFile.h"
#include "SoftLimitsFeed.h"

#include <bus/BusSession.h>
#include <drive/ControlLimits.h>
#include <drive/ControlView.h>
#include <drive/DriveInfoView.h>
#include <drive/DriveSettingsStore.h>
#include <drive/EncoderResolutions.h>
#include <drive/EncoderView.h>
#include <drive/MultiTorquePanel.h>
#include <drive/TuningView.h>
#include <panels/BusModel.h>

#include <QtCore/QCoreApplication>

namespace lk::ui {

DriveViews::DriveViews(BusModel *model, BusController *controller, TelemetryStore *store,
                       SettingsFile &settingsFile, QWidget *parentWidget)
    : QObject(parentWidget), m_model(model), m_controller(controller),
      // The soft limits the views apply also bound the bus thread's speed watch.
      m_settings(std::make_unique<SoftLimitsFeed>(
          std::make_unique<IniDriveStore>(settingsFile.settings()), controller->session())),
      m_resolutions(new EncoderResolutions(this)), m_tuning(new TuningView(parentWidget)),
      m_control(new ControlView(parentWidget)), m_encoder(new EncoderView(parentWidget)),
      m_info(new DriveInfoView(parentWidget)), m_multiTorque(new MultiTorquePanel(m_control))
{
    m_tuning->setTelemetryStore(store);
    m_control->setTelemetryStore(store);
    m_control->setSettingsStore(m_settings.get());
    m_encoder->setSettingsStore(m_settings.get());
    m_info->setToolVersion(QCoreApplication::applicationVersion());
    bus::BusSession *session = m_controller->session();
    m_resolutions->setSettingsStore(m_settings.get());
    m_resolutions->setSession(session);
    m_encoder->setEncoderResolutions(m_resolutions);
    m_tuning->setSession(session);
    m_control->setSession(session);
    m_encoder->setSession(session);
    m_info->setSession(session);
    // Step tests obey the limits the Control view holds for the drive.
    m_tuning->setStepTestLimits([this](QString *why) { return m_control->limitsInForce(why); });
    connect(m_tuning, &TuningView::emergencyStopRequested, this,
            &DriveViews::emergencyStopRequested);
    // Every drive of the frame is bounded as the Control view bounds the drive it shows: its
    // limits in force there, the stored soft limits for the others.
    m_multiTorque->setLimitsLookup([this](int id, const bus::KnownMotor &motor, QString *why) {
        if (id == m_control->driveId())
            return m_control->limitsInForce(why);
        return ControlLimits::stored(*m_settings, id, motor,
                                     MultiTorquePanel::driveTitle(id, motor), why);
    });
    m_multiTorque->setSession(session);
    m_control->addSidePanel(m_multiTorque);

    connect(m_model, &BusModel::currentDriveChanged, this, &DriveViews::syncDrive);
    connect(m_model, &BusModel::drivesChanged, this, &DriveViews::syncDrive);
    connect(m_model, &BusModel::connectionChanged, this, &DriveViews::syncConnection);
    connect(m_model, &BusModel::selectionChanged, this,
            [this] { m_control->setSelectedDrives(m_model->selectedIds()); });
    syncConnection();
    syncDrive();
}

DriveViews::~DriveViews() = default;

void DriveViews::haltLocalMotion(const QString &reason)
{
    m_tuning->haltLocalMotion(reason);
    m_control->haltLocalMotion(reason);
    m_multiTorque->reset(reason);
}

void DriveViews::syncDrive()
{
    const int id = m_model->currentId();
    const bus::KnownMotors motors = m_controller->session()->knownMotors();
    if (id == 0 || !motors.contains(id)) {
        if (m_shownId != 0) {
            m_tuning->clearDrive();
            m_control->clearDrive();
            m_encoder->clearDrive();
            m_info->clearDrive();
        }
        m_shownId = 0;
        m_shownKey.clear();
        m_shownProtocol = {};
        return;
    }
    // A rescan that finds the same drive must not throw away pending edits or undo history;
    // another motor at the same ID is a new drive.
    const bus::KnownMotor &motor = motors.value(id);
    const QString key = DriveSettingsStore::driveKey(id, motor);
    const auto facts = std::make_tuple(motor.series, motor.generation, motor.generationKnown());
    if (key == m_shownKey && facts == m_shownProtocol)
        return;
    // Same key, other protocol facts: the same drive better known (setDrive with the same ID
    // is MotorInfo news, nothing pending is dropped).
    m_shownId = id;
    m_shownKey = key;
    m_shownProtocol = facts;
    m_tuning->setDrive(id, motor);
    m_control->setDrive(id, motor);
    m_encoder->setDrive(id, motor);
    m_info->setDrive(id, motor);
}

void DriveViews::syncConnection()
{
    // The one capability: a listen-only link is open but sends nothing, so every view's
    // reads on selection, buttons and generators go quiet here, not refused one by one.
    const bool canSend = m_model->canSend();
    const QString why = m_model->isListening() ? m_model->sendBlockedReason() : QString();
    m_tuning->setLink(m_model->link()); // first: a V2.36 CAN drive is never read with 0x40
    m_control->setLink(m_model->link());
    m_encoder->setLink(m_model->link());
    m_tuning->setConnected(canSend, why);
    m_control->setConnected(canSend, why);
    m_encoder->setConnected(canSend, why);
    m_info->setConnected(canSend, why);
    m_multiTorque->setLink(m_model->link());
    m_multiTorque->setConnected(canSend, why);
    if (!canSend)
        m_control->haltLocalMotion(m_model->isListening() ? why : tr("The bus is not connected."));
}

} // namespace lk::ui
