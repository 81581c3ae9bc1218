#include "SpeedLoopTransfer.h"

#include <cmath>
#include <utility>

namespace lk::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kT = DrivePhysics::kStepSeconds;
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

using Complex = std::complex<double>;

// Solves m x = rhs in place by Gaussian elimination with partial pivoting.
template <int N>
std::array<Complex, N> solve(std::array<std::array<Complex, N>, N> m, std::array<Complex, N> rhs)
{
    for (int c = 0; c < N; ++c) {
        int pivot = c;
        for (int r = c + 1; r < N; ++r)
            if (std::abs(m[r][c]) > std::abs(m[pivot][c]))
                pivot = r;
        std::swap(m[c], m[pivot]);
        std::swap(rhs[c], rhs[pivot]);
        for (int r = c + 1; r < N; ++r) {
            const Complex f = m[r][c] / m[c][c];
            for (int k = c; k < N; ++k)
                m[r][k] -= f * m[c][k];
            rhs[r] -= f * rhs[c];
        }
    }
    std::array<Complex, N> x{};
    for (int r = N - 1; r >= 0; --r) {
        Complex s = rhs[r];
        for (int k = r + 1; k < N; ++k)
            s -= m[r][k] * x[k];
        x[r] = s / m[r][r];
    }
    return x;
}
} // namespace

SpeedLoopTransfer::SpeedLoopTransfer(const RotorParams &rotor, const PhysicalGains &gains,
                                     const MechanicalResonance &resonance)
    : m_rotor(rotor), m_gains(gains), m_mechanics(rotor.inertia, rotor.viscousFriction, resonance)
{
    // The update is linear: its matrix is its image of the unit states, B its image of r = 1.
    for (int j = 0; j < kStates; ++j) {
        State unit{};
        unit[j] = 1;
        m_a[j] = step(unit, 0);
    }
    m_b = step(State{}, 1);
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
    physics.setPlantOptions(PlantOptions{resonance, {}});
    return of(physics);
}

SpeedLoopTransfer::State SpeedLoopTransfer::step(const State &x, double r) const
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
    // H(z) = C (zI - A)^-1 B with C picking the speed.
    const Complex z = std::polar(1.0, 2 * kPi * hz * kT);
    std::array<std::array<Complex, kStates>, kStates> m{};
    std::array<Complex, kStates> rhs{};
    for (int r = 0; r < kStates; ++r) {
        for (int c = 0; c < kStates; ++c)
            m[r][c] = -m_a[c][r];
        m[r][r] += z;
        rhs[r] = m_b[r];
    }
    return solve<kStates>(m, rhs)[Speed];
}

std::complex<double> SpeedLoopTransfer::response(double hz) const
{
    // A reference held over each substep has, at hz, the sampled sine's component times
    // sinc(wT/2) e^{-jwT/2}: the measured ratio divides that out of the samples' ratio.
    const double half = kPi * hz * kT;
    const Complex hold = half > 0 ? std::polar(std::sin(half) / half, -half) : Complex(1, 0);
    return discrete(hz) / hold;
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
