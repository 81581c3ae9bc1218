// Gaps in the data (a silent drive, a dropped link) break the plotted line: no segment is
// drawn across one, decimation never joins across one, and the outage is shaded.

#include <plot/SampleGaps.h>
#include <plot/SampleRing.h>
#include <plot/StripChart.h>
#include <plot/TelemetryStore.h>

#include <QtTest/QTest>

using lk::bus::TelemetryBatch;
using lk::bus::TelemetryField;
using lk::bus::TelemetrySample;
using lk::ui::DecimationMethod;
using lk::ui::LineSegments;
using lk::ui::SampleGap;
using lk::ui::SampleGaps;
using lk::ui::SampleRing;
using lk::ui::TelemetryChannel;
using lk::ui::TelemetryStore;

Q_DECLARE_METATYPE(lk::ui::DecimationMethod)

namespace {

TelemetrySample speedSample(int id, double t, double speed)
{
    TelemetrySample s;
    s.id = id;
    s.time = t;
    s.fields = TelemetryField::Speed;
    s.speedDps = speed;
    return s;
}

/// 10 ms samples of a ramp over [from, to).
void fillRamp(SampleRing &ring, double from, double to, double value)
{
    for (double t = from; t < to - 1e-9; t += 0.01)
        ring.append(t, value + t);
}

/// No segment holds points on both sides of `gap`.
bool neverJoins(const LineSegments &segments, const SampleGap &gap)
{
    for (const QList<QPointF> &segment : segments) {
        bool before = false, after = false;
        for (const QPointF &p : segment) {
            before = before || p.x() <= gap.from;
            after = after || p.x() >= gap.to;
        }
        if (before && after)
            return false;
    }
    return true;
}

} // namespace

class tst_PlotGaps : public QObject {
    Q_OBJECT
private slots:
    void silenceIsAGap();
    void slowCadenceIsNotAGap();
    void lowerPollRateCostsAtMostOneCut();
    void breakForcesAGap();
    void decimationNeverJoinsAcrossAGap_data();
    void decimationNeverJoinsAcrossAGap();
    void disconnectBreaksEveryChannel();
    void chartBreaksTheLineAndShadesTheOutage();
};

void tst_PlotGaps::silenceIsAGap()
{
    SampleRing ring(10000);
    fillRamp(ring, 0, 1, 0);
    const double last = ring.timeAt(ring.size() - 1);
    fillRamp(ring, 3, 4, 0); // two seconds without a sample at a 10 ms cadence
    const QVector<SampleGap> gaps = ring.gaps(0, 10);
    QCOMPARE(gaps.size(), 1);
    QCOMPARE(gaps.first().from, last);
    QCOMPARE(gaps.first().to, 3.0);
    QVERIFY(ring.inGap(2.0));
    QVERIFY(!ring.inGap(0.5));
}

void tst_PlotGaps::slowCadenceIsNotAGap()
{
    SampleGaps gaps;
    for (int i = 1; i < 30; ++i)
        QVERIFY(!gaps.noteSample(i - 1.0, i)); // 1 Hz from the start
    QVERIFY(gaps.isEmpty());
}

void tst_PlotGaps::lowerPollRateCostsAtMostOneCut()
{
    SampleGaps gaps;
    double t = 0;
    for (int i = 0; i < 200; ++i, t += 0.01)
        gaps.noteSample(t, t + 0.01);
    int cuts = 0;
    for (int i = 0; i < 20; ++i, t += 1.0)
        cuts += gaps.noteSample(t, t + 1.0) ? 1 : 0;
    QVERIFY(cuts <= 1);
}

void tst_PlotGaps::breakForcesAGap()
{
    SampleGaps gaps;
    gaps.noteSample(0, 0.01);
    gaps.breakNext();
    QVERIFY(gaps.noteSample(0.01, 0.02)); // however short the outage
    QCOMPARE(gaps.within(0, 1), (QVector<SampleGap>{{0.01, 0.02}}));
}

