// The metrics-to-JSON mapping lkctl step --json and the run files share: lkctl's keys, null
// plus a machine word for a metric without a value, never a 0 standing in for unknown.

#include <tuning/StepRun.h>
#include <tuning/StepRunJson.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtTest/QtTest>

#include <cmath>

using namespace lk::tuning;

namespace {

/// A first-order step 0 -> 100 at t = 0.1 s (tau 0.1 s), sampled every 10 ms to 1.5 s, with
/// the current `effort` on every sample.
StepRun firstOrderRun(double effort)
{
    StepRun run;
    run.number = 1;
    for (int i = 0; i <= 150; ++i) {
        const double t = i * 0.01;
        const double v = t < 0.1 ? 0 : 100 * (1 - std::exp(-(t - 0.1) / 0.1));
        run.trace.append(t, v, effort);
    }
    run.trace.edges = {StepEdge{0.1, 0, 100}};
    run.gains = QJsonObject{{"angle_kp", 100}, {"angle_ki", 100}, {"speed_kp", 50},
                            {"speed_ki", 40},  {"iq_kp", 50},     {"iq_ki", 50}};
    return run;
}

QStringList sorted(QStringList keys)
{
    keys.sort();
    return keys;
}

} // namespace

class tst_StepRunJson : public QObject {
    Q_OBJECT
private slots:
    void keysOfAMeasuredStep();
    void valuesAreRounded();
    void gapsAreNullWithAWord();
    void powerOnMs();
    void runWithoutEdges();
    void gapWords();
};

void tst_StepRunJson::keysOfAMeasuredStep()
{
    StepRun run = firstOrderRun(2.5);
    run.effortLimit = 10;
    const QJsonObject o = StepRunJson::toJson(run);
    QCOMPARE(sorted(o.keys()),
             sorted({"rise_time_s", "overshoot_pct", "settling_time_s", "settling_time_5pct_s",
                     "steady_state_error", "peak_iq_a", "saturated_s", "oscillations", "samples",
                     "sample_rate_hz", "gains"}));
    QCOMPARE(o.value("gains").toObject(), run.gains);
    QCOMPARE(o.value("samples").toInt(), 141);
    QCOMPARE(o.value("sample_rate_hz").toDouble(), 100.0);
    QCOMPARE(o.value("peak_iq_a").toDouble(), 2.5);
    QCOMPARE(o.value("saturated_s").toDouble(), 0.0);
    QCOMPARE(o.value("overshoot_pct").toDouble(), 0.0);
    QVERIFY(o.value("oscillations").isDouble());
    QCOMPARE(o.value("oscillations").toInt(-1), 0);
    QVERIFY(std::abs(o.value("rise_time_s").toDouble() - 0.1 * std::log(9)) < 0.001);
    QVERIFY(std::abs(o.value("settling_time_s").toDouble() - 0.1 * std::log(50)) < 0.002);
    QVERIFY(std::abs(o.value("settling_time_5pct_s").toDouble() - 0.1 * std::log(20)) < 0.002);
}

void tst_StepRunJson::valuesAreRounded()
{
    EdgeMetrics m;
    m.samples = 12;
    m.sampleRateHz = 123.456;
    m.riseTimeS = Metric::of(0.123456);
    m.overshootPct = Metric::of(12.3456);
    m.settling2S = Metric::of(1.00004);
    m.settling5S = Metric::of(0.99996);
    m.steadyStateError = Metric::of(-0.00001); // rounds to -0, printed as 0
    m.peakEffort = Metric::of(3.14159);
    m.saturatedS = Metric::of(0.05);
    m.oscillations = Metric::of(3);
    const QJsonObject o = StepRunJson::metricsObject(m, false);
    QCOMPARE(o.value("sample_rate_hz").toDouble(), 123.5);
    QCOMPARE(o.value("rise_time_s").toDouble(), 0.1235);
    QCOMPARE(o.value("overshoot_pct").toDouble(), 12.35);
    QCOMPARE(o.value("settling_time_s").toDouble(), 1.0);
    QCOMPARE(o.value("settling_time_5pct_s").toDouble(), 1.0);
    QCOMPARE(o.value("peak_iq_a").toDouble(), 3.142);
    QCOMPARE(o.value("oscillations").toInt(), 3);
    const QByteArray text = QJsonDocument(o).toJson(QJsonDocument::Compact);
    QVERIFY2(text.contains("\"steady_state_error\":0}"), text.constData());
    QVERIFY2(!text.contains("-0"), text.constData());
    QVERIFY2(!text.contains("_why"), text.constData());
}

// The response settles at 80 %: rise, settling and steady-state error have no value; with no
// current carried and no limit known the effort metrics have none either.
void tst_StepRunJson::gapsAreNullWithAWord()
{
    StepRun run = firstOrderRun(StepTrace::missing());
    for (double &v : run.trace.value)
        v *= 0.8;
    const QJsonObject o = StepRunJson::toJson(run);
    const QList<QPair<QString, QString>> expected = {{"rise_time_s", "not_reached"},
                                                     {"settling_time_s", "never_settled"},
                                                     {"settling_time_5pct_s", "never_settled"},
                                                     {"steady_state_error", "never_settled"},
                                                     {"peak_iq_a", "no_effort"},
                                                     {"saturated_s", "no_effort"}};
    for (const auto &[key, why] : expected) {
        QVERIFY2(o.value(key).isNull(), qPrintable(key));
        QCOMPARE(o.value(key + "_why").toString(), why);
    }
    QCOMPARE(o.value("overshoot_pct").toDouble(-1), 0.0);
    QVERIFY(!o.contains("overshoot_pct_why"));

    run = firstOrderRun(1.0);
    QCOMPARE(StepRunJson::toJson(run).value("saturated_s_why").toString(), QString("no_limit"));
}

void tst_StepRunJson::powerOnMs()
{
    StepRun run = firstOrderRun(-420);
    run.trace.effortIsPower = true;
    const QJsonObject o = StepRunJson::toJson(run);
    QVERIFY(!o.contains("peak_iq_a"));
    QCOMPARE(o.value("peak_power").toDouble(), 420.0);
}

void tst_StepRunJson::runWithoutEdges()
{
    StepRun run = firstOrderRun(1.0);
    run.trace.edges.clear();
    const QJsonObject o = StepRunJson::toJson(run);
    QVERIFY(o.value("rise_time_s").isNull());
    QCOMPARE(o.value("rise_time_s_why").toString(), QString("too_few_samples"));
    QCOMPARE(o.value("samples").toInt(-1), 0);
}

void tst_StepRunJson::gapWords()
{
    QSet<QString> words;
    for (MetricGap gap :
         {MetricGap::None, MetricGap::TooFewSamples, MetricGap::NoStep, MetricGap::NotReached,
          MetricGap::NeverSettled, MetricGap::NoEffort, MetricGap::NoLimit}) {
        const QString word = StepRunJson::gapWord(gap);
        QVERIFY(!words.contains(word));
        words.insert(word);
        QCOMPARE(StepRunJson::gapFromWord(word), std::optional<MetricGap>(gap));
    }
    QCOMPARE(StepRunJson::gapWord(MetricGap::NeverSettled), QString("never_settled"));
    QVERIFY(!StepRunJson::gapFromWord("Never_Settled"));
}

QTEST_GUILESS_MAIN(tst_StepRunJson)
#include "tst_steprunjson.moc"
