// Step-response metrics on synthetic traces with known answers: first- and second-order
// responses, negative steps, noise, traces that never settle, missing effort, saturation,
// square waves and position-sized values.

#include <tuning/StepMetrics.h>

#include <QtCore/QRandomGenerator>
#include <QtTest/QtTest>

#include <cmath>
#include <functional>

using namespace lk::tuning;

namespace {

using Signal = std::function<double(double)>;

/// Samples `value(t)` (and `effort(t)`) every `dt` from 0 to `end`; times are i x dt so the
/// sampling grid does not drift.
StepTrace sampled(double dt, double end, const Signal &value, const Signal &effort = {})
{
    StepTrace trace;
    const int n = int(std::lround(end / dt)) + 1;
    for (int i = 0; i < n; ++i) {
        const double t = i * dt;
        trace.append(t, value(t), effort ? effort(t) : StepTrace::missing());
    }
    return trace;
}

/// First-order response to a step from `from` to `to` at `t0` with time constant `tau`,
/// settling at `from + reach x (to - from)`.
Signal firstOrder(double t0, double from, double to, double tau, double reach = 1.0)
{
    return [=](double t) {
        if (t < t0)
            return from;
        return from + reach * (to - from) * (1 - std::exp(-(t - t0) / tau));
    };
}

/// Unit second-order step response (damping zeta < 1, natural frequency wn) starting at t0.
double secondOrderUnit(double t, double t0, double zeta, double wn)
{
    if (t < t0)
        return 0;
    const double s = t - t0;
    const double root = std::sqrt(1 - zeta * zeta);
    const double wd = wn * root;
    return 1 - std::exp(-zeta * wn * s) * (std::cos(wd * s) + zeta / root * std::sin(wd * s));
}

Signal secondOrder(double t0, double from, double to, double zeta, double wn)
{
    return [=](double t) { return from + (to - from) * secondOrderUnit(t, t0, zeta, wn); };
}

/// Reference answers from the continuous signal on a fine grid (1 us), no sampling involved.
double fineFirstCrossing(const Signal &unit, double t0, double end, double level)
{
    for (double t = t0; t <= end; t += 1e-6)
        if (unit(t) >= level)
            return t;
    return NAN;
}

double fineSettling(const Signal &unit, double t0, double end, double band)
{
    double last = t0;
    for (double t = t0; t <= end; t += 1e-6)
        if (std::abs(unit(t) - 1) > band)
            last = t;
    return last - t0;
}

StepEdge edge(double t, double from, double to)
{
    StepEdge e;
    e.time = t;
    e.from = from;
    e.to = to;
    return e;
}

double valueOf(const Metric &m)
{
    if (!m.known())
        qFatal("metric has no value (gap %d)", int(m.gap));
    return *m.value;
}

} // namespace

class tst_StepMetrics : public QObject {
    Q_OBJECT
private slots:
    void firstOrderResponse_data();
    void firstOrderResponse();
    void riseTimeIsInterpolatedBetweenSamples();
    void secondOrderUnderdamped_data();
    void secondOrderUnderdamped();
    void noiseKeepsMetricsClose();
    void noiseInsideTheBandIsNoOscillation();
    void neverSettles();
    void neverReachesNinetyPercent();
    void steadyStateError();
    void tooFewSamples();
    void edgeOutOfRange();
    void zeroAmplitude();
    void missingEffort();
    void effortWithGaps();
    void saturation();
    void saturationNeedsALimit();
    void shortSaturationIsZero();
    void squareWaveWindowsEndAtTheNextEdge();
    void positionTrace();
    void sampleRate();
};

void tst_StepMetrics::firstOrderResponse_data()
{
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::newRow("up") << 0.0 << 100.0;
    QTest::newRow("down") << 100.0 << -50.0;
    QTest::newRow("down from negative") << -20.0 << -320.0;
}

