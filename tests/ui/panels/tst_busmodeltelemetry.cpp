#include <bus/TelemetryFieldInfo.h>
#include <panels/BusModel.h>

#include <QtCore/QRandomGenerator>
#include <QtTest/QTest>

using namespace lk;
using lk::bus::TelemetryField;
using lk::bus::TelemetrySample;
using lk::ui::BusModel;

namespace {

constexpr int kDrives = 3;

/// A model listening (drives appear as they reply), fed `batches` one after another.
void feed(BusModel &model, const QList<lk::bus::TelemetryBatch> &batches)
{
    // The model's clock starts with it: a few ms on, every stamp it gives a field is above 0
    // (what DriveRecord::updatedMs calls never), so that "stamped" can be compared.
    QTest::qWait(5);
    bus::ConnectionStatus listening;
    listening.state = transport::Transport::State::Open;
    listening.canTransmit = false;
    model.setConnection(listening, false);
    for (const lk::bus::TelemetryBatch &batch : batches)
        model.applyTelemetry(batch);
}

/// Samples of drives 1..kDrives with random subsets of fields and values, some with an
/// encoder reading: what a replay's Load all hands on in one batch.
lk::bus::TelemetryBatch randomBatch(QRandomGenerator &random, int samples)
{
    static const TelemetryField kFields[] = {
        TelemetryField::Temperature, TelemetryField::IqA,           TelemetryField::Speed,
        TelemetryField::Encoder,     TelemetryField::Voltage,       TelemetryField::MultiTurn,
        TelemetryField::SingleTurn,  TelemetryField::CommandedSpeed};
    lk::bus::TelemetryBatch batch;
    for (int i = 0; i < samples; ++i) {
        TelemetrySample s;
        s.id = 1 + int(random.bounded(kDrives));
        s.time = i * 0.001;
        s.cycle = quint64(i);
        for (TelemetryField f : kFields) {
            if (random.bounded(3) == 0)
                s.fields |= f;
        }
        s.temperatureC = int(random.bounded(80));
        s.iqA = random.bounded(20.0) - 10;
        s.speedDps = random.bounded(7200.0);
        s.encoder = int(random.bounded(65536));
        s.voltageV = random.bounded(48.0);
        s.multiTurnDeg = random.bounded(36000.0);
        s.singleTurnDeg = random.bounded(360.0);
        s.commandedSpeedDps = random.bounded(3600.0);
        if (random.bounded(5) == 0)
            s.encoderReading = protocol::EncoderReading{quint16(random.bounded(65536)),
                                                        quint16(random.bounded(65536)), 0};
        batch.append(s);
    }
    return batch;
}

} // namespace

/// BusModel::applyTelemetry applies only the samples whose values stay (the newest of each
/// field of each drive): the model must end exactly as if every sample had been applied.
class tst_BusModelTelemetry : public QObject {
    Q_OBJECT
private slots:
    void batchEndsAsSampleBySample_data()
    {
        QTest::addColumn<quint32>("seed");
        QTest::addColumn<int>("samples");
        for (quint32 seed : {1u, 2u, 3u, 4u, 5u})
            QTest::newRow(qPrintable(QStringLiteral("seed %1").arg(seed))) << seed << 400;
        QTest::newRow("one sample") << 9u << 1;
    }
    void batchEndsAsSampleBySample()
    {
        QFETCH(quint32, seed);
        QFETCH(int, samples);
        QRandomGenerator random(seed);
        const lk::bus::TelemetryBatch batch = randomBatch(random, samples);
        BusModel whole;
        feed(whole, {batch});
        BusModel single;
        QList<lk::bus::TelemetryBatch> one;
        for (const TelemetrySample &s : batch)
            one.append({s});
        feed(single, one);
        QCOMPARE(whole.ids(), single.ids());
        for (int id : single.ids()) {
            const TelemetrySample &a = whole.drive(id)->latest;
            const TelemetrySample &b = single.drive(id)->latest;
            QCOMPARE(a.fields, b.fields);
            for (const bus::TelemetryFieldInfo &info : bus::TelemetryFieldInfo::all()) {
                if (b.has(info.field))
                    QCOMPARE(info.value(a), info.value(b));
            }
            QCOMPARE(a.encoderReading.has_value(), b.encoderReading.has_value());
            if (b.encoderReading)
                QCOMPARE(a.encoderReading->encoderRaw, b.encoderReading->encoderRaw);
            QCOMPARE(a.time, b.time);
            QCOMPARE(a.cycle, b.cycle);
            for (int f = 0; f < lk::ui::DriveRecord::kFieldCount; ++f)
                QCOMPARE(whole.drive(id)->updatedMs[size_t(f)] > 0,
                         single.drive(id)->updatedMs[size_t(f)] > 0);
        }
    }
};

QTEST_GUILESS_MAIN(tst_BusModelTelemetry)
#include "tst_busmodeltelemetry.moc"
