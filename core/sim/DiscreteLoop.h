#pragma once

#include <array>
#include <complex>
#include <utility>

namespace lk::sim {

/// A linear discrete-time loop x[k+1] = A x[k] + B r[k] of N states, built from its one-step
/// update (linear in x and r: A is its image of the unit states, B its image of r = 1), and
/// its transfer function to one state, C (zI - A)^-1 B, on the unit circle. What
/// SpeedLoopTransfer and PositionLoopTransfer evaluate.
template <int N> class DiscreteLoop {
public:
    using State = std::array<double, N>;
    using Complex = std::complex<double>;

    DiscreteLoop() = default;
    template <typename Step> explicit DiscreteLoop(const Step &step)
    {
        for (int j = 0; j < N; ++j) {
            State unit{};
            unit[j] = 1;
            m_a[j] = step(unit, 0.0);
        }
        m_b = step(State{}, 1.0);
    }

    /// H(z) from the reference to state `output`, z = e^{j 2 pi hz T}.
    Complex transfer(double hz, double stepSeconds, int output) const
    {
        constexpr double kPi = 3.14159265358979323846;
        const Complex z = std::polar(1.0, 2 * kPi * hz * stepSeconds);
        std::array<std::array<Complex, N>, N> m{};
        std::array<Complex, N> rhs{};
        for (int r = 0; r < N; ++r) {
            for (int c = 0; c < N; ++c)
                m[r][c] = -m_a[c][r];
            m[r][r] += z;
            rhs[r] = m_b[r];
        }
        return solve(m, rhs)[output];
    }

private:
    // Solves m x = rhs by Gaussian elimination with partial pivoting.
    static std::array<Complex, N> solve(std::array<std::array<Complex, N>, N> m,
                                        std::array<Complex, N> rhs)
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

    std::array<State, N> m_a{}; ///< columns of A
    State m_b{};
};

} // namespace lk::sim
