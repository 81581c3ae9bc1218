#include <plot/TelemetryStore.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

using lk::bus::TelemetryBatch;
using lk::bus::TelemetryField;
using lk::bus::TelemetrySample;
using lk::ui::TelemetryChannel;
using lk::ui::TelemetryStore;

namespace {

TelemetrySample mfSample(int id, double t, double iq, double speed, int encoder)
{
    TelemetrySample s;
    s.id = id;
    s.time = t;
    s.fields = TelemetryField::IqA | TelemetryField::Speed | TelemetryField::Encoder |
               TelemetryField::Temperature;
    s.iqA = iq;
    s.speedDps = speed;
    s.encoder = encoder;
    s.temperatureC = 30;
    return s;
}

TelemetrySample msSample(int id, double t, int power)
{
    TelemetrySample s;
    s.id = id;
    s.time = t;
    s.fields = TelemetryField::Power | TelemetryField::Speed;
    s.power = power;
    s.iqA = 99; // not flagged: must be ignored
    s.speedDps = 5;
    return s;
}

} // namespace

class tst_TelemetryStore : public QObject {
    Q_OBJECT
private slots:
    void routesFields();
    void routesCommandedPositionFields();
    void powerVersusIq_data();
    void powerVersusIq();
    void torqueKindChangeDropsOldUnit();
    void capacityBoundKeepsNewest();
    void queriesOverWrappedData();
    void valueAtIsLastSampleAtOrBefore();
    void coalescesNotifications();
    void clearDropsEverything();
    void rejectsTimeGoingBack();
};

void tst_TelemetryStore::routesFields()
{
    TelemetryStore store(100);
    TelemetrySample s = mfSample(3, 1.0, 0.5, 120, 8000);
    s.fields |= TelemetryField::MultiTurn | TelemetryField::SingleTurn | TelemetryField::Voltage |
                TelemetryField::PhaseCurrents;
    s.multiTurnDeg = 720.5;
    s.singleTurnDeg = 10.25;
    s.voltageV = 24.1;
    s.iaA = 1;
    s.ibA = -2;
    s.icA = 1.5;
    store.append({s});
    QCOMPARE(store.driveIds(), QVector<int>{3});
    const std::pair<TelemetryChannel, double> expected[] = {
        {TelemetryChannel::Torque, 0.5},       {TelemetryChannel::Speed, 120},
        {TelemetryChannel::Encoder, 8000},     {TelemetryChannel::MultiTurn, 720.5},
        {TelemetryChannel::SingleTurn, 10.25}, {TelemetryChannel::Temperature, 30},
        {TelemetryChannel::Voltage, 24.1},     {TelemetryChannel::PhaseA, 1},
        {TelemetryChannel::PhaseB, -2},        {TelemetryChannel::PhaseC, 1.5},
    };
    for (const auto &[channel, value] : expected) {
        QCOMPARE(store.count(3, channel), 1);
        QCOMPARE(store.valueAt(3, channel, 1.0), value);
    }
    QCOMPARE(store.count(4, TelemetryChannel::Speed), 0);
    QVERIFY(store.ring(3, TelemetryChannel::Torque) != nullptr);
}

// What another master commanded with 0xA5..0xA8 (listen-only) is plotted beside the replies.
void tst_TelemetryStore::routesCommandedPositionFields()
{
    TelemetryStore store(100);
    TelemetrySample s;
    s.id = 2;
    s.time = 1.0;
    s.fields = TelemetryField::CommandedSingleTurn | TelemetryField::CommandedIncrement |
               TelemetryField::CommandedMaxSpeed;
    s.commandedSingleTurnDeg = 90.5;
    s.commandedIncrementDeg = -30;
    s.commandedMaxSpeedDps = 360;
    store.append({s});
    QCOMPARE(store.valueAt(2, TelemetryChannel::CommandedSingleTurn, 1.0), 90.5);
    QCOMPARE(store.valueAt(2, TelemetryChannel::CommandedIncrement, 1.0), -30.0);
    QCOMPARE(store.valueAt(2, TelemetryChannel::CommandedMaxSpeed, 1.0), 360.0);
    QCOMPARE(store.count(2, TelemetryChannel::CommandedAngle), 0);
}

void tst_TelemetryStore::powerVersusIq_data()
{
    QTest::addColumn<bool>("ms");
    QTest::addColumn<bool>("power");
    QTest::addColumn<double>("torque");
    QTest::newRow("MF reports iq") << false << false << 1.25;
    QTest::newRow("MS reports power") << true << true << -640.0;
}

void tst_TelemetryStore::powerVersusIq()
{
    QFETCH(bool, ms);
    QFETCH(bool, power);
    QFETCH(double, torque);
    TelemetryStore store(100);
    QVERIFY(!store.torqueIsPower(7).has_value());
    store.append({ms ? msSample(7, 0.1, -640) : mfSample(7, 0.1, 1.25, 0, 0)});
    QCOMPARE(store.torqueIsPower(7), std::optional<bool>(power));
    QCOMPARE(store.valueAt(7, TelemetryChannel::Torque, 0.1), torque);
}

void tst_TelemetryStore::torqueKindChangeDropsOldUnit()
{
    TelemetryStore store(100);
    store.append({mfSample(2, 0.1, 1.0, 0, 0), mfSample(2, 0.2, 2.0, 0, 0)});
    QCOMPARE(store.count(2, TelemetryChannel::Torque), 2);
    store.append({msSample(2, 0.3, 500)});
    QCOMPARE(store.count(2, TelemetryChannel::Torque), 1); // amps are not power
    QCOMPARE(store.torqueIsPower(2), std::optional<bool>(true));
    QCOMPARE(store.count(2, TelemetryChannel::Speed), 3); // other channels kept
}

