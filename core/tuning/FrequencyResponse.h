#pragma once

#include "SineFit.h"

#include <QtCore/QMetaType>
#include <QtCore/QVector>

#include <optional>

namespace lk::tuning {

/// One frequency of a measured response: the output's sine over the input's.
struct FrequencyPoint {
    double hz = 0;
    double magnitudeDb = 0; ///< 20 log10(|Y| / |U|)
    double phaseDeg = 0;    ///< arg(Y / U), unwrapped along the response (continuous)
    double quality = 0;     ///< the output fit's quality (SineComponent::quality), 0..1
    int samples = 0;        ///< output samples in the fit window
    double inputAmplitude = 0;
    double outputAmplitude = 0;
};

/// Why a planned frequency has no point.
enum class DroppedReason {
    AboveResolution, ///< fewer than samplesPerPeriod samples per period at the achieved rate
    /// The window held fewer than SineFit::kMinSamples samples, or fewer than samplesPerPeriod
    /// a period (the host or the bus stalled during it)
    TooFewSamples,
    NoInput, ///< the setpoints did not cover the window (a stop, lost replies)
};

struct DroppedFrequency {
    double hz = 0;
    DroppedReason reason = DroppedReason::AboveResolution;
};

/// Figures of a Bode magnitude: what a technician reads off the plot. Empty when the response
/// has too few points; bandwidth empty when the magnitude never fell 3 dB below its
/// low-frequency level.
struct BodeFigures {
    std::optional<double> bandwidthHz;      ///< first -3 dB crossing (interpolated in log f)
    std::optional<double> phaseAtBandwidth; ///< degrees, interpolated likewise
    std::optional<double> peakDb;           ///< largest magnitude, dB
    std::optional<double> peakHz;
    double referenceDb = 0; ///< the lowest frequency's magnitude: the -3 dB is against it
};

/// A measured frequency response: points, the frequencies dropped and why, the sample rate
/// the bus achieved.
struct FrequencyResponse {
    QVector<FrequencyPoint> points;
    QVector<DroppedFrequency> dropped;
    double sampleRateHz = 0;
    /// The samples a period this response needed (kSpeedSamplesPerPeriod or
    /// kPositionSamplesPerPeriod): frequencies above resolvedHz() are not resolved, not shown.
    double samplesPerPeriod = kSpeedSamplesPerPeriod;

    /// A stepped sine of the speed loop needs this many samples per period at least.
    static constexpr double kSpeedSamplesPerPeriod = 4;
    /// The position loop is measured through the speed its replies carry, and each setpoint
    /// step makes the speed jump: a reply samples that jump at a moment the bus's timing
    /// decides. With few samples a period the jumps dominate the fit and the magnitude reads
    /// high (lksim's MF: 0.1 dB at 12 samples a period on a loaded host, 7 to 9 dB at 8.6)
    /// while the phase holds. Sixteen keeps the jumps small beside the sine.
    static constexpr double kPositionSamplesPerPeriod = 16;
    /// The highest frequency the rate reached resolves.
    double resolvedHz() const { return sampleRateHz / samplesPerPeriod; }

    /// One point: the held input's component (SineFit::ofHeld) and the sampled output's
    /// (SineFit::fitSampled) over [from, to]; nullopt (and `why`) when either has none, or
    /// when the window holds fewer than `minSamplesPerPeriod` output samples a period (a host
    /// or bus that stalled during it: the point would be as wrong as one above the
    /// resolution, though the whole sweep's rate resolves it).
    static std::optional<FrequencyPoint>
    measure(const QVector<double> &inputT, const QVector<double> &inputV,
            const QVector<double> &outputT, const QVector<double> &outputY, double hz, double from,
            double to, DroppedReason *why = nullptr, double minSamplesPerPeriod = 0);
    /// A point of the speed's response (dps per unit of setpoint) as the response of its
    /// integral, the angle (deg per unit): magnitude over w, phase less 90 degrees; the
    /// amplitude becomes the angle's.
    static FrequencyPoint integrated(const FrequencyPoint &speed);
    /// Makes the phases continuous from the lowest frequency on (points in ascending order).
    void unwrapPhases();
    BodeFigures figures() const;
};

} // namespace lk::tuning

Q_DECLARE_METATYPE(lk::tuning::FrequencyResponse)
