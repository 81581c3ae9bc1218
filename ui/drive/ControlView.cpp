#include "ControlView.h"

#include "BrakePanel.h"
#include "ControlCommandBox.h"
#include "ControlLimits.h"
#include "ControlModePanel.h"
#include "DriveStateCheck.h"
#include "DriveText.h"
#include "JogKeys.h"
#include "JogPanel.h"
#include "LoopPlot.h"
#include "RequestTracker.h"
#include "SetpointPanel.h"
#include "SoftLimitsEditor.h"

#include <bus/BusSession.h>
#include <bus/NewestSample.h>
#include <motor/ModelNameInfo.h>
#include <panels/StatusColors.h>
#include <protocol/RequestBuilder.h>

#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr int kRightColumnWidth = 380;
using protocol::Command;
namespace build = protocol::build;
} // namespace

ControlView::ControlView(QWidget *parent)
    : DriveView(parent), m_generator(new SetpointGenerator(this))
{
    const auto reader = [this](const protocol::Request &request, RequestTracker::Callback done) {
        return tracker()->send(request, std::move(done));
    };
    m_limitSet = new ControlLimits(reader, this);
    m_driveState = new DriveStateCheck(reader, this);
    setObjectName(QStringLiteral("control"));
    setFocusPolicy(Qt::StrongFocus);
    m_title = new QLabel(this);
    QFont big = m_title->font();
    big.setPointSizeF(big.pointSizeF() * 1.2);
    big.setBold(true);
    m_title->setFont(big);
    m_readout = new QLabel(this);
    m_readout->setObjectName(QStringLiteral("readout"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    m_jog = new JogPanel(this);
    m_limitsEditor = new SoftLimitsEditor(this);
    m_setpointPanel = new SetpointPanel(this);
    m_brake = new BrakePanel(this);
    m_brake->setSender(
        [this](const protocol::Request &request, RequestTracker::Callback done, int retries) {
            return tracker()->send(request, std::move(done), bus::Priority::Operator, retries);
        });

    auto *left = new QVBoxLayout;
    left->addWidget(m_title);
    m_commandBox = new ControlCommandBox(this);
    m_modes = m_commandBox->modePanel();
    left->addWidget(m_commandBox);
    left->addWidget(m_jog);
    left->addWidget(m_readout);
    left->addWidget(m_status);
    m_plot = new LoopPlot(this);
    left->addWidget(m_plot, 1);
    auto *right = m_side = new QVBoxLayout;
    right->addWidget(m_limitsEditor);
    right->addWidget(m_setpointPanel);
    right->addWidget(m_brake);
    right->addStretch();
    auto *rightWidget = new QWidget(this);
    rightWidget->setLayout(right);
    rightWidget->setFixedWidth(kRightColumnWidth);
    auto *layout = new QHBoxLayout(this);
    layout->addLayout(left, 1);
    layout->addWidget(rightWidget);

    wire();
    m_keys = new JogKeys(this, {[this] { return m_jog->keyboardJog() && canSendToDrive(); },
                                [this](int direction) {
                                    startJog(direction);
                                    return m_jogging;
                                },
                                [this] { endJog(); }, [this](int direction) { step(direction); }});
    contextChanged(Change::Session | Change::Drive);
}

ControlView::~ControlView()
{
    delete m_keys; // off the application's filters before this view's members go
}

void ControlView::wire()
{
    connect(m_commandBox, &ControlCommandBox::sendRequested, this, [this] { sendCommand(); });
    connect(m_commandBox, &ControlCommandBox::motorOffRequested, this, &ControlView::motorOff);
    connect(m_commandBox, &ControlCommandBox::motorStopRequested, this, &ControlView::motorStop);
    connect(m_commandBox, &ControlCommandBox::motorRunRequested, this, &ControlView::motorRun);
    connect(m_jog, &JogPanel::holdStarted, this, &ControlView::startJog);
    connect(m_jog, &JogPanel::holdEnded, this, &ControlView::endJog);
    connect(m_jog, &JogPanel::stepRequested, this, &ControlView::step);
    connect(m_limitsEditor, &SoftLimitsEditor::limitsApplied, this, &ControlView::setSoftLimits);
    connect(m_setpointPanel, &SetpointPanel::startRequested, this, &ControlView::startGenerator);
    connect(m_setpointPanel, &SetpointPanel::stopRequested, this, &ControlView::stopGenerator);
    // The plot follows what the command moves: angle for positions, iq for torque.
    connect(m_commandBox, &ControlCommandBox::loopChanged, m_plot, &LoopPlot::setLoop);
    m_setpointPanel->follow(m_generator);
    // The stream refused a setpoint on the bus thread: said here as any refused command.
    connect(m_generator, &SetpointGenerator::refused, this,
            [this](const MotionOutcome &out) { report(out, {}); });
    connect(m_generator, &SetpointGenerator::setpointFailed, this, &ControlView::onMotionResult);
    connect(m_driveState, &DriveStateCheck::changed, this, &ControlView::showDriveState);
    connect(m_brake, &BrakePanel::stateRead, m_driveState, &DriveStateCheck::noteBrake);
    connect(m_limitSet, &ControlLimits::driveLimitsChanged, this, [this] {
        showDriveState();
        keepGeneratorWithinLimits();
    });
}

void ControlView::setTelemetryStore(TelemetryStore *store)
{
    m_plot->setStore(store);
}

void ControlView::setSettingsStore(DriveSettingsStore *store)
{
    m_limitSet->setStore(store);
    loadLimits();
}

void ControlView::loadLimits()
{
    const QString broke = m_limitSet->load(driveId(), motor(), series(), driveTitle());
    if (!broke.isEmpty())
        setStatus(broke, true);
    m_limitsEditor->setLimits(m_limitSet->soft(), series());
    m_limitsEditor->setProblem(m_limitSet->problem());
}

safety::SoftLimits ControlView::softLimits() const
{
    return m_limitSet->soft();
}

std::optional<safety::SoftLimits> ControlView::limitsInForce(QString *why) const
{
    if (!m_limitSet->problem().isEmpty()) {
        if (why)
            *why = m_limitSet->problem();
        return std::nullopt;
    }
    return m_limitSet->inForce();
}

void ControlView::setSoftLimits(const safety::SoftLimits &limits)
{
    m_limitSet->apply(driveId(), motor(), limits);
    m_limitsEditor->setProblem(QString());
    if (!(m_limitsEditor->limits() == limits))
        m_limitsEditor->setLimits(limits, series());
    setStatus(tr("Soft limits of %1 applied and saved.").arg(driveTitle()));
    keepGeneratorWithinLimits();
}

void ControlView::keepGeneratorWithinLimits()
{
    // The bus thread checks each setpoint against the limits and series the generator started
    // with: once either changes, it must not go on under the old ones.
    if (!m_generator->isRunning())
        return;
    const bus::SetpointStreamPlan &plan = m_generator->plan();
    if (plan.limits == m_limitSet->inForce() && plan.series == series() &&
        m_limitSet->problem().isEmpty())
        return;
    m_generator->stop(tr("Stopped: the soft limits or the series changed."));
    if (m_motionId == driveId())
        sendRunState(Command::MotorStop);
}

void ControlView::setSelectedDrives(const QVector<int> &ids)
{
    m_selected = ids;
    refreshSelectionNote();
}

void ControlView::refreshSelectionNote()
{
    m_commandBox->setSelection(hasDrive() ? int(m_selected.size()) : 0, driveTitle());
}

safety::DrivePosition ControlView::drivePosition() const
{
    safety::DrivePosition p;
    p.angleDeg = m_angleDeg;
    if (motor().model)
        p.gearRatio = motor::ModelNameInfo::parse(motor().model->motorName).gearRatio;
    return p;
}

void ControlView::readAngle(std::function<void()> then)
{
    if (!canSendToDrive())
        return;
    const int id = driveId();
    const auto done = [this, id, then](const bus::RequestResult &r) {
        const auto *a =
            r.ok() && r.reply ? std::get_if<protocol::MultiTurnAngle>(&r.reply->payload) : nullptr;
        if (a)
            onAngle(id, a->degrees());
        if (!then)
            return;
        if (a && id == driveId()) {
            then();
            return;
        }
        // What waited for the angle is dropped, and says so.
        refuse(a ? tr("Refused: the drive changed while its angle was read. Nothing sent.")
                 : tr("Refused: could not read the drive's current angle, so nothing was sent. "
                      "%1")
                       .arg(DriveText::failure(r)));
    };
    tracker()->send(*build::plain(Command::ReadMultiTurn, id).request, done);
}

void ControlView::onAngle(int id, double deg)
{
    if (id != driveId())
        return;
    m_angleDeg = deg;
    m_setpointPanel->setDriveAngle(deg);
    // The multi-turn target starts where the drive is, never at 0 absolute.
    if (!m_modes->hasMultiTarget())
        m_modes->setMultiAngle(deg);
}

void ControlView::contextChanged(Changes changes)
{
    if (changes & Change::Session) {
        disconnect(m_telemetryConnection);
        disconnect(m_stopConnection);
        if (session()) {
            m_telemetryConnection = connect(session(), &bus::BusSession::telemetryReceived, this,
                                            [this](const bus::TelemetryBatch &batch) {
                                                m_plot->appendTelemetry(batch);
                                                onTelemetry(batch);
                                            });
            m_stopConnection =
                connect(session(), &bus::BusSession::emergencyStopFinished, this, [this] {
                    haltLocalMotion(DriveText::stopReason(bus::SetpointStopReason::EmergencyStop));
                });
        }
    }
    if (changes & (Change::Session | Change::Drive | Change::Connection)) {
        // Whatever drove the previous drive must not keep driving it.
        const bool moving = m_generator->isRunning() || m_jogging;
        const int previous = m_motionId;
        haltLocalMotion(tr("Stopped: the drive or the connection changed."));
        m_generator->setSession(session());
        // The drive is no longer selected: reach it directly, ahead of queued work.
        if (moving && !(changes & Change::Session) && isConnected() && previous > 0)
            session()->send(*build::plain(Command::MotorStop, previous).request,
                            bus::Priority::Emergency);
        m_readout->clear();
        // Nothing typed for one drive goes to another, and no angle is assumed.
        if (changes & (Change::Session | Change::Drive))
            m_modes->resetInputs();
        m_angleDeg.reset();
        if (changes & (Change::Session | Change::Drive))
            m_setpointPanel->setDriveAngle(std::nullopt);
        readAngle();
    }
    if (changes & (Change::Session | Change::Drive | Change::MotorInfo)) {
        m_modes->setSeries(series());
        m_modes->setGeneration(motor().generation);
        m_setpointPanel->setSeries(series());
        m_plot->setDrive(driveId(), series() == protocol::Series::MS);
        loadLimits();
        keepGeneratorWithinLimits();
    }
    if (changes & (Change::Session | Change::Drive | Change::MotorInfo | Change::Connection))
        readDriveState();
    m_title->setText(driveTitle());
    refreshSelectionNote();
    const QString offline = cannotSendText(tr("Disconnected: nothing can be sent."));
    if (!isConnected() && hasDrive())
        setStatus(offline);
    else if ((changes & Change::Drive) || statusText() == m_offlineShown)
        setStatus(QString()); // connected again (an automatic reconnect too): no longer true
    m_offlineShown = offline;
    refreshEnabled();
}

void ControlView::readDriveState()
{
    // A V2.35 drive tells whether it is on, its brake and its own limits: read them now.
    m_driveState->setDrive(driveId(), motor());
    m_commandBox->setGeneration(motor().generation);
    if (!canSendToDrive())
        return;
    m_driveState->refresh();
    m_limitSet->readDriveLimits(driveId(), motor(), series());
}

void ControlView::showDriveState()
{
    m_commandBox->showDriveState(*m_driveState, m_limitSet->driveText());
}

void ControlView::refreshEnabled()
{
    const bool can = canSendToDrive();
    m_commandBox->setSendEnabled(can);
    m_jog->setEnabled(can);
    m_setpointPanel->setStartEnabled(can);
    m_limitsEditor->setEnabled(hasDrive());
    m_modes->setEnabled(hasDrive());
    m_brake->setDrive(driveId(), motor(), can, link());
}

QString ControlView::statusText() const
{
    return m_status->text();
}

void ControlView::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(
        error ? StatusColors::textStyle(StatusColors::Role::Error, palette(), true) : QString());
}

void ControlView::report(const MotionOutcome &outcome, const QString &sentText)
{
    m_last = outcome;
    if (outcome.sent) {
        setStatus(sentText);
        return;
    }
    setStatus(outcome.refusal, true);
    emit commandRefused(outcome.refusal);
}

MotionOutcome ControlView::refuse(const QString &why, safety::LimitKind limit)
{
    MotionOutcome none;
    none.refusal = why;
    none.limit = limit;
    report(none, {});
    return none;
}

MotionOutcome ControlView::pendingOn(const QString &status)
{
    MotionOutcome pending;
    pending.pending = true;
    m_last = pending;
    setStatus(status);
    return pending;
}

MotionOutcome ControlView::sendMotion(const protocol::BuildResult &built)
{
    if (!canSendToDrive())
        return refuse(tr("Not connected or no drive selected: nothing sent."));
    // V2.35: a drive that is off does not act on a control command (docs/V2.35.md s. 11), and
    // it may have been switched off (or tripped) since it was last read: read it now.
    if (built.ok() && m_driveState->gates(*built.request)) {
        m_driveState->whenKnown(
            [this, built] {
                const QString off = m_driveState->refusal();
                if (off.isEmpty())
                    moveFromWhereTheDriveIs(built);
                else
                    refuse(off);
            },
            [this](const QString &why) { refuse(why); });
        return pendingOn(
            tr("Reading whether the motor of %1 is on before the command\u2026").arg(driveTitle()));
    }
    return moveFromWhereTheDriveIs(built);
}

MotionOutcome ControlView::moveFromWhereTheDriveIs(const protocol::BuildResult &built)
{
    // Targets start where the drive is: read its angle now rather than trust an old one.
    if (built.ok() && safety::MotionPlanner::needsAngle(*built.request, m_limitSet->inForce())) {
        readAngle([this, built] { submitMotion(built); });
        return pendingOn(tr("Reading the drive's current angle before the move\u2026"));
    }
    return submitMotion(built);
}

MotionOutcome ControlView::submitMotion(const protocol::BuildResult &built)
{
    if (!m_limitSet->problem().isEmpty())
        return refuse(m_limitSet->problem());
    const int id = driveId();
    MotionOutcome out = MotionGate::submit(
        *tracker(), built, series(), m_limitSet->soft(), drivePosition(),
        [this](const bus::RequestResult &r) { onMotionResult(r); }, m_limitSet->drive());
    QString sent;
    if (out.sent && out.bound.isEmpty())
        sent = tr("Sent %1 to drive %2.").arg(DriveText::command(out.request->command)).arg(id);
    else if (out.sent)
        sent = tr("Sent %1 to drive %2, %3.")
                   .arg(DriveText::command(out.request->command))
                   .arg(id)
                   .arg(out.bound);
    // The brake holds the shaft whatever is sent: said with the command, not only beside it.
    if (out.sent && m_driveState->gates(*out.request) && !m_driveState->warning().isEmpty())
        sent += QLatin1Char(' ') + m_driveState->warning();
    report(out, sent);
    return out;
}

void ControlView::onMotionResult(const bus::RequestResult &result)
{
    if (result.ok() && result.request.command == Command::MotorRun)
        m_driveState->refresh({}, true); // V2.35 Motor On: read what the drive says now
    if (result.ok())
        return;
    // The bus cancels queued motion on an emergency stop: nothing here may send more.
    if (result.status == bus::RequestStatus::Cancelled)
        haltLocalMotion(DriveText::stopReason(bus::SetpointStopReason::Cancelled));
    setStatus(DriveText::motionFailure(result), true);
}

MotionOutcome ControlView::sendCommand()
{
    if (m_modes->mode() == ControlMode::MultiPosition && !m_modes->hasMultiTarget()) {
        readAngle();
        return refuse(tr("Refused: the target starts at the drive's current angle, which is "
                         "being read. Nothing sent."),
                      safety::LimitKind::AngleUnknown);
    }
    return sendMotion(m_modes->buildRequest(driveId()));
}

void ControlView::sendRunState(Command command)
{
    if (!canSendToDrive())
        return;
    // Off and stop jump ahead of queued work; run resumes motion, so it passes the gate.
    if (command == Command::MotorRun) {
        sendMotion(build::plain(command, driveId()));
        return;
    }
    tracker()->send(
        *build::plain(command, driveId()).request,
        [this](const bus::RequestResult &r) {
            if (!r.ok())
                setStatus(DriveText::failure(r), true);
            else
                m_driveState->refresh({}, true); // V2.35: off now reads off
        },
        bus::Priority::Emergency);
    setStatus(tr("Sent %1 to drive %2.").arg(DriveText::command(command)).arg(driveId()));
}

void ControlView::motorOff()
{
    haltLocalMotion(tr("Stopped by Motor Off."));
    sendRunState(Command::MotorOff);
}

void ControlView::motorStop()
{
    haltLocalMotion(tr("Stopped by Stop."));
    sendRunState(Command::MotorStop);
}

void ControlView::motorRun()
{
    sendRunState(Command::MotorRun);
}

void ControlView::startJog(int direction)
{
    if (m_generator->isRunning())
        m_generator->stop(tr("Stopped: jog took over."));
    const MotionOutcome out = sendMotion(build::speed(driveId(), direction * m_jog->speedDps()));
    m_jogging = out.sent;
    if (out.sent) {
        m_motionId = driveId();
        setStatus(tr("Jogging at %1 dps: release to stop.").arg(direction * m_jog->speedDps()));
    }
}

void ControlView::endJog()
{
    if (!m_jogging)
        return;
    m_jogging = false;
    m_keys->jogEnded();
    if (m_motionId == driveId() && canSendToDrive()) {
        sendMotion(build::speed(driveId(), 0));
        setStatus(tr("Jog released: speed 0 sent."));
    }
}

void ControlView::step(int direction)
{
    const double delta = direction * m_jog->stepDeg();
    const double speed = m_jog->speedDps();
    const MotionOutcome out =
        sendMotion(speed > 0 ? build::incrementPosition(driveId(), delta, speed)
                             : build::incrementPosition(driveId(), delta));
    if (out.sent)
        setStatus(tr("Step of %1\u00b0 sent.").arg(delta));
}

void ControlView::startGenerator(const bus::SetpointWaveform::Settings &settings)
{
    if (!canSendToDrive())
        return;
    if (settings.target == bus::SetpointWaveform::Target::Position) {
        // Position setpoints are checked from where the drive is: read it first. A halt while
        // the angle is read (an emergency stop, Stop, Motor Off) cancels the start.
        const quint64 halts = m_halts;
        readAngle([this, settings, halts] {
            if (halts == m_halts)
                startGeneratorNow(settings);
        });
        return;
    }
    startGeneratorNow(settings);
}

void ControlView::startGeneratorNow(const bus::SetpointWaveform::Settings &settings)
{
    if (!canSendToDrive())
        return;
    endJog();
    // Damaged limits, or a V2.35 drive that reads off (it would not act on a setpoint).
    QString problem = m_limitSet->problem();
    if (problem.isEmpty())
        problem = m_driveState->refusal();
    if (!problem.isEmpty()) {
        refuse(problem);
        m_setpointPanel->setRunning(false, problem);
        return;
    }
    m_motionId = driveId();
    // The bus thread checks every setpoint as submitMotion() would: these limits, the
    // series, and position targets from the angle just read (not read again meanwhile).
    bus::SetpointStreamPlan plan;
    plan.id = driveId();
    plan.settings = settings;
    plan.series = series();
    plan.limits = m_limitSet->inForce();
    plan.position = drivePosition();
    m_generator->start(plan);
}

void ControlView::stopGenerator()
{
    if (!m_generator->isRunning())
        return;
    m_generator->stop(DriveText::stopReason(bus::SetpointStopReason::Requested));
    if (m_motionId == driveId())
        sendRunState(Command::MotorStop);
}

void ControlView::haltLocalMotion(const QString &reason)
{
    ++m_halts;
    m_generator->stop(reason);
    m_jogging = false;
    m_keys->jogEnded();
}

void ControlView::onTelemetry(const bus::TelemetryBatch &batch)
{
    m_driveState->noteTelemetry(batch);
    // Only the newest angle counts (targets start where the drive is now); setting the
    // targets' spin boxes once per sample of a batch cost the GUI thread for nothing.
    if (const bus::TelemetrySample *s =
            bus::newestSample(batch, driveId(), bus::TelemetryField::MultiTurn))
        onAngle(s->id, s->multiTurnDeg);
    const bus::TelemetrySample *s = bus::newestSample(batch, driveId(), bus::TelemetryField::Speed);
    if (!s)
        return;
    QString text = tr("Now: %1 dps").arg(s->speedDps, 0, 'f', 0);
    if (s->has(bus::TelemetryField::IqA))
        text += tr(", iq %1 A").arg(s->iqA, 0, 'f', 2);
    if (s->has(bus::TelemetryField::Power))
        text += tr(", power %1").arg(s->power);
    m_readout->setText(text);
}

} // namespace lk::ui