// y = from + A(1 - exp(-t/tau)): rise 10-90 % = tau ln 9, settling to 2 % = tau ln 50, to 5 %
// = tau ln 20, no overshoot, no oscillation, no steady-state error.
void tst_StepMetrics::firstOrderResponse()
{
    QFETCH(double, from);
    QFETCH(double, to);
    const double tau = 0.0979; // tau ln 9 = 0.2151 s: half a sample off the 10 ms grid
    const double t0 = 0.1037;
    StepTrace trace = sampled(0.01, 1.5, firstOrder(t0, from, to, tau));
    trace.edges = {edge(t0, from, to)};

    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    QCOMPARE(m.samples, 140); // 0.11 .. 1.50
    QVERIFY(std::abs(m.sampleRateHz - 100) < 1e-6);
    QVERIFY2(std::abs(valueOf(m.riseTimeS) - tau * std::log(9)) < 0.001,
             qPrintable(QString::number(*m.riseTimeS.value)));
    QVERIFY2(std::abs(valueOf(m.settling2S) - tau * std::log(50)) < 0.002,
             qPrintable(QString::number(*m.settling2S.value)));
    QVERIFY2(std::abs(valueOf(m.settling5S) - tau * std::log(20)) < 0.002,
             qPrintable(QString::number(*m.settling5S.value)));
    QCOMPARE(valueOf(m.overshootPct), 0.0);
    QCOMPARE(valueOf(m.oscillations), 0.0);
    QVERIFY(std::abs(valueOf(m.steadyStateError)) < 1e-4 * std::abs(to - from));
    QCOMPARE(m.edge.to, to);
}

// A quantised crossing (the first sample past the level) would be off by up to one sample
// period; interpolated, the rise time is exact to well under a millisecond at 10 ms sampling,
// whatever the phase of the edge against the sampling grid.
void tst_StepMetrics::riseTimeIsInterpolatedBetweenSamples()
{
    const double tau = 0.0979;
    for (double t0 = 0.1; t0 < 0.11; t0 += 0.0013) {
        StepTrace trace = sampled(0.01, 1.2, firstOrder(t0, 0, 10, tau));
        trace.edges = {edge(t0, 0, 10)};
        const double rise = valueOf(StepMetrics::forEdge(trace, 0).riseTimeS);
        QVERIFY2(std::abs(rise - tau * std::log(9)) < 0.001,
                 qPrintable(QStringLiteral("edge at %1: rise %2").arg(t0).arg(rise)));
    }
}

void tst_StepMetrics::secondOrderUnderdamped_data()
{
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<int>("oscillations");
    // Peaks past `to` alternate sides with |y - 1| = Mp^k, Mp = exp(-zeta pi / sqrt(1 - zeta^2)).
    // zeta 0.25: 44.4, 19.7, 8.8, 3.9, 1.7 % -> 4 outside the 2 % band.
    QTest::newRow("zeta 0.25 up") << 0.25 << 0.0 << 500.0 << 4;
    QTest::newRow("zeta 0.25 down") << 0.25 << 500.0 << 0.0 << 4;
    // zeta 0.5: 16.3, 2.7, 0.4 % -> 2.
    QTest::newRow("zeta 0.5 up") << 0.5 << -100.0 << 100.0 << 2;
    // zeta 0.7: 4.6, 0.2 % -> 1.
    QTest::newRow("zeta 0.7 down") << 0.7 << 30.0 << 10.0 << 1;
}

void tst_StepMetrics::secondOrderUnderdamped()
{
    QFETCH(double, zeta);
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(int, oscillations);
    const double wn = 2 * M_PI * 2;
    const double t0 = 0.0503;
    const double end = 4.0;
    StepTrace trace = sampled(0.002, end, secondOrder(t0, from, to, zeta, wn));
    trace.edges = {edge(t0, from, to)};
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);

    const double overshoot = 100 * std::exp(-zeta * M_PI / std::sqrt(1 - zeta * zeta));
    QVERIFY2(std::abs(valueOf(m.overshootPct) - overshoot) < 0.05,
             qPrintable(QStringLiteral("%1 vs %2").arg(*m.overshootPct.value).arg(overshoot)));
    QCOMPARE(valueOf(m.oscillations), double(oscillations));

    const Signal unit = [=](double t) { return secondOrderUnit(t, t0, zeta, wn); };
    const double rise =
        fineFirstCrossing(unit, t0, end, 0.9) - fineFirstCrossing(unit, t0, end, 0.1);
    QVERIFY2(std::abs(valueOf(m.riseTimeS) - rise) < 0.0005,
             qPrintable(QStringLiteral("%1 vs %2").arg(*m.riseTimeS.value).arg(rise)));
    const double settle2 = fineSettling(unit, t0, end, 0.02);
    const double settle5 = fineSettling(unit, t0, end, 0.05);
    QVERIFY2(std::abs(valueOf(m.settling2S) - settle2) < 0.002,
             qPrintable(QStringLiteral("%1 vs %2").arg(*m.settling2S.value).arg(settle2)));
    QVERIFY2(std::abs(valueOf(m.settling5S) - settle5) < 0.002,
             qPrintable(QStringLiteral("%1 vs %2").arg(*m.settling5S.value).arg(settle5)));
    QVERIFY(std::abs(valueOf(m.steadyStateError)) < 1e-3 * std::abs(to - from));
}

