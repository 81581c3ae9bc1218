#pragma once

#include <QtCore/QVector>

#include <cmath>
#include <limits>

namespace lk::tuning {

/// Which loop a step test exercises.
enum class StepLoop {
    Speed,    ///< speed commands (0xA2); the response is the speed in dps
    Position, ///< position commands (0xA4); the response is the multi-turn angle in rotor degrees
};

/// One setpoint change of a step test: at `time` the target went from `from` to `to`.
struct StepEdge {
    double time = 0; ///< s, same clock as StepTrace::time (when the drive acknowledged it)
    double from = 0;
    double to = 0;
    double amplitude() const { return to - from; }
};

/// What one step test recorded from one drive, in physical units.
///
/// Times are the bus thread's host timestamps (TelemetrySample::time), ascending. `effort` is
/// the torque current in A (iq), or the relative power -1000..1000 on MS drives
/// (`effortIsPower`); it has one entry per sample and is NaN where that sample did not carry
/// it (a 0x92 angle reply carries no current): unknown is never 0.
struct StepTrace {
    StepLoop loop = StepLoop::Speed;
    bool effortIsPower = false;
    QVector<double> time;
    QVector<double> value;
    QVector<double> effort;
    QVector<StepEdge> edges; ///< in time order; the first is the step under test

    static double missing() { return std::numeric_limits<double>::quiet_NaN(); }
    static bool isMissing(double v) { return std::isnan(v); }
    int size() const { return int(time.size()); }
    /// Appends one sample; pass missing() for an effort the sample did not carry.
    void append(double t, double v, double e)
    {
        time.append(t);
        value.append(v);
        effort.append(e);
    }
};

} // namespace lk::tuning
