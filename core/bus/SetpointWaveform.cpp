#include "SetpointWaveform.h"

#include <algorithm>
#include <cmath>

namespace lk::bus {

namespace {
constexpr double kPi = 3.14159265358979323846;

double steppedSineAt(const SetpointWaveform::Settings &s, double t)
{
    double start = std::max(s.periodS, 0.0);
    if (t < start)
        return s.offset;
    for (const SetpointWaveform::SineStep &step : s.steps) {
        if (!(step.hz > 0) || step.cycles < 1)
            continue;
        const double end = start + step.durationS();
        if (t < end)
            return s.offset + s.amplitude * std::sin(2 * kPi * step.hz * (t - start));
        start = end;
    }
    return s.offset;
}
} // namespace

double SetpointWaveform::valueAt(const Settings &s, double t)
{
    if (s.waveform == Waveform::SteppedSine)
        return steppedSineAt(s, t);
    const double period = std::max(s.periodS, kMinPeriodS);
    const double phase = std::fmod(std::max(t, 0.0), period) / period; // 0..1
    switch (s.waveform) {
    case Waveform::Step:
        return t < period / 2 ? s.offset : s.offset + s.amplitude;
    case Waveform::Square:
        return phase < 0.5 ? s.offset + s.amplitude : s.offset - s.amplitude;
    case Waveform::Sine:
        return s.offset + s.amplitude * std::sin(2 * kPi * phase);
    case Waveform::Ramp: {
        // Triangle starting at the offset: up to +A at 1/4, down to -A at 3/4, back at 1.
        const double tri = phase < 0.25 ? phase * 4 : phase < 0.75 ? 2 - phase * 4 : phase * 4 - 4;
        return s.offset + s.amplitude * tri;
    }
    case Waveform::SteppedSine:
        break;
    }
    return s.offset;
}

double SetpointWaveform::steppedSineEndS(const Settings &settings)
{
    double end = std::max(settings.periodS, 0.0);
    for (const SineStep &step : settings.steps)
        if (step.hz > 0 && step.cycles >= 1)
            end += step.durationS();
    return end;
}

SetpointWaveform::Settings SetpointWaveform::bounded(const Settings &settings)
{
    Settings s = settings;
    const double maxRate = s.waveform == Waveform::SteppedSine ? kMaxSweepRateHz : kMaxRateHz;
    s.rateHz = std::clamp(settings.rateHz, kMinRateHz, maxRate);
    s.periodS = std::max(settings.periodS, kMinPeriodS);
    return s;
}

} // namespace lk::bus