// Seeded noise of +-0.2 % of the amplitude: every metric stays close to the clean answer.
void tst_StepMetrics::noiseKeepsMetricsClose()
{
    const double t0 = 0.05, zeta = 0.25, wn = 2 * M_PI * 2, a = 500;
    const Signal clean = secondOrder(t0, 0, a, zeta, wn);
    StepTrace reference = sampled(0.002, 4.0, clean);
    reference.edges = {edge(t0, 0, a)};
    QRandomGenerator random(42);
    const Signal noisy = [&](double t) {
        return clean(t) + a * 0.002 * (2 * random.generateDouble() - 1);
    };
    StepTrace trace = sampled(0.002, 4.0, noisy);
    trace.edges = reference.edges;

    const EdgeMetrics c = StepMetrics::forEdge(reference, 0);
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    QVERIFY(std::abs(valueOf(m.riseTimeS) - valueOf(c.riseTimeS)) < 0.002);
    QVERIFY(std::abs(valueOf(m.overshootPct) - valueOf(c.overshootPct)) < 0.3);
    QVERIFY(std::abs(valueOf(m.settling2S) - valueOf(c.settling2S)) < 0.05);
    QVERIFY(std::abs(valueOf(m.settling5S) - valueOf(c.settling5S)) < 0.05);
    QVERIFY(std::abs(valueOf(m.steadyStateError)) < 0.2);
    QCOMPARE(valueOf(m.oscillations), 4.0);
}

// A first-order response with +-1 % noise crosses `to` again and again once it arrives, but
// never leaves the 2 % band after that: no oscillation.
void tst_StepMetrics::noiseInsideTheBandIsNoOscillation()
{
    const double tau = 0.1, a = 100;
    const Signal clean = firstOrder(0.1, 0, a, tau);
    QRandomGenerator random(7);
    const Signal noisy = [&](double t) {
        return clean(t) + a * 0.01 * (2 * random.generateDouble() - 1);
    };
    StepTrace trace = sampled(0.005, 2.0, noisy);
    trace.edges = {edge(0.1, 0, a)};
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    QCOMPARE(valueOf(m.oscillations), 0.0);
    QVERIFY(std::abs(valueOf(m.riseTimeS) - tau * std::log(9)) < 0.01);
    // Noise of up to 1 % moves the last exit from the 2 % band to between 3 % and 1 % of A.
    QVERIFY(valueOf(m.settling2S) >= tau * std::log(100.0 / 3) - 0.005);
    QVERIFY(valueOf(m.settling2S) <= tau * std::log(100.0) + 0.005);
    QVERIFY(valueOf(m.overshootPct) <= 1.0 + 1e-9);
}

// A sustained oscillation of +-10 % around the target: the response rises but never settles,
// and a steady-state error of a response that never settled would be a made-up number.
void tst_StepMetrics::neverSettles()
{
    const Signal ringing = [](double t) {
        if (t < 0.1)
            return 0.0;
        return 100 * (1 - std::exp(-(t - 0.1) / 0.05)) + 10 * std::sin(2 * M_PI * 3 * (t - 0.1));
    };
    StepTrace trace = sampled(0.005, 2.0, ringing);
    trace.edges = {edge(0.1, 0, 100)};
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    QVERIFY(m.riseTimeS.known());
    QCOMPARE(m.settling2S.gap, MetricGap::NeverSettled);
    QVERIFY(!m.settling2S.known());
    QCOMPARE(m.settling5S.gap, MetricGap::NeverSettled);
    QCOMPARE(m.steadyStateError.gap, MetricGap::NeverSettled);
    QVERIFY(!m.steadyStateError.known());
    QVERIFY(valueOf(m.oscillations) >= 10); // 3 Hz for 1.9 s: two half-cycles per period
}

