// The Bode chart of the frequency-response view (#25) on responses made in the test: only the
// points measured are drawn, the resolution limit is a line with its reason, the figures and
// each point's fit quality are shown.
#include <tuning/BodeChart.h>
#include <tuning/FrequencyRunList.h>

#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>
#include <QtTest/QtTest>

using lk::tuning::DroppedReason;
using lk::tuning::FrequencyPoint;
using lk::tuning::FrequencyResponse;
using lk::ui::BodeChart;
using lk::ui::BodeRun;

namespace {

/// A first-order lag with its corner at `cornerHz`, measured at `hz`, sampled at `rateHz`:
/// what the rate does not resolve at `samplesPerPeriod` is dropped, as the runner drops it.
FrequencyResponse lag(double cornerHz, const QVector<double> &hz, double rateHz,
                      double samplesPerPeriod = FrequencyResponse::kSpeedSamplesPerPeriod)
{
    FrequencyResponse r;
    r.sampleRateHz = rateHz;
    r.samplesPerPeriod = samplesPerPeriod;
    for (double f : hz) {
        if (f > r.resolvedHz()) {
            r.dropped.append({f, DroppedReason::AboveResolution});
            continue;
        }
        const double x = f / cornerHz;
        FrequencyPoint p;
        p.hz = f;
        p.magnitudeDb = -10 * std::log10(1 + x * x);
        p.phaseDeg = -std::atan(x) * 180 / M_PI;
        p.quality = 0.9 + 0.01 * r.points.size();
        p.samples = 100;
        r.points.append(p);
    }
    return r;
}

/// Points as given, every frequency resolved.
FrequencyResponse measured(const QVector<double> &hz, const QVector<double> &db,
                           const QVector<double> &deg)
{
    FrequencyResponse r;
    r.sampleRateHz = 1000;
    for (int i = 0; i < hz.size(); ++i) {
        FrequencyPoint p;
        p.hz = hz[i];
        p.magnitudeDb = db[i];
        p.phaseDeg = deg[i];
        p.quality = 0.9 + 0.01 * i;
        p.samples = 100;
        r.points.append(p);
    }
    return r;
}

} // namespace

class tst_BodeChart : public QObject {
    Q_OBJECT
private slots:
    void onlyMeasuredPointsAreDrawn();
    void resolutionLimitIsALineWithItsReason();
    void noLineWhenEverythingWasResolved();
    void figuresAndFitQualityAreShown();
    void runsOverlayInTheirColours();
};

void tst_BodeChart::onlyMeasuredPointsAreDrawn()
{
    BodeChart chart;
    const FrequencyResponse r = lag(10, {1, 3, 10, 30, 100, 300}, 400); // resolves up to 100 Hz
    QCOMPARE(r.points.size(), 5);
    chart.setRuns({{QStringLiteral("Run 1"), Qt::red, r}});
    QCOMPARE(chart.magnitudePoints(0)->count(), 5);
    QCOMPARE(chart.phasePoints(0)->count(), 5);
    for (const QPointF &p : chart.magnitudePoints(0)->points())
        QVERIFY(p.x() <= 100);
}

void tst_BodeChart::resolutionLimitIsALineWithItsReason()
{
    BodeChart chart;
    chart.setRuns({{QStringLiteral("Run 1"), Qt::red, lag(10, {1, 10, 100, 300}, 400)}});
    QLineSeries *line = chart.resolutionLine();
    QVERIFY(line);
    QCOMPARE(line->count(), 2);
    QCOMPARE(line->at(0).x(), 100.0); // a quarter of 400 samples/s
    QCOMPARE(line->at(1).x(), 100.0);
    const QString text = chart.resolutionText();
    QVERIFY2(text.contains(QStringLiteral("100.0 Hz")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("400 samples/s")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("300.0 Hz")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("4 samples a period")), qPrintable(text));

    // A position loop's response needs 16 samples a period: its line sits at 25 Hz.
    chart.setRuns({{QStringLiteral("Run 2"), Qt::blue,
                    lag(10, {1, 10, 20, 40}, 400, FrequencyResponse::kPositionSamplesPerPeriod)}});
    line = chart.resolutionLine();
    QVERIFY(line);
    QCOMPARE(line->at(0).x(), 25.0);
    const QString position = chart.resolutionText();
    QVERIFY2(position.contains(QStringLiteral("25.0 Hz")) &&
                 position.contains(QStringLiteral("16 samples a period")) &&
                 position.contains(QStringLiteral("40.0 Hz")),
             qPrintable(position));
}

void tst_BodeChart::noLineWhenEverythingWasResolved()
{
    BodeChart chart;
    chart.setRuns({{QStringLiteral("Run 1"), Qt::red, lag(10, {1, 10, 50}, 400)}});
    QVERIFY(!chart.resolutionLine());
    QVERIFY(chart.resolutionText().isEmpty());
}

void tst_BodeChart::figuresAndFitQualityAreShown()
{
    BodeChart chart;
    // -3 dB between 10 Hz (-2 dB) and 100 Hz (-12 dB): a tenth of the decade, 12.6 Hz, where
    // the phase is -44 degrees; the peak +0.5 dB at 3 Hz.
    chart.setRuns({{QStringLiteral("Run 1"), Qt::red,
                    measured({1, 3, 10, 100}, {0, 0.5, -2, -12}, {0, -10, -40, -80})}});
    const QString figures = chart.figuresText();
    QCOMPARE(figures, QStringLiteral("Run 1: -3 dB bandwidth 12.6 Hz (phase there -44\u00b0); "
                                     "peak 0.5 dB at 3.0 Hz."));
    const QString tip = chart.pointText(0, 2);
    QCOMPARE(tip, QStringLiteral("Run 1\n10.0 Hz: -2.00 dB, -40.0\u00b0\nFit quality 0.920 (100 "
                                 "samples)"));
    QVERIFY(chart.pointText(0, 4).isEmpty());
    QVERIFY(chart.pointText(1, 0).isEmpty());
}

void tst_BodeChart::runsOverlayInTheirColours()
{
    BodeChart chart;
    chart.setRuns({{QStringLiteral("Run 1"), Qt::red, lag(10, {1, 10, 100}, 1000)},
                   {QStringLiteral("Run 2"), Qt::blue, measured({1, 10}, {0, -1}, {0, -20})}});
    QCOMPARE(chart.runCount(), 2);
    QCOMPARE(chart.magnitudePoints(1)->color(), QColor(Qt::blue));
    const QStringList lines = chart.figuresText().split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), 2);
    QVERIFY2(lines.at(0).startsWith(QStringLiteral("Run 1: -3 dB bandwidth ")),
             qPrintable(lines.at(0)));
    QCOMPARE(lines.at(1), QStringLiteral("Run 2: no -3 dB bandwidth within the frequencies "
                                         "measured; peak 0.0 dB at 1.0 Hz."));
    // The list the view keeps them in numbers them as the step runs are numbered.
    lk::ui::FrequencyRunList runs;
    runs.add({});
    const int key = runs.add({});
    QCOMPARE(runs.title(runs.indexOf(key)), QStringLiteral("Run 2"));
}

QTEST_MAIN(tst_BodeChart)
#include "tst_bodechart.moc"
