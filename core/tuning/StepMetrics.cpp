#include "StepMetrics.h"

#include <algorithm>
#include <cmath>

namespace lk::tuning {

namespace {

constexpr double band2 = 0.02;
constexpr double band5 = 0.05;

/// The time at which the line from (t0, v0) to (t1, v1) passes `level`.
double crossingTime(double t0, double v0, double t1, double v1, double level)
{
    if (v1 == v0)
        return t1;
    return t0 + (level - v0) / (v1 - v0) * (t1 - t0);
}

/// One edge's window of a trace: samples [first, end), from the edge to the next edge (or the
/// trace's end), with the edge's levels.
class EdgeWindow {
public:
    EdgeWindow(const StepTrace &trace, int edgeIndex)
        : m_trace(trace), m_edge(trace.edges[edgeIndex])
    {
        const bool lastEdge = edgeIndex + 1 >= trace.edges.size();
        const auto begin = trace.time.cbegin();
        const auto from = std::lower_bound(begin, trace.time.cend(), m_edge.time);
        const auto to =
            lastEdge ? trace.time.cend()
                     : std::lower_bound(from, trace.time.cend(), trace.edges[edgeIndex + 1].time);
        m_first = int(from - begin);
        m_end = int(to - begin);
        m_sign = m_edge.amplitude() < 0 ? -1.0 : 1.0;
    }

    int size() const { return m_end - m_first; }
    double spanS() const { return size() < 2 ? 0.0 : t(m_end - 1) - t(m_first); }
    const StepEdge &edge() const { return m_edge; }
    double t(int i) const { return m_trace.time[i]; }
    double v(int i) const { return m_trace.value[i]; }
    /// Progress towards `to` along the step's direction, in units of value: 0 at `from`, |A| at
    /// `to`, so one comparison serves rising and falling steps.
    double progress(int i) const { return (v(i) - m_edge.from) * m_sign; }
    double absAmplitude() const { return std::abs(m_edge.amplitude()); }

    /// First time the response reaches `from + fraction x A`, interpolated between samples;
    /// nullopt if it never does. The last sample before the edge anchors a crossing that falls
    /// between it and the window's first sample, so a response faster than the sampling does
    /// not read as crossing exactly at the first sample.
    std::optional<double> firstCrossing(double fraction) const
    {
        const double level = fraction * absAmplitude();
        for (int i = m_first; i < m_end; ++i) {
            if (progress(i) < level)
                continue;
            const int before = i - 1;
            if (before < 0 || progress(before) >= level)
                return t(i);
            return crossingTime(t(before), progress(before), t(i), progress(i), level);
        }
        return std::nullopt;
    }

    /// Index of the first sample at or past `to`; -1 if none.
    int firstAtTarget() const
    {
        for (int i = m_first; i < m_end; ++i)
            if (progress(i) >= absAmplitude())
                return i;
        return -1;
    }

    bool outside(int i, double band) const { return std::abs(v(i) - m_edge.to) > band; }

    Metric settling(double fraction) const
    {
        const double band = fraction * absAmplitude();
        int lastOut = -1;
        for (int i = m_end - 1; i >= m_first && lastOut < 0; --i)
            if (outside(i, band))
                lastOut = i;
        if (lastOut == m_end - 1)
            return Metric::none(MetricGap::NeverSettled);
        if (lastOut < 0 && m_first > 0 && outside(m_first - 1, band))
            lastOut = m_first - 1; // entered the band between the edge and the first sample
        if (lastOut < 0)
            return Metric::of(0);
        const int in = lastOut + 1;
        const double boundary = m_edge.to + (v(lastOut) > m_edge.to ? band : -band);
        const double entered = crossingTime(t(lastOut), v(lastOut), t(in), v(in), boundary);
        return Metric::of(std::max(0.0, entered - m_edge.time));
    }

    Metric riseTime() const
    {
        const auto t10 = firstCrossing(0.1);
        const auto t90 = firstCrossing(0.9);
        if (!t10 || !t90)
            return Metric::none(MetricGap::NotReached);
        return Metric::of(*t90 - *t10);
    }

    Metric overshootPct() const
    {
        double most = 0;
        for (int i = m_first; i < m_end; ++i)
            most = std::max(most, progress(i) - absAmplitude());
        return Metric::of(100.0 * most / absAmplitude());
    }

    /// Half-cycles after the first crossing of `to` whose peak leaves the 2 % band. A
    /// half-cycle runs from one crossing of `to` to the next, so noise that wanders across the
    /// band's edge within one half-cycle counts once, and noise inside the band never counts.
    Metric oscillations() const
    {
        const int start = firstAtTarget();
        if (start < 0)
            return Metric::of(0);
        const double band = band2 * absAmplitude();
        int count = 0;
        double side = 1; // sign of value - to in the current half-cycle
        double peak = 0; // largest |value - to| in it
        for (int i = start; i < m_end; ++i) {
            const double d = v(i) - m_edge.to;
            if (d * side < 0) {
                count += peak > band ? 1 : 0;
                side = -side;
                peak = 0;
            }
            peak = std::max(peak, std::abs(d));
        }
        count += peak > band ? 1 : 0;
        return Metric::of(count);
    }

