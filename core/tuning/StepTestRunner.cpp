#include "StepTestRunner.h"

#include "StepMetrics.h"

#include <bus/BusSession.h>
#include <bus/ConnectionStatus.h>
#include <protocol/Command.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QMap>

#include <cmath>
#include <limits>

namespace lk::tuning {

using bus::RequestStatus;
using bus::TelemetryField;
using bus::TelemetrySample;
using protocol::Command;

namespace {

// The effort a sample carries (A, or power on MS), or missing.
double effortOf(const TelemetrySample &s)
{
    if (s.has(TelemetryField::IqA))
        return s.iqA;
    if (s.has(TelemetryField::Power))
        return s.power;
    return StepTrace::missing();
}

} // namespace

StepTestRunner::StepTestRunner(bus::BusSession &session, QObject *parent)
    : QObject(parent), m_session(session)
{
    m_sendTimer.setSingleShot(true);
    m_sendTimer.setTimerType(Qt::PreciseTimer);
    m_graceTimer.setSingleShot(true);
    m_graceTimer.setInterval(kSampleGraceMs);
    connect(&m_sendTimer, &QTimer::timeout, this, &StepTestRunner::sendDue);
    connect(&m_graceTimer, &QTimer::timeout, this, &StepTestRunner::finishRun);
    connect(&m_session, &bus::BusSession::telemetryReceived, this, &StepTestRunner::onTelemetry);
    connect(&m_session, &bus::BusSession::connectionChanged, this, &StepTestRunner::onConnection);
}

StepTestRunner::~StepTestRunner()
{
    // Give the poll plan back; nobody is left to hear a signal.
    restorePolling();
}

bool StepTestRunner::start(const StepTestSpec &spec, const safety::SoftLimits &limits,
                           double gearRatio)
{
    if (isRunning())
        return false;
    m_spec = spec;
    m_limits = limits;
    m_gearRatio = gearRatio;
    m_plan = StepTestPlan{};
    m_result = StepTestResult{};
    m_result.spec = spec;
    ++m_run;
    m_samples.clear();
    m_next = m_replySamples = m_completions = 0;
    m_focused = false;
    m_previousPlan.reset();
    m_phase = Phase::Reading;
    const QString bad = StepTestPlan::checkSpec(spec);
    if (!bad.isEmpty()) {
        QTimer::singleShot(0, this, [this, bad] {
            end(StepTestFailure::BadSpec, bad + QStringLiteral("; nothing was sent"));
        });
        return true;
    }
    // Targets start where the drive is: a position test reads the angle, a speed test the
    // speed (and either finds out whether the drive answers before anything moves).
    const Command read =
        spec.loop == StepLoop::Position ? Command::ReadMultiTurn : Command::ReadState2;
    const protocol::BuildResult built = protocol::build::plain(read, spec.id);
    if (!built.ok()) {
        const QString why = built.error.message();
        QTimer::singleShot(0, this, [this, why] {
            end(StepTestFailure::BadSpec, why + QStringLiteral("; nothing was sent"));
        });
        return true;
    }
    m_session.send(*built.request, this, [this, run = m_run](const bus::RequestResult &result) {
        if (run == m_run && m_phase == Phase::Reading)
            onRead(result);
    });
    return true;
}

void StepTestRunner::abort()
{
    if (!isRunning())
        return;
    end(StepTestFailure::Aborted,
        QStringLiteral("aborted: no further setpoint is sent; %1").arg(stillMoving()));
}

void StepTestRunner::onSetpointDone(quint64 run, int index, const bus::RequestResult &result)
{
    if (run != m_run || !isRunning())
        return;
    StepSent &sent = m_result.sent[index];
    ++m_completions;
    if (!result.ok()) {
        const StepTestFailure why = result.status == RequestStatus::Disconnected
                                        ? StepTestFailure::Disconnected
                                        : StepTestFailure::Silent;
        end(why, QStringLiteral("drive %1 did not answer %2 (%3, sent %4 time(s)): the test "
                                "stopped, no further setpoint is sent; %5")
                     .arg(m_spec.id)
                     .arg(protocol::CommandTable::name(result.request.command))
                     .arg(QLatin1String(bus::requestStatusName(result.status)))
                     .arg(result.attempts)
                     .arg(stillMoving()));
        return;
    }
    sent.acknowledged = true;
    if (m_phase == Phase::Draining)
        drainCheck();
}

void StepTestRunner::onRead(const bus::RequestResult &result)
{
    const Command read = result.request.command;
    std::optional<double> value;
    if (result.ok() && result.reply) {
        if (const auto *a = std::get_if<protocol::MultiTurnAngle>(&result.reply->payload))
            value = a->degrees();
        else if (const auto *s = std::get_if<protocol::State2>(&result.reply->payload))
            value = double(s->speedDps);
    }
    if (!value) {
        end(result.status == RequestStatus::Disconnected ? StepTestFailure::Disconnected
                                                         : StepTestFailure::Silent,
            QStringLiteral("drive %1 did not answer %2 (%3); nothing was sent")
                .arg(m_spec.id)
                .arg(protocol::CommandTable::name(read))
                .arg(result.reason.isEmpty() ? QLatin1String(bus::requestStatusName(result.status))
                                             : result.reason));
        return;
    }
    m_result.startValue = value;
    begin(m_spec.loop == StepLoop::Position ? value : std::nullopt);
}

void StepTestRunner::begin(std::optional<double> angleDeg)
{
    safety::DrivePosition position;
    position.angleDeg = angleDeg;
    position.gearRatio = m_gearRatio;
    m_plan = StepTestPlan::make(m_spec, m_session.series(m_spec.id), m_limits, position);
    if (!m_plan.allowed()) {
        m_result.refusal = m_plan.refusal();
        // The limit's refusal is typed (result.refusal): lkctl and the UI word it.
        if (!m_plan.verdict().allowed())
            end(StepTestFailure::Refused, QStringLiteral("refused for safety, nothing was sent"));
        else
            end(StepTestFailure::BadSpec,
                QStringLiteral("%1; nothing was sent").arg(m_plan.specError()));
        return;
    }
    m_result.bound = m_plan.bound();
    m_result.boundDps = m_plan.boundDps();
    focusPolling();
    m_phase = Phase::Running;
    emit started(m_plan);
    m_clock.start();
    sendDue();
}

void StepTestRunner::focusPolling()
{
    // The angle comes from 0x92; the current from 0x9C of the same round.
    const QVector<Command> reads =
        m_spec.loop == StepLoop::Position
            ? QVector<Command>{Command::ReadState2, Command::ReadMultiTurn}
            : QVector<Command>{Command::ReadState2};
    m_previousPlan = m_session.pollPlan();
    // Without a plan of its own the session polls the focus drive alone.
    const bus::PollPlan focus = m_previousPlan ? *m_previousPlan : bus::PollPlan{};
    m_session.startPolling(focus.focusedOn(m_spec.id, reads));
    m_focused = true;
}

void StepTestRunner::restorePolling()
{
    if (!m_focused)
        return;
    m_focused = false;
    if (m_previousPlan)
        m_session.startPolling(*m_previousPlan);
    else
        m_session.stopPolling();
}

void StepTestRunner::sendDue()
{
    if (m_phase != Phase::Running)
        return;
    const QVector<StepSetpoint> &setpoints = m_plan.setpoints();
    double elapsed = m_clock.nsecsElapsed() * 1e-9;
    while (m_next < setpoints.size() && setpoints.at(m_next).atS <= elapsed + 0.0005) {
        const StepSetpoint &s = setpoints.at(m_next++);
        // Absolute commands: the session's retries (BusConfig::retries) are the only repeats.
        const int index = int(m_result.sent.size());
        m_result.sent.append(StepSent{s});
        m_session.send(s.request, this,
                       [this, run = m_run, index](const bus::RequestResult &result) {
                           onSetpointDone(run, index, result);
                       });
    }
    const double nextAt = m_next < setpoints.size() ? setpoints.at(m_next).atS : m_plan.endS();
    elapsed = m_clock.nsecsElapsed() * 1e-9;
    if (m_next >= setpoints.size() && elapsed >= m_plan.endS()) {
        m_phase = Phase::Draining;
        drainCheck();
        return;
    }
    m_sendTimer.start(std::max(0, int(std::ceil((nextAt - elapsed) * 1e3))));
}

void StepTestRunner::drainCheck()
{
    if (m_completions < m_result.sent.size())
        return; // every request completes (the engine's timeouts), then the samples follow
    if (m_replySamples >= m_result.sent.size())
        finishRun();
    else if (!m_graceTimer.isActive())
        m_graceTimer.start();
}

void StepTestRunner::onTelemetry(const QVector<TelemetrySample> &batch)
{
    if (m_phase != Phase::Running && m_phase != Phase::Draining)
        return;
    const Command motion = StepTestPlan::commandOf(m_spec.loop);
    for (const TelemetrySample &s : batch) {
        if (s.id != m_spec.id)
            continue;
        // The replies to the setpoints come in the order they were sent: the k-th is the
        // k-th setpoint's, and its time is the edge's.
        if (s.source == motion && m_replySamples < m_result.sent.size())
            m_result.sent[m_replySamples++].time = s.time;
        m_samples.append(s);
    }
    if (m_phase == Phase::Draining)
        drainCheck();
}

void StepTestRunner::onConnection(const bus::ConnectionStatus &status)
{
    if (!isRunning() || status.isOpen())
        return;
    end(StepTestFailure::Disconnected,
        QStringLiteral("the bus went away (%1): the test stopped; %2")
            .arg(status.reason.isEmpty() ? QStringLiteral("closed") : status.reason,
                 stillMoving()));
}

void StepTestRunner::finishRun()
{
    if (m_phase != Phase::Draining)
        return;
    m_graceTimer.stop();
    end(StepTestFailure::None, stillMoving());
}

void StepTestRunner::buildTrace()
{
    StepTrace &trace = m_result.trace;
    trace = StepTrace{};
    trace.loop = m_spec.loop;
    if (m_result.sent.isEmpty() || std::isnan(m_result.sent.first().time))
        return;
    const double from = m_result.sent.first().time;
    // A single speed step's return is no edge: the trace ends where it was acknowledged.
    double until = std::numeric_limits<double>::infinity();
    for (const StepSent &s : m_result.sent) {
        if (s.setpoint.role == StepSetpoint::Role::Edge && !std::isnan(s.time))
            trace.edges.append(StepEdge{s.time, s.setpoint.previous, s.setpoint.target});
        if (s.setpoint.role == StepSetpoint::Role::Return && !std::isnan(s.time))
            until = s.time;
    }
    // A position sample's effort is the current of the 0x9C reply of the same poll round.
    QMap<quint64, double> roundEffort;
    for (const TelemetrySample &s : m_samples) {
        if (s.cycle != 0 && !StepTrace::isMissing(effortOf(s)))
            roundEffort.insert(s.cycle, effortOf(s));
        trace.effortIsPower = trace.effortIsPower || s.has(TelemetryField::Power);
    }
    const TelemetryField valueField =
        m_spec.loop == StepLoop::Speed ? TelemetryField::Speed : TelemetryField::MultiTurn;
    for (const TelemetrySample &s : m_samples) {
        if (s.time < from || s.time > until || !s.has(valueField))
            continue;
        if (m_spec.loop == StepLoop::Speed)
            trace.append(s.time, s.speedDps, effortOf(s));
        else
            trace.append(s.time, s.multiTurnDeg,
                         s.cycle != 0 ? roundEffort.value(s.cycle, StepTrace::missing())
                                      : StepTrace::missing());
    }
    m_result.sampleRateHz = StepMetrics::sampleRateHz(trace);
}

void StepTestRunner::end(StepTestFailure failure, const QString &message)
{
    const bool ran = m_phase == Phase::Running || m_phase == Phase::Draining;
    m_sendTimer.stop();
    m_graceTimer.stop();
    if (ran)
        buildTrace();
    restorePolling();
    m_phase = Phase::Idle;
    m_result.failure = failure;
    m_result.message = message;
    if (failure == StepTestFailure::None)
        emit finished(m_result);
    else
        emit failed(m_result);
}

QString StepTestRunner::stillMoving() const
{
    if (m_result.sent.isEmpty())
        return QStringLiteral("nothing was sent");
    const StepSent &last = m_result.sent.last();
    const double target = last.setpoint.target;
    QString what;
    if (m_spec.loop == StepLoop::Position)
        what = QStringLiteral("at or moving to %1 deg").arg(target);
    else if (target == 0)
        what = QStringLiteral("holding 0 dps (the motor stays on)");
    else
        what = QStringLiteral("turning at %1 dps").arg(target);
    QString text =
        QStringLiteral("drive %1 keeps its last command: it is %2").arg(m_spec.id).arg(what);
    if (!last.acknowledged)
        text += QStringLiteral(" (unanswered: it may have acted on it or still be on the "
                               "previous one)");
    if (m_spec.loop == StepLoop::Speed && target != 0)
        text += QStringLiteral("; stop it with motor stop or off");
    return text;
}

} // namespace lk::tuning
