// FrequencyRunFile (#25): a frequency run saved and loaded back as it was, and every bad value
// of a file refused with its key named.
#include <tuning/FrequencyRunFile.h>

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace lk;
using record::ParameterFileError;
using tuning::FrequencyRun;
using tuning::FrequencyRunFile;
using Kind = ParameterFileError::Kind;

Q_DECLARE_METATYPE(ParameterFileError::Kind)

namespace {

FrequencyRun sampleRun()
{
    FrequencyRun run;
    run.number = 3;
    run.label = QStringLiteral("after the new coupling");
    run.ranAt = QDateTime(QDate(2026, 11, 27), QTime(17, 3, 4, 500), Qt::UTC);
    run.driveId = 7;
    run.series = QStringLiteral("MG");
    run.model = QStringLiteral("MG5010E-i10");
    run.spec.id = 7;
    run.spec.loop = tuning::SweepLoop::Position;
    run.spec.fromHz = 1;
    run.spec.toHz = 40;
    run.spec.points = 6;
    run.spec.amplitude = 4.5;
    run.spec.operatingPoint = 52.52;
    tuning::LoopGains g;
    g.generation = protocol::Generation::V2_35;
    g.angle = {100, 100, 3};
    g.speed = {50, 40, 0};
    g.current = {50, 50, 0};
    g.accelerationDps2 = 36000;
    run.gains = g;
    run.response.sampleRateHz = 1890.5;
    run.response.points.append({1.0, -0.03, -6.0, 0.998, 2020, 4.5, 4.48});
    run.response.points.append({9.1, -1.49, -45.2, 0.996, 220, 4.5, 3.78});
    run.response.dropped.append({450, tuning::DroppedReason::AboveResolution});
    return run;
}

QJsonObject sampleJson()
{
    return FrequencyRunFile::toJson(sampleRun());
}

} // namespace

class tst_FrequencyRunFile : public QObject {
    Q_OBJECT
private slots:
    void roundTrip();
    void speedRunWithoutGains();
    void badValuesNameTheKey_data();
    void badValuesNameTheKey();
    void fileErrors();
};

void tst_FrequencyRunFile::roundTrip()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a") + FrequencyRunFile::kSuffix);
    const FrequencyRun run = sampleRun();
    QCOMPARE(FrequencyRunFile::save(path, run), QString());
    ParameterFileError error;
    const auto back = FrequencyRunFile::load(path, &error);
    QVERIFY2(back, qPrintable(error.key));
    QCOMPARE(back->number, 3);
    QCOMPARE(back->label, run.label);
    QCOMPARE(back->ranAt, run.ranAt);
    QCOMPARE(back->driveId, 7);
    QCOMPARE(back->series, run.series);
    QCOMPARE(back->model, run.model);
    QCOMPARE(back->spec.loop, tuning::SweepLoop::Position);
    QCOMPARE(back->spec.centre(), 52.52);
    QCOMPARE(back->spec.amplitude, 4.5);
    QCOMPARE(back->spec.points, 6);
    QCOMPARE(back->gains, run.gains);
    QCOMPARE(back->response.sampleRateHz, 1890.5);
    QCOMPARE(back->response.points.size(), 2);
    QCOMPARE(back->response.points.at(1).phaseDeg, -45.2);
    QCOMPARE(back->response.points.at(1).samples, 220);
    QCOMPARE(back->response.points.at(1).outputAmplitude, 3.78);
    QCOMPARE(back->response.dropped.size(), 1);
    QCOMPARE(back->response.dropped.first().reason, tuning::DroppedReason::AboveResolution);
    QVERIFY(back->comparableWith(run));
}

void tst_FrequencyRunFile::speedRunWithoutGains()
{
    FrequencyRun run = sampleRun();
    run.spec.loop = tuning::SweepLoop::Speed;
    run.gains.reset();
    run.series.clear();
    const auto back = FrequencyRunFile::fromJson(FrequencyRunFile::toJson(run));
    QVERIFY(back);
    QCOMPARE(back->spec.loop, tuning::SweepLoop::Speed);
    QVERIFY(!back->gains);
    QVERIFY(!back->comparableWith(sampleRun())); // a speed run and a position run
}

