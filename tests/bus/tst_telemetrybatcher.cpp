#include "../support/ManualTimers.h"

#include <bus/TelemetryBatcher.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using lk::bus::TelemetryBatch;
using lk::bus::TelemetryBatcher;
using lk::bus::TelemetrySample;
using lk::testsupport::ManualClock;
using lk::testsupport::ManualTimers;

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
    void atMostRateHzBatchesWhateverTheSampleRate_data();
    void atMostRateHzBatchesWhateverTheSampleRate();
    void intervalFollowsTheRate_data();
    void intervalFollowsTheRate();
};

void tst_TelemetryBatcher::samplesArriveAsOneBatch()
{
    ManualTimers timers(std::make_shared<ManualClock>());
    TelemetryBatcher b(nullptr, timers.factory());
    b.setRateHz(20);
    QSignalSpy ready(&b, &TelemetryBatcher::batchReady);
    for (int i = 0; i < 5; ++i)
        b.add(sample(i + 1, i * 0.001));
    timers.advance(49);
    QCOMPARE(ready.count(), 0); // nothing until the interval has passed
    timers.advance(1);
    QCOMPARE(ready.count(), 1);
    const auto batch = ready.at(0).at(0).value<TelemetryBatch>();
    QCOMPARE(batch.size(), 5);
    for (int i = 0; i < 5; ++i)
        QCOMPARE(batch.at(i).id, i + 1);
    b.add(sample(9, 1.0)); // the next sample starts the next batch
    timers.advance(50);
    QCOMPARE(ready.count(), 2);
    QCOMPARE(ready.at(1).at(0).value<TelemetryBatch>().size(), 1);
}

void tst_TelemetryBatcher::flushHandsOnAtOnceAndNothingWhenEmpty()
{
    ManualTimers timers(std::make_shared<ManualClock>());
    TelemetryBatcher b(nullptr, timers.factory());
    b.setRateHz(1); // a second: flush() must not wait for it
    QSignalSpy ready(&b, &TelemetryBatcher::batchReady);
    b.flush();
    QCOMPARE(ready.count(), 0);
    b.add(sample(3, 0));
    b.flush();
    QCOMPARE(ready.count(), 1);
    timers.advance(1200); // the stopped clock sends no second, empty batch
    QCOMPARE(ready.count(), 1);
}

void tst_TelemetryBatcher::atMostRateHzBatchesWhateverTheSampleRate_data()
{
    QTest::addColumn<int>("samplesPerInterval");
    QTest::newRow("one") << 1;
    QTest::newRow("a 1 Mbaud bus of 4 drives") << 40;
    QTest::newRow("a flood") << 5000;
}

void tst_TelemetryBatcher::atMostRateHzBatchesWhateverTheSampleRate()
{
    // The rate bound, on a clock the test runs: however many samples come, the receiving
    // thread gets one batch per interval, and none between two ticks of the clock.
    QFETCH(int, samplesPerInterval);
    ManualTimers timers;
    TelemetryBatcher b(nullptr, timers.factory());
    b.setRateHz(60);
    QSignalSpy ready(&b, &TelemetryBatcher::batchReady);
    QCOMPARE(timers.count(), 1);
    int sent = 0;
    const int intervals = 100;
    for (int k = 0; k < intervals; ++k) {
        for (int i = 0; i < samplesPerInterval; ++i)
            b.add(sample(1 + sent++ % 32, k + i * 1e-6));
        QCOMPARE(ready.count(), k); // samples alone never hand a batch on
        QVERIFY(timers.at(0).active);
        QCOMPARE(timers.at(0).lastMs, 16);
        QVERIFY(timers.fire());
        QCOMPARE(ready.count(), k + 1);
    }
    QCOMPARE(timers.at(0).starts, intervals); // one start per batch, not per sample
    int received = 0;
    for (const QList<QVariant> &args : ready)
        received += int(args.at(0).value<TelemetryBatch>().size());
    QCOMPARE(received, sent);
    QVERIFY(!timers.fire()); // idle: the clock is stopped, no empty batch follows
    QCOMPARE(ready.count(), intervals);
}

void tst_TelemetryBatcher::intervalFollowsTheRate_data()
{
    QTest::addColumn<double>("rateHz");
    QTest::addColumn<int>("intervalMs");
    QTest::newRow("60 Hz (the product's)") << 60.0 << 16;
    QTest::newRow("20 Hz") << 20.0 << 50;
    QTest::newRow("1 Hz") << 1.0 << 1000;
    QTest::newRow("below 1 Hz is 1 Hz") << 0.1 << 1000;
    QTest::newRow("0 is 1 Hz, never a busy loop") << 0.0 << 1000;
}

void tst_TelemetryBatcher::intervalFollowsTheRate()
{
    QFETCH(double, rateHz);
    QFETCH(int, intervalMs);
    ManualTimers timers;
    TelemetryBatcher b(nullptr, timers.factory());
    b.setRateHz(rateHz);
    QCOMPARE(b.intervalMs(), intervalMs);
    b.add(sample(1, 0));
    QCOMPARE(timers.at(0).lastMs, intervalMs);
}

QTEST_GUILESS_MAIN(tst_TelemetryBatcher)
#include "tst_telemetrybatcher.moc"
