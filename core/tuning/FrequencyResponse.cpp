#include "FrequencyResponse.h"

#include <cmath>

namespace lk::tuning {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kBandwidthDropDb = 3;

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
                                                         double from, double to, DroppedReason *why)
{
    const SineComponent u = SineFit::ofHeld(inputT, inputV, hz, from, to);
    if (!u.ok || u.amplitude <= 0) {
        if (why)
            *why = DroppedReason::NoInput;
        return std::nullopt;
    }
    const SineComponent y = SineFit::fitSampled(outputT, outputY, hz, from, to);
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
    p.samples = y.samples;
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
