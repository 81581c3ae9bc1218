#include "GainSearchStrategy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace lk::tuning {

namespace {
quint16 scaled(quint16 gain, double factor, quint16 max)
{
    const double v = std::round(gain * factor);
    // Always a different value: a gain of 1 still moves.
    const double moved = factor > 1 ? std::max(v, gain + 1.0) : std::min(v, gain - 1.0);
    return quint16(std::clamp(moved, 1.0, double(max)));
}

} // namespace

double CandidateScore::riseS() const
{
    return metrics.riseTimeS.known() ? *metrics.riseTimeS.value
                                     : std::numeric_limits<double>::infinity();
}

GainSearchStrategy::GainSearchStrategy(const LoopGains &read, double maxOvershootPct,
                                       int maxCandidates, StepLoop loop)
    : m_read(read), m_loop(loop), m_maxOvershootPct(maxOvershootPct),
      m_maxCandidates(maxCandidates), m_rowKp(tuned(read, loop).kp), m_rowKi(tuned(read, loop).ki),
      m_next(read)
{
}

const PidTriple &GainSearchStrategy::tuned(const LoopGains &gains, StepLoop loop)
{
    return loop == StepLoop::Position ? gains.angle : gains.speed;
}

PidTriple &GainSearchStrategy::tuned(LoopGains &gains, StepLoop loop)
{
    return loop == StepLoop::Position ? gains.angle : gains.speed;
}

std::optional<LoopGains> GainSearchStrategy::next() const
{
    if (m_stage == Stage::Done || m_scores.size() >= m_maxCandidates)
        return std::nullopt;
    return m_next;
}

bool GainSearchStrategy::swingsGrow(const StepTrace &trace, const StepEdge &edge, double until)
{
    // The error's extreme in each half-cycle between crossings of the target, after the first.
    QVector<double> peaks;
    double peak = 0;
    int side = 0;
    bool crossed = false;
    const double band = 0.02 * std::abs(edge.amplitude());
    for (int i = 0; i < trace.size(); ++i) {
        if (trace.time[i] < edge.time || trace.time[i] >= until)
            continue;
        const double e = (trace.value[i] - edge.to) * (edge.amplitude() >= 0 ? 1 : -1);
        const int s = e > 0 ? 1 : -1;
        if (!crossed) {
            crossed = s > 0;
            side = s;
            peak = e;
            continue;
        }
        if (s != side) {
            if (std::abs(peak) > band)
                peaks.append(std::abs(peak));
            side = s;
            peak = e;
        } else if (std::abs(e) > std::abs(peak)) {
            peak = e;
        }
    }
    if (peaks.size() < 3)
        return false;
    for (int i = 1; i < peaks.size(); ++i)
        if (peaks[i] <= peaks[i - 1])
            return false;
    return true;
}

CandidateVerdict GainSearchStrategy::judge(const EdgeMetrics &m, const StepTrace &trace,
                                           double maxOvershootPct)
{
    if (m.saturatedS.known() && *m.saturatedS.value > 0)
        return CandidateVerdict::Saturated;
    for (int i = 0; i < trace.edges.size(); ++i) {
        const double until = i + 1 < trace.edges.size() ? trace.edges[i + 1].time
                                                        : std::numeric_limits<double>::max();
        if (swingsGrow(trace, trace.edges[i], until))
            return CandidateVerdict::Growing;
    }
    if (!m.riseTimeS.known() || !m.steadyStateError.known() || !m.overshootPct.known() ||
        std::abs(*m.steadyStateError.value) > kMaxSteadyPct / 100 * std::abs(m.edge.amplitude()))
        return CandidateVerdict::NotSettled;
    if (*m.overshootPct.value > maxOvershootPct)
        return CandidateVerdict::Overshoot;
    if (m.oscillations.known() && *m.oscillations.value > kMaxSwings)
        return CandidateVerdict::Oscillates;
    return CandidateVerdict::Accepted;
}

