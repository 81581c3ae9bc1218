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
    EdgeMetrics metrics;
    /// The error's area per step, seconds: the mean over the edges of the integral of
    /// |to - value| / |to - from| from each edge to the next. What candidates are ranked by: it
    /// falls as the rise gets faster and rises with overshoot and ringing, and unlike a
    /// crossing time it is not moved by the jitter of a few samples' timestamps.
    double errorAreaS = 0;
    CandidateVerdict verdict = CandidateVerdict::NotSettled;
    bool accepted() const { return verdict == CandidateVerdict::Accepted; }
    bool unstable() const
    {
        return verdict == CandidateVerdict::Saturated || verdict == CandidateVerdict::Growing;
    }
};

/// Which speed-loop gains to try next, from the gains read and the scores so far, in rows:
/// row k has Kp = the read Kp x kKpFactor^k, and tries Ki as read, then Ki / kKiFactor, ... (at
/// most kKiSteps) until one is accepted (a lower Ki overshoots less and settles slower). The
/// first candidate is the gains read (the baseline). Kp climbs to the next row until
/// kPatienceRows rows in a row brought no accepted error area kMinGain smaller than all before
/// (rows before anything was accepted always climb). Only the speed loop's Kp and Ki change; every
/// other value stays as read (never beyond the generation's range). Stops at the first unstable
/// candidate or after `maxCandidates`. Pure.
class GainSearchStrategy {
public:
    static constexpr double kKpFactor = 1.3;
    static constexpr double kKiFactor = 1.5;
    static constexpr int kKiSteps = 4;
    static constexpr int kPatienceRows = 2;      ///< rows no better in a row that end the climb
    static constexpr double kMinGain = 0.03;     ///< 3 % less error area, or Kp stops climbing
    static constexpr int kMaxSwings = 2;         ///< oscillations allowed in a step
    static constexpr double kMaxSteadyPct = 2.0; ///< of the step

    GainSearchStrategy(const LoopGains &read, double maxOvershootPct, int maxCandidates);

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

    const QVector<CandidateScore> &scores() const { return m_scores; }
    /// The accepted candidate with the least error area (index into scores()); nullopt: none
    /// was accepted.
    std::optional<int> best() const;
    bool stoppedByInstability() const;

private:
    enum class Stage { Searching, Done };
    LoopGains rowCandidate(quint16 max) const;

    LoopGains m_read;
    double m_maxOvershootPct;
    int m_maxCandidates;
    Stage m_stage = Stage::Searching;
    int m_kpStep = 0;
    int m_kiStep = 0;
    int m_rowsWithoutGain = 0;
    double m_bestBeforeRow = 1e9; ///< the least accepted error area of the rows before
    QVector<CandidateScore> m_rowScores;
    QVector<CandidateScore> m_scores;
    std::optional<LoopGains> m_next;
};

} // namespace lk::tuning
