#include "SetpointGenerator.h"

#include <algorithm>
#include <cmath>

namespace lk::ui {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

SetpointGenerator::SetpointGenerator(QObject *parent) : QObject(parent)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SetpointGenerator::tick);
}

double SetpointGenerator::valueAt(const Settings &s, double t)
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

void SetpointGenerator::start(const Settings &settings)
{
    m_settings = settings;
    m_settings.rateHz = std::clamp(settings.rateHz, kMinRateHz, kMaxRateHz);
    m_settings.periodS = std::max(settings.periodS, kMinPeriodS);
    m_emitted = 0;
    m_clock.start();
    m_timer.start(static_cast<int>(std::lround(1000.0 / m_settings.rateHz)));
    emit started();
    tick();
}

void SetpointGenerator::stop(const QString &reason)
{
    if (!m_timer.isActive())
        return;
    m_timer.stop();
    emit stopped(reason);
}

void SetpointGenerator::tick()
{
    if (!m_timer.isActive())
        return;
    ++m_emitted;
    emit setpointDue(valueAt(m_settings, m_clock.nsecsElapsed() * 1e-9));
}

} // namespace lk::ui