void tst_FrequencyRunFile::badValuesNameTheKey_data()
{
    QTest::addColumn<QString>("key");      // dotted path; [i] into arrays
    QTest::addColumn<QJsonValue>("value"); // Undefined: the key removed
    QTest::addColumn<Kind>("kind");
    QTest::addColumn<QString>("named");
    const QJsonValue gone = QJsonValue::Undefined;
    QTest::newRow("format") << "format" << QJsonValue("lkstudio-step-runs") << Kind::WrongFormat
                            << "format";
    QTest::newRow("newer") << "version" << QJsonValue(2) << Kind::NewerVersion << "version";
    QTest::newRow("unknown key") << "colour" << QJsonValue("red") << Kind::UnknownKey << "colour";
    QTest::newRow("drive id") << "drive_id" << QJsonValue(33) << Kind::OutOfRange << "drive_id";
    QTest::newRow("drive id text")
        << "drive_id" << QJsonValue("7") << Kind::WrongType << "drive_id";
    QTest::newRow("missing loop") << "loop" << gone << Kind::MissingKey << "loop";
    QTest::newRow("loop word") << "loop" << QJsonValue("angle") << Kind::WrongType << "loop";
    QTest::newRow("date") << "ran_at" << QJsonValue("yesterday") << Kind::BadTimestamp << "ran_at";
    QTest::newRow("series") << "series" << QJsonValue("MX") << Kind::UnknownSeries << "series";
    QTest::newRow("from") << "from_hz" << QJsonValue(0) << Kind::OutOfRange << "from_hz";
    QTest::newRow("planned") << "points_planned" << QJsonValue(61) << Kind::OutOfRange
                             << "points_planned";
    QTest::newRow("gain") << "gains.speed_kp" << QJsonValue(70000) << Kind::OutOfRange
                          << "gains.speed_kp";
    QTest::newRow("generation") << "gains.generation" << QJsonValue("v3") << Kind::UnknownGeneration
                                << "gains.generation";
    QTest::newRow("gain missing") << "gains.angle_kd" << gone << Kind::MissingKey
                                  << "gains.angle_kd";
    QTest::newRow("points missing") << "points" << gone << Kind::MissingKey << "points";
    QTest::newRow("points not list") << "points" << QJsonValue(3) << Kind::WrongType << "points";
    QTest::newRow("point hz") << "points[1].hz" << QJsonValue("9") << Kind::WrongType
                              << "points[1].hz";
    QTest::newRow("point quality")
        << "points[0].quality" << QJsonValue(1.5) << Kind::OutOfRange << "points[0].quality";
    QTest::newRow("point extra") << "points[1].colour" << QJsonValue(1) << Kind::UnknownKey
                                 << "points[1].colour";
    QTest::newRow("point missing")
        << "points[0].phase_deg" << gone << Kind::MissingKey << "points[0].phase_deg";
    QTest::newRow("dropped reason")
        << "dropped[0].reason" << QJsonValue("tired") << Kind::WrongType << "dropped[0].reason";
}

void tst_FrequencyRunFile::badValuesNameTheKey()
{
    QFETCH(QString, key);
    QFETCH(QJsonValue, value);
    QFETCH(Kind, kind);
    QFETCH(QString, named);
    QJsonObject root = sampleJson();
    // Set `value` at the dotted key (one array index at most), or remove it.
    const QStringList parts = key.split(QLatin1Char('.'));
    const auto setIn = [&value](QJsonObject o, const QString &k) {
        if (value.isUndefined())
            o.remove(k);
        else
            o.insert(k, value);
        return o;
    };
    if (parts.size() == 1) {
        root = setIn(root, key);
    } else if (parts.first().contains(QLatin1Char('['))) {
        const QString array = parts.first().section(QLatin1Char('['), 0, 0);
        const int i = parts.first().section(QLatin1Char('['), 1).chopped(1).toInt();
        QJsonArray a = root.value(array).toArray();
        a[i] = setIn(a.at(i).toObject(), parts.at(1));
        root.insert(array, a);
    } else {
        root.insert(parts.first(), setIn(root.value(parts.first()).toObject(), parts.at(1)));
    }
    ParameterFileError error;
    QVERIFY(!FrequencyRunFile::fromJson(root, &error));
    QCOMPARE(error.kind, kind);
    QCOMPARE(error.key, named);
}

void tst_FrequencyRunFile::fileErrors()
{
    QTemporaryDir dir;
    ParameterFileError error;
    // A directory, not JSON, a duplicated key, too large: refused with the path named.
    QVERIFY(!FrequencyRunFile::load(dir.path(), &error));
    QCOMPARE(error.kind, Kind::CannotRead);
    QCOMPARE(error.path, dir.path());
    const auto write = [&](const QString &name, const QByteArray &bytes) {
        QFile f(dir.filePath(name));
        f.open(QIODevice::WriteOnly);
        f.write(bytes);
        return f.fileName();
    };
    QVERIFY(!FrequencyRunFile::load(write("bad.json", "{\"format\":"), &error));
    QCOMPARE(error.kind, Kind::NotJson);
    const QByteArray json = QJsonDocument(sampleJson()).toJson();
    QByteArray twice = json;
    twice.insert(1, "\"label\":\"x\",");
    QVERIFY(!FrequencyRunFile::load(write("twice.json", twice), &error));
    QCOMPARE(error.kind, Kind::DuplicateKey);
    QCOMPARE(error.key, QStringLiteral("label"));
    QByteArray big = json;
    big.append(QByteArray(FrequencyRunFile::kMaxFileBytes, ' '));
    QVERIFY(!FrequencyRunFile::load(write("big.json", big), &error));
    QCOMPARE(error.kind, Kind::TooLarge);
    QVERIFY(FrequencyRunFile::load(write("good.json", json), &error));
}

QTEST_APPLESS_MAIN(tst_FrequencyRunFile)
#include "tst_frequencyrunfile.moc"
