#pragma once

#include "SpeedLoopTransfer.h"

namespace lk::sim {

/// The simulator's position loop as a known transfer function: DrivePhysics's angle PI (with
/// its Kd on the speed estimate) feeding the speed loop of SpeedLoopTransfer, substep for
/// substep, from the angle target to the rotor's angle and speed.
///
/// Exact for DrivePhysics in the small-signal region of a position sweep, where the angle
/// loop is linear: no acceleration limit (the sweep lifts it), the speed command below the
/// move's max speed and below the stopping bound sqrt(2 a |error|), i.e. the error under
/// 2 a / Kp^2 (a: half the current-limited acceleration), the current and voltage below their
/// limits. Coulomb friction is not in it: the rotor of a sine around an angle reverses twice a
/// cycle, and friction then acts as a torque switching with the speed's sign, which the sine
/// fit sees as a small error where the response is low (low amplitudes, high frequencies).
class PositionLoopTransfer {
public:
    /// The speed loop's states, then the angle and its integral.
    static constexpr int kStates = SpeedLoopTransfer::kStates + 2;
    enum Index { Angle = SpeedLoopTransfer::kStates, AngleIntegral };

    PositionLoopTransfer(const RotorParams &rotor, const PhysicalGains &gains,
                         const MechanicalResonance &resonance = {});
    /// The transfer function of `physics` as its gains stand now.
    static PositionLoopTransfer of(const DrivePhysics &physics);
    /// The transfer function of a simulated drive of `series` with these gains.
    static PositionLoopTransfer forSeries(protocol::Series series, const protocol::PidGains &gains,
                                          const DerivativeGains &kd = {},
                                          const MechanicalResonance &resonance = {});

    /// Angle over angle target, samples to samples (T = DrivePhysics::kStepSeconds).
    std::complex<double> angleDiscrete(double hz) const;
    /// Speed (rad/s) over angle target (rad), samples to samples.
    std::complex<double> speedDiscrete(double hz) const;
    /// What a position sweep measures: the speed the drive replies over jw times the held
    /// angle setpoint's sine (deg per deg). The drives' replies carry the speed, not the
    /// multi-turn angle; for a sine the angle is the speed over jw. It differs from
    /// angleDiscrete() over the hold by the simulator's own integration (the angle moves by
    /// the substep's end speed): half a substep of phase, 1.8 degrees at 50 Hz.
    std::complex<double> response(double hz) const;
    double magnitudeDb(double hz) const;
    double phaseDeg(double hz) const; ///< -180..180

private:
    using State = std::array<double, kStates>;
    State substep(const State &x, double r) const;

    SpeedLoopTransfer m_speed;
    PhysicalGains m_gains;
    DiscreteLoop<kStates> m_loop;
};

} // namespace lk::sim
