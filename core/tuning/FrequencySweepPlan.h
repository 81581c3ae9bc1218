#pragma once

#include "FrequencyResponse.h"
#include "StepTrace.h"

#include <bus/SetpointWaveform.h>
#include <protocol/Series.h>
#include <safety/MotionGuard.h>
#include <safety/SoftLimits.h>

#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::tuning {

/// The loop a sweep measures: its setpoint is the speed (0xA2) or the multi-turn angle (0xA3,
/// sent as 0xA4 at the speed limit).
enum class SweepLoop { Speed, Position };

/// A frequency response measurement of the speed or position loop as the user asks for it: a
/// stepped sine of the setpoint around an operating point.
struct FrequencySweepSpec {
    int id = 1;
    SweepLoop loop = SweepLoop::Speed;
    double fromHz = 1;
    double toHz = 100;
    int points = 12;       ///< log-spaced frequencies from fromHz to toHz
    double amplitude = 50; ///< the sine's peak: dps (speed) or deg (position)
    /// Speed: the speed (dps) the sine is centred on; nullopt: twice the amplitude, so that the
    /// rotor never stops (friction would then bend the response). Position: the multi-turn
    /// angle (deg) the drive was read at, which the runner sets: the sine starts where the
    /// drive is; nullopt refuses the sweep (AngleUnknown).
    std::optional<double> operatingPoint;
    /// Speed: the speed the sweep ends at; nullopt: the speed read before it. A caller that
    /// knows the speed it commanded (a search, a sweep after a sweep) sets it: each speed read
    /// differs from the command by the rotor's ripple, and sweep after sweep the drive would
    /// wander off the speed it was given.
    std::optional<double> returnSpeedDps;
    double leadInS = 0.5;   ///< held at the operating point before the first frequency
    double minPointS = 0.3; ///< each frequency lasts at least this long
    double rateHz = bus::SetpointWaveform::kMaxSweepRateHz; ///< the bus sets the pace below it

    static constexpr double kMinHz = 0.1;
    static constexpr double kMaxHz = 500;
    static constexpr int kMaxPoints = 60;
    static constexpr int kSettleCycles = 1; ///< cycles of each frequency left out of the fit
    static constexpr int kMinFitCycles = 3;
    double centre() const
    {
        return loop == SweepLoop::Position ? operatingPoint.value_or(0)
                                           : operatingPoint.value_or(2 * amplitude);
    }
    /// The samples a period the loop's response needs (FrequencyResponse explains the
    /// position loop's larger figure).
    double samplesPerPeriod() const
    {
        return loop == SweepLoop::Position ? FrequencyResponse::kPositionSamplesPerPeriod
                                           : FrequencyResponse::kSpeedSamplesPerPeriod;
    }
    /// The fastest the setpoint moves: the amplitude (speed) or 2 pi toHz x amplitude
    /// (position: dps), which the soft speed limit bounds.
    double peakSpeedDps() const;
};

/// One frequency of the sweep: when it plays and the window it is fitted over (whole cycles
/// after the settling ones), seconds from the stream's start.
struct SweepSegment {
    double hz = 0;
    double startS = 0;
    double endS = 0;
    double fitFromS = 0;
    double fitToS = 0;
};

/// The stepped sine of a sweep, its segments, and the check of its extremes against the
/// series and the soft limits (the stream checks every setpoint again on the bus thread). A
/// position sweep's extremes are checked from its centre (the angle window, one output turn)
/// and its peak speed, 2 pi f A at the top frequency, against the speed limit: the refusal
/// names it. Keeping 2 pi f A under the speed limit also keeps the drive's angle loop short of
/// its move speed, the small-signal region its response is linear in. Pure.
class FrequencySweepPlan {
public:
    static FrequencySweepPlan make(const FrequencySweepSpec &spec,
                                   std::optional<protocol::Series> series,
                                   const safety::SoftLimits &limits);
    /// What is wrong with the spec before any limit is looked at (English), or empty.
    static QString checkSpec(const FrequencySweepSpec &spec);
    /// `points` log-spaced frequencies from `from` to `to` (one: `from`).
    static QVector<double> frequencies(double from, double to, int points);

    bool allowed() const { return !m_segments.isEmpty(); }
    const FrequencySweepSpec &spec() const { return m_spec; }
    const bus::SetpointWaveform::Settings &settings() const { return m_settings; }
    const QVector<SweepSegment> &segments() const { return m_segments; }
    double endS() const { return m_endS; }
    const QString &specError() const { return m_specError; }
    /// The limit that refused the sweep (kind None when allowed or the spec was bad).
    const safety::Verdict &verdict() const { return m_verdict; }
    /// The speed (or, for a position sweep's extremes, the angle) the refused extreme asked for.
    double refusedDps() const { return m_refusedDps; }

private:
    /// The extremes' check: false (and the refusal or the spec error set) when refused.
    bool checkExtremes(std::optional<protocol::Series> series, const safety::SoftLimits &limits);

    FrequencySweepSpec m_spec;
    bus::SetpointWaveform::Settings m_settings;
    QVector<SweepSegment> m_segments;
    QString m_specError;
    safety::Verdict m_verdict;
    double m_refusedDps = 0;
    double m_endS = 0;
};

} // namespace lk::tuning
