#include "GainSearchStrategy.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lk::tuning {

namespace {
quint16 scaled(quint16 gain, double factor, quint16 max)
{
    const double v = std::round(gain * factor);
    // Always a different value: a gain of 1 still moves.
    const double moved = factor > 1 ? std::max(v, gain + 1.0) : std::min(v, gain - 1.0);
    return quint16(std::clamp(moved, 1.0, double(max)));
}

double riseOf(const CandidateScore &s)
{
    return s.errorAreaS > 0 ? s.errorAreaS : 1e9;
}
} // namespace

GainSearchStrategy::GainSearchStrategy(const LoopGains &read, double maxOvershootPct,
                                       int maxCandidates)
    : m_read(read), m_maxOvershootPct(maxOvershootPct), m_maxCandidates(maxCandidates), m_next(read)
{
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

std::optional<int> GainSearchStrategy::best() const
{
    std::optional<int> best;
    for (int i = 0; i < m_scores.size(); ++i) {
        const CandidateScore &s = m_scores[i];
        if (!s.accepted())
            continue;
        if (!best || riseOf(s) < riseOf(m_scores[*best]))
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
    const quint16 max = m_read.maxGain();
    // Down the row (Ki lower: less overshoot) until a candidate is accepted or the row ends.
    if (!score.accepted() && m_kiStep + 1 < kKiSteps) {
        ++m_kiStep;
        m_next = rowCandidate(max);
        return;
    }
    // The row is over: its best against the rows before.
    double rowBest = 1e9;
    for (const CandidateScore &c : m_rowScores)
        if (c.accepted())
            rowBest = std::min(rowBest, riseOf(c));
    const bool improved = rowBest < m_bestBeforeRow * (1 - kMinGain);
    const bool anyAccepted = m_bestBeforeRow < 1e9 || rowBest < 1e9;
    m_bestBeforeRow = std::min(m_bestBeforeRow, rowBest);
    m_rowScores.clear();
    // Kp climbs while rows get better (or none was accepted yet) and the range allows; one row
    // that is no better may be the noise of a few samples: two in a row end the climb.
    m_rowsWithoutGain = anyAccepted && !improved ? m_rowsWithoutGain + 1 : 0;
    if (m_rowsWithoutGain >= kPatienceRows || score.gains.speed.kp >= max) {
        m_stage = Stage::Done;
        return;
    }
    ++m_kpStep;
    m_kiStep = 0;
    m_next = rowCandidate(max);
}

LoopGains GainSearchStrategy::rowCandidate(quint16 max) const
{
    LoopGains g = m_read;
    g.speed.kp = m_read.speed.kp;
    for (int i = 0; i < m_kpStep; ++i)
        g.speed.kp = scaled(g.speed.kp, kKpFactor, max);
    for (int i = 0; i < m_kiStep; ++i)
        g.speed.ki = scaled(g.speed.ki, 1 / kKiFactor, max);
    return g;
}

} // namespace lk::tuning