    Metric steadyStateError(double steadyFraction) const
    {
        const double last = t(m_end - 1);
        const double from = last - steadyFraction * (last - m_edge.time);
        double sum = 0;
        int n = 0;
        for (int i = m_end - 1; i >= m_first && t(i) >= from; --i) {
            sum += v(i);
            ++n;
        }
        return Metric::of(m_edge.to - sum / n);
    }

    /// Indices of the window's samples that carried the effort.
    QVector<int> effortSamples() const
    {
        QVector<int> known;
        for (int i = m_first; i < m_end; ++i)
            if (!StepTrace::isMissing(m_trace.effort.value(i, StepTrace::missing())))
                known.append(i);
        return known;
    }

    double e(int i) const { return std::abs(m_trace.effort[i]); }

    /// Longest run of effort samples at or above `threshold`, its ends interpolated to where
    /// |effort| crosses the threshold. Samples without an effort neither break nor extend it.
    double longestRunAtOrAbove(const QVector<int> &known, double threshold) const
    {
        double longest = 0;
        for (int k = 0; k < known.size(); ++k) {
            if (e(known[k]) < threshold)
                continue;
            const int startK = k;
            while (k + 1 < known.size() && e(known[k + 1]) >= threshold)
                ++k;
            const int a = known[startK];
            const int b = known[k];
            const double begin = startK == 0
                                     ? t(a)
                                     : crossingTime(t(known[startK - 1]), e(known[startK - 1]),
                                                    t(a), e(a), threshold);
            const double end = k + 1 == known.size() ? t(b)
                                                     : crossingTime(t(b), e(b), t(known[k + 1]),
                                                                    e(known[k + 1]), threshold);
            longest = std::max(longest, end - begin);
        }
        return longest;
    }

private:
    const StepTrace &m_trace;
    StepEdge m_edge;
    int m_first = 0;
    int m_end = 0;
    double m_sign = 1;
};

void setAll(EdgeMetrics &m, MetricGap gap)
{
    for (Metric *metric : {&m.riseTimeS, &m.overshootPct, &m.settling2S, &m.settling5S,
                           &m.steadyStateError, &m.peakEffort, &m.saturatedS, &m.oscillations})
        *metric = Metric::none(gap);
}

void setEffortMetrics(EdgeMetrics &m, const EdgeWindow &w, const StepMetricOptions &options)
{
    const QVector<int> known = w.effortSamples();
    if (known.isEmpty()) {
        m.peakEffort = Metric::none(MetricGap::NoEffort);
        m.saturatedS = Metric::none(MetricGap::NoEffort);
        return;
    }
    double peak = 0;
    for (int i : known)
        peak = std::max(peak, w.e(i));
    m.peakEffort = Metric::of(peak);
    if (!options.effortLimit) {
        m.saturatedS = Metric::none(MetricGap::NoLimit);
        return;
    }
    const double threshold = options.saturationFraction * std::abs(*options.effortLimit);
    const double longest = w.longestRunAtOrAbove(known, threshold);
    m.saturatedS = Metric::of(longest >= options.saturationMinS ? longest : 0.0);
}

void setResponseMetrics(EdgeMetrics &m, const EdgeWindow &w, const StepMetricOptions &options)
{
    if (w.absAmplitude() == 0) {
        for (Metric *metric :
             {&m.riseTimeS, &m.overshootPct, &m.settling2S, &m.settling5S, &m.oscillations})
            *metric = Metric::none(MetricGap::NoStep);
        m.steadyStateError = w.steadyStateError(options.steadyFraction);
        return;
    }
    m.riseTimeS = w.riseTime();
    m.overshootPct = w.overshootPct();
    m.settling2S = w.settling(band2);
    m.settling5S = w.settling(band5);
    m.oscillations = w.oscillations();
    // A response still outside the 5 % band at the end has no steady state to speak of.
    m.steadyStateError = m.settling5S.known() ? w.steadyStateError(options.steadyFraction)
                                              : Metric::none(MetricGap::NeverSettled);
}

} // namespace

EdgeMetrics StepMetrics::forEdge(const StepTrace &trace, int edgeIndex,
                                 const StepMetricOptions &options)
{
    EdgeMetrics m;
    if (edgeIndex < 0 || edgeIndex >= trace.edges.size()) {
        setAll(m, MetricGap::TooFewSamples);
        return m;
    }
    const EdgeWindow w(trace, edgeIndex);
    m.edge = w.edge();
    m.samples = w.size();
    if (m.samples >= 2 && w.spanS() > 0)
        m.sampleRateHz = (m.samples - 1) / w.spanS();
    if (m.samples < std::max(2, options.minSamples)) {
        setAll(m, MetricGap::TooFewSamples);
        return m;
    }
    setResponseMetrics(m, w, options);
    setEffortMetrics(m, w, options);
    return m;
}

QVector<EdgeMetrics> StepMetrics::forAllEdges(const StepTrace &trace,
                                              const StepMetricOptions &options)
{
    QVector<EdgeMetrics> all;
    all.reserve(trace.edges.size());
    for (int i = 0; i < trace.edges.size(); ++i)
        all.append(forEdge(trace, i, options));
    return all;
}

double StepMetrics::sampleRateHz(const StepTrace &trace)
{
    const int n = trace.size();
    if (n < 2)
        return 0;
    const double span = trace.time.last() - trace.time.first();
    return span > 0 ? (n - 1) / span : 0;
}

} // namespace lk::tuning
