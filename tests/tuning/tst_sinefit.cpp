// Sine fits on uneven sample times (issue #25): the sampled fit against known sines with
// jittered times, offset, drift, noise and quantisation; the held (zero-order-hold) component
// against its closed form; a response's point, phase unwrapping and Bode figures.
#include <tuning/FrequencyResponse.h>
#include <tuning/SineFit.h>

#include <QtCore/QRandomGenerator>
#include <QtTest/QTest>

#include <cmath>

using namespace lk::tuning;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Sample times at `rateHz` on average, each interval +-`jitter` of the mean (deterministic).
QVector<double> jitteredTimes(double rateHz, double seconds, double jitter, quint32 seed)
{
    QRandomGenerator random(seed);
    QVector<double> t;
    double now = 0.0123; // the bus clock never starts at 0
    while (now < seconds) {
        t.append(now);
        now += (1 + jitter * (2 * random.generateDouble() - 1)) / rateHz;
    }
    return t;
}

double wrap(double deg)
{
    return std::remainder(deg, 360.0);
}

} // namespace

class tst_SineFit : public QObject {
    Q_OBJECT
private slots:
    void sampledFit_data();
    void sampledFit();
    void tooFewSamplesOrTooShort();
    void heldComponent_data();
    void heldComponent();
    void responsePointAndFigures();
    void sparseWindowIsDropped();
};

void tst_SineFit::sampledFit_data()
{
    QTest::addColumn<double>("hz");
    QTest::addColumn<double>("amplitude");
    QTest::addColumn<double>("phaseDeg");
    QTest::addColumn<double>("rateHz");
    QTest::addColumn<double>("jitter");
    QTest::addColumn<double>("drift"); ///< per second
    QTest::addColumn<double>("noise"); ///< uniform +-, units of y
    QTest::addColumn<double>("quantum");
    QTest::addColumn<double>("minQuality");
    // rows: clean; jittered; slow; near a quarter of the rate; drifting; noisy; quantised to
    // 1 dps as the drives report speed
    QTest::newRow("clean 5 Hz") << 5.0 << 100.0 << 30.0 << 500.0 << 0.0 << 0.0 << 0.0 << 0.0
                                << 0.999;
    QTest::newRow("jitter 40 %") << 17.0 << 50.0 << -120.0 << 400.0 << 0.4 << 0.0 << 0.0 << 0.0
                                 << 0.999;
    QTest::newRow("1 Hz jitter 60 %")
        << 1.0 << 20.0 << 179.0 << 100.0 << 0.6 << 0.0 << 0.0 << 0.0 << 0.999;
    QTest::newRow("4 samples per period")
        << 100.0 << 10.0 << -45.0 << 400.0 << 0.3 << 0.0 << 0.0 << 0.0 << 0.999;
    QTest::newRow("drift") << 8.0 << 30.0 << 60.0 << 300.0 << 0.3 << 25.0 << 0.0 << 0.0 << 0.999;
    QTest::newRow("noise") << 12.0 << 40.0 << -10.0 << 600.0 << 0.3 << 0.0 << 20.0 << 0.0 << 0.7;
    QTest::newRow("quantised 1 dps")
        << 30.0 << 6.0 << 90.0 << 800.0 << 0.3 << 0.0 << 0.0 << 1.0 << 0.95;
}