// The response stops at 80 % of the step: no 90 % crossing, never inside the bands.
void tst_StepMetrics::neverReachesNinetyPercent()
{
    StepTrace trace = sampled(0.01, 2.0, firstOrder(0.1, 0, 100, 0.1, 0.8));
    trace.edges = {edge(0.1, 0, 100)};
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    QCOMPARE(m.riseTimeS.gap, MetricGap::NotReached);
    QVERIFY(!m.riseTimeS.known());
    QCOMPARE(m.settling2S.gap, MetricGap::NeverSettled);
    QCOMPARE(m.settling5S.gap, MetricGap::NeverSettled);
    QCOMPARE(m.steadyStateError.gap, MetricGap::NeverSettled);
    QCOMPARE(valueOf(m.overshootPct), 0.0);
    QCOMPARE(valueOf(m.oscillations), 0.0);
}

// Settling at 99 % of the step inside the band: the error is the 1 % left, in value units,
// with the sign of `to - value`.
void tst_StepMetrics::steadyStateError()
{
    StepTrace up = sampled(0.01, 2.0, firstOrder(0.1, 0, 200, 0.05, 0.99));
    up.edges = {edge(0.1, 0, 200)};
    QVERIFY(std::abs(valueOf(StepMetrics::forEdge(up, 0).steadyStateError) - 2.0) < 1e-6);
    StepTrace down = sampled(0.01, 2.0, firstOrder(0.1, 200, 0, 0.05, 0.99));
    down.edges = {edge(0.1, 200, 0)};
    QVERIFY(std::abs(valueOf(StepMetrics::forEdge(down, 0).steadyStateError) + 2.0) < 1e-6);
}

void tst_StepMetrics::tooFewSamples()
{
    // Seven samples after the edge at 0.095 (0.10 .. 0.16).
    StepTrace trace =
        sampled(0.01, 0.16, firstOrder(0.095, 0, 100, 0.001), [](double) { return 1.0; });
    trace.edges = {edge(0.095, 0, 100)};
    const EdgeMetrics few = StepMetrics::forEdge(trace, 0);
    QCOMPARE(few.samples, 7);
    for (const Metric *metric :
         {&few.riseTimeS, &few.overshootPct, &few.settling2S, &few.settling5S,
          &few.steadyStateError, &few.peakEffort, &few.saturatedS, &few.oscillations}) {
        QVERIFY(!metric->known());
        QCOMPARE(metric->gap, MetricGap::TooFewSamples);
    }
    StepMetricOptions fewer;
    fewer.minSamples = 7;
    QVERIFY(StepMetrics::forEdge(trace, 0, fewer).settling2S.known());
    trace.append(0.17, 100, 1);
    QCOMPARE(StepMetrics::forEdge(trace, 0).samples, 8);
    QVERIFY(StepMetrics::forEdge(trace, 0).peakEffort.known());
}

void tst_StepMetrics::edgeOutOfRange()
{
    StepTrace trace = sampled(0.01, 1.0, firstOrder(0.1, 0, 100, 0.1));
    trace.edges = {edge(0.1, 0, 100)};
    for (int index : {-1, 1}) {
        const EdgeMetrics m = StepMetrics::forEdge(trace, index);
        QCOMPARE(m.samples, 0);
        QCOMPARE(m.riseTimeS.gap, MetricGap::TooFewSamples);
    }
    StepTrace empty;
    QVERIFY(StepMetrics::forAllEdges(empty).isEmpty());
}

// from == to: nothing to rise, overshoot or settle to; the error from the target and the
// effort are still measured.
void tst_StepMetrics::zeroAmplitude()
{
    StepTrace trace = sampled(
        0.01, 1.0, [](double) { return 49.0; }, [](double) { return 0.5; });
    trace.edges = {edge(0.1, 50, 50)};
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    for (const Metric *metric :
         {&m.riseTimeS, &m.overshootPct, &m.settling2S, &m.settling5S, &m.oscillations})
        QCOMPARE(metric->gap, MetricGap::NoStep);
    QCOMPARE(valueOf(m.steadyStateError), 1.0);
    QCOMPARE(valueOf(m.peakEffort), 0.5);
}

