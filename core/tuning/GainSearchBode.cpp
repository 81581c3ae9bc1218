#include "GainSearchBode.h"

#include "GainKeeper.h"

#include <bus/BusSession.h>

#include <QtCore/QTimer>

namespace lk::tuning {

GainSearchBode::GainSearchBode(bus::BusSession &session, GainKeeper &keeper, QObject *parent)
    : QObject(parent), m_session(session), m_keeper(keeper),
      m_sweep(std::make_unique<FrequencySweepRunner>(session))
{
    connect(m_sweep.get(), &FrequencySweepRunner::finished, this, &GainSearchBode::onSwept);
    connect(m_sweep.get(), &FrequencySweepRunner::failed, this, &GainSearchBode::onSweepFailed);
    connect(m_sweep.get(), &FrequencySweepRunner::started, this,
            [this](const FrequencySweepPlan &plan) {
                if (m_phase == Phase::SweepRead || m_phase == Phase::SweepBest)
                    emit sweepStarted(m_phase == Phase::SweepBest, plan.endS());
            });
}

GainSearchBode::~GainSearchBode()
{
    if (!isRunning())
        return;
    // In this order: the sweep's own restore (the best's gains, in the second) goes out first,
    // the gains read after it.
    m_sweep.reset();
    m_session.emergencyStop({m_spec.id});
    m_keeper.restore([](bool, const QString &) {});
}

bool GainSearchBode::start(const FrequencySweepSpec &spec, const LoopGains &best,
                           const safety::SoftLimits &limits)
{
    if (isRunning() || !m_keeper.gains())
        return false;
    m_spec = spec;
    m_spec.id = m_keeper.id();
    m_best = best;
    m_limits = limits;
    m_result = GainSearchBodeResult{};
    m_aborting = false;
    ++m_run;
    m_phase = Phase::SweepRead;
    // The sweep reads the gains in RAM itself: the gains read, put back by the search.
    if (!m_sweep->start(m_spec, m_limits)) {
        QTimer::singleShot(0, this, [this, run = m_run] {
            if (run == m_run)
                end(StepTestFailure::BadSpec, QStringLiteral("a sweep was already running; "
                                                             "nothing was sent"));
        });
    }
    return true;
}

void GainSearchBode::abort()
{
    switch (m_phase) {
    case Phase::Idle:
    case Phase::Halting:
        return;
    case Phase::SweepRead:
    case Phase::SweepBest:
        if (!m_sweep->isRunning()) {
            haltAndRestore(StepTestFailure::Aborted, QStringLiteral("aborted"));
            return;
        }
        // The sweep halts and puts back what it read; then the gains read go back (below).
        m_aborting = true;
        m_sweep->abort();
        return;
    case Phase::WritingBest:
    case Phase::Restoring:
        haltAndRestore(StepTestFailure::Aborted, QStringLiteral("aborted"));
        return;
    }
}

void GainSearchBode::onSwept(const FrequencySweepResult &result)
{
    if (m_aborting) {
        // The abort came as the sweep finished: it stops here all the same.
        haltAndRestore(StepTestFailure::Aborted, QStringLiteral("aborted"));
        return;
    }
    if (m_phase == Phase::SweepRead) {
        m_result.read = result.response;
        if (m_best == *m_keeper.gains()) {
            // The best is the set read: one response is both.
            m_result.best = result.response;
            m_phase = Phase::Restoring;
            restoreAndEnd(StepTestFailure::None, result.message);
            return;
        }
        m_phase = Phase::WritingBest;
        // Back to where the first sweep ended, not to a second reading of it.
        const std::optional<double> ended =
            m_spec.returnSpeedDps ? m_spec.returnSpeedDps : result.startSpeed;
        m_keeper.write(m_best, [this, ended, run = m_run](bool ok, const QString &why) {
            if (run != m_run || m_phase != Phase::WritingBest)
                return;
            if (!ok) {
                haltAndRestore(StepTestFailure::Silent,
                               QStringLiteral("the best candidate's gains could not be written "
                                              "for its sweep (%1)")
                                   .arg(why));
                return;
            }
            m_phase = Phase::SweepBest;
            FrequencySweepSpec second = m_spec;
            second.returnSpeedDps = ended;
            if (!m_sweep->start(second, m_limits))
                haltAndRestore(StepTestFailure::BadSpec,
                               QStringLiteral("the second sweep could not start"));
        });
        return;
    }
    if (m_phase == Phase::SweepBest) {
        m_result.best = result.response;
        m_phase = Phase::Restoring;
        restoreAndEnd(StepTestFailure::None, result.message);
    }
}

void GainSearchBode::onSweepFailed(const FrequencySweepResult &result)
{
    if (m_phase != Phase::SweepRead && m_phase != Phase::SweepBest)
        return;
    const StepTestFailure failure = m_aborting ? StepTestFailure::Aborted : result.failure;
    if (!m_aborting && result.sent == 0 &&
        (result.failure == StepTestFailure::Refused ||
         result.failure == StepTestFailure::BadSpec)) {
        // Refused before its first setpoint: nothing moved, the drive does what it did; only
        // the best's gains (the second sweep) go back.
        m_phase = Phase::Restoring;
        restoreAndEnd(failure, QStringLiteral("a sweep was refused (%1)").arg(result.message));
        return;
    }
    // The sweep has halted (or never moved) and put back what it read: now Motor Off, whatever
    // it did, and the gains read.
    haltAndRestore(failure, QStringLiteral("a sweep ended: %1").arg(result.message));
}

void GainSearchBode::restoreAndEnd(StepTestFailure failure, const QString &message)
{
    m_keeper.restore([this, failure, message, run = m_run](bool ok, const QString &why) {
        if (run != m_run || m_phase != Phase::Restoring)
            return;
        if (!ok) {
            haltAndRestore(
                StepTestFailure::Silent,
                QStringLiteral("the gains read could not be written back (%1)").arg(why));
            return;
        }
        m_result.restored = true;
        end(failure, message);
    });
}

void GainSearchBode::haltAndRestore(StepTestFailure failure, const QString &message)
{
    m_phase = Phase::Halting;
    TuningEnd::halt(m_session, m_keeper, m_spec.id, this,
                    [this, failure, message, run = m_run](const HaltOutcome &h) {
                        if (run != m_run)
                            return;
                        m_result.halt = h;
                        m_result.restored = h.gainsRestored;
                        end(failure, QStringLiteral("%1: %2").arg(message, h.words()));
                    });
}

void GainSearchBode::end(StepTestFailure failure, const QString &message)
{
    m_phase = Phase::Idle;
    m_aborting = false;
    m_result.failure = failure;
    m_result.message = message;
    emit ended(m_result);
}

} // namespace lk::tuning
