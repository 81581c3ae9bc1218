#include <plot/DecimatedSeries.h>
#include <plot/SampleRing.h>

#include <QtCore/QRandomGenerator>
#include <QtTest/QTest>

#include <map>

using lk::ui::DecimationMethod;
using lk::ui::MinMax;
using lk::ui::SampleRing;

namespace {

// Fills a ring with `total` points at 1 kHz and random values; returns every value appended.
QVector<double> fill(SampleRing &ring, int total, quint32 seed)
{
    QRandomGenerator random(seed);
    QVector<double> all;
    for (int i = 0; i < total; ++i) {
        const double v = random.bounded(200.0) - 100.0;
        all.append(v);
        ring.append(i * 0.001, v);
    }
    return all;
}

// ring.minMax over 300 random index ranges against a scan of `all` (oldest first).
void checkMinMaxAgainstBruteForce(const SampleRing &ring, const QVector<double> &all)
{
    const int oldest = int(all.size() - ring.size());
    QRandomGenerator random(99);
    for (int trial = 0; trial < 300; ++trial) {
        qsizetype a = random.bounded(int(ring.size()));
        qsizetype b = random.bounded(int(ring.size()) + 1);
        if (trial == 0) {
            a = 0;
            b = ring.size(); // everything held
        }
        if (a > b) {
            std::swap(a, b);
        }
        MinMax expected;
        for (qsizetype i = a; i < b; ++i) {
            expected.add(all[oldest + i]);
        }
        const MinMax got = ring.minMax(a, b);
        QCOMPARE(got.isValid(), expected.isValid());
        if (expected.isValid()) {
            QCOMPARE(got.min, expected.min);
            QCOMPARE(got.max, expected.max);
        }
    }
}

using ColumnExtremes = std::map<int, std::pair<double, double>>;

ColumnExtremes extremes(const QList<QPointF> &points, double t0, double t1, int columns)
{
    ColumnExtremes result;
    for (const QPointF &p : points) {
        if (p.x() < t0 || p.x() > t1) {
            continue;
        }
        const int c = lk::ui::decimationColumn(p.x(), t0, t1, columns);
        auto [it, fresh] = result.try_emplace(c, p.y(), p.y());
        if (!fresh) {
            it->second.first = std::min(it->second.first, p.y());
            it->second.second = std::max(it->second.second, p.y());
        }
    }
    return result;
}

} // namespace

class tst_SampleRing : public QObject {
    Q_OBJECT
private slots:
    void wrapKeepsNewest_data();
    void wrapKeepsNewest();
    void refusesTimeGoingBack();
    void minMaxMatchesBruteForce_data();
    void minMaxMatchesBruteForce();
    void pyramidMatchesScan_data();
    void pyramidMatchesScan();
    void pyramidKeepsSpike();
    void boundsOnWrappedData();
    void retentionClosesTheRing();
    void closedRingStaysExact();
};

void tst_SampleRing::wrapKeepsNewest_data()
{
    QTest::addColumn<int>("capacity");
    QTest::addColumn<int>("appended");
    QTest::newRow("not full") << 100 << 40;
    QTest::newRow("exactly full") << 100 << 100;
    QTest::newRow("one over") << 100 << 101;
    QTest::newRow("many wraps") << 100 << 1234;
    QTest::newRow("capacity 1") << 1 << 5;
    QTest::newRow("capacity not a power of two") << 1000 << 5555;
}

void tst_SampleRing::wrapKeepsNewest()
{
    QFETCH(int, capacity);
    QFETCH(int, appended);
    SampleRing ring(capacity);
    for (int i = 0; i < appended; ++i) {
        QVERIFY(ring.append(i, i * 10.0));
    }
    const int held = std::min(capacity, appended);
    QCOMPARE(ring.size(), held);
    QCOMPARE(ring.capacity(), capacity);
    QCOMPARE(ring.totalAppended(), quint64(appended));
    const int oldest = appended - held;
    for (int i = 0; i < held; ++i) {
        QCOMPARE(ring.timeAt(i), double(oldest + i));
        QCOMPARE(ring.valueAt(i), (oldest + i) * 10.0);
    }
}

void tst_SampleRing::refusesTimeGoingBack()
{
    SampleRing ring(10);
    QVERIFY(ring.append(1.0, 1));
    QVERIFY(ring.append(1.0, 2)); // equal times are fine (two fields of one reply)
    QVERIFY(!ring.append(0.5, 3));
    QVERIFY(!ring.append(qQNaN(), 3));
    QVERIFY(!ring.append(2.0, qInf()));
    QCOMPARE(ring.size(), 2);
}

void tst_SampleRing::minMaxMatchesBruteForce_data()
{
    QTest::addColumn<int>("capacity");
    QTest::addColumn<int>("appended");
    QTest::newRow("unwrapped") << 5000 << 3000;
    QTest::newRow("wrapped once") << 5000 << 7321;
    QTest::newRow("wrapped many, odd capacity") << 4099 << 40000;
    QTest::newRow("large blocks") << 200000 << 450000;
}

void tst_SampleRing::minMaxMatchesBruteForce()
{
    QFETCH(int, capacity);
    QFETCH(int, appended);
    SampleRing ring(capacity);
    const QVector<double> all = fill(ring, appended, 7);
    checkMinMaxAgainstBruteForce(ring, all);
}

