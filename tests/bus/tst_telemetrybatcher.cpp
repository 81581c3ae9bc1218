#include <bus/TelemetryBatcher.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using lk::bus::TelemetryBatch;
using lk::bus::TelemetryBatcher;
using lk::bus::TelemetrySample;

namespace {
TelemetrySample sample(int id, double t)
{
    TelemetrySample s;
    s.id = id;
    s.time = t;
    return s;
}
} // namespace

/// Samples go out in batches, in order, each sample exactly once.
class tst_TelemetryBatcher : public QObject {
    Q_OBJECT
private slots:
    void samplesArriveAsOneBatch();
    void flushHandsOnAtOnceAndNothingWhenEmpty();
};

void tst_TelemetryBatcher::samplesArriveAsOneBatch()
{
    TelemetryBatcher b;
    b.setRateHz(20);
    QSignalSpy ready(&b, &TelemetryBatcher::batchReady);
    for (int i = 0; i < 5; ++i)
        b.add(sample(i + 1, i * 0.001));
    QCOMPARE(ready.count(), 0); // nothing until the interval has passed
    QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, 10000);
    const auto batch = ready.at(0).at(0).value<TelemetryBatch>();
    QCOMPARE(batch.size(), 5);
    for (int i = 0; i < 5; ++i)
        QCOMPARE(batch.at(i).id, i + 1);
    b.add(sample(9, 1.0)); // the next sample starts the next batch
    QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 2, 10000);
    QCOMPARE(ready.at(1).at(0).value<TelemetryBatch>().size(), 1);
}

void tst_TelemetryBatcher::flushHandsOnAtOnceAndNothingWhenEmpty()
{
    TelemetryBatcher b;
    b.setRateHz(1); // a second: flush() must not wait for it
    QSignalSpy ready(&b, &TelemetryBatcher::batchReady);
    b.flush();
    QCOMPARE(ready.count(), 0);
    b.add(sample(3, 0));
    b.flush();
    QCOMPARE(ready.count(), 1);
    QTest::qWait(1200); // the stopped clock sends no second, empty batch
    QCOMPARE(ready.count(), 1);
}

QTEST_GUILESS_MAIN(tst_TelemetryBatcher)
#include "tst_telemetrybatcher.moc"
