// The gain search on every series of both generations (issue #25): GainSearchStrategy scoring
// each candidate's step test on the simulator's drive at 1 Mbaud, on the test's clock
// (SimStepRig), must find gains with a faster rise than the defaults and overshoot within the
// bound, in at most 60 s of bus time, and stop at the first unstable candidate; the position
// loop's search likewise, its steps from the angle the drive is at inside an angle window.
// On the test's clock: a loaded host changes none of these figures.
#include "SimStepRig.h"

#include <tuning/GainSearchRunner.h>

#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::tuning;

namespace {

struct Search {
    QVector<CandidateScore> scores;
    std::optional<int> best;
    bool stoppedByInstability = false;
    double seconds = 0;
    std::optional<LoopGains> read, after;
};

/// What GainSearchRunner does, on the rig: read (a position search: the angle too, with a
/// window of 90 deg either side of it), each candidate written without the acceleration limit
/// and stepped, the gains read written back.
Search search(test::SimStepRig &rig, const GainSearchSpec &spec)
{
    Search out;
    const double start = rig.now();
    out.read = rig.readGains();
    if (!out.read)
        return out;
    safety::SoftLimits limits = safety::SoftLimits::defaults(rig.series());
    double angle = 0;
    if (spec.loop == StepLoop::Position) {
        const std::optional<double> read = rig.readAngle();
        if (!read)
            return out;
        angle = *read;
        limits.minAngleDeg = angle - 90;
        limits.maxAngleDeg = angle + 90;
    }
    GainSearchStrategy strategy(*out.read, spec.maxOvershootPct, spec.maxCandidates, spec.loop);
    while (const std::optional<LoopGains> candidate = strategy.next()) {
        LoopGains unramped = *candidate;
        unramped.accelerationDps2 = 0;
        if (!rig.writeGains(unramped))
            return out;
        const StepTrace trace = rig.runStep(spec.step(angle), limits);
        strategy.record(GainSearchStrategy::score(
            *candidate, trace, seriesEffortLimit(rig.series()), spec.maxOvershootPct));
    }
    rig.writeGains(*out.read);
    out.after = rig.readGains();
    out.scores = strategy.scores();
    out.best = strategy.best();
    out.stoppedByInstability = strategy.stoppedByInstability();
    out.seconds = rig.now() - start;
    return out;
}

void print(const Search &s)
{
    for (const CandidateScore &c : s.scores)
        qInfo("Kp %3d Ki %3d: rise %6.2f ms, overshoot %5.1f %%, area %6.2f ms, verdict %d",
              GainSearchStrategy::tuned(c.gains, c.trace.loop).kp,
              GainSearchStrategy::tuned(c.gains, c.trace.loop).ki, c.riseS() * 1e3,
              c.metrics.overshootPct.value.value_or(-1), c.errorAreaS * 1e3, int(c.verdict));
    qInfo("%.1f s of bus time for %d candidates", s.seconds, int(s.scores.size()));
}

} // namespace

class tst_GainSearchSeries : public QObject {
    Q_OBJECT
private slots:
    void fasterThanTheDefaults_data();
    void fasterThanTheDefaults();
    void positionFasterThanTheDefaults_data() { fasterThanTheDefaults_data(); }
    void positionFasterThanTheDefaults();
    void stopsAtTheFirstSaturation();
};

void tst_GainSearchSeries::fasterThanTheDefaults_data()
{
    QTest::addColumn<QString>("drive");
    for (const char *series : {"MS", "MF", "MG", "MH"})
        for (const char *generation : {"", "@2.35"})
            QTest::newRow(qPrintable(
                QStringLiteral("%1%2").arg(QLatin1String(series), QLatin1String(generation))))
                << QStringLiteral("1:%1%2").arg(QLatin1String(series), QLatin1String(generation));
}

void tst_GainSearchSeries::fasterThanTheDefaults()
{
    QFETCH(QString, drive);
    test::SimStepRig rig(drive);
    const Search s = search(rig, GainSearchSpec{});
    print(s);
    QVERIFY(s.read);
    QVERIFY(!s.stoppedByInstability);
    QVERIFY(s.best);
    const CandidateScore &defaults = s.scores.first();
    const CandidateScore &best = s.scores[*s.best];
    QCOMPARE(defaults.gains, *s.read);
    QVERIFY(best.accepted());
    QVERIFY(*best.metrics.overshootPct.value <= GainSearchSpec{}.maxOvershootPct);
    // Clearly faster, not within a sample's jitter: at least a fifth off the defaults' rise.
    QVERIFY2(best.riseS() < 0.8 * defaults.riseS(),
             qPrintable(QStringLiteral("rise %1 ms against the defaults' %2 ms")
                            .arg(best.riseS() * 1e3)
                            .arg(defaults.riseS() * 1e3)));
    QVERIFY2(s.seconds <= 60, qPrintable(QString::number(s.seconds)));
    QCOMPARE(s.after, s.read);
}

void tst_GainSearchSeries::positionFasterThanTheDefaults()
{
    QFETCH(QString, drive);
    test::SimStepRig rig(drive);
    const std::optional<double> start = rig.readAngle();
    QVERIFY(start);
    const GainSearchSpec spec = GainSearchSpec::forPosition(rig.id());
    const Search s = search(rig, spec);
    print(s);
    QVERIFY(s.read);
    QVERIFY(!s.stoppedByInstability);
    QVERIFY(s.best);
    const CandidateScore &defaults = s.scores.first();
    const CandidateScore &best = s.scores[*s.best];
    QCOMPARE(defaults.gains, *s.read);
    QVERIFY(best.accepted());
    QVERIFY(*best.metrics.overshootPct.value <= spec.maxOvershootPct);
    for (const CandidateScore &c : s.scores) {
        QCOMPARE(c.gains.speed, s.read->speed); // the angle gains only
        QVERIFY(c.trace.edges.size() == 2 * spec.periods);
    }
    QVERIFY2(best.riseS() < 0.8 * defaults.riseS(),
             qPrintable(QStringLiteral("rise %1 ms against the defaults' %2 ms")
                            .arg(best.riseS() * 1e3)
                            .arg(defaults.riseS() * 1e3)));
    QVERIFY2(s.seconds <= 60, qPrintable(QString::number(s.seconds)));
    QCOMPARE(s.after, s.read);
    // Every square ends where it began: the drive holds the angle it started at.
    const std::optional<double> end = rig.readAngle();
    QVERIFY(end && std::abs(*end - *start) < 0.5);
}

void tst_GainSearchSeries::stopsAtTheFirstSaturation()
{
    // Steps of 11900 dps ask the MH rotor for more than its current limit: the first candidate
    // already sits at the limit, and nothing more is tried.
    test::SimStepRig rig(QStringLiteral("1:MH"));
    GainSearchSpec spec;
    spec.from = 100;
    spec.to = 12000;
    const Search s = search(rig, spec);
    print(s);
    QCOMPARE(s.scores.size(), 1);
    QCOMPARE(s.scores.first().verdict, CandidateVerdict::Saturated);
    QVERIFY(s.stoppedByInstability);
    QVERIFY(!s.best);
    QCOMPARE(s.after, s.read);
}

QTEST_GUILESS_MAIN(tst_GainSearchSeries)
#include "tst_gainsearchseries.moc"
