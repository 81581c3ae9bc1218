#pragma once

#include "GainKeeper.h"
#include "GainSearchBode.h"
#include "GainSearchStrategy.h"
#include "StepTestRunner.h"

#include <QtCore/QObject>

#include <optional>

namespace lk::bus {
class BusSession;
}

namespace lk::tuning {

/// A gain search as the user asks for it: the speed loop's Kp and Ki, scored by short speed
/// steps FROM -> TO, or the position loop's (LoopGains::angle), scored by short position steps
/// from the angle the drive is at.
struct GainSearchSpec {
    int id = 1;
    StepLoop loop = StepLoop::Speed;
    /// Speed: dps, away from 0, where friction would bend the steps. Position: deg from the
    /// angle read at the start (forPosition(): 0 and kPositionStepDeg); the steps go the other
    /// way when the angle window has no room for them the first way.
    double from = 100;
    double to = 300;
    double maxOvershootPct = 5;
    double stepS = 0.25;    ///< how long each step is held
    int periods = 3;        ///< a square of this many periods: 2N steps per candidate
    double preRollS = 0.15; ///< FROM held before it
    int maxCandidates = 24;
    /// After the search, the Bode of the gains read and of the best (GainSearchBode).
    bool measureBode = false;

    static constexpr double kPositionStepDeg = 10; ///< rotor deg: a few encoder counts x 1000

    /// A position search's defaults: steps of kPositionStepDeg from the angle the drive is at.
    static GainSearchSpec forPosition(int id);
    /// The step test each candidate is scored by; `startAngle`: the angle read at the start
    /// (position: FROM and TO are offsets from it; the square ends at FROM, so the drive ends
    /// where it started).
    StepTestSpec step(double startAngle = 0) const
    {
        const double base = loop == StepLoop::Position ? startAngle : 0;
        return StepTestSpec{id, loop, base + from, base + to, stepS, periods, preRollS, {}};
    }
    /// What is wrong with the search as set, before anything is sent (English), or "".
    /// `limits`: a position search needs their angle window.
    QString check(const safety::SoftLimits &limits) const;
    /// The short sweep the Bode step measures each set with: a sine between FROM and TO's
    /// middle and half-way to each (where the steps already went), 9 frequencies from 5 to 100 Hz.
    FrequencySweepSpec bode() const;
    /// About how long the Bode step takes on `series` within `limits`, seconds (both sweeps,
    /// their reads and writes); nullopt when its sweep is refused there.
    std::optional<double> bodeSeconds(std::optional<protocol::Series> series,
                                      const safety::SoftLimits &limits) const;
};

/// What a gain search tried and found. Nothing of it stays in the drive: the gains read are
/// back in RAM at the end (the caller writes `best` only when the user asks).
struct GainSearchResult {
    GainSearchSpec spec;
    std::optional<LoopGains> read; ///< the gains read before anything moved
    /// Position: the angle read before anything moved, deg, and the sign the steps went
    /// (-1: down from it, the window had no room above).
    std::optional<double> startAngle;
    int direction = 1;
    QVector<CandidateScore> candidates;
    std::optional<int> baseline; ///< the read gains' score (the first candidate), if measured
    std::optional<int> best;     ///< the fastest accepted candidate
    /// measureBode: the speed loop's response with the gains read and with the best (the
    /// Bode step runs once the search found a best; a failed one leaves what it measured).
    std::optional<FrequencyResponse> bodeRead, bodeBest;
    bool stoppedByInstability = false;
    double seconds = 0; ///< the search's wall time
    StepTestFailure failure = StepTestFailure::None;
    StepRefusal refusal;   ///< a Refused step: which setpoint and limit
    QString message;       ///< English: how it ended and what the drive was left doing
    TuningOutcome outcome; ///< the same as facts
    bool ok() const { return failure == StepTestFailure::None; }
};

/// Runs a gain search on a BusSession: reads the gains and acceleration limit (nothing runs
/// without them), lifts the acceleration limit, and for each candidate of GainSearchStrategy
/// writes its gains to RAM and runs a step test (StepTestRunner: every setpoint checked
/// against the limits, a refusal sends nothing more), until the strategy is done or a
/// candidate shows instability (current at its limit, swings growing). Then it writes the
/// gains read back to RAM and returns the drive to the speed it had (speed), or leaves it
/// holding the angle it had (position: every square ends where it began).
///
/// abort() (Esc, Ctrl-C) stops the step at once, sends motor off (an emergency stop) and
/// writes the gains read back to RAM; failed(Aborted) follows once both ended.
class GainSearchRunner : public QObject {
    Q_OBJECT
public:
    explicit GainSearchRunner(bus::BusSession &session, QObject *parent = nullptr);
    ~GainSearchRunner() override; ///< running: motor off, the read gains written back

    bool start(const GainSearchSpec &spec, const safety::SoftLimits &limits);
    void abort();
    bool isRunning() const { return m_phase != Phase::Idle; }

signals:
    /// A candidate's step was scored (index into the result's candidates).
    void candidateScored(const lk::tuning::CandidateScore &score, int index);
    /// measureBode: a sweep of the Bode step began (`best`: with the best's gains in RAM).
    void bodeSweepStarted(bool best, double seconds);
    void finished(const lk::tuning::GainSearchResult &result);
    void failed(const lk::tuning::GainSearchResult &result);

private:
    enum class Phase { Idle, Reading, Searching, Restoring, Measuring, Aborting };

    void onRead();
    void onAngleRead(const bus::RequestResult &result);
    void startStrategy();
    void tryNext();
    void onStepFinished(const StepTestResult &result);
    void onStepFailed(const StepTestResult &result);
    void finishSearch();
    void returnToStart();
    void measureBode(const QString &returned);
    void onBodeEnded(const GainSearchBodeResult &bode);
    void bodeFailed(const GainSearchBodeResult &bode);
    /// Finished, or Unstable when the search stopped at an unstable candidate.
    SearchEnd finishedEnd() const;
    void haltAndRestore(StepTestFailure failure, SearchEnd why, const QString &message);
    /// Ends with `failure`; m_result.outcome has been filled in.
    void end(StepTestFailure failure, const QString &message);
    void end(StepTestFailure failure, SearchEnd why, DriveLeft drive, bool restored,
             const QString &message);

    bus::BusSession &m_session;
    GainKeeper m_keeper;
    StepTestRunner m_step;
    GainSearchBode m_bode;
    Phase m_phase = Phase::Idle;
    GainSearchSpec m_spec;
    safety::SoftLimits m_limits;
    std::optional<GainSearchStrategy> m_strategy;
    GainSearchResult m_result;
    std::optional<double> m_startSpeed;
    double m_startAngle = 0;      ///< position: the angle read (FROM and TO are offsets from it)
    bool m_measured = false;      ///< the Bode step is done: the return to the start speed ends it
    bool m_emergencyStop = false; ///< one came in the Bode step: its abort is worded as one
    bool m_userAbort = false;     ///< abort() came first in the Bode step
    DriveLeft m_returned = DriveLeft::Untouched; ///< what the last return to the start left
    quint64 m_run = 0;
    QElapsedTimer m_clock;
};

} // namespace lk::tuning

Q_DECLARE_METATYPE(lk::tuning::GainSearchResult)
Q_DECLARE_METATYPE(lk::tuning::CandidateScore)
