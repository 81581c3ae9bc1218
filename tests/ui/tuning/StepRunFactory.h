#pragma once

// Step runs made in the test: a first-order response 0 -> `to` with time constant `tau`,
// sampled every 5 ms, the effort `effort` on every sample.

#include <tuning/StepRun.h>

#include <cmath>

namespace lk::tuningtest {

struct RunShape {
    tuning::StepLoop loop = tuning::StepLoop::Speed;
    double tau = 0.05;   ///< s
    double to = 100;     ///< dps or degrees
    double effort = 2.0; ///< A, or power when `power`
    bool power = false;  ///< the drive reports power (MS)
    QString series = QStringLiteral("MF");
    QString model = QStringLiteral("MF4015");
    int driveId = 1;
};

inline tuning::StepRun makeRun(const RunShape &s)
{
    tuning::StepRun r;
    r.driveId = s.driveId;
    r.series = s.series;
    r.model = s.model;
    r.spec.loop = s.loop;
    r.spec.to = s.to;
    r.trace.loop = s.loop;
    r.trace.effortIsPower = s.power;
    for (int i = 0; i <= 200; ++i) {
        const double t = i * 0.005;
        r.trace.append(t, t < 0.1 ? 0 : s.to * (1 - std::exp(-(t - 0.1) / s.tau)), s.effort);
    }
    r.trace.edges = {tuning::StepEdge{0.1, 0, s.to}};
    return r;
}

inline RunShape msPower(double effort, double tau = 0.05)
{
    RunShape s;
    s.power = true;
    s.effort = effort;
    s.tau = tau;
    s.series = QStringLiteral("MS");
    s.model = QStringLiteral("MS4015");
    s.driveId = 3;
    return s;
}

} // namespace lk::tuningtest