// A trace of angle replies carries no current: NaN everywhere gives NoEffort, never 0.
void tst_StepMetrics::missingEffort()
{
    StepTrace trace = sampled(0.01, 1.0, firstOrder(0.1, 0, 100, 0.1));
    trace.edges = {edge(0.1, 0, 100)};
    StepMetricOptions options;
    options.effortLimit = 10;
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0, options);
    QCOMPARE(m.peakEffort.gap, MetricGap::NoEffort);
    QVERIFY(!m.peakEffort.known());
    QCOMPARE(m.saturatedS.gap, MetricGap::NoEffort);
    QVERIFY(m.riseTimeS.known());
}

// Every other sample carries the current (negative here): the peak is the largest magnitude of
// the known ones; the missing ones are not zeros.
void tst_StepMetrics::effortWithGaps()
{
    int n = 0;
    StepTrace trace = sampled(0.01, 1.0, firstOrder(0.1, 0, -100, 0.1),
                              [&](double t) { return n++ % 2 ? StepTrace::missing() : -3.0 - t; });
    trace.edges = {edge(0.1, 0, -100)};
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    QVERIFY(std::abs(valueOf(m.peakEffort) - 4.0) < 1e-9); // the sample at t = 1.00
    QCOMPARE(m.saturatedS.gap, MetricGap::NoLimit);
}

// The current sits at its limit from 0.2 s to 0.35 s (negative: magnitude counts), with a
// sample that carried no current in the middle of it.
void tst_StepMetrics::saturation()
{
    const Signal effort = [](double t) {
        if (t > 0.195 && t < 0.355)
            return -5.0;
        return -1.0;
    };
    StepTrace trace = sampled(0.01, 1.0, firstOrder(0.1, 0, 100, 0.1), effort);
    trace.effort[27] = StepTrace::missing();
    trace.edges = {edge(0.1, 0, 100)};
    StepMetricOptions options;
    options.effortLimit = 5;
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0, options);
    // Samples 0.20 .. 0.35 are at the limit; the threshold (4.9 A) is crossed 97.5 % of the
    // way from 1 A to 5 A, so the run is 0.19975 .. 0.35025 s.
    QVERIFY2(std::abs(valueOf(m.saturatedS) - 0.1505) < 1e-6,
             qPrintable(QString::number(*m.saturatedS.value)));
    QCOMPARE(valueOf(m.peakEffort), 5.0);

    options.effortLimit = 6; // 5 A is below 98 % of 6 A
    QCOMPARE(valueOf(StepMetrics::forEdge(trace, 0, options).saturatedS), 0.0);
}

void tst_StepMetrics::saturationNeedsALimit()
{
    StepTrace trace = sampled(0.01, 1.0, firstOrder(0.1, 0, 100, 0.1), [](double) { return 5.0; });
    trace.edges = {edge(0.1, 0, 100)};
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    QCOMPARE(m.saturatedS.gap, MetricGap::NoLimit);
    QVERIFY(!m.saturatedS.known());
    QCOMPARE(valueOf(m.peakEffort), 5.0);
}

// A touch of the limit shorter than saturationMinS is not saturation.
void tst_StepMetrics::shortSaturationIsZero()
{
    const Signal effort = [](double t) { return (t > 0.195 && t < 0.205) ? 5.0 : 1.0; };
    StepTrace trace = sampled(0.01, 1.0, firstOrder(0.1, 0, 100, 0.1), effort);
    trace.edges = {edge(0.1, 0, 100)};
    StepMetricOptions options;
    options.effortLimit = 5;
    QCOMPARE(valueOf(StepMetrics::forEdge(trace, 0, options).saturatedS), 0.0);
    // One sample at the limit: the run is where |effort| is interpolated at or above 4.9 A.
    options.saturationMinS = 0.0001;
    QVERIFY(std::abs(valueOf(StepMetrics::forEdge(trace, 0, options).saturatedS) - 0.0005) < 1e-9);
}