void tst_PlotGaps::decimationNeverJoinsAcrossAGap_data()
{
    QTest::addColumn<DecimationMethod>("method");
    QTest::addColumn<int>("columns");
    QTest::newRow("scan") << DecimationMethod::Scan << 800;
    QTest::newRow("pyramid") << DecimationMethod::Pyramid << 50;
    QTest::newRow("auto, narrow") << DecimationMethod::Auto << 7;
}

void tst_PlotGaps::decimationNeverJoinsAcrossAGap()
{
    QFETCH(DecimationMethod, method);
    QFETCH(int, columns);
    SampleRing ring(100000);
    fillRamp(ring, 0, 5, 0);
    fillRamp(ring, 8, 12, 100);
    const SampleGap gap = ring.gaps(0, 20).value(0);
    QVERIFY(gap.to == 8.0);
    // The window shows both sides; a window inside the gap shows nothing to join.
    const LineSegments both = ring.decimate(0, 12, columns, method);
    QCOMPARE(both.size(), 2);
    QVERIFY(neverJoins(both, gap));
    QVERIFY(both.first().last().x() <= gap.from);
    QCOMPARE(both.last().first().x(), gap.to);
    QVERIFY(neverJoins(ring.decimate(6, 7, columns, method), gap));
    QVERIFY(neverJoins(ring.decimate(4.5, 8.5, columns, method), gap));
}

void tst_PlotGaps::disconnectBreaksEveryChannel()
{
    TelemetryStore store(10000);
    TelemetryBatch before, after;
    for (int i = 0; i < 100; ++i)
        before.append(speedSample(2, i * 0.01, 360));
    store.append(before);
    store.breakLines(); // the link dropped
    // Back after 30 ms: too short to look like silence, but nothing was measured meanwhile.
    for (int i = 0; i < 100; ++i)
        after.append(speedSample(2, 1.02 + i * 0.01, 0));
    store.append(after);
    const QVector<lk::ui::TimeSpan> out = store.outages(2, TelemetryChannel::Speed, 0, 5);
    QCOMPARE(out.size(), 1);
    QCOMPARE(out.first().begin, 0.99);
    QCOMPARE(out.first().end, 1.02);
    QVERIFY(!store.valueAt(2, TelemetryChannel::Speed, 1.0).has_value());
    QCOMPARE(store.valueAt(2, TelemetryChannel::Speed, 0.5), std::optional<double>(360));
    QCOMPARE(store.decimated(2, TelemetryChannel::Speed, 0, 3, 400).size(), 2);
}

void tst_PlotGaps::chartBreaksTheLineAndShadesTheOutage()
{
    TelemetryStore store(10000);
    TelemetryBatch b;
    for (int i = 0; i < 200; ++i)
        b.append(speedSample(1, i * 0.01, 360)); // turning at 360 dps ...
    for (int i = 0; i < 200; ++i)
        b.append(speedSample(1, 6 + i * 0.01, 0)); // ... seen again stopped, 4 s later
    store.append(b);
    lk::ui::StripChart chart;
    chart.resize(800, 300);
    chart.setTraces({lk::ui::PlotTrace{1, TelemetryChannel::Speed, false}},
                    lk::ui::StripChart::Coloring::ByDrive);
    chart.refresh(store, lk::ui::TimeSpan{0, 8}, true);
    const LineSegments pieces = chart.segments(0);
    QCOMPARE(pieces.size(), 2);
    const SampleGap gap{1.99, 6.0};
    for (const QList<QPointF> &piece : pieces) {
        LineSegments one{piece};
        QVERIFY(neverJoins(one, gap)); // no ramp from 360 to 0 across the outage
    }
    QCOMPARE(chart.outageBands().size(), 1);
    QCOMPARE(chart.outageBands().first().begin, 1.99);
    QCOMPARE(chart.outageBands().first().end, 6.0);
    // Without the gap in view, nothing is shaded and one line is left.
    chart.refresh(store, lk::ui::TimeSpan{6, 8}, true);
    QCOMPARE(chart.segments(0).size(), 1);
    QVERIFY(chart.outageBands().isEmpty());
}

QTEST_MAIN(tst_PlotGaps)
#include "tst_plotgaps.moc"
