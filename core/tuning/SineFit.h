#pragma once

#include <QtCore/QVector>

namespace lk::tuning {

/// One sinusoid at a known frequency: value = amplitude x sin(2 pi f t + phase) (+ whatever
/// else the fit took out: offset and drift).
struct SineComponent {
    double amplitude = 0; ///< >= 0, units of the samples
    double phaseRad = 0;  ///< -pi..pi, against sin(2 pi f t) with t the samples' own clock
    double offset = 0;    ///< the mean level the fit took out
    /// Share of the signal's variance (offset and drift taken out) that the sine explains,
    /// 0..1: near 1 for a clean response, low where noise, quantisation or a nonlinearity
    /// (friction, a limit) dominate. The coherence figure of a stepped-sine point.
    double quality = 0;
    int samples = 0;
    bool ok = false; ///< false: too few samples, or the window is shorter than one period
};

/// Least-squares sine fits on samples at their real (uneven) times, and the exact sine
/// component of a held (zero-order-hold) signal: the two halves of a stepped-sine point.
/// Pure.
class SineFit {
public:
    /// Fewer samples than this in a window give no fit.
    static constexpr int kMinSamples = 8;

    /// Fits y = a sin(wt) + b cos(wt) + c + d t on the samples with from <= t <= to (the
    /// drift term d soaks up a slow wander of the operating point). `t` ascending, seconds.
    static SineComponent fitSampled(const QVector<double> &t, const QVector<double> &y, double hz,
                                    double from, double to);
    /// The component at `hz` of a signal that holds value v[k] from t[k] until t[k + 1] (the
    /// setpoints as the drive got them), over [from, to]: its Fourier coefficient computed in
    /// closed form on each hold, so that the hold's own lag (half a setpoint interval) is in
    /// it. `to - from` should be a whole number of periods. quality is 1 (nothing is fitted).
    static SineComponent ofHeld(const QVector<double> &t, const QVector<double> &v, double hz,
                                double from, double to);
};

} // namespace lk::tuning