void tst_SampleRing::pyramidMatchesScan_data()
{
    QTest::addColumn<int>("capacity");
    QTest::addColumn<int>("appended");
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("t1");
    QTest::addColumn<int>("columns");
    QTest::newRow("whole, unwrapped") << 100000 << 60000 << 0.0 << 60.0 << 1400;
    QTest::newRow("wrapped, whole held") << 50000 << 123456 << 73.456 << 123.455 << 1400;
    QTest::newRow("wrapped, inner window") << 50000 << 123456 << 80.0 << 110.0 << 333;
    QTest::newRow("window past the newest") << 50000 << 123456 << 100.0 << 200.0 << 500;
    QTest::newRow("narrow plot") << 100000 << 100000 << 0.0 << 100.0 << 7;
}

void tst_SampleRing::pyramidMatchesScan()
{
    QFETCH(int, capacity);
    QFETCH(int, appended);
    QFETCH(double, t0);
    QFETCH(double, t1);
    QFETCH(int, columns);
    SampleRing ring(capacity);
    fill(ring, appended, 3);
    const lk::ui::LineSegments scanned = ring.decimate(t0, t1, columns, DecimationMethod::Scan);
    const lk::ui::LineSegments pyramided =
        ring.decimate(t0, t1, columns, DecimationMethod::Pyramid);
    QCOMPARE(scanned.size(), 1); // regular samples: no gap, one line
    QCOMPARE(pyramided.size(), 1);
    const QList<QPointF> scan = scanned.first();
    const QList<QPointF> pyramid = pyramided.first();
    QVERIFY(!scan.isEmpty());
    QCOMPARE(extremes(pyramid, t0, t1, columns), extremes(scan, t0, t1, columns));
    QVERIFY(pyramid.size() <= 2 * columns + 4);
    QCOMPARE(pyramid.first(), scan.first()); // same neighbour (or first point)
    QCOMPARE(pyramid.last(), scan.last());
    for (qsizetype i = 1; i < pyramid.size(); ++i) {
        QVERIFY(pyramid[i].x() >= pyramid[i - 1].x());
    }
}

void tst_SampleRing::pyramidKeepsSpike()
{
    SampleRing ring(600000);
    for (int i = 0; i < 600000; ++i) {
        ring.append(i * 0.001, i == 431234 ? 50.0 : (i == 77777 ? -20.0 : 0.0));
    }
    const QList<QPointF> out = ring.decimate(0, 600, 1400, DecimationMethod::Pyramid).value(0);
    bool up = false, down = false;
    for (const QPointF &p : out) {
        up = up || p.y() == 50.0;
        down = down || p.y() == -20.0;
    }
    QVERIFY(up);
    QVERIFY(down);
}

void tst_SampleRing::boundsOnWrappedData()
{
    SampleRing ring(1000);
    for (int i = 0; i < 2500; ++i) {
        ring.append(i / 100.0, i);
    }
    // Held: times 15.00 .. 24.99.
    QCOMPARE(ring.timeAt(0), 15.0);
    QCOMPARE(ring.lowerBound(0), 0);
    QCOMPARE(ring.lowerBound(20.0), 500);
    QCOMPARE(ring.upperBound(20.0), 501);
    QCOMPARE(ring.lowerBound(30.0), 1000);
    QCOMPARE(ring.valueAt(ring.lowerBound(20.0)), 2000.0);
}

// A ring that would hold 600,000 points at 1 kHz gets points at 100 Hz: it closes once it
// spans the retention (2 s here), so memory follows the retention at the real rate (the
// GUI's recording grew for an hour before, at ~5 MB a minute).
void tst_SampleRing::retentionClosesTheRing()
{
    SampleRing ring(600000, 2.0);
    for (int i = 0; i < 1000; ++i) {
        QVERIFY(ring.append(i * 0.01, i));
    }
    QCOMPARE(ring.capacity(), qsizetype(201)); // 0.00 .. 2.00 s held when 2.01 s came
    QCOMPARE(ring.size(), ring.capacity());
    QCOMPARE(ring.valueAt(ring.size() - 1), 999.0);
    QVERIFY(ring.timeAt(ring.size() - 1) - ring.timeAt(0) >= 2.0 - 1e-9);
    // A new recording may come at another rate: clear() starts over at the full capacity.
    ring.clear();
    QCOMPARE(ring.capacity(), qsizetype(600000));
    // Without a retention the ring fills to its capacity as before.
    SampleRing unbounded(5000);
    for (int i = 0; i < 3000; ++i) {
        unbounded.append(i * 0.01, i);
    }
    QCOMPARE(unbounded.size(), qsizetype(3000));
}

// After closing early, min/max and decimation agree with brute force across many wraps.
void tst_SampleRing::closedRingStaysExact()
{
    SampleRing ring(100000, 3.0);
    const QVector<double> all = fill(ring, 25000, 11); // 1 kHz: closes at 3001 points
    QCOMPARE(ring.capacity(), qsizetype(3001));
    checkMinMaxAgainstBruteForce(ring, all);
    const double t0 = ring.timeAt(0), t1 = ring.timeAt(ring.size() - 1);
    const auto scan = ring.decimate(t0, t1, 97, DecimationMethod::Scan);
    const auto pyramid = ring.decimate(t0, t1, 97, DecimationMethod::Pyramid);
    QCOMPARE(scan.size(), 1);
    QCOMPARE(pyramid.size(), 1);
    QCOMPARE(extremes(pyramid.first(), t0, t1, 97), extremes(scan.first(), t0, t1, 97));
}

QTEST_APPLESS_MAIN(tst_SampleRing)
#include "tst_samplering.moc"