void tst_SineFit::sampledFit()
{
    QFETCH(double, hz);
    QFETCH(double, amplitude);
    QFETCH(double, phaseDeg);
    QFETCH(double, rateHz);
    QFETCH(double, jitter);
    QFETCH(double, drift);
    QFETCH(double, noise);
    QFETCH(double, quantum);
    QFETCH(double, minQuality);
    const double seconds = std::max(1.0, 10 / hz) + 0.05;
    const QVector<double> t = jitteredTimes(rateHz, seconds, jitter, 7);
    QRandomGenerator random(11);
    QVector<double> y;
    for (double ti : t) {
        double v =
            200 + drift * ti + amplitude * std::sin(2 * kPi * hz * ti + phaseDeg * kPi / 180);
        v += noise * (2 * random.generateDouble() - 1);
        if (quantum > 0)
            v = std::round(v / quantum) * quantum;
        y.append(v);
    }
    const double from = t.first();
    const double to = from + std::floor((t.last() - from) * hz) / hz;
    const SineComponent s = SineFit::fitSampled(t, y, hz, from, to);
    QVERIFY(s.ok);
    // Noise of +-n over N samples moves the amplitude by about n / sqrt(N).
    const double tolerance = 0.002 * amplitude + 3 * (noise + quantum) / std::sqrt(s.samples);
    QVERIFY2(std::abs(s.amplitude - amplitude) < tolerance,
             qPrintable(QStringLiteral("amplitude %1 of %2").arg(s.amplitude).arg(amplitude)));
    const double phaseTol = 0.2 + 180 / kPi * tolerance / amplitude;
    QVERIFY2(
        std::abs(wrap(s.phaseRad * 180 / kPi - phaseDeg)) < phaseTol,
        qPrintable(QStringLiteral("phase %1 of %2").arg(s.phaseRad * 180 / kPi).arg(phaseDeg)));
    QVERIFY2(s.quality >= minQuality && s.quality <= 1, qPrintable(QString::number(s.quality)));
}

void tst_SineFit::tooFewSamplesOrTooShort()
{
    QVector<double> t, y;
    for (int i = 0; i < SineFit::kMinSamples - 1; ++i) {
        t.append(i * 0.01);
        y.append(std::sin(2 * kPi * 10 * i * 0.01));
    }
    QVERIFY(!SineFit::fitSampled(t, y, 10, 0, 0.1).ok); // one sample short
    t.append(0.07);
    y.append(0);
    QVERIFY(!SineFit::fitSampled(t, y, 10, 0, 0.07).ok); // under one period
    QVERIFY(!SineFit::ofHeld(t, y, 10, -0.05, 0.05).ok); // starts before the first hold
    QVERIFY(!SineFit::ofHeld({}, {}, 10, 0, 1).ok);
}

void tst_SineFit::heldComponent_data()
{
    QTest::addColumn<double>("hz");
    QTest::addColumn<double>("rateHz");
    QTest::addColumn<double>("jitter");
    QTest::newRow("even 10 Hz at 500") << 10.0 << 500.0 << 0.0;
    QTest::newRow("even 100 Hz at 400") << 100.0 << 400.0 << 0.0;
    QTest::newRow("jittered 50 Hz at 300") << 50.0 << 300.0 << 0.4;
}

void tst_SineFit::heldComponent()
{
    // A sine sampled at uneven times and held: the closed form against a fine numerical
    // integration of the same staircase; evenly held, against sinc(wh/2) e^{-jwh/2}.
    QFETCH(double, hz);
    QFETCH(double, rateHz);
    QFETCH(double, jitter);
    const QVector<double> t = jitteredTimes(rateHz, 20 / hz + 0.1, jitter, 3);
    QVector<double> v;
    for (double ti : t)
        v.append(5 + 100 * std::sin(2 * kPi * hz * ti));
    const double from = t.first();
    const double to = from + 20 / hz;
    const SineComponent s = SineFit::ofHeld(t, v, hz, from, to);
    QVERIFY(s.ok);
    double a = 0, b = 0;
    const int n = 400000;
    int k = 0;
    for (int i = 0; i < n; ++i) {
        const double ti = from + (i + 0.5) * (to - from) / n;
        while (k + 1 < t.size() && t[k + 1] <= ti)
            ++k;
        a += v[k] * std::sin(2 * kPi * hz * ti);
        b += v[k] * std::cos(2 * kPi * hz * ti);
    }
    const double numericAmp = 2 * std::hypot(a, b) / n;
    const double numericPhase = std::atan2(b, a);
    QVERIFY2(std::abs(s.amplitude - numericAmp) < 0.01,
             qPrintable(QStringLiteral("%1 vs %2").arg(s.amplitude).arg(numericAmp)));
    QVERIFY(std::abs(wrap((s.phaseRad - numericPhase) * 180 / kPi)) < 0.05);
    QVERIFY(std::abs(s.offset - 5) < 1);
    if (jitter == 0) {
        const double half = kPi * hz / rateHz;
        QVERIFY(std::abs(s.amplitude - 100 * std::sin(half) / half) < 0.05);
        // The hold lags the sampled sine by half an interval.
        QVERIFY(std::abs(wrap((s.phaseRad + half) * 180 / kPi)) < 0.05);
    }
}

