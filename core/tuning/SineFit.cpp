#include "SineFit.h"

#include <array>
#include <cmath>
#include <utility>

namespace lk::tuning {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kTerms = 4; // sin, cos, 1, t

using Row = std::array<double, kTerms + 1>; // the normal equations, augmented

// Solves the normal equations in place (partial pivoting); false when singular.
bool solve(std::array<Row, kTerms> &m, std::array<double, kTerms> &x)
{
    for (int c = 0; c < kTerms; ++c) {
        int pivot = c;
        for (int r = c + 1; r < kTerms; ++r)
            if (std::abs(m[r][c]) > std::abs(m[pivot][c]))
                pivot = r;
        if (std::abs(m[pivot][c]) < 1e-300)
            return false;
        std::swap(m[c], m[pivot]);
        for (int r = 0; r < kTerms; ++r) {
            if (r == c)
                continue;
            const double f = m[r][c] / m[c][c];
            for (int k = c; k <= kTerms; ++k)
                m[r][k] -= f * m[c][k];
        }
    }
    for (int c = 0; c < kTerms; ++c)
        x[c] = m[c][kTerms] / m[c][c];
    return true;
}

SineComponent fromCoefficients(double a, double b)
{
    SineComponent s;
    s.amplitude = std::hypot(a, b);
    s.phaseRad = std::atan2(b, a); // a sin + b cos = A sin(wt + phase)
    return s;
}

} // namespace

SineComponent SineFit::fitSampled(const QVector<double> &t, const QVector<double> &y, double hz,
                                  double from, double to)
{
    const double w = 2 * kPi * hz;
    const double mid = (from + to) / 2; // the drift term about the middle: well conditioned
    std::array<Row, kTerms> m{};
    int n = 0;
    for (int i = 0; i < t.size() && i < y.size(); ++i) {
        if (t[i] < from || t[i] > to)
            continue;
        const std::array<double, kTerms> f{std::sin(w * t[i]), std::cos(w * t[i]), 1.0, t[i] - mid};
        for (int r = 0; r < kTerms; ++r) {
            for (int c = 0; c < kTerms; ++c)
                m[r][c] += f[r] * f[c];
            m[r][kTerms] += f[r] * y[i];
        }
        ++n;
    }
    SineComponent none;
    none.samples = n;
    if (n < kMinSamples || !(hz > 0) || (to - from) * hz < 1)
        return none;
    std::array<double, kTerms> x{};
    if (!solve(m, x))
        return none;
    SineComponent s = fromCoefficients(x[0], x[1]);
    s.offset = x[2];
    s.samples = n;
    // Variance explained by the sine, with offset and drift taken out of both.
    double residual = 0;
    double detrended = 0;
    for (int i = 0; i < t.size() && i < y.size(); ++i) {
        if (t[i] < from || t[i] > to)
            continue;
        const double trend = x[2] + x[3] * (t[i] - mid);
        const double sine = x[0] * std::sin(w * t[i]) + x[1] * std::cos(w * t[i]);
        residual += std::pow(y[i] - trend - sine, 2);
        detrended += std::pow(y[i] - trend, 2);
    }
    s.quality = detrended > 0 ? std::max(0.0, 1.0 - residual / detrended) : 0.0;
    s.ok = true;
    return s;
}

SineComponent SineFit::ofHeld(const QVector<double> &t, const QVector<double> &v, double hz,
                              double from, double to)
{
    const double w = 2 * kPi * hz;
    SineComponent none;
    if (!(hz > 0) || !(to > from) || (to - from) * hz < 1)
        return none;
    // 2/T x integral of v sin(wt) and v cos(wt) over [from, to], hold by hold.
    double a = 0;
    double b = 0;
    double sum = 0;
    int n = 0;
    for (int k = 0; k < t.size() && k < v.size(); ++k) {
        const double start = std::max(t[k], from);
        const double end = std::min(k + 1 < t.size() ? t[k + 1] : to, to);
        if (end <= start)
            continue;
        a += v[k] * (std::cos(w * start) - std::cos(w * end)) / w;
        b += v[k] * (std::sin(w * end) - std::sin(w * start)) / w;
        sum += v[k] * (end - start);
        ++n;
    }
    // Before the first hold nothing is known: a window that starts there is no window.
    if (n == 0 || t.first() > from)
        return none;
    const double span = to - from;
    SineComponent s = fromCoefficients(2 * a / span, 2 * b / span);
    s.offset = sum / span;
    s.samples = n;
    s.quality = 1;
    s.ok = true;
    return s;
}

} // namespace lk::tuning
