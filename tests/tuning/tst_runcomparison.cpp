// The best value of each metric column across runs: closest to zero, ties all marked,
// a value without a number never best.

#include <tuning/RunComparison.h>

#include <QtTest/QtTest>

#include <cmath>

using namespace lk::tuning;

namespace {

EdgeMetrics metrics(double value)
{
    EdgeMetrics m;
    for (Metric *metric : {&m.riseTimeS, &m.overshootPct, &m.settling2S, &m.settling5S,
                           &m.steadyStateError, &m.peakEffort, &m.saturatedS, &m.oscillations})
        *metric = Metric::of(value);
    return m;
}

Metric none()
{
    return Metric::none(MetricGap::NeverSettled);
}

/// A first-order step 0 -> 100 (time constant tau) with the effort `effort` on every sample.
StepRun run(double tau, double effort, bool power)
{
    StepRun r;
    for (int i = 0; i <= 200; ++i) {
        const double t = i * 0.005;
        r.trace.append(t, t < 0.1 ? 0 : 100 * (1 - std::exp(-(t - 0.1) / tau)), effort);
    }
    r.trace.edges = {StepEdge{0.1, 0, 100}};
    r.trace.effortIsPower = power;
    return r;
}

} // namespace

class tst_RunComparison : public QObject {
    Q_OBJECT
private slots:
    void lowestWins();
    void steadyStateErrorByMagnitude();
    void tiesAreAllBest();
    void unknownIsNeverBest();
    void everyColumnReadsItsOwnMetric();
    void runsFromTraces();
    void mixedEffortKindsHaveNoBestPeak();
    void onlyLikeRunsCompare_data();
    void onlyLikeRunsCompare();
};

void tst_RunComparison::lowestWins()
{
    const QVector<EdgeMetrics> runs = {metrics(0.3), metrics(0.1), metrics(0.2)};
    for (MetricColumn c : RunComparison::columns())
        QCOMPARE(RunComparison::best(runs, c), QVector<int>{1});
    QVERIFY(RunComparison::best(QVector<EdgeMetrics>{}, MetricColumn::RiseTime).isEmpty());
}

void tst_RunComparison::steadyStateErrorByMagnitude()
{
    QCOMPARE(RunComparison::closestToZero({Metric::of(1.0), Metric::of(-0.5), Metric::of(0.7)}),
             QVector<int>{1});
    QCOMPARE(RunComparison::closestToZero({Metric::of(-2.0), Metric::of(-3.0)}), QVector<int>{0});
}

void tst_RunComparison::tiesAreAllBest()
{
    QCOMPARE(RunComparison::closestToZero({Metric::of(0), Metric::of(2), Metric::of(0)}),
             (QVector<int>{0, 2}));
    QCOMPARE(RunComparison::closestToZero({Metric::of(0.2), Metric::of(0.2 + 1e-12)}),
             (QVector<int>{0, 1}));
    QCOMPARE(RunComparison::closestToZero({Metric::of(0.2001), Metric::of(0.2)}), QVector<int>{1});
    QCOMPARE(RunComparison::closestToZero({Metric::of(-1.0), Metric::of(1.0)}),
             (QVector<int>{0, 1}));
}

void tst_RunComparison::unknownIsNeverBest()
{
    QCOMPARE(RunComparison::closestToZero({none(), Metric::of(5), none()}), QVector<int>{1});
    QVERIFY(RunComparison::closestToZero({none(), none()}).isEmpty());
    QVERIFY(RunComparison::closestToZero({}).isEmpty());
    // A default Metric has no value either, whatever its gap says.
    QCOMPARE(RunComparison::closestToZero({Metric{}, Metric::of(1e9)}), QVector<int>{1});
}

void tst_RunComparison::everyColumnReadsItsOwnMetric()
{
    EdgeMetrics m;
    m.riseTimeS = Metric::of(1);
    m.overshootPct = Metric::of(2);
    m.settling2S = Metric::of(3);
    m.settling5S = Metric::of(4);
    m.steadyStateError = Metric::of(5);
    m.peakEffort = Metric::of(6);
    m.saturatedS = Metric::of(7);
    m.oscillations = Metric::of(8);
    const QVector<MetricColumn> columns = RunComparison::columns();
    QCOMPARE(columns.size(), 8);
    for (int i = 0; i < columns.size(); ++i)
        QCOMPARE(*RunComparison::metric(m, columns[i]).value, double(i + 1));
}