void tst_SineFit::responsePointAndFigures()
{
    // A first-order lag 1/(1 + s/wc), wc = 2 pi 20 Hz, sampled at 1 kHz with jitter: points,
    // then the -3 dB bandwidth at 20 Hz with -45 degrees there.
    const double fc = 20;
    FrequencyResponse response;
    for (double hz : {1.0, 2.0, 5.0, 10.0, 15.0, 20.0, 30.0, 50.0, 100.0, 200.0}) {
        const QVector<double> t = jitteredTimes(1000, 10 / hz + 0.2, 0.3, 5);
        const double gain = 1 / std::sqrt(1 + std::pow(hz / fc, 2));
        const double lag = -std::atan(hz / fc);
        QVector<double> u, y, yt;
        for (double ti : t) {
            u.append(50 * std::sin(2 * kPi * hz * ti));
            // The output sampled at the same instants the input changes, from the continuous
            // response to the held input: the sine of the held input's component.
            yt.append(ti);
        }
        const SineComponent held = SineFit::ofHeld(t, u, hz, t.first(), t.first() + 10 / hz);
        for (double ti : yt)
            y.append(held.amplitude * gain * std::sin(2 * kPi * hz * ti + held.phaseRad + lag));
        const auto p = FrequencyResponse::measure(t, u, yt, y, hz, t.first(), t.first() + 10 / hz);
        QVERIFY(p);
        QVERIFY2(std::abs(p->magnitudeDb - 20 * std::log10(gain)) < 0.01,
                 qPrintable(QString::number(p->magnitudeDb)));
        QVERIFY(std::abs(p->phaseDeg - lag * 180 / kPi) < 0.1);
        response.points.append(*p);
    }
    response.unwrapPhases();
    const BodeFigures f = response.figures();
    QVERIFY(f.bandwidthHz);
    QVERIFY2(std::abs(*f.bandwidthHz - fc) < 1.0, qPrintable(QString::number(*f.bandwidthHz)));
    QVERIFY(std::abs(*f.phaseAtBandwidth + 45) < 3);
    QCOMPARE(*f.peakHz, 1.0);
    // No input over the window: no point, and the reason.
    DroppedReason why = DroppedReason::AboveResolution;
    QVERIFY(!FrequencyResponse::measure({5.0}, {1.0}, {}, {}, 10, 0, 1, &why));
    QCOMPARE(why, DroppedReason::NoInput);
}

/// A window where the samples thinned out (the host stalled: one sample in 20 kept for half of
/// it) gives no point when the loop needs more samples a period than it holds, though the
/// samples around it are dense; the same window without that need still gives its point.
void tst_SineFit::sparseWindowIsDropped()
{
    const double hz = 40;
    const QVector<double> all = jitteredTimes(1000, 1.0, 0.3, 9); // 25 samples a period
    const double from = 0.3;
    const double to = from + 10 / hz;
    QVector<double> t, u;
    int kept = 0;
    for (int k = 0; k < all.size(); ++k) {
        const bool stalled = all[k] > from && all[k] < from + 5 / hz;
        if (stalled && k % 20 != 0)
            continue;
        t.append(all[k]);
        u.append(50 * std::sin(2 * kPi * hz * all[k]));
        kept += all[k] >= from && all[k] <= to ? 1 : 0;
    }
    const double perPeriod = kept / ((to - from) * hz);
    QVERIFY2(perPeriod > 12 && perPeriod < 16, qPrintable(QString::number(perPeriod)));
    DroppedReason why = DroppedReason::NoInput;
    QVERIFY(!FrequencyResponse::measure(t, u, t, u, hz, from, to, &why, 16));
    QCOMPARE(why, DroppedReason::TooFewSamples);
    const auto p = FrequencyResponse::measure(t, u, t, u, hz, from, to, &why, 4);
    QVERIFY(p);
    QCOMPARE(p->samples, kept);
}

QTEST_APPLESS_MAIN(tst_SineFit)
#include "tst_sinefit.moc"
