#include "FrequencySweepRunner.h"

#include "TuningEnd.h"

#include <bus/BusSession.h>
#include <bus/ConnectionStatus.h>
#include <bus/SetpointStream.h>
#include <protocol/Command.h>
#include <protocol/RequestBuilder.h>

#include <algorithm>
#include <cmath>

namespace lk::tuning {

using bus::RequestStatus;
using protocol::Command;

namespace {
QString stopReasonText(bus::SetpointStopReason reason)
{
    using R = bus::SetpointStopReason;
    switch (reason) {
    case R::Refused:
        return QStringLiteral("a setpoint was refused by a limit");
    case R::EmergencyStop:
        return QStringLiteral("an emergency stop");
    case R::Cancelled:
        return QStringLiteral("the bus cancelled a setpoint");
    case R::Disconnected:
        return QStringLiteral("the link went away");
    case R::Closed:
        return QStringLiteral("the session closed");
    case R::BusChanged:
        return QStringLiteral("the port was reopened");
    case R::SpeedLimit:
        return QStringLiteral("the speed watch stopped the drive");
    case R::Requested:
    case R::Replaced:
        break;
    }
    return QStringLiteral("another stream replaced it");
}
} // namespace

FrequencySweepRunner::FrequencySweepRunner(bus::BusSession &session, QObject *parent)
    : QObject(parent), m_session(session), m_keeper(session)
{
    m_endTimer.setSingleShot(true);
    connect(&m_endTimer, &QTimer::timeout, this, &FrequencySweepRunner::sweepDone);
    connect(&m_session, &bus::BusSession::requestCompleted, this,
            &FrequencySweepRunner::onCompleted);
    connect(&m_session, &bus::BusSession::telemetryReceived, this,
            &FrequencySweepRunner::onTelemetry);
    connect(&m_session, &bus::BusSession::setpointStreamStopped, this,
            &FrequencySweepRunner::onStreamStopped);
    connect(&m_session, &bus::BusSession::connectionChanged, this,
            &FrequencySweepRunner::onConnection);
}

FrequencySweepRunner::~FrequencySweepRunner()
{
    if (m_phase == Phase::Sweeping || m_phase == Phase::Returning || m_phase == Phase::Aborting) {
        // Nobody is left to hear the outcome: stop everything that moves, and put the gains
        // read back (the writes go out; their ends are not waited for).
        m_session.stopSetpointStream();
        m_session.emergencyStop({m_spec.id});
        m_keeper.restore([](bool, const QString &) {});
    }
    restorePolling();
}

bool FrequencySweepRunner::start(const FrequencySweepSpec &spec, const safety::SoftLimits &limits)
{
    if (isRunning())
        return false;
    m_spec = spec;
    m_limits = limits;
    m_plan = FrequencySweepPlan{};
    m_result = FrequencySweepResult{};
    m_result.spec = spec;
    ++m_run;
    m_stream = 0;
    m_sentValues.clear();
    m_latencies.clear();
    m_replyTimes.clear();
    m_replySpeeds.clear();
    m_previousPlan.reset();
    m_pollingPaused = false;
    m_phase = Phase::ReadingGains;
    TuningEnd::readFirst(m_keeper, spec.id, FrequencySweepPlan::checkSpec(spec), this,
                         [this, run = m_run](StepTestFailure failure, const QString &why) {
                             if (run != m_run || m_phase != Phase::ReadingGains)
                                 return;
                             if (failure == StepTestFailure::None)
                                 onGainsRead();
                             else
                                 end(failure,
                                     failure == StepTestFailure::BadSpec ? SearchEnd::BadSpec
                                                                         : SearchEnd::FailedToRead,
                                     DriveLeft::Untouched, true, why);
                         });
    return true;
}

void FrequencySweepRunner::abort()
{
    switch (m_phase) {
    case Phase::Idle:
    case Phase::Aborting:
        return;
    case Phase::ReadingGains:
    case Phase::ReadingSpeed:
        // The acceleration limit may have been lifted already: endBeforeMotion puts it back.
        endBeforeMotion(StepTestFailure::Aborted, SearchEnd::AbortedByUser,
                        QStringLiteral("aborted before anything moved"));
        return;
    case Phase::Sweeping:
    case Phase::Returning:
        haltAndRestore(StepTestFailure::Aborted, SearchEnd::AbortedByUser,
                       QStringLiteral("aborted"));
        return;
    }
}

void FrequencySweepRunner::onGainsRead()
{
    m_result.gains = m_keeper.gains();
    m_phase = Phase::ReadingSpeed;
    // The acceleration limit ramps each setpoint change and would bend the sine: lifted in
    // RAM for the sweep, put back with the gains.
    LoopGains unramped = *m_keeper.gains();
    unramped.accelerationDps2 = 0;
    if (unramped == *m_keeper.gains()) {
        readSpeed();
        return;
    }
    m_keeper.write(unramped, [this, run = m_run](bool written, const QString &failure) {
        if (run != m_run || m_phase != Phase::ReadingSpeed)
            return;
        if (written) {
            readSpeed();
            return;
        }
        endBeforeMotion(
            StepTestFailure::Silent, SearchEnd::DriveSilent,
            QStringLiteral("the acceleration limit could not be lifted (%1); nothing moved")
                .arg(failure));
    });
}

void FrequencySweepRunner::readSpeed()
{
    // A position sweep is centred on where the drive is: its multi-turn angle (0x92).
    const bool position = m_spec.loop == SweepLoop::Position;
    const protocol::BuildResult read =
        protocol::build::plain(position ? Command::ReadMultiTurn : Command::ReadState2, m_spec.id);
    m_session.send(*read.request, this, [this, run = m_run, position](const bus::RequestResult &r) {
        if (run != m_run || m_phase != Phase::ReadingSpeed)
            return;
        if (position)
            onAngleRead(r);
        else
            onSpeedRead(r);
    });
}

void FrequencySweepRunner::unanswered(const bus::RequestResult &result, const char *read)
{
    const bool lost = result.status == RequestStatus::Disconnected;
    endBeforeMotion(
        lost ? StepTestFailure::Disconnected : StepTestFailure::Silent,
        lost ? SearchEnd::LinkLost : SearchEnd::FailedToRead,
        QStringLiteral("drive %1 did not answer %2 (%3); nothing moved")
            .arg(m_spec.id)
            .arg(QLatin1String(read), QLatin1String(bus::requestStatusName(result.status))));
}

void FrequencySweepRunner::onAngleRead(const bus::RequestResult &result)
{
    const auto *angle = result.ok() && result.reply
                            ? std::get_if<protocol::MultiTurnAngle>(&result.reply->payload)
                            : nullptr;
    if (!angle) {
        unanswered(result, "read_multi_turn");
        return;
    }
    m_result.startAngle = angle->degrees();
    m_spec.operatingPoint = angle->degrees();
    m_result.spec = m_spec;
    startSweep();
}

void FrequencySweepRunner::onSpeedRead(const bus::RequestResult &result)
{
    const auto *state = result.ok() && result.reply
                            ? std::get_if<protocol::State2>(&result.reply->payload)
                            : nullptr;
    if (!state) {
        unanswered(result, "read_state2");
        return;
    }
    m_result.startSpeed = double(state->speedDps);
    startSweep();
}

void FrequencySweepRunner::startSweep()
{
    m_plan = FrequencySweepPlan::make(m_spec, m_session.series(m_spec.id), m_limits);
    if (!m_plan.allowed()) {
        m_result.refusal = m_plan.verdict();
        m_result.refusedDps = m_plan.refusedDps();
        if (m_plan.verdict().allowed())
            endBeforeMotion(StepTestFailure::BadSpec, SearchEnd::BadSpec,
                            m_plan.specError() + QStringLiteral("; nothing moved"));
        else
            endBeforeMotion(StepTestFailure::Refused, SearchEnd::Refused,
                            QStringLiteral("refused for safety, nothing moved"));
        return;
    }
    // Each setpoint's reply carries the speed: polling would only take bus time from them.
    m_previousPlan = m_session.pollPlan();
    if (m_previousPlan) {
        m_session.stopPolling();
        m_pollingPaused = true;
    }
    bus::SetpointStreamPlan stream;
    stream.id = m_spec.id;
    stream.settings = m_plan.settings();
    stream.series = m_session.series(m_spec.id);
    stream.limits = m_limits;
    stream.position.angleDeg = m_result.startAngle; // position setpoints are checked from it
    m_phase = Phase::Sweeping;
    m_stream = m_session.startSetpointStream(stream);
    emit started(m_plan);
    m_endTimer.start(int(std::ceil(m_plan.endS() * 1000)) + kTailMs);
}

void FrequencySweepRunner::onCompleted(const bus::RequestResult &result)
{
    if ((m_phase != Phase::Sweeping && m_phase != Phase::Returning) ||
        !bus::SetpointStream::isSetpointTicket(result.ticket) || result.request.id != m_spec.id)
        return;
    ++m_result.sent;
    if (!result.ok())
        return;
    if (const auto *speed = std::get_if<protocol::SpeedCommand>(&result.request.payload)) {
        m_sentValues.append(speed->speedDps());
        m_latencies.append(result.latencyMs * 1e-3);
    } else if (const auto *angle =
                   std::get_if<protocol::MultiPositionCommand>(&result.request.payload)) {
        m_sentValues.append(double(angle->angleRaw) * protocol::kCentiUnits);
        m_latencies.append(result.latencyMs * 1e-3);
    }
}

void FrequencySweepRunner::onTelemetry(const bus::TelemetryBatch &batch)
{
    if (m_phase != Phase::Sweeping && m_phase != Phase::Returning)
        return;
    for (const bus::TelemetrySample &s : batch) {
        const bool setpointReply = s.source == Command::Speed ||
                                   s.source == Command::MultiPosition ||
                                   s.source == Command::MultiPositionLimited;
        if (s.id != m_spec.id || !setpointReply || !s.has(bus::TelemetryField::Speed))
            continue;
        m_replyTimes.append(s.time);
        m_replySpeeds.append(s.speedDps);
    }
}

void FrequencySweepRunner::onStreamStopped(const bus::SetpointStop &stop)
{
    if (stop.stream != m_stream || m_phase != Phase::Sweeping)
        return;
    if (stop.reason == bus::SetpointStopReason::Requested)
        return;
    if (stop.reason == bus::SetpointStopReason::Refused) {
        m_result.refusal = stop.verdict;
        haltAndRestore(StepTestFailure::Refused, SearchEnd::Refused,
                       QStringLiteral("a setpoint was refused by a limit mid-sweep"));
        return;
    }
    const bool lost = stop.reason == bus::SetpointStopReason::Disconnected;
    haltAndRestore(lost ? StepTestFailure::Disconnected : StepTestFailure::Aborted,
                   lost ? SearchEnd::LinkLost
                   : stop.reason == bus::SetpointStopReason::EmergencyStop
                       ? SearchEnd::EmergencyStop
                       : SearchEnd::AbortedByUser,
                   QStringLiteral("the sweep stopped: %1").arg(stopReasonText(stop.reason)));
}

void FrequencySweepRunner::onConnection(const bus::ConnectionStatus &status)
{
    if (status.isOpen() || (m_phase != Phase::Sweeping && m_phase != Phase::Returning))
        return;
    haltAndRestore(StepTestFailure::Disconnected, SearchEnd::LinkLost,
                   QStringLiteral("the bus went away"));
}

void FrequencySweepRunner::sweepDone()
{
    if (m_phase != Phase::Sweeping)
        return;
    m_phase = Phase::Returning;
    m_session.stopSetpointStream();
    m_keeper.restore([this, run = m_run](bool ok, const QString &why) {
        if (run != m_run || m_phase != Phase::Returning)
            return;
        if (ok)
            returnToStart();
        else
            haltAndRestore(
                StepTestFailure::Silent, SearchEnd::FailedToRestore,
                QStringLiteral("the gains read could not be written back (%1)").arg(why));
    });
}

void FrequencySweepRunner::returnToStart()
{
    if (m_spec.loop == SweepLoop::Position) {
        // The stepped sine ends on its centre, the angle read at the start: the drive holds it.
        QTimer::singleShot(StepTestRunner::kSampleGraceMs, this, [this, run = m_run] {
            if (run != m_run || m_phase != Phase::Returning)
                return;
            restorePolling();
            m_result.outcome.angleDeg = m_result.startAngle.value_or(0);
            end(StepTestFailure::None, SearchEnd::Finished, DriveLeft::HoldsAngle, true,
                QStringLiteral("the gains and acceleration read are back in RAM; the drive holds "
                               "the angle it started at (%1 deg)")
                    .arg(m_result.startAngle.value_or(0), 0, 'f', 2));
        });
        return;
    }
    // Back to the speed the drive had before the sweep, through the same gate.
    TuningEnd::returnToSpeed(
        m_session, m_spec.id, returnSpeed(), m_limits, this,
        [this, run = m_run](bool ok, const QString &words) {
            if (run != m_run || m_phase != Phase::Returning)
                return;
            if (!ok) {
                haltAndRestore(StepTestFailure::Silent, SearchEnd::DriveSilent, words);
                return;
            }
            // The last replies' samples arrive in the next telemetry batch.
            QTimer::singleShot(StepTestRunner::kSampleGraceMs, this, [this, run, words] {
                if (run != m_run || m_phase != Phase::Returning)
                    return;
                restorePolling();
                const double speed = returnSpeed();
                m_result.outcome.speedDps = speed;
                end(StepTestFailure::None, SearchEnd::Finished,
                    speed == 0 ? DriveLeft::HoldsZero : DriveLeft::BackAtSpeed, true,
                    QStringLiteral("the gains and acceleration read are back in RAM; %1")
                        .arg(words));
            });
        });
}

double FrequencySweepRunner::returnSpeed() const
{
    return m_spec.returnSpeedDps.value_or(m_result.startSpeed.value_or(0));
}

void FrequencySweepRunner::analyse()
{
    // The k-th acknowledged setpoint's reply is the k-th reply sample: the drive got the
    // value and reported its speed at that moment. Both are placed at the request's write
    // (the reply's time less its latency): the reply's way back and the host's handling of it
    // jitter by milliseconds on a loaded machine, the write does not wait on them.
    const int n = int(std::min(m_sentValues.size(), m_replyTimes.size()));
    m_result.time.clear();
    for (int k = 0; k < n; ++k)
        m_result.time.append(m_replyTimes[k] - m_latencies[k]);
    m_result.setpoint = m_sentValues.mid(0, n);
    m_result.speed = m_replySpeeds.mid(0, n);
    FrequencyResponse &r = m_result.response;
    r = FrequencyResponse{};
    if (n < 2)
        return;
    const double span = m_result.time.last() - m_result.time.first();
    r.sampleRateHz = span > 0 ? (n - 1) / span : 0;
    r.samplesPerPeriod = m_spec.samplesPerPeriod();
    // The stream's time 0 is its first setpoint, which the first reply answers.
    const double origin = m_result.time.first();
    for (const SweepSegment &s : m_plan.segments()) {
        if (s.hz > r.resolvedHz()) {
            r.dropped.append({s.hz, DroppedReason::AboveResolution});
            continue;
        }
        // The rate within this frequency's own window counts too: a host or bus that stalled
        // during it leaves fewer samples a period than the loop needs (a loaded host's
        // position loop read 9 dB high at 40 Hz with 6.5 samples a period in its window while
        // the whole sweep averaged more than 16).
        DroppedReason why = DroppedReason::TooFewSamples;
        std::optional<FrequencyPoint> p = FrequencyResponse::measure(
            m_result.time, m_result.setpoint, m_result.time, m_result.speed, s.hz,
            origin + s.fitFromS, origin + s.fitToS, &why, r.samplesPerPeriod);
        if (p && m_spec.loop == SweepLoop::Position)
            *p = FrequencyResponse::integrated(*p); // the angle is the speed over jw
        if (p)
            r.points.append(*p);
        else
            r.dropped.append({s.hz, why});
    }
    r.unwrapPhases();
}

void FrequencySweepRunner::haltAndRestore(StepTestFailure failure, SearchEnd why,
                                          const QString &message)
{
    m_phase = Phase::Aborting;
    m_endTimer.stop();
    TuningEnd::halt(m_session, m_keeper, m_spec.id, this,
                    [this, failure, why, message, run = m_run](const HaltOutcome &h) {
                        if (run != m_run)
                            return;
                        restorePolling();
                        end(failure, why,
                            h.offAcknowledged ? DriveLeft::Off : DriveLeft::MayBeMoving,
                            h.gainsRestored, QStringLiteral("%1: %2").arg(message, h.words()));
                    });
}

void FrequencySweepRunner::endBeforeMotion(StepTestFailure failure, SearchEnd why,
                                           const QString &message)
{
    // Only reads went out unless the acceleration limit was lifted (onGainsRead writes it
    // when it is not 0; that write may still be on its way: the restore queues behind it).
    if (!m_keeper.gains() || m_keeper.gains()->accelerationDps2 == 0) {
        end(failure, why, DriveLeft::Untouched, true,
            QStringLiteral("%1; nothing was sent").arg(message));
        return;
    }
    m_phase = Phase::Aborting;
    m_keeper.restore([this, failure, why, message, run = m_run](bool ok, const QString &) {
        if (run == m_run)
            end(failure, why, DriveLeft::NoStepSent, ok,
                QStringLiteral("%1; %2").arg(
                    message, ok ? QStringLiteral("the settings read are back in RAM")
                                : QStringLiteral("the settings read could not be written back")));
    });
}

void FrequencySweepRunner::restorePolling()
{
    if (!m_pollingPaused)
        return;
    m_pollingPaused = false;
    if (m_previousPlan)
        m_session.startPolling(*m_previousPlan);
}

void FrequencySweepRunner::end(StepTestFailure failure, SearchEnd why, DriveLeft drive,
                               bool restored, const QString &message)
{
    m_result.outcome.end = why;
    m_result.outcome.drive = drive;
    m_result.outcome.gainsRestored = restored;
    m_endTimer.stop();
    analyse();
    m_phase = Phase::Idle;
    m_result.failure = failure;
    m_result.message = message;
    if (failure == StepTestFailure::None)
        emit finished(m_result);
    else
        emit failed(m_result);
}

} // namespace lk::tuning
