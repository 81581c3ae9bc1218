#pragma once

#include <QtCore/QVector>

namespace lk::bus {

/// Setpoints for tuning as a pure function of time: step, square, sine or ramp (triangle)
/// around an offset, at a bounded rate, or a stepped sine (a frequency response's sweep).
/// SetpointStream sends them on the bus thread; the setpoint panel edits the settings.
class SetpointWaveform {
public:
    /// SteppedSine: the offset for periodS (the lead-in at the operating point), then each
    /// of `steps` in turn, a whole number of cycles of offset + amplitude x sin, each starting
    /// at phase 0 (so the setpoint never jumps), then the offset again.
    enum class Waveform { Step, Square, Sine, Ramp, SteppedSine };
    enum class Target { Speed, Position, Torque };
    static constexpr double kMinRateHz = 1;
    static constexpr double kMaxRateHz = 50; ///< leaves room on the bus for polling
    /// A stepped sine's setpoint replies are its samples: it may take the whole bus (the
    /// stream skips a tick while a setpoint is in flight, so the bus sets the pace).
    static constexpr double kMaxSweepRateHz = 1000;
    static constexpr double kMinPeriodS = 0.1;

    /// One frequency of a stepped sine.
    struct SineStep {
        double hz = 1;
        int cycles = 1;
        double durationS() const { return cycles / hz; }
    };

    struct Settings {
        Waveform waveform = Waveform::Square;
        Target target = Target::Speed;
        double amplitude = 90; ///< dps, deg or A
        double offset = 0;
        double periodS = 2;
        double rateHz = 20;
        QVector<SineStep> steps; ///< SteppedSine only
    };

    /// The value at `t` seconds after the start. Step: offset for the first half period, then
    /// offset + amplitude. Square/sine/ramp: offset +- amplitude, one cycle per period (the
    /// ramp is a triangle, so the setpoint never jumps).
    static double valueAt(const Settings &settings, double t);
    /// When a stepped sine's last step ends (its lead-in included), seconds from the start.
    static double steppedSineEndS(const Settings &settings);
    /// `settings` with rate and period clamped to their bounds (a stepped sine's rate to
    /// kMaxSweepRateHz).
    static Settings bounded(const Settings &settings);
};

} // namespace lk::bus