EdgeMetrics GainSearchStrategy::combine(const QVector<EdgeMetrics> &edges)
{
    if (edges.isEmpty())
        return {};
    EdgeMetrics out = edges.first();
    QVector<double> rises;
    const auto worst = [](Metric &into, const Metric &m, bool absolute) {
        if (!m.known() || !into.known()) {
            into = m.known() ? into : m;
            return;
        }
        const auto size = [absolute](double v) { return absolute ? std::abs(v) : v; };
        if (size(*m.value) > size(*into.value))
            into = m;
    };
    for (int i = 0; i < edges.size(); ++i) {
        const EdgeMetrics &e = edges[i];
        if (e.riseTimeS.known())
            rises.append(*e.riseTimeS.value);
        if (i == 0)
            continue;
        worst(out.overshootPct, e.overshootPct, false);
        worst(out.oscillations, e.oscillations, false);
        worst(out.saturatedS, e.saturatedS, false);
        worst(out.steadyStateError, e.steadyStateError, true);
        worst(out.peakEffort, e.peakEffort, true);
        worst(out.settling2S, e.settling2S, false);
        worst(out.settling5S, e.settling5S, false);
        out.samples += e.samples;
    }
    if (rises.size() == edges.size()) {
        std::sort(rises.begin(), rises.end());
        const int n = int(rises.size());
        out.riseTimeS = Metric::of(n % 2 ? rises[n / 2] : (rises[n / 2 - 1] + rises[n / 2]) / 2);
    } else {
        out.riseTimeS = Metric::none(MetricGap::NotReached);
    }
    return out;
}

double GainSearchStrategy::errorArea(const StepTrace &trace)
{
    double total = 0;
    int edges = 0;
    for (int e = 0; e < trace.edges.size(); ++e) {
        const StepEdge &edge = trace.edges[e];
        const double until = e + 1 < trace.edges.size() ? trace.edges[e + 1].time
                                                        : std::numeric_limits<double>::max();
        const double step = std::abs(edge.amplitude());
        if (step <= 0)
            continue;
        double area = 0;
        double lastT = edge.time;
        double lastE = 1; // at the edge the whole step is still to go
        for (int i = 0; i < trace.size(); ++i) {
            if (trace.time[i] <= edge.time || trace.time[i] >= until)
                continue;
            const double err = std::abs(edge.to - trace.value[i]) / step;
            area += (trace.time[i] - lastT) * (err + lastE) / 2;
            lastT = trace.time[i];
            lastE = err;
        }
        total += area;
        ++edges;
    }
    return edges > 0 ? total / edges : 0;
}

CandidateScore GainSearchStrategy::score(const LoopGains &gains, const StepTrace &trace,
                                         std::optional<double> effortLimit, double maxOvershootPct)
{
    StepMetricOptions options;
    options.effortLimit = effortLimit;
    CandidateScore s;
    s.gains = gains;
    s.metrics = combine(StepMetrics::forAllEdges(trace, options));
    s.errorAreaS = errorArea(trace);
    s.verdict = judge(s.metrics, trace, maxOvershootPct);
    s.trace = trace;
    return s;
}

std::optional<int> GainSearchStrategy::best() const
{
    std::optional<int> best;
    for (int i = 0; i < m_scores.size(); ++i) {
        const CandidateScore &s = m_scores[i];
        if (!s.accepted())
            continue;
        if (!best) {
            best = i;
            continue;
        }
        const CandidateScore &b = m_scores[*best];
        const bool tie = std::abs(s.riseS() - b.riseS()) <= kRiseTieS;
        if (tie ? s.errorAreaS < b.errorAreaS : s.riseS() < b.riseS())
            best = i;
    }
    return best;
}

bool GainSearchStrategy::stoppedByInstability() const
{
    return !m_scores.isEmpty() && m_scores.last().unstable();
}

void GainSearchStrategy::record(const CandidateScore &score)
{
    m_scores.append(score);
    m_rowScores.append(score);
    if (score.unstable()) {
        m_stage = Stage::Done; // the first sign of instability ends the search
        return;
    }
    if (m_stage == Stage::Refining) {
        ++m_refinements;
        if (score.accepted())
            m_accepted = tunedOf(score);
        else
            m_rejectedKp = tunedOf(score).kp;
        nextRefinement();
        return;
    }
    // Down the row (Ki lower: less overshoot) until a candidate is accepted, the row ends or
    // a lower Ki stops helping.
    if (!score.accepted() && m_kiStep + 1 < kKiSteps && tunedOf(score).ki > 1 &&
        lowerKiHelps(score)) {
        ++m_kiStep;
        m_next = candidate(m_rowKp, scaled(tunedOf(score).ki, 1 / kKiFactor, m_read.maxGain()));
        return;
    }
    endRow(score);
}

