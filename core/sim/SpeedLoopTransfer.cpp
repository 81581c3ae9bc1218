#include "SpeedLoopTransfer.h"

#include <cmath>

namespace lk::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kT = DrivePhysics::kStepSeconds;

} // namespace

SpeedLoopTransfer::SpeedLoopTransfer(const RotorParams &rotor, const PhysicalGains &gains,
                                     const MechanicalResonance &resonance)
    : m_rotor(rotor), m_gains(gains), m_mechanics(rotor.inertia, rotor.viscousFriction, resonance)
{
    m_loop = DiscreteLoop<kStates>([this](const State &x, double r) { return substep(x, r); });
}

SpeedLoopTransfer SpeedLoopTransfer::of(const DrivePhysics &physics)
{
    return SpeedLoopTransfer(physics.params(), physics.physicalGains(),
                             physics.plantOptions().resonance);
}

SpeedLoopTransfer SpeedLoopTransfer::forSeries(protocol::Series series,
                                               const protocol::PidGains &gains,
                                               const DerivativeGains &kd,
                                               const MechanicalResonance &resonance)
{
    // The limits do not enter the linear loop.
    DrivePhysics physics(RotorParams::forSeries(series), 1, 1);
    physics.setGains(gains);
    physics.setDerivativeGains(kd);
    PlantOptions plant;
    plant.resonance = resonance;
    physics.setPlantOptions(plant);
    return of(physics);
}

SpeedLoopTransfer::State SpeedLoopTransfer::substep(const State &x, double r) const
{
    // DrivePhysics::step in Speed mode, term for term, without its limits and friction sign.
    const PhysicalGains &g = m_gains;
    State n{};
    const double error = r - x[Estimate];
    const double iRef = g.kpSpeed * error + g.kiSpeed * (x[SpeedIntegral] + error * kT) -
                        g.kdSpeed * x[EstimateAccel];
    n[SpeedIntegral] = x[SpeedIntegral] + error * kT;
    const double a = (m_rotor.inductance + g.kdIq) / kT;
    const double denom = a + m_rotor.resistance + g.kpIq + g.kiIq * kT;
    const double i =
        (a * x[Current] + g.kpIq * iRef + g.kiIq * (x[CurrentIntegral] + kT * iRef)) / denom;
    n[Current] = i;
    n[CurrentIntegral] = x[CurrentIntegral] + kT * (iRef - i);
    const TwoMassMechanics::State m =
        m_mechanics.step({x[Speed], x[LoadSpeed], x[Twist]}, m_rotor.torqueConstant * i, kT);
    n[Speed] = m.motor;
    n[LoadSpeed] = m.load;
    n[Twist] = m.twist;
    const double gain = kT / (DrivePhysics::kSpeedFilterSeconds + kT);
    n[Estimate] = x[Estimate] + (n[Speed] - x[Estimate]) * gain;
    n[EstimateAccel] = (n[Estimate] - x[Estimate]) / kT;
    return n;
}

std::complex<double> SpeedLoopTransfer::discrete(double hz) const
{
    return m_loop.transfer(hz, kT, Speed);
}

std::complex<double> SpeedLoopTransfer::substepHold(double hz)
{
    // A reference held over each substep has, at hz, the sampled sine's component times
    // sinc(wT/2) e^{-jwT/2}: the measured ratio divides that out of the samples' ratio.
    const double half = kPi * hz * kT;
    return half > 0 ? std::polar(std::sin(half) / half, -half) : std::complex<double>(1, 0);
}

std::complex<double> SpeedLoopTransfer::response(double hz) const
{
    return discrete(hz) / substepHold(hz);
}

double SpeedLoopTransfer::magnitudeDb(double hz) const
{
    return 20 * std::log10(std::abs(response(hz)));
}

double SpeedLoopTransfer::phaseDeg(double hz) const
{
    return std::arg(response(hz)) * 180 / kPi;
}

} // namespace lk::sim
