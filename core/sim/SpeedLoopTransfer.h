#pragma once

#include "DiscreteLoop.h"
#include "DrivePhysics.h"

#include <array>
#include <complex>

namespace lk::sim {

/// The simulator's speed loop as a known transfer function: DrivePhysics's substep update
/// (speed PID on the filtered speed estimate, the current PI with its backward-Euler
/// winding, the rotor with its optional resonance (TwoMassMechanics), the estimate's
/// low-pass) written as a linear discrete-time system
/// x[k+1] = A x[k] + B r[k], from the speed reference to the rotor's speed, and evaluated on
/// the unit circle. Exact for DrivePhysics in its linear range: no acceleration limit, the
/// current and voltage below their limits, the speed away from zero (Coulomb friction is then
/// a constant torque, which shifts the operating point and not the response). Sensor
/// quantisation (PlantOptions::sensor) is not in it: its linear part is the speed itself, the
/// rest is noise a sine fit rejects. A measurement
/// against it checks the whole chain: setpoint stream, wire, sampling and the sine fits.
class SpeedLoopTransfer {
public:
    /// current, its integral, speed, estimate, accel., integral, the load's speed, the twist
    static constexpr int kStates = 8;

    SpeedLoopTransfer(const RotorParams &rotor, const PhysicalGains &gains,
                      const MechanicalResonance &resonance = {});
    /// The transfer function of `physics` as its gains stand now.
    static SpeedLoopTransfer of(const DrivePhysics &physics);
    /// The transfer function of a simulated drive of `series` (RotorParams::forSeries) with
    /// these gains, as lksim's drives of that series run them.
    static SpeedLoopTransfer forSeries(protocol::Series series, const protocol::PidGains &gains,
                                       const DerivativeGains &kd = {},
                                       const MechanicalResonance &resonance = {});

    /// H(e^{jwT}): reference samples to speed samples, T = DrivePhysics::kStepSeconds.
    std::complex<double> discrete(double hz) const;
    /// What a stepped sine measures with SineFit: the speed's sine over the sine component
    /// of the held reference, i.e. discrete() over the substep hold (sinc and half-substep
    /// lag), the reference being held between substeps.
    std::complex<double> response(double hz) const;
    double magnitudeDb(double hz) const;
    double phaseDeg(double hz) const; ///< -180..180

    using State = std::array<double, kStates>;
    /// One substep of the linear loop from state `x` with speed reference `r` (rad/s): what
    /// PositionLoopTransfer runs under its angle loop.
    State substep(const State &x, double r) const;
    /// The substep hold of a reference at hz (sinc(wT/2) e^{-jwT/2}): a stepped sine measures
    /// discrete() over it.
    static std::complex<double> substepHold(double hz);
    /// The states' indices.
    enum Index {
        Current,
        CurrentIntegral,
        Speed,
        Estimate,
        EstimateAccel,
        SpeedIntegral,
        LoadSpeed,
        Twist
    };

private:
    RotorParams m_rotor;
    PhysicalGains m_gains;
    TwoMassMechanics m_mechanics;
    DiscreteLoop<kStates> m_loop;
};

} // namespace lk::sim
