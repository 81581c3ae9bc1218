#pragma once

namespace lk::bus {

/// Setpoints for tuning as a pure function of time: step, square, sine or ramp (triangle)
/// around an offset, at a bounded rate. SetpointStream sends them on the bus thread; the
/// setpoint panel edits the settings.
class SetpointWaveform {
public:
    enum class Waveform { Step, Square, Sine, Ramp };
    enum class Target { Speed, Position, Torque };
    static constexpr double kMinRateHz = 1;
    static constexpr double kMaxRateHz = 50; ///< leaves room on the bus for polling
    static constexpr double kMinPeriodS = 0.1;

    struct Settings {
        Waveform waveform = Waveform::Square;
        Target target = Target::Speed;
        double amplitude = 90; ///< dps, deg or A
        double offset = 0;
        double periodS = 2;
        double rateHz = 20;
    };

    /// The value at `t` seconds after the start. Step: offset for the first half period, then
    /// offset + amplitude. Square/sine/ramp: offset +- amplitude, one cycle per period (the
    /// ramp is a triangle, so the setpoint never jumps).
    static double valueAt(const Settings &settings, double t);
    /// `settings` with rate and period clamped to their bounds.
    static Settings bounded(const Settings &settings);
};

} // namespace lk::bus