// Square wave 0 -> 100 -> 0 -> 100 with edges every 0.5 s: each edge's window ends at the next
// edge, so each edge sees only its own first-order response.
void tst_StepMetrics::squareWaveWindowsEndAtTheNextEdge()
{
    const double tau = 0.0979;
    const QVector<StepEdge> edges = {edge(0.1003, 0, 100), edge(0.6003, 100, 0),
                                     edge(1.1003, 0, 100), edge(1.6003, 100, 0)};
    const Signal square = [&](double t) {
        double y = 0;
        for (const StepEdge &e : edges)
            if (t >= e.time)
                y += e.amplitude() * (1 - std::exp(-(t - e.time) / tau));
        return y;
    };
    StepTrace trace = sampled(0.01, 2.15, square);
    trace.edges = edges;
    const QVector<EdgeMetrics> all = StepMetrics::forAllEdges(trace);
    QCOMPARE(all.size(), 4);
    const QVector<int> samples = {50, 50, 50, 55};
    for (int i = 0; i < all.size(); ++i) {
        const EdgeMetrics &m = all[i];
        QCOMPARE(m.edge.time, edges[i].time);
        QCOMPARE(m.samples, samples[i]);
        QVERIFY2(std::abs(valueOf(m.riseTimeS) - tau * std::log(9)) < 0.001,
                 qPrintable(QStringLiteral("edge %1").arg(i)));
        QVERIFY2(std::abs(valueOf(m.settling2S) - tau * std::log(50)) < 0.002,
                 qPrintable(QStringLiteral("edge %1").arg(i)));
        QVERIFY(valueOf(m.overshootPct) < 0.01);
        QCOMPARE(valueOf(m.oscillations), 0.0);
        // The last fifth of a 0.5 s window starts 4 tau after the edge: 1.7 % still to go,
        // on the side the step came from.
        const double error = valueOf(m.steadyStateError) * (edges[i].amplitude() > 0 ? 1 : -1);
        QVERIFY2(error > 0.5 && error < 2.0, qPrintable(QString::number(error)));
    }
    QCOMPARE(StepMetrics::forEdge(trace, 2).edge.to, 100.0);
}

// Position loop: 36000 -> 36090 deg, underdamped, stopping 0.5 deg short. Large absolute
// values must not disturb metrics that depend on the 90 deg step.
void tst_StepMetrics::positionTrace()
{
    const double zeta = 0.5, wn = 2 * M_PI * 1.5, t0 = 0.02;
    const Signal unit = [=](double t) { return secondOrderUnit(t, t0, zeta, wn); };
    StepTrace trace = sampled(0.004, 5.0, [&](double t) { return 36000 + 89.5 * unit(t); });
    trace.loop = StepLoop::Position;
    trace.edges = {edge(t0, 36000, 36090)};
    const EdgeMetrics m = StepMetrics::forEdge(trace, 0);
    QVERIFY(std::abs(valueOf(m.steadyStateError) - 0.5) < 1e-3);
    // Peak 89.5 x 1.163 = 104.1 deg past the start: 14.1 deg past 36090, 15.6 % of 90.
    const double peak = 89.5 * (1 + std::exp(-zeta * M_PI / std::sqrt(1 - zeta * zeta))) - 90;
    QVERIFY2(std::abs(valueOf(m.overshootPct) - 100 * peak / 90) < 0.05,
             qPrintable(QString::number(*m.overshootPct.value)));
    QCOMPARE(valueOf(m.oscillations), 2.0);
    QVERIFY(m.settling2S.known());
    QVERIFY(m.riseTimeS.known());
}

void tst_StepMetrics::sampleRate()
{
    QCOMPARE(StepMetrics::sampleRateHz(StepTrace{}), 0.0);
    StepTrace one;
    one.append(1, 2, 3);
    QCOMPARE(StepMetrics::sampleRateHz(one), 0.0);
    const StepTrace trace = sampled(0.004, 2.0, [](double) { return 0.0; });
    QVERIFY(std::abs(StepMetrics::sampleRateHz(trace) - 250) < 1e-9);
}

QTEST_GUILESS_MAIN(tst_StepMetrics)
#include "tst_stepmetrics.moc"
