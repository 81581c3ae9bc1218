#include <plot/DecimatedSeries.h>

#include <QtCore/QRandomGenerator>
#include <QtTest/QTest>

#include <map>

using lk::ui::DecimatedSeries;
using lk::ui::decimationColumn;

namespace {

QList<QPointF> flatWithSpikes(int n, double dt, const std::map<int, double> &spikes)
{
    QList<QPointF> points;
    for (int i = 0; i < n; ++i) {
        const auto it = spikes.find(i);
        points.append({i * dt, it == spikes.end() ? 0.0 : it->second});
    }
    return points;
}

bool isAscending(const QList<QPointF> &points)
{
    for (qsizetype i = 1; i < points.size(); ++i) {
        if (points[i].x() < points[i - 1].x()) {
            return false;
        }
    }
    return true;
}

} // namespace

class tst_DecimatedSeries : public QObject {
    Q_OBJECT
private slots:
    void spikeSurvives_data();
    void spikeSurvives();
    void exactMinMaxPerColumn_data();
    void exactMinMaxPerColumn();
    void smallInputs_data();
    void smallInputs();
    void windowEdges();
    void keepsRealFirstAndLast();
    void columnOfTimes_data();
    void columnOfTimes();
};

void tst_DecimatedSeries::spikeSurvives_data()
{
    QTest::addColumn<int>("columns");
    QTest::addColumn<int>("spikeIndex");
    QTest::addColumn<double>("spikeValue");
    QTest::newRow("one column, middle") << 1 << 5000 << 100.0;
    QTest::newRow("100 columns, up") << 100 << 5003 << 100.0;
    QTest::newRow("100 columns, down") << 100 << 7777 << -50.0;
    QTest::newRow("1400 columns, first sample") << 1400 << 0 << 3.0;
    QTest::newRow("1400 columns, last sample") << 1400 << 9999 << -3.0;
    QTest::newRow("more columns than points") << 20000 << 4321 << 9.0;
}

void tst_DecimatedSeries::spikeSurvives()
{
    QFETCH(int, columns);
    QFETCH(int, spikeIndex);
    QFETCH(double, spikeValue);
    const QList<QPointF> points = flatWithSpikes(10000, 0.001, {{spikeIndex, spikeValue}});
    const QList<QPointF> out = DecimatedSeries::decimate(points, 0, 9.999, columns);
    QVERIFY(out.contains(points[spikeIndex]));
    QVERIFY(out.size() <= 2 * columns + 4);
    QVERIFY(isAscending(out));
}

void tst_DecimatedSeries::exactMinMaxPerColumn_data()
{
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("columns");
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("t1");
    QTest::newRow("whole, 10 per column") << 10000 << 1000 << 0.0 << 9.999;
    QTest::newRow("whole, 1 per column") << 1000 << 1000 << 0.0 << 0.999;
    QTest::newRow("inner window") << 50000 << 640 << 12.3456 << 31.5;
    QTest::newRow("window wider than data") << 3000 << 300 << -5.0 << 10.0;
    QTest::newRow("odd column count") << 7919 << 13 << 0.5 << 7.0;
}

void tst_DecimatedSeries::exactMinMaxPerColumn()
{
    QFETCH(int, n);
    QFETCH(int, columns);
    QFETCH(double, t0);
    QFETCH(double, t1);
    QRandomGenerator random(42);
    QList<QPointF> points;
    for (int i = 0; i < n; ++i) {
        points.append({i * 0.001, random.bounded(2000.0) - 1000.0});
    }
    std::map<int, std::pair<double, double>> expected; // column -> (min, max), brute force
    for (const QPointF &p : points) {
        if (p.x() < t0 || p.x() > t1) {
            continue;
        }
        const int c = decimationColumn(p.x(), t0, t1, columns);
        auto [it, fresh] = expected.try_emplace(c, p.y(), p.y());
        if (!fresh) {
            it->second.first = std::min(it->second.first, p.y());
            it->second.second = std::max(it->second.second, p.y());
        }
    }
    const QList<QPointF> out = DecimatedSeries::decimate(points, t0, t1, columns);
    std::map<int, std::pair<double, double>> got;
    for (const QPointF &p : out) {
        if (p.x() < t0 || p.x() > t1) {
            continue;
        }
        QVERIFY2(points.contains(p), "every output point is a real input point");
        const int c = decimationColumn(p.x(), t0, t1, columns);
        auto [it, fresh] = got.try_emplace(c, p.y(), p.y());
        if (!fresh) {
            it->second.first = std::min(it->second.first, p.y());
            it->second.second = std::max(it->second.second, p.y());
        }
    }
    QCOMPARE(got, expected);
    QVERIFY(out.size() <= 2 * columns + 4);
    QVERIFY(isAscending(out));
}

