#pragma once

#include "LoopGains.h"
#include "StepMetrics.h"
#include "StepTrace.h"

#include <QtCore/QVector>

#include <optional>

namespace lk::tuning {

/// How a candidate's step test came out against the search's bounds.
enum class CandidateVerdict {
    Accepted,   ///< within every bound: it competes on rise time
    Overshoot,  ///< overshoot above the bound
    Oscillates, ///< more than kMaxSwings swings past the 2 % band
    NotSettled, ///< no rise or steady state could be measured (never reached, never settled)
    Saturated,  ///< the current sat at its limit: instability, the search stops
    Growing,    ///< each swing larger than the one before: instability, the search stops
};

/// One candidate tried: its gains and the metrics of its step.
struct CandidateScore {
    LoopGains gains;
    /// combine()d over the step's edges: the median rise time (what accepted candidates are
    /// ranked by), the worst overshoot, oscillations and saturation.
    EdgeMetrics metrics;
    /// The error's area per step, seconds: the mean over the edges of the integral of
    /// |to - value| / |to - from| from each edge to the next. It falls as the rise gets faster
    /// and rises with overshoot and ringing; it breaks ties between equally fast candidates.
    double errorAreaS = 0;
    CandidateVerdict verdict = CandidateVerdict::NotSettled;
    /// The step test it was scored on (what the views overlay: the search's own samples).
    StepTrace trace;
    bool accepted() const { return verdict == CandidateVerdict::Accepted; }
    bool unstable() const
    {
        return verdict == CandidateVerdict::Saturated || verdict == CandidateVerdict::Growing;
    }
    /// The median rise time, seconds; infinity when there is none.
    double riseS() const;
};

/// Which gains of one loop (the speed loop's, or the position loop's: LoopGains::angle) to try
/// next, from the gains read and the scores so far. The same climb serves both: each is a PI
/// whose Kp sets its bandwidth and whose Ki, too high, overshoots.
///
/// Climbing, in rows: row k has Kp = the read Kp x kKpFactor^k and starts at the Ki the row
/// before accepted (the read Ki until something is accepted); while a candidate overshoots or
/// rings, Ki goes down by kKiFactor (at most kKiSteps in a row), but only as long as that
/// helps: when a lower Ki left the overshoot as it was, the overshoot is the loop's lag, not
/// the PI zero, and the row ends. The first candidate is the gains read (the baseline). Kp
/// climbs while rows are accepted and faster; kPatienceRows rows in a row no kMinGain faster
/// end it (rows before anything was accepted always climb).
///
/// Refining: once a row finds nothing within the bounds after a row that did, the fastest
/// acceptable Kp lies between the two: up to kRefinements candidates halve that interval
/// (geometric middle, with the accepted Ki), each accepted one its new lower end.
///
/// The best is the accepted candidate with the fastest (median) rise, the least error area
/// among rises within kRiseTieS of it. Only the searched loop's Kp and Ki change; every other
/// value stays as read (never beyond the generation's range). The first unstable candidate
/// (current at its limit, swings growing) or `maxCandidates` end the search. Pure.
class GainSearchStrategy {
public:
    static constexpr double kKpFactor = 1.3;
    static constexpr double kKiFactor = 1.5;
    static constexpr int kKiSteps = 4;
    static constexpr int kPatienceRows = 2; ///< rows no better in a row that end the climb
    static constexpr int kBlindRows = 3;    ///< rows, none accepted yet, whose rise got no faster
    static constexpr int kRefinements = 3;  ///< halvings between accepted and rejected Kp
    /// A lower Ki "helped" when the overshoot fell by this many points, or the swings fewer.
    static constexpr double kKiHelpPct = 0.5;
    static constexpr double kMinGain = 0.03;     ///< 3 % faster rise, or Kp stops climbing
    static constexpr double kRiseTieS = 0.0002;  ///< rises this close are equally fast
    static constexpr int kMaxSwings = 2;         ///< oscillations allowed in a step
    static constexpr double kMaxSteadyPct = 2.0; ///< of the step

    GainSearchStrategy(const LoopGains &read, double maxOvershootPct, int maxCandidates,
                       StepLoop loop = StepLoop::Speed);

    /// The gains of `loop` in `gains`: speed, or angle for the position loop.
    static const PidTriple &tuned(const LoopGains &gains, StepLoop loop);
    static PidTriple &tuned(LoopGains &gains, StepLoop loop);
    StepLoop loop() const { return m_loop; }

    /// The next candidate; nullopt: the search is over.
    std::optional<LoopGains> next() const;
    /// The score of the candidate next() gave.
    void record(const CandidateScore &score);

    /// The verdict of a candidate whose steps gave `metrics` (combine()d) on `trace` (whose
    /// every edge is looked at for growing swings).
    static CandidateVerdict judge(const EdgeMetrics &metrics, const StepTrace &trace,
                                  double maxOvershootPct);
    /// Whether the error's peaks after the first crossing of the target grow, swing by swing,
    /// from `edge` until `until` (the next edge).
    static bool swingsGrow(const StepTrace &trace, const StepEdge &edge, double until);
    /// One candidate's figures from several edges (a square wave: up and down steps), so that
    /// one edge's sampling gap does not decide: the median rise time, the worst overshoot,
    /// oscillations, saturation and steady-state error (unknown if any edge's is).
    static EdgeMetrics combine(const QVector<EdgeMetrics> &edges);
    /// CandidateScore::errorAreaS of a trace (trapezoids on the samples' times).
    static double errorArea(const StepTrace &trace);
    /// The score of a candidate whose step test gave `trace`: its combined metrics, error area,
    /// verdict and the trace itself. `effortLimit`: the drive's current (power) limit, for
    /// saturation.
    static CandidateScore score(const LoopGains &gains, const StepTrace &trace,
                                std::optional<double> effortLimit, double maxOvershootPct);

    const QVector<CandidateScore> &scores() const { return m_scores; }
    /// The accepted candidate with the fastest rise (index into scores()); nullopt: none was
    /// accepted.
    std::optional<int> best() const;
    bool stoppedByInstability() const;

private:
    enum class Stage { Climbing, Refining, Done };
    void endRow(const CandidateScore &last);
    void nextRefinement();
    bool lowerKiHelps(const CandidateScore &score) const;
    LoopGains candidate(quint16 kp, quint16 ki) const;

    const PidTriple &tunedOf(const CandidateScore &s) const { return tuned(s.gains, m_loop); }

    LoopGains m_read;
    StepLoop m_loop = StepLoop::Speed;
    double m_maxOvershootPct;
    int m_maxCandidates;
    Stage m_stage = Stage::Climbing;
    quint16 m_rowKp = 0; ///< the row's Kp
    quint16 m_rowKi = 0; ///< the Ki the row starts at
    int m_kiStep = 0;
    int m_rowsWithoutGain = 0;
    int m_blindRows = 0;
    double m_riseBeforeRow = 1e9; ///< the fastest rise of any candidate of the rows before, s
    double m_bestBeforeRow = 1e9; ///< the fastest accepted rise of the rows before, seconds
    std::optional<PidTriple> m_accepted; ///< the last accepted row's (or refinement's) gains
    quint16 m_rejectedKp = 0;            ///< Refining: the lowest Kp found outside the bounds
    int m_refinements = 0;
    QVector<CandidateScore> m_rowScores;
    QVector<CandidateScore> m_scores;
    std::optional<LoopGains> m_next;
};

} // namespace lk::tuning
