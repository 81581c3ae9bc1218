#include "SetpointWaveform.h"

#include <algorithm>
#include <cmath>

namespace lk::bus {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double SetpointWaveform::valueAt(const Settings &s, double t)
{
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
    }
    return s.offset;
}

SetpointWaveform::Settings SetpointWaveform::bounded(const Settings &settings)
{
    Settings s = settings;
    s.rateHz = std::clamp(settings.rateHz, kMinRateHz, kMaxRateHz);
    s.periodS = std::max(settings.periodS, kMinPeriodS);
    return s;
}

} // namespace lk::bus