void tst_DecimatedSeries::smallInputs_data()
{
    QTest::addColumn<QList<QPointF>>("points");
    QTest::addColumn<QList<QPointF>>("expected");
    QTest::newRow("empty") << QList<QPointF>{} << QList<QPointF>{};
    QTest::newRow("one inside") << QList<QPointF>{{5, 1}} << QList<QPointF>{{5, 1}};
    QTest::newRow("one before") << QList<QPointF>{{-1, 2}} << QList<QPointF>{{-1, 2}};
    QTest::newRow("one after") << QList<QPointF>{{11, 3}} << QList<QPointF>{{11, 3}};
    QTest::newRow("two in one column")
        << QList<QPointF>{{5, 1}, {5.001, 1}} << QList<QPointF>{{5, 1}, {5.001, 1}};
    QTest::newRow("flat column keeps ends")
        << QList<QPointF>{{5, 1}, {5.001, 1}, {5.002, 1}, {5.003, 1}}
        << QList<QPointF>{{5, 1}, {5.003, 1}};
}

void tst_DecimatedSeries::smallInputs()
{
    QFETCH(QList<QPointF>, points);
    QFETCH(QList<QPointF>, expected);
    QCOMPARE(DecimatedSeries::decimate(points, 0, 10, 10), expected);
}

void tst_DecimatedSeries::windowEdges()
{
    // Points exactly on t0 and t1 are inside; only the nearest point outside each edge stays.
    const QList<QPointF> points{{-2, 9}, {-1, 8}, {0, 1}, {5, 2}, {10, 3}, {11, 7}, {12, 6}};
    const QList<QPointF> out = DecimatedSeries::decimate(points, 0, 10, 4);
    const QList<QPointF> expected{{-1, 8}, {0, 1}, {5, 2}, {10, 3}, {11, 7}};
    QCOMPARE(out, expected);
    QCOMPARE(decimationColumn(10, 0, 10, 4), 3); // t1 belongs to the last column
    QCOMPARE(decimationColumn(0, 0, 10, 4), 0);
}

void tst_DecimatedSeries::keepsRealFirstAndLast()
{
    // First and last points are neither the minimum nor the maximum of their column.
    QList<QPointF> points;
    const double values[] = {5, 0, 10, 5, 7, 1, 9, 6};
    for (int i = 0; i < 8; ++i) {
        points.append({i * 0.1, values[i]});
    }
    const QList<QPointF> out = DecimatedSeries::decimate(points, 0, 1.0, 1);
    const QList<QPointF> expected{{0, 5}, {0.1, 0}, {0.2, 10}, {0.7, 6}};
    QCOMPARE(out, expected);
}

void tst_DecimatedSeries::columnOfTimes_data()
{
    QTest::addColumn<double>("time");
    QTest::addColumn<int>("column");
    QTest::newRow("start") << 0.0 << 0;
    QTest::newRow("just before boundary") << 0.999 << 0;
    QTest::newRow("boundary") << 1.0 << 1;
    QTest::newRow("end") << 10.0 << 9;
    QTest::newRow("before window clamps") << -3.0 << 0;
    QTest::newRow("after window clamps") << 13.0 << 9;
}

void tst_DecimatedSeries::columnOfTimes()
{
    QFETCH(double, time);
    QFETCH(int, column);
    QCOMPARE(decimationColumn(time, 0, 10, 10), column);
}

QTEST_APPLESS_MAIN(tst_DecimatedSeries)
#include "tst_decimatedseries.moc"