// Three real traces: the fastest response rises and settles first; the one with the least
// current has the lowest peak; the one that never settles is never best for settling.
void tst_RunComparison::runsFromTraces()
{
    StepRun slow = run(0.08, 2.0, false);
    StepRun fast = run(0.03, 4.0, false);
    // Stops at half the step: no rise time, never settles, yet the smallest error would be
    // its own if an unknown counted as 0.
    StepRun stuck = run(0.01, 3.0, false);
    for (double &v : stuck.trace.value)
        v *= 0.5;
    const QVector<StepRun> runs = {slow, fast, stuck};
    QCOMPARE(RunComparison::best(runs, MetricColumn::RiseTime), QVector<int>{1});
    QCOMPARE(RunComparison::best(runs, MetricColumn::Settling2), QVector<int>{1});
    QCOMPARE(RunComparison::best(runs, MetricColumn::SteadyStateError), QVector<int>{1});
    QCOMPARE(RunComparison::best(runs, MetricColumn::PeakEffort), QVector<int>{0});
    QCOMPARE(RunComparison::best(runs, MetricColumn::Oscillations), (QVector<int>{0, 1, 2}));
    QVERIFY(RunComparison::best(runs, MetricColumn::Saturation).isEmpty()); // no limit known
}

void tst_RunComparison::mixedEffortKindsHaveNoBestPeak()
{
    const QVector<StepRun> mixed = {run(0.05, 2.0, false), run(0.03, 300, true)};
    QVERIFY(RunComparison::best(mixed, MetricColumn::PeakEffort).isEmpty());
    QCOMPARE(RunComparison::best(mixed, MetricColumn::RiseTime), QVector<int>{1});
    const QVector<StepRun> power = {run(0.05, 400, true), run(0.03, 300, true)};
    QCOMPARE(RunComparison::best(power, MetricColumn::PeakEffort), QVector<int>{1});
}

// Each row: three runs (rise-time constants 0.05, 0.01, 0.08 s: the middle one is fastest and
// has the least effort) that differ in one respect; which runs are best.
void tst_RunComparison::onlyLikeRunsCompare_data()
{
    QTest::addColumn<QString>("middle"); // how the middle run differs
    QTest::addColumn<int>("column");
    QTest::addColumn<QVector<int>>("best");
    const int rise = int(MetricColumn::RiseTime);
    const int peak = int(MetricColumn::PeakEffort);
    QTest::newRow("alike: the fastest wins") << "" << rise << QVector<int>{1};
    QTest::newRow("position step: apart") << "position" << rise << QVector<int>{0};
    QTest::newRow("position step: error in degrees")
        << "position" << int(MetricColumn::SteadyStateError) << QVector<int>{0};
    QTest::newRow("power: peak apart") << "power" << peak << QVector<int>{2};
    QTest::newRow("power: its time compares") << "power" << rise << QVector<int>{1};
    QTest::newRow("another drive, amps: compares") << "drive" << peak << QVector<int>{1};
}

void tst_RunComparison::onlyLikeRunsCompare()
{
    QFETCH(QString, middle);
    QFETCH(int, column);
    QFETCH(QVector<int>, best);
    StepRun a = run(0.05, 3.0, false);
    StepRun b = run(0.01, 1.0, middle == QLatin1String("power"));
    StepRun c = run(0.08, 2.5, false);
    for (StepRun *r : {&a, &b, &c}) {
        r->series = QStringLiteral("MF");
        r->model = QStringLiteral("MF4015");
        r->driveId = 1;
    }
    if (middle == QLatin1String("position"))
        b.spec.loop = b.trace.loop = StepLoop::Position;
    if (middle == QLatin1String("drive"))
        b.driveId = 2;
    QCOMPARE(RunComparison::best({a, b, c}, MetricColumn(column)), best);
}

QTEST_GUILESS_MAIN(tst_RunComparison)
#include "tst_runcomparison.moc"