void tst_TelemetryStore::capacityBoundKeepsNewest()
{
    TelemetryStore store(1000);
    QCOMPARE(store.capacity(), 1000);
    for (int batch = 0; batch < 25; ++batch) {
        TelemetryBatch b;
        for (int i = 0; i < 100; ++i) {
            const int k = batch * 100 + i;
            b.append(mfSample(1, k * 0.001, k, 0, 0));
        }
        store.append(b);
    }
    const lk::ui::SampleRing *ring = store.ring(1, TelemetryChannel::Torque);
    QVERIFY(ring);
    QCOMPARE(ring->size(), 1000);
    QCOMPARE(ring->totalAppended(), quint64(2500));
    QCOMPARE(ring->valueAt(0), 1500.0);
    QCOMPARE(ring->valueAt(999), 2499.0);
    const std::optional<lk::ui::TimeSpan> span = store.timeSpan();
    QVERIFY(span);
    QCOMPARE(span->begin, 1.5);
    QCOMPARE(span->end, 2.499);
}

void tst_TelemetryStore::queriesOverWrappedData()
{
    TelemetryStore store(1000);
    TelemetryBatch b;
    for (int k = 0; k < 3500; ++k) {
        // A ramp with one spike in the held part.
        b.append(mfSample(1, k * 0.001, k == 3000 ? 1e6 : k, 0, 0));
    }
    store.append(b);
    // Only 2.500 .. 3.499 is held; a window reaching back further starts at the oldest.
    const lk::ui::SampleRing *ring = store.ring(1, TelemetryChannel::Torque);
    const lk::ui::LineSegments segments =
        store.decimated(1, TelemetryChannel::Torque, 0.0, 10.0, 100);
    QCOMPARE(segments.size(), 1);
    const QList<QPointF> points = segments.first();
    QVERIFY(points.size() <= 2 * 100 + 4);
    QCOMPARE(points.first(), QPointF(ring->timeAt(0), 2500));
    QCOMPARE(points.last(), QPointF(ring->timeAt(999), 3499));
    bool spike = false;
    for (const QPointF &p : points) {
        spike = spike || p.y() == 1e6;
        QVERIFY(p.x() >= ring->timeAt(0));
    }
    QVERIFY(spike);
    // A window before the held data shows only the neighbour after it (the line's start).
    QCOMPARE(store.decimated(1, TelemetryChannel::Torque, 0, 2.4, 100),
             lk::ui::LineSegments{{QPointF(ring->timeAt(0), 2500)}});
    QVERIFY(store.decimated(9, TelemetryChannel::Torque, 0, 10, 100).isEmpty());
}

void tst_TelemetryStore::valueAtIsLastSampleAtOrBefore()
{
    TelemetryStore store(100);
    store.append({mfSample(1, 1.0, 10, 0, 0), mfSample(1, 2.0, 20, 0, 0)});
    QCOMPARE(store.valueAt(1, TelemetryChannel::Torque, 0.5), std::nullopt);
    QCOMPARE(store.valueAt(1, TelemetryChannel::Torque, 1.0), 10.0);
    QCOMPARE(store.valueAt(1, TelemetryChannel::Torque, 1.99), 10.0);
    QCOMPARE(store.valueAt(1, TelemetryChannel::Torque, 5.0), 20.0);
    QCOMPARE(store.valueAt(1, TelemetryChannel::Voltage, 5.0), std::nullopt);
}

void tst_TelemetryStore::coalescesNotifications()
{
    TelemetryStore store(100);
    QSignalSpy spy(&store, &TelemetryStore::dataAppended);
    const quint64 before = store.revision();
    store.append({mfSample(1, 0.1, 1, 0, 0)});
    store.append({mfSample(1, 0.2, 1, 0, 0)});
    store.append({mfSample(1, 0.3, 1, 0, 0)});
    QVERIFY(store.revision() != before);
    QCOMPARE(spy.count(), 0); // not emitted from inside append()
    QTRY_COMPARE(spy.count(), 1);
    store.append({});
    QTest::qWait(50);
    QCOMPARE(spy.count(), 1); // an empty batch is no news
    store.append({mfSample(1, 0.4, 1, 0, 0)});
    QTRY_COMPARE(spy.count(), 2);
}

void tst_TelemetryStore::clearDropsEverything()
{
    TelemetryStore store(100);
    QSignalSpy spy(&store, &TelemetryStore::cleared);
    store.append({mfSample(1, 0.1, 1, 0, 0), msSample(2, 0.1, 3)});
    store.clear();
    QCOMPARE(spy.count(), 1);
    QVERIFY(store.driveIds().isEmpty());
    QVERIFY(!store.timeSpan().has_value());
    QCOMPARE(store.ring(1, TelemetryChannel::Torque), nullptr);
}

void tst_TelemetryStore::rejectsTimeGoingBack()
{
    TelemetryStore store(100);
    store.append({mfSample(1, 1.0, 1, 0, 0), mfSample(1, 0.5, 2, 0, 0)});
    QCOMPARE(store.count(1, TelemetryChannel::Torque), 1);
    QVERIFY(store.rejectedSamples() > 0);
}

QTEST_GUILESS_MAIN(tst_TelemetryStore)
#include "tst_telemetrystore.moc"
