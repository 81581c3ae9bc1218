#include "FrequencyResponse.h"

#include <algorithm>
#include <cmath>

namespace lk::tuning {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kBandwidthDropDb = 3;

// Samples filled in, linearly, across gaps longer than twice the median interval. In a gap the
// drive held a stale setpoint: the input's component counts it, and an output fitted on its
// samples alone would not see the response to it (the ratio would lead). Across a gap the
// input is constant, so the output relaxes smoothly and a straight line is close to it.
void fillGaps(QVector<double> &t, QVector<double> &y, double from, double to)
{
    QVector<double> intervals;
    for (int i = 1; i < t.size(); ++i)
        if (t[i] >= from && t[i - 1] <= to)
            intervals.append(t[i] - t[i - 1]);
    if (intervals.size() < 2)
        return;
    std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
    const double median = intervals[intervals.size() / 2];
    if (!(median > 0))
        return;
    QVector<double> ft, fy;
    for (int i = 0; i < t.size(); ++i) {
        if (i > 0 && t[i] - t[i - 1] > 2 * median && t[i] >= from && t[i - 1] <= to) {
            const int n = int(std::round((t[i] - t[i - 1]) / median));
            for (int k = 1; k < n; ++k) {
                const double u = double(k) / n;
                ft.append(t[i - 1] + u * (t[i] - t[i - 1]));
                fy.append(y[i - 1] + u * (y[i] - y[i - 1]));
            }
        }
        ft.append(t[i]);
        fy.append(y[i]);
    }
    t = ft;
    y = fy;
}

// Linear interpolation in log frequency between two points at `level` of `value`.
double crossing(double f0, double v0, double f1, double v1, double level)
{
    if (v1 == v0)
        return f0;
    const double u = (level - v0) / (v1 - v0);
    return std::exp(std::log(f0) + u * (std::log(f1) - std::log(f0)));
}
} // namespace

std::optional<FrequencyPoint> FrequencyResponse::measure(const QVector<double> &inputT,
                                                         const QVector<double> &inputV,
                                                         const QVector<double> &outputT,
                                                         const QVector<double> &outputY, double hz,
                                                         double from, double to, DroppedReason *why,
                                                         double minSamplesPerPeriod)
{
    const SineComponent u = SineFit::ofHeld(inputT, inputV, hz, from, to);
    if (!u.ok || u.amplitude <= 0) {
        if (why)
            *why = DroppedReason::NoInput;
        return std::nullopt;
    }
    const int samples = int(std::count_if(outputT.begin(), outputT.end(),
                                          [&](double t) { return t >= from && t <= to; }));
    if (double(samples) < minSamplesPerPeriod * (to - from) * hz) {
        if (why)
            *why = DroppedReason::TooFewSamples;
        return std::nullopt;
    }
    QVector<double> yt = outputT;
    QVector<double> yv = outputY;
    fillGaps(yt, yv, from, to);
    SineComponent y = SineFit::fitSampled(yt, yv, hz, from, to);
    if (!y.ok) {
        if (why)
            *why = DroppedReason::TooFewSamples;
        return std::nullopt;
    }
    FrequencyPoint p;
    p.hz = hz;
    p.inputAmplitude = u.amplitude;
    p.outputAmplitude = y.amplitude;
    p.magnitudeDb = 20 * std::log10(std::max(y.amplitude, 1e-300) / u.amplitude);
    double phase = (y.phaseRad - u.phaseRad) * 180 / kPi;
    phase = std::remainder(phase, 360.0); // -180..180
    p.phaseDeg = phase;
    p.quality = y.quality;
    p.samples = samples;
    return p;
}

FrequencyPoint FrequencyResponse::integrated(const FrequencyPoint &speed)
{
    FrequencyPoint p = speed;
    const double w = 2 * 3.14159265358979323846 * speed.hz;
    p.magnitudeDb -= 20 * std::log10(w);
    p.phaseDeg -= 90;
    p.outputAmplitude /= w;
    return p;
}

void FrequencyResponse::unwrapPhases()
{
    for (int i = 1; i < points.size(); ++i) {
        const double before = points[i - 1].phaseDeg;
        points[i].phaseDeg = before + std::remainder(points[i].phaseDeg - before, 360.0);
    }
}

BodeFigures FrequencyResponse::figures() const
{
    BodeFigures f;
    if (points.isEmpty())
        return f;
    f.referenceDb = points.first().magnitudeDb;
    f.peakDb = points.first().magnitudeDb;
    f.peakHz = points.first().hz;
    for (const FrequencyPoint &p : points) {
        if (p.magnitudeDb > *f.peakDb) {
            f.peakDb = p.magnitudeDb;
            f.peakHz = p.hz;
        }
    }
    const double level = f.referenceDb - kBandwidthDropDb;
    for (int i = 1; i < points.size(); ++i) {
        const FrequencyPoint &a = points[i - 1];
        const FrequencyPoint &b = points[i];
        if (a.magnitudeDb >= level && b.magnitudeDb < level) {
            const double hz = crossing(a.hz, a.magnitudeDb, b.hz, b.magnitudeDb, level);
            f.bandwidthHz = hz;
            const double u = (std::log(hz) - std::log(a.hz)) / (std::log(b.hz) - std::log(a.hz));
            f.phaseAtBandwidth = a.phaseDeg + u * (b.phaseDeg - a.phaseDeg);
            break;
        }
    }
    return f;
}

} // namespace lk::tuning