bool GainSearchStrategy::lowerKiHelps(const CandidateScore &score) const
{
    if (score.verdict != CandidateVerdict::Overshoot &&
        score.verdict != CandidateVerdict::Oscillates)
        return false; // a lower Ki settles slower still
    if (m_rowScores.size() < 2)
        return true;
    const EdgeMetrics &before = m_rowScores[m_rowScores.size() - 2].metrics;
    const EdgeMetrics &now = score.metrics;
    const auto value = [](const Metric &m) { return m.value.value_or(0); };
    return value(before.overshootPct) - value(now.overshootPct) >= kKiHelpPct ||
           value(now.oscillations) < value(before.oscillations);
}

void GainSearchStrategy::endRow(const CandidateScore &last)
{
    // The row is over: its fastest accepted rise against the rows before. A row stops at its
    // first accepted candidate, so the last one says whether it found any.
    double rowBest = std::numeric_limits<double>::infinity();
    for (const CandidateScore &c : m_rowScores)
        if (c.accepted())
            rowBest = std::min(rowBest, c.riseS());
    const QVector<CandidateScore> endedRow = std::exchange(m_rowScores, {});
    const bool rowAccepted = last.accepted();
    const bool acceptedBefore = m_accepted.has_value();
    if (!rowAccepted && acceptedBefore) {
        // The climb met the bounds: the fastest Kp within them is below this row's.
        m_stage = Stage::Refining;
        m_rejectedKp = m_rowKp;
        nextRefinement();
        return;
    }
    const bool improved = rowBest < m_bestBeforeRow * (1 - kMinGain);
    m_bestBeforeRow = std::min(m_bestBeforeRow, rowBest);
    // Before any candidate is accepted the climb goes on only while some rise gets faster: a
    // drive whose step is never reached (no rise measured) would otherwise climb to the gain
    // ceiling (65535 on V2.35), each candidate a stiffer loop tried on a real axis.
    double rowRise = std::numeric_limits<double>::infinity();
    for (const CandidateScore &c : endedRow)
        rowRise = std::min(rowRise, c.riseS());
    const bool riseImproved = rowRise < m_riseBeforeRow * (1 - kMinGain);
    m_riseBeforeRow = std::min(m_riseBeforeRow, rowRise);
    m_blindRows = !rowAccepted && !acceptedBefore && !riseImproved ? m_blindRows + 1 : 0;
    if (rowAccepted) {
        m_accepted = tunedOf(last);
        m_rowKi = tunedOf(last).ki;
    }
    // One row that is no faster may be the noise of a few samples: two in a row end the climb.
    m_rowsWithoutGain = rowAccepted && !improved ? m_rowsWithoutGain + 1 : 0;
    const quint16 max = m_read.maxGain();
    if (m_rowsWithoutGain >= kPatienceRows || m_blindRows >= kBlindRows || m_rowKp >= max) {
        m_stage = Stage::Done;
        return;
    }
    m_rowKp = scaled(m_rowKp, kKpFactor, max);
    m_kiStep = 0;
    m_next = candidate(m_rowKp, m_rowKi);
}

void GainSearchStrategy::nextRefinement()
{
    const quint16 low = m_accepted->kp;
    const auto middle = quint16(std::lround(std::sqrt(double(low) * m_rejectedKp)));
    if (m_refinements >= kRefinements || middle <= low || middle >= m_rejectedKp) {
        m_stage = Stage::Done;
        return;
    }
    m_next = candidate(middle, m_accepted->ki);
}

LoopGains GainSearchStrategy::candidate(quint16 kp, quint16 ki) const
{
    LoopGains g = m_read;
    tuned(g, m_loop).kp = kp;
    tuned(g, m_loop).ki = ki;
    return g;
}

} // namespace lk::tuning
