#pragma once

#include "FrequencySweepRunner.h"
#include "TuningEnd.h"

#include <QtCore/QObject>

#include <memory>
#include <optional>

namespace lk::bus {
class BusSession;
}

namespace lk::tuning {

class GainKeeper;

/// What the Bode step of a gain search measured: the speed loop's response with the gains
/// read and with the best candidate's.
struct GainSearchBodeResult {
    std::optional<FrequencyResponse> read; ///< with the gains read
    std::optional<FrequencyResponse> best; ///< with the best candidate's (the same set: `read`)
    StepTestFailure failure = StepTestFailure::None;
    QString message; ///< English: how it ended, what the drive was left doing
    /// It ended with Motor Off (an abort, a failure): what that halt did.
    std::optional<HaltOutcome> halt;
    bool restored = false; ///< the gains read are back in RAM
    bool ok() const { return failure == StepTestFailure::None; }
};

/// The Bode step of a gain search: two short frequency sweeps of the speed loop
/// (FrequencySweepRunner, as it is: soft limits, its own read of the gains in RAM, its return
/// to the speed it read), the first with the gains read, the second with the best candidate's
/// written to RAM for it. At the end, whatever happens, `keeper`'s gains read go back to RAM:
/// the candidate stays written only for its sweep.
///
/// abort() (Esc, an emergency stop) aborts the sweep and waits for it to have put back what it
/// read (the candidate's gains, while the second runs) before it sends Motor Off and writes the
/// gains read back: two writers never race.
class GainSearchBode : public QObject {
    Q_OBJECT
public:
    /// `keeper` has read the gains (the search's own keeper): what is put back at the end.
    GainSearchBode(bus::BusSession &session, GainKeeper &keeper, QObject *parent = nullptr);
    /// Running: the sweep halts and puts back what it read, then the gains read go back.
    ~GainSearchBode() override;

    /// Measures drive `keeper.id()` with the gains read, then with `best` (the read set's
    /// speed Kp and Ki changed), by `spec`'s sweep. ended() follows, never from inside start().
    bool start(const FrequencySweepSpec &spec, const LoopGains &best,
               const safety::SoftLimits &limits);
    void abort();
    bool isRunning() const { return m_phase != Phase::Idle; }

signals:
    /// A sweep began to move the drive: with the gains read (`best` false) or the best's.
    void sweepStarted(bool best, double seconds);
    void ended(const lk::tuning::GainSearchBodeResult &result);

private:
    enum class Phase { Idle, SweepRead, WritingBest, SweepBest, Restoring, Halting };

    void onSwept(const FrequencySweepResult &result);
    void onSweepFailed(const FrequencySweepResult &result);
    void restoreAndEnd(StepTestFailure failure, const QString &message);
    void haltAndRestore(StepTestFailure failure, const QString &message);
    void end(StepTestFailure failure, const QString &message);

    bus::BusSession &m_session;
    GainKeeper &m_keeper;
    std::unique_ptr<FrequencySweepRunner> m_sweep; ///< reset first when destroyed while running
    Phase m_phase = Phase::Idle;
    FrequencySweepSpec m_spec;
    LoopGains m_best;
    safety::SoftLimits m_limits;
    GainSearchBodeResult m_result;
    bool m_aborting = false; ///< abort() came while the sweep was running: it ends first
    quint64 m_run = 0;
};

} // namespace lk::tuning

Q_DECLARE_METATYPE(lk::tuning::GainSearchBodeResult)
