#include "GainSearchRunner.h"

#include "StepRun.h"
#include "TuningEnd.h"

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QTimer>

#include <algorithm>
#include <cmath>

namespace lk::tuning {

FrequencySweepSpec GainSearchSpec::bode() const
{
    FrequencySweepSpec s;
    s.id = id;
    s.operatingPoint = (from + to) / 2;
    s.amplitude = std::abs(to - from) / 4;
    s.fromHz = 5;
    // Up to 100 Hz: a quarter of the sample rate a loaded host still reaches at 1 Mbaud.
    s.toHz = 100;
    s.points = 9;
    s.leadInS = 0.3;
    s.minPointS = 0.25;
    return s;
}

GainSearchSpec GainSearchSpec::forPosition(int id)
{
    GainSearchSpec s;
    s.id = id;
    s.loop = StepLoop::Position;
    s.from = 0;
    s.to = kPositionStepDeg;
    return s;
}

QString GainSearchSpec::check(const safety::SoftLimits &limits) const
{
    if (!(maxOvershootPct >= 0 && maxOvershootPct <= 100))
        return QStringLiteral("the overshoot bound must be 0..100 %, got %1").arg(maxOvershootPct);
    if (maxCandidates < 1 || maxCandidates > 50)
        return QStringLiteral("the candidates must be 1..50, got %1").arg(maxCandidates);
    if (loop == StepLoop::Position) {
        // Position targets are checked against the window; without one a step could go
        // anywhere the motor's multi-turn range allows.
        if (!limits.minAngleDeg || !limits.maxAngleDeg)
            return QStringLiteral("the position loop's search needs an angle window (min and "
                                  "max angle in the soft limits)");
        if (measureBode)
            return QStringLiteral("the Bode step measures the speed loop; a position search "
                                  "has none");
        if (periods < 2)
            return QStringLiteral("a position search steps in a square (2 periods or more) "
                                  "so that it ends where it began");
    }
    return StepTestPlan::checkSpec(step());
}

std::optional<double> GainSearchSpec::bodeSeconds(std::optional<protocol::Series> series,
                                                  const safety::SoftLimits &limits) const
{
    const FrequencySweepPlan plan = FrequencySweepPlan::make(bode(), series, limits);
    if (!plan.allowed())
        return std::nullopt;
    // Two sweeps, each with its reads, writes and return (about half a second at 1 Mbaud).
    return 2 * (plan.endS() + 0.5);
}

GainSearchRunner::GainSearchRunner(bus::BusSession &session, QObject *parent)
    : QObject(parent), m_session(session), m_keeper(session), m_step(session),
      m_bode(session, m_keeper)
{
    connect(&m_step, &StepTestRunner::finished, this, &GainSearchRunner::onStepFinished);
    connect(&m_bode, &GainSearchBode::ended, this, &GainSearchRunner::onBodeEnded);
    connect(&m_bode, &GainSearchBode::sweepStarted, this, &GainSearchRunner::bodeSweepStarted);
    connect(&m_step, &StepTestRunner::failed, this, &GainSearchRunner::onStepFailed);
    // An emergency stop from anywhere (Esc, another view, another command) ends the search.
    // Between two steps no stream runs for it to stop: without this, the next candidate's
    // step would start after the Motor Off. (The runner's own halt comes while Aborting.)
    const auto onEmergencyStop = [this] {
        if (m_phase == Phase::Searching) {
            haltAndRestore(StepTestFailure::Aborted, SearchEnd::EmergencyStop,
                           QStringLiteral("an emergency stop"));
        } else if (m_phase == Phase::Measuring) {
            m_emergencyStop = true;
            m_bode.abort(); // its sweep may be between two: nothing else would stop it
        }
    };
    connect(&m_session, &bus::BusSession::emergencyStopProgress, this, onEmergencyStop);
    connect(&m_session, &bus::BusSession::emergencyStopFinished, this, onEmergencyStop);
}

GainSearchRunner::~GainSearchRunner()
{
    // Measuring: m_bode's destructor halts its sweep and then puts the gains read back.
    if (m_phase == Phase::Searching || m_phase == Phase::Restoring || m_phase == Phase::Aborting) {
        // Nobody is left to hear the outcome: motor off, and the gains read go back (the
        // writes go out; their ends are not waited for).
        m_step.abort();
        m_session.emergencyStop({m_spec.id});
        m_keeper.restore([](bool, const QString &) {});
    }
}

bool GainSearchRunner::start(const GainSearchSpec &spec, const safety::SoftLimits &limits)
{
    if (isRunning())
        return false;
    m_spec = spec;
    m_limits = limits;
    m_result = GainSearchResult{};
    m_result.spec = spec;
    m_strategy.reset();
    m_startSpeed.reset();
    m_startAngle = 0;
    m_measured = false;
    m_emergencyStop = false;
    m_userAbort = false;
    m_returned = DriveLeft::Untouched;
    ++m_run;
    m_clock.start();
    m_phase = Phase::Reading;
    const QString bad = spec.check(limits);
    TuningEnd::readFirst(m_keeper, spec.id, bad, this,
                         [this, run = m_run](StepTestFailure failure, const QString &why) {
                             if (run != m_run || m_phase != Phase::Reading)
                                 return;
                             if (failure == StepTestFailure::None)
                                 onRead();
                             else
                                 end(failure,
                                     failure == StepTestFailure::BadSpec ? SearchEnd::BadSpec
                                                                         : SearchEnd::FailedToRead,
                                     DriveLeft::Untouched, true, why);
                         });
    return true;
}

void GainSearchRunner::abort()
{
    switch (m_phase) {
    case Phase::Idle:
    case Phase::Aborting:
        return;
    case Phase::Reading:
        end(StepTestFailure::Aborted, SearchEnd::AbortedByUser, DriveLeft::Untouched, true,
            QStringLiteral("aborted before anything moved; nothing was sent"));
        return;
    case Phase::Searching:
    case Phase::Restoring:
        haltAndRestore(StepTestFailure::Aborted, SearchEnd::AbortedByUser,
                       QStringLiteral("aborted"));
        return;
    case Phase::Measuring:
        // Its sweep's own Motor Off is an emergency stop too: this one was the user's.
        m_userAbort = true;
        m_bode.abort(); // ends with onBodeEnded(Aborted): Motor Off, the gains read back
        return;
    }
}

void GainSearchRunner::onRead()
{
    m_result.read = m_keeper.gains();
    if (m_spec.loop != StepLoop::Position) {
        startStrategy();
        return;
    }
    // Position steps go from the angle the drive is at (its multi-turn angle, 0x92).
    const protocol::BuildResult read =
        protocol::build::plain(protocol::Command::ReadMultiTurn, m_spec.id);
    if (!read.ok()) {
        end(StepTestFailure::BadSpec, SearchEnd::BadSpec, DriveLeft::NoStepSent, true,
            QStringLiteral("%1; nothing was sent").arg(read.error.message()));
        return;
    }
    m_session.send(*read.request, this, [this, run = m_run](const bus::RequestResult &r) {
        if (run == m_run && m_phase == Phase::Reading)
            onAngleRead(r);
    });
}

void GainSearchRunner::onAngleRead(const bus::RequestResult &result)
{
    const auto *angle = result.ok() && result.reply
                            ? std::get_if<protocol::MultiTurnAngle>(&result.reply->payload)
                            : nullptr;
    if (!angle) {
        // Only reads went out: nothing to put back, nothing moved.
        const bool lost = result.status == bus::RequestStatus::Disconnected;
        end(lost ? StepTestFailure::Disconnected : StepTestFailure::Silent, SearchEnd::FailedToRead,
            DriveLeft::Untouched, true,
            QStringLiteral("drive %1 did not answer read_multi_turn_angle; nothing was sent")
                .arg(m_spec.id));
        return;
    }
    m_startAngle = angle->degrees();
    m_result.startAngle = m_startAngle;
    // Toward the side of the window with room for the step; the plan checks every target.
    const double reach = std::max(std::abs(m_spec.from), std::abs(m_spec.to));
    if (m_limits.maxAngleDeg && m_startAngle + reach > *m_limits.maxAngleDeg &&
        (!m_limits.minAngleDeg || m_startAngle - reach >= *m_limits.minAngleDeg)) {
        m_spec.from = -m_spec.from;
        m_spec.to = -m_spec.to;
        m_result.direction = -1;
    }
    startStrategy();
}

void GainSearchRunner::startStrategy()
{
    m_strategy.emplace(*m_keeper.gains(), m_spec.maxOvershootPct, m_spec.maxCandidates,
                       m_spec.loop);
    m_phase = Phase::Searching;
    tryNext();
}

void GainSearchRunner::tryNext()
{
    const std::optional<LoopGains> candidate = m_strategy->next();
    if (!candidate) {
        finishSearch();
        return;
    }
    // Steps are measured without the acceleration limit: it would ramp every one of them
    // whatever the gains. It goes back with the gains read.
    LoopGains unramped = *candidate;
    unramped.accelerationDps2 = 0;
    m_keeper.write(unramped, [this, run = m_run](bool ok, const QString &why) {
        if (run != m_run || m_phase != Phase::Searching)
            return;
        if (!ok) {
            haltAndRestore(
                StepTestFailure::Silent, SearchEnd::DriveSilent,
                QStringLiteral("a candidate's gains could not be written (%1)").arg(why));
            return;
        }
        m_step.start(m_spec.step(m_startAngle), m_limits);
    });
}

void GainSearchRunner::onStepFinished(const StepTestResult &result)
{
    if (m_phase != Phase::Searching)
        return;
    if (!m_startSpeed && m_spec.loop == StepLoop::Speed)
        m_startSpeed = result.startValue;
    const CandidateScore score = GainSearchStrategy::score(
        *m_strategy->next(), result.trace, seriesEffortLimit(m_session.series(m_spec.id)),
        m_spec.maxOvershootPct);
    m_strategy->record(score);
    emit candidateScored(score, int(m_strategy->scores().size()) - 1);
    tryNext();
}

void GainSearchRunner::onStepFailed(const StepTestResult &result)
{
    if (m_phase != Phase::Searching)
        return;
    if (result.failure == StepTestFailure::Refused && !result.anythingSent()) {
        // Nothing moved: only the settings written so far go back.
        m_result.refusal = result.refusal;
        m_phase = Phase::Restoring;
        m_keeper.restore([this, run = m_run](bool ok, const QString &) {
            if (run == m_run)
                end(StepTestFailure::Refused, SearchEnd::Refused, DriveLeft::NoStepSent, ok,
                    ok ? QStringLiteral("refused for safety, no step was sent; the gains read "
                                        "are back in RAM")
                       : QStringLiteral("refused for safety, no step was sent; the gains read "
                                        "could not be written back"));
        });
        return;
    }
    const bool lost = result.failure == StepTestFailure::Disconnected;
    haltAndRestore(lost ? StepTestFailure::Disconnected : StepTestFailure::Silent,
                   lost ? SearchEnd::LinkLost : SearchEnd::DriveSilent,
                   QStringLiteral("a step failed: %1").arg(result.message));
}

void GainSearchRunner::finishSearch()
{
    m_phase = Phase::Restoring;
    m_keeper.restore([this, run = m_run](bool ok, const QString &why) {
        if (run != m_run || m_phase != Phase::Restoring)
            return;
        if (!ok) {
            haltAndRestore(
                StepTestFailure::Silent, SearchEnd::FailedToRestore,
                QStringLiteral("the gains read could not be written back (%1)").arg(why));
            return;
        }
        if (m_spec.loop == StepLoop::Position) {
            // Every square ended at FROM, the angle read: the drive holds it, and a speed
            // command would take it out of the position loop.
            m_result.outcome.angleDeg = m_startAngle;
            end(StepTestFailure::None, finishedEnd(), DriveLeft::HoldsAngle, true,
                QStringLiteral("the gains and acceleration read are back in RAM; drive %1 "
                               "holds %2 deg, the angle it started at")
                    .arg(m_spec.id)
                    .arg(m_startAngle, 0, 'f', 2));
            return;
        }
        returnToStart();
    });
}

void GainSearchRunner::returnToStart()
{
    TuningEnd::returnToSpeed(
        m_session, m_spec.id, m_startSpeed.value_or(0), m_limits, this,
        [this, run = m_run](bool ok, const QString &words) {
            if (run != m_run || m_phase != Phase::Restoring)
                return;
            if (!ok) {
                haltAndRestore(StepTestFailure::Silent, SearchEnd::DriveSilent, words);
                return;
            }
            const double speed = m_startSpeed.value_or(0);
            m_returned = speed == 0 ? DriveLeft::HoldsZero : DriveLeft::BackAtSpeed;
            m_result.outcome.speedDps = speed;
            if (m_spec.measureBode && m_strategy->best() && !m_measured)
                measureBode(words);
            else
                end(StepTestFailure::None, finishedEnd(), m_returned, true,
                    QStringLiteral("the gains and acceleration read are back in RAM; %1")
                        .arg(words));
        });
}

void GainSearchRunner::measureBode(const QString &returned)
{
    m_phase = Phase::Measuring;
    const LoopGains &best = m_strategy->scores().at(*m_strategy->best()).gains;
    // Both sweeps end at the search's own start speed (the one the drive is back at now).
    FrequencySweepSpec bode = m_spec.bode();
    bode.returnSpeedDps = m_startSpeed.value_or(0);
    if (!m_bode.start(bode, best, m_limits))
        end(StepTestFailure::None, finishedEnd(), m_returned, true,
            QStringLiteral("the gains and acceleration read are back in "
                           "RAM; %1; the Bode step could not start")
                .arg(returned));
}

void GainSearchRunner::onBodeEnded(const GainSearchBodeResult &bode)
{
    if (m_phase != Phase::Measuring)
        return;
    m_result.bodeRead = bode.read;
    m_result.bodeBest = bode.best;
    if (bode.ok()) {
        // Each sweep went back to the speed it read, which a rotor still settling from the
        // search may have left a few dps off: back to the search's own start speed.
        m_measured = true;
        m_phase = Phase::Restoring;
        returnToStart();
    } else {
        bodeFailed(bode);
    }
}

void GainSearchRunner::bodeFailed(const GainSearchBodeResult &bode)
{
    using F = StepTestFailure;
    const SearchEnd why = bode.failure == F::Aborted
                              ? (m_emergencyStop && !m_userAbort ? SearchEnd::EmergencyStop
                                                                 : SearchEnd::AbortedByUser)
                          : bode.failure == F::Refused      ? SearchEnd::Refused
                          : bode.failure == F::BadSpec      ? SearchEnd::BadSpec
                          : bode.failure == F::Disconnected ? SearchEnd::LinkLost
                                                            : SearchEnd::DriveSilent;
    // Halted: Motor Off as acknowledged; refused before it moved: where the search left it.
    const DriveLeft drive = !bode.halt                   ? m_returned
                            : bode.halt->offAcknowledged ? DriveLeft::Off
                                                         : DriveLeft::MayBeMoving;
    end(bode.failure, why, drive, bode.restored,
        QStringLiteral("the Bode step: %1").arg(bode.message));
}

void GainSearchRunner::haltAndRestore(StepTestFailure failure, SearchEnd why,
                                      const QString &message)
{
    m_phase = Phase::Aborting;
    m_step.abort();
    TuningEnd::halt(m_session, m_keeper, m_spec.id, this,
                    [this, failure, why, message, run = m_run](const HaltOutcome &h) {
                        if (run == m_run)
                            end(failure, why,
                                h.offAcknowledged ? DriveLeft::Off : DriveLeft::MayBeMoving,
                                h.gainsRestored, QStringLiteral("%1: %2").arg(message, h.words()));
                    });
}

SearchEnd GainSearchRunner::finishedEnd() const
{
    return m_strategy && m_strategy->stoppedByInstability() ? SearchEnd::Unstable
                                                            : SearchEnd::Finished;
}

void GainSearchRunner::end(StepTestFailure failure, SearchEnd why, DriveLeft drive, bool restored,
                           const QString &message)
{
    m_result.outcome.end = why;
    m_result.outcome.drive = drive;
    m_result.outcome.gainsRestored = restored;
    end(failure, message);
}

void GainSearchRunner::end(StepTestFailure failure, const QString &message)
{
    m_phase = Phase::Idle;
    if (m_strategy) {
        m_result.candidates = m_strategy->scores();
        m_result.best = m_strategy->best();
        m_result.stoppedByInstability = m_strategy->stoppedByInstability();
        if (!m_result.candidates.isEmpty())
            m_result.baseline = 0;
    }
    m_result.seconds = m_clock.nsecsElapsed() * 1e-9;
    m_result.failure = failure;
    m_result.message = message;
    if (failure == StepTestFailure::None)
        emit finished(m_result);
    else
        emit failed(m_result);
}

} // namespace lk::tuning
