#include <bus/NewestSample.h>

#include <QtTest/QTest>

using lk::bus::newestSample;
using lk::bus::TelemetryBatch;
using lk::bus::TelemetryField;
using lk::bus::TelemetrySample;

namespace {
TelemetrySample sample(int id, double time, TelemetryField field)
{
    TelemetrySample s;
    s.id = id;
    s.time = time;
    s.fields = field;
    return s;
}
} // namespace

/// A view's "present state" of a drive is the newest of its samples that carries the field.
class tst_NewestSample : public QObject {
    Q_OBJECT
private slots:
    void newestOfThatDriveWithThatField();
    void nullWhenNoSampleCarriesIt();
};

void tst_NewestSample::newestOfThatDriveWithThatField()
{
    const TelemetryBatch batch{
        sample(1, 0.1, TelemetryField::Speed), sample(1, 0.2, TelemetryField::MultiTurn),
        sample(2, 0.3, TelemetryField::Speed), sample(1, 0.4, TelemetryField::Speed),
        sample(1, 0.5, TelemetryField::MultiTurn)};
    const TelemetrySample *speed = newestSample(batch, 1, TelemetryField::Speed);
    QVERIFY(speed);
    QCOMPARE(speed->time, 0.4); // not drive 2's newer one, not the newer angle sample
    const TelemetrySample *angle = newestSample(batch, 1, TelemetryField::MultiTurn);
    QVERIFY(angle);
    QCOMPARE(angle->time, 0.5);
    const TelemetrySample *other = newestSample(batch, 2, TelemetryField::Speed);
    QVERIFY(other);
    QCOMPARE(other->time, 0.3);
}

void tst_NewestSample::nullWhenNoSampleCarriesIt()
{
    const TelemetryBatch batch{sample(1, 0.1, TelemetryField::Speed)};
    QCOMPARE(newestSample(batch, 1, TelemetryField::MultiTurn), nullptr);
    QCOMPARE(newestSample(batch, 3, TelemetryField::Speed), nullptr);
    QCOMPARE(newestSample(TelemetryBatch{}, 1, TelemetryField::Speed), nullptr);
}

QTEST_APPLESS_MAIN(tst_NewestSample)
#include "tst_newestsample.moc"
