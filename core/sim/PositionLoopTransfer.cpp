#include "PositionLoopTransfer.h"

#include <cmath>

namespace lk::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kT = DrivePhysics::kStepSeconds;
} // namespace

PositionLoopTransfer::PositionLoopTransfer(const RotorParams &rotor, const PhysicalGains &gains,
                                           const MechanicalResonance &resonance)
    : m_speed(rotor, gains, resonance), m_gains(gains)
{
    m_loop = DiscreteLoop<kStates>([this](const State &x, double r) { return substep(x, r); });
}

PositionLoopTransfer PositionLoopTransfer::of(const DrivePhysics &physics)
{
    return PositionLoopTransfer(physics.params(), physics.physicalGains(),
                                physics.plantOptions().resonance);
}

PositionLoopTransfer PositionLoopTransfer::forSeries(protocol::Series series,
                                                     const protocol::PidGains &gains,
                                                     const DerivativeGains &kd,
                                                     const MechanicalResonance &resonance)
{
    DrivePhysics physics(RotorParams::forSeries(series), 1, 1); // no limit enters the loop
    physics.setGains(gains);
    physics.setDerivativeGains(kd);
    PlantOptions plant;
    plant.resonance = resonance;
    physics.setPlantOptions(plant);
    return of(physics);
}

PositionLoopTransfer::State PositionLoopTransfer::substep(const State &x, double r) const
{
    // DrivePhysics::outerLoops in Position mode, term for term, inside its bounds: the command
    // uses the integral before this substep's error is added.
    const double error = r - x[Angle];
    const double command = m_gains.kpPos * error + m_gains.kiPos * x[AngleIntegral] -
                           m_gains.kdPos * x[SpeedLoopTransfer::Estimate];
    SpeedLoopTransfer::State inner{};
    for (int i = 0; i < SpeedLoopTransfer::kStates; ++i)
        inner[i] = x[i];
    inner = m_speed.substep(inner, command);
    State n{};
    for (int i = 0; i < SpeedLoopTransfer::kStates; ++i)
        n[i] = inner[i];
    n[AngleIntegral] = x[AngleIntegral] + error * kT;
    n[Angle] = x[Angle] + inner[SpeedLoopTransfer::Speed] * kT; // as DrivePhysics::mechanics
    return n;
}

std::complex<double> PositionLoopTransfer::angleDiscrete(double hz) const
{
    return m_loop.transfer(hz, kT, Angle);
}

std::complex<double> PositionLoopTransfer::speedDiscrete(double hz) const
{
    return m_loop.transfer(hz, kT, SpeedLoopTransfer::Speed);
}

std::complex<double> PositionLoopTransfer::response(double hz) const
{
    const std::complex<double> jw(0, 2 * kPi * hz);
    return speedDiscrete(hz) / SpeedLoopTransfer::substepHold(hz) / jw;
}

double PositionLoopTransfer::magnitudeDb(double hz) const
{
    return 20 * std::log10(std::abs(response(hz)));
}

double PositionLoopTransfer::phaseDeg(double hz) const
{
    return std::arg(response(hz)) * 180 / kPi;
}

} // namespace lk::sim
