#pragma once

#include "StepMetrics.h"
#include "StepTrace.h"

#include <protocol/Series.h>

#include <QtCore/QDateTime>
#include <QtCore/QJsonObject>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>

namespace lk::tuning {

/// What a kept step test asked for (the fields of the runner's StepTestSpec that describe the
/// test, not how it was carried out).
struct StepRunSpec {
    StepLoop loop = StepLoop::Speed;
    double from = 0; ///< dps (speed) or multi-turn rotor deg (position)
    double to = 0;
    double durationS = 1; ///< each step (each half-period of a square)
    int periods = 1;      ///< 1: one step; N > 1: a square of N periods
};

/// One step test kept in the session: what was tested, on which drive, with which gains, and
/// the trace it recorded. The metrics are not part of it: metrics() computes them from the
/// trace, so a loaded run can never carry numbers its trace does not give.
struct StepRun {
    int number = 0;     ///< sequence number in the session (1, 2, ...), shown as "Run 3"
    QString label;      ///< the user's name for it; may be empty
    QDateTime ranAt;    ///< when the first edge was sent, UTC
    int driveId = 0;    ///< 1..32
    QString series;     ///< "MS", "MF", "MG" or "MH"; empty if unknown
    QString model;      ///< the drive's motor name (read_model), e.g. "MF4015"; empty if unknown
    QString generation; ///< "v2.3" or "v2.35" (protocol::generationName()); empty if unknown
    StepRunSpec spec;
    /// The gains in force during the test, under lkctl's field names: angle_kp angle_ki
    /// speed_kp speed_ki iq_kp iq_ki (integers), plus angle_kd speed_kd iq_kd on V2.35. A gain
    /// that was not read is absent, never 0.
    QJsonObject gains;
    /// Acceleration and ramps in force: accel_dps2 (V2.3); current_ramp, speed_ramp_dps2
    /// (V2.35). Absent when not read.
    QJsonObject ramps;
    /// |effort| at the drive's current (power) limit, for the saturation metric; nullopt when
    /// unknown (saturation is then MetricGap::NoLimit).
    std::optional<double> effortLimit;
    StepTrace trace;

    /// The options the metrics of this run are computed with (defaults plus effortLimit).
    StepMetricOptions metricOptions() const;
    /// The metrics of every edge of the trace, computed now.
    QVector<EdgeMetrics> metrics() const;
    /// The metrics of the step under test (the trace's first edge); TooFewSamples everywhere
    /// when the trace has no edge.
    EdgeMetrics stepMetrics() const;
};

/// What saturation is measured against: the closed loops' current limit of the series (A), or
/// 1000 (relative power) on MS, whose replies carry power. nullopt for an unknown series.
std::optional<double> seriesEffortLimit(std::optional<protocol::Series> series);

/// The gain keys of lkctl (CLI.md), in display order: angle, speed, current loop; Kp, Ki, Kd.
QStringList stepRunGainKeys();
/// The acceleration and ramp keys of lkctl: accel_dps2, current_ramp, speed_ramp_dps2.
QStringList stepRunRampKeys();
/// "speed" or "position": the loop as lkctl step names it.
QString stepLoopWord(StepLoop loop);
/// The loop named by stepLoopWord(); nullopt for any other text.
std::optional<StepLoop> stepLoopFromWord(const QString &word);

} // namespace lk::tuning
