#include <record/BusReport.h>
#include <record/ParameterSet.h>

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::record::BusReport;
using lk::record::BusReportDrive;
using lk::record::ParameterFileError;
using lk::record::ParameterSet;
using Kind = lk::record::ParameterFileError::Kind;

namespace {
ParameterSet sample()
{
    ParameterSet s;
    s.driveId = 7;
    s.driverName = QStringLiteral("LK-MF4015-DRV");
    s.motorName = QStringLiteral("MF4015");
    s.series = lk::protocol::Series::MF;
    s.hardwareVersion = 1.0;
    s.firmwareVersion = 2.3;
    s.savedAt = QDateTime(QDate(2026, 5, 4), QTime(3, 2, 1), Qt::UTC);
    s.pid = lk::protocol::PidGains{1, 2, 3, 4, 255, 0};
    s.accelDps2 = 2147483647;
    return s;
}
} // namespace

class tst_ParameterSet : public QObject {
    Q_OBJECT
private slots:
    void roundTrip();
    void withoutAcceleration();
    void generations();
    void refused_data();
    void refused();
    void keysInsideTextAreNotKeys();
    void saveIsAtomic();
    void busReportJsonAndHtml();
};

void tst_ParameterSet::roundTrip()
{
    const ParameterSet s = sample();
    ParameterFileError error;
    const auto back = ParameterSet::fromJson(s.toJsonBytes(), &error);
    QVERIFY2(back, qPrintable(error.key));
    QCOMPARE(back->driveId, 7);
    QCOMPARE(back->motorName, s.motorName);
    QCOMPARE(back->driverName, s.driverName);
    QCOMPARE(back->series, s.series);
    QCOMPARE(back->firmwareVersion, 2.3);
    QCOMPARE(back->savedAt, s.savedAt);
    QCOMPARE(back->pid, s.pid);
    QCOMPARE(back->accelDps2, s.accelDps2);
    const QJsonObject pid = s.toJson().value(QStringLiteral("pid")).toObject();
    QCOMPARE(pid.value(QStringLiteral("iq_kp")).toInt(), 255); // CLI.md field names
}

void tst_ParameterSet::withoutAcceleration()
{
    ParameterSet s = sample();
    s.accelDps2.reset();
    const auto back = ParameterSet::fromJson(s.toJsonBytes());
    QVERIFY(back);
    QVERIFY(!back->accelDps2);
}

void tst_ParameterSet::generations()
{
    // A file saved before V2.35 support (no "generation") is V2.3.
    QJsonObject old = sample().toJson();
    old.remove(QStringLiteral("generation"));
    auto back = ParameterSet::fromJson(QJsonDocument(old).toJson());
    QVERIFY(back);
    QCOMPARE(back->generation, lk::protocol::Generation::V2_3);
    QCOMPARE(sample().toJson().value(QStringLiteral("generation")).toString(),
             QStringLiteral("v2.3"));

    ParameterSet v235 = sample();
    v235.generation = lk::protocol::Generation::V2_35;
    v235.pidV235 = {1, 2, 3, 400, 500, 600, 65535, 0, 9};
    ParameterFileError error;
    back = ParameterSet::fromJson(v235.toJsonBytes(), &error);
    QVERIFY2(back, qPrintable(error.key));
    QCOMPARE(back->generation, lk::protocol::Generation::V2_35);
    QVERIFY(back->pidV235 == v235.pidV235);
    QVERIFY(!back->accelDps2); // V2.35 has no 0x33/0x34
    const QJsonObject json = v235.toJson();
    QCOMPARE(json.value(QStringLiteral("pid")).toObject().value(QStringLiteral("speed_kd")).toInt(),
             600);

    QJsonObject bad = json;
    bad.insert(QStringLiteral("generation"), QStringLiteral("v3"));
    QVERIFY(!ParameterSet::fromJson(QJsonDocument(bad).toJson(), &error));
    QCOMPARE(int(error.kind), int(Kind::UnknownGeneration));
    bad = json;
    bad.insert(QStringLiteral("accel_dps2"), 100);
    QVERIFY(!ParameterSet::fromJson(QJsonDocument(bad).toJson(), &error));
    QCOMPARE(error.key, QStringLiteral("accel_dps2"));
    QJsonObject pid = json.value(QStringLiteral("pid")).toObject();
    pid.insert(QStringLiteral("iq_kd"), 65536);
    bad = json;
    bad.insert(QStringLiteral("pid"), pid);
    QVERIFY(!ParameterSet::fromJson(QJsonDocument(bad).toJson(), &error));
    QCOMPARE(int(error.kind), int(Kind::OutOfRange));
    QCOMPARE(error.key, QStringLiteral("pid.iq_kd"));
    QCOMPARE(error.max, 65535.0);
}

void tst_ParameterSet::refused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("min");
    QTest::addColumn<double>("max");
    const QByteArray good = sample().toJsonBytes();
    auto replace = [&](const char *from, const char *to) {
        QByteArray b = good;
        Q_ASSERT(b.contains(from));
        return b.replace(from, to);
    };
    auto row = [](const char *name, const QByteArray &json, Kind kind, const char *key = "",
                  double min = 0, double max = 0) {
        QTest::newRow(name) << json << int(kind) << QString::fromLatin1(key) << min << max;
    };
    const double int32Max = 2147483647;
    row("empty", QByteArray(), Kind::NotJson);
    row("array", "[1,2]", Kind::NotObject);
    row("garbage", "\x01\x02\xff", Kind::NotJson);
    row("wrong format", replace("lkstudio-parameters", "other"), Kind::WrongFormat, "format");
    row("no format", R"({"version":1})", Kind::WrongFormat, "format");
    row("newer version", replace("\"version\": 1", "\"version\": 9"), Kind::NewerVersion,
        "version");
    row("version text", replace("\"version\": 1", "\"version\": \"1\""), Kind::WrongType, "version",
        1, 1000000);
    row("gain 256", replace("\"iq_kp\": 255", "\"iq_kp\": 256"), Kind::OutOfRange, "pid.iq_kp", 0,
        255);
    row("gain negative", replace("\"angle_kp\": 1", "\"angle_kp\": -1"), Kind::OutOfRange,
        "pid.angle_kp", 0, 255);
    row("gain fraction", replace("\"angle_ki\": 2", "\"angle_ki\": 2.5"), Kind::WrongType,
        "pid.angle_ki", 0, 255);
    row("gain text", replace("\"speed_kp\": 3", "\"speed_kp\": \"3\""), Kind::WrongType,
        "pid.speed_kp", 0, 255);
    row("gain null", replace("\"speed_kp\": 3", "\"speed_kp\": null"), Kind::WrongType,
        "pid.speed_kp", 0, 255);
    row("gain missing", replace("\"speed_ki\": 4,", ""), Kind::MissingKey, "pid.speed_ki", 0, 255);
    row("pid not an object",
        R"({"format":"lkstudio-parameters","version":1,"drive":{"id":1},)"
        R"("pid":5})",
        Kind::WrongType, "pid");
    row("accel negative", replace("\"accel_dps2\": 2147483647", "\"accel_dps2\": -5"),
        Kind::OutOfRange, "accel_dps2", 0, int32Max);
    row("accel too big", replace("\"accel_dps2\": 2147483647", "\"accel_dps2\": 2147483648"),
        Kind::OutOfRange, "accel_dps2", 0, int32Max);
    row("id 0", replace("\"id\": 7", "\"id\": 0"), Kind::OutOfRange, "drive.id", 1, 32);
    row("bad series", replace("\"MF\"", "\"MX\""), Kind::UnknownSeries, "drive.series");
    row("driver name number", replace("\"LK-MF4015-DRV\"", "5"), Kind::WrongType,
        "drive.driver_name");
    row("firmware text", replace("\"firmware_version\": 2.3", "\"firmware_version\": \"2.3\""),
        Kind::WrongType, "drive.firmware_version", 0, 6553.5);
    row("bad timestamp", replace("2026-05-04T03:02:01.000Z", "yesterday"), Kind::BadTimestamp,
        "saved_at");
    row("unknown key at the top", replace("\"version\": 1", "\"version\": 1, \"comment\": \"x\""),
        Kind::UnknownKey, "comment");
    row("unknown gain", replace("\"iq_ki\": 0", "\"iq_ki\": 0, \"iq_kd\": 3"), Kind::UnknownKey,
        "pid.iq_kd");
    row("unknown drive key", replace("\"id\": 7", "\"id\": 7, \"baud\": 115200"), Kind::UnknownKey,
        "drive.baud");
    row("duplicate gain", replace("\"iq_kp\": 255", "\"iq_kp\": 255, \"iq_kp\": 1"),
        Kind::DuplicateKey, "pid.iq_kp");
    row("duplicate gain escaped", replace("\"iq_kp\": 255", "\"iq_kp\": 255, \"iq\\u005fkp\": 1"),
        Kind::DuplicateKey, "pid.iq_kp");
    row("duplicate version", replace("\"version\": 1", "\"version\": 1, \"version\": 1"),
        Kind::DuplicateKey, "version");
    row("duplicate drive id", replace("\"id\": 7", "\"id\": 7, \"id\": 8"), Kind::DuplicateKey,
        "drive.id");
}

void tst_ParameterSet::refused()
{
    QFETCH(QByteArray, json);
    QFETCH(int, kind);
    QFETCH(QString, key);
    QFETCH(double, min);
    QFETCH(double, max);
    ParameterFileError error;
    QVERIFY(!ParameterSet::fromJson(json, &error));
    QCOMPARE(int(error.kind), kind);
    QCOMPARE(error.key, key);
    if (kind == int(Kind::OutOfRange) || kind == int(Kind::WrongType) ||
        kind == int(Kind::MissingKey)) {
        QCOMPARE(error.min, min);
        QCOMPARE(error.max, max);
    }
}

void tst_ParameterSet::keysInsideTextAreNotKeys()
{
    // Quotes, braces and a key-like text inside names: the duplicate-key check follows JSON
    // strings, so none of this is taken for a second "id".
    ParameterSet s = sample();
    s.motorName = QStringLiteral("MF4015 {\"id\": 2, \"id\": 3} [\\\"");
    s.driverName = QStringLiteral("\"id\"");
    ParameterFileError error;
    const auto back = ParameterSet::fromJson(s.toJsonBytes(), &error);
    QVERIFY2(back, qPrintable(error.key));
    QCOMPARE(back->motorName, s.motorName);
    QCOMPARE(back->driverName, s.driverName);
}

void tst_ParameterSet::saveIsAtomic()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    QCOMPARE(sample().save(path), QString());
    ParameterFileError error;
    QVERIFY(ParameterSet::load(path, &error));
    const QString missing = dir.filePath(QStringLiteral("missing.json"));
    QVERIFY(!ParameterSet::load(missing, &error));
    QCOMPARE(int(error.kind), int(Kind::CannotRead));
    QCOMPARE(error.path, missing);
    // A directory that does not exist: an error, no exception, no file.
    QVERIFY(!sample().save(dir.filePath(QStringLiteral("no/such/dir/p.json"))).isEmpty());
}

void tst_ParameterSet::busReportJsonAndHtml()
{
    BusReport r;
    r.createdAt = QDateTime(QDate(2026, 1, 2), QTime(3, 4, 5), Qt::UTC);
    r.connection = QStringLiteral("Simulated <bus> & co");
    r.baud = 115200;
    BusReportDrive a;
    a.id = 1;
    a.series = lk::protocol::Series::MS;
    lk::protocol::ModelInfo m;
    m.driverName = QStringLiteral("DRV");
    m.motorName = QStringLiteral("MS5005");
    m.firmwareRaw = 23;
    m.hardwareRaw = 10;
    a.model = m;
    a.pid = lk::protocol::PidGains{1, 2, 3, 4, 5, 6};
    a.accelDps2 = 100;
    lk::protocol::State1 s;
    s.voltageRaw = 120;
    s.errorState = 0x09;
    a.state1 = s;
    BusReportDrive b;
    b.id = 5;
    b.problems << QStringLiteral("read_pid: timeout");
    r.drives = {a, b};

    const QJsonObject root = QJsonDocument::fromJson(r.toJsonBytes()).object();
    QCOMPARE(root.value(QStringLiteral("drive_count")).toInt(), 2);
    const QJsonArray drives = root.value(QStringLiteral("drives")).toArray();
    QCOMPARE(drives.at(0).toObject().value(QStringLiteral("accel_dps2")).toInt(), 100);
    const QJsonObject state = drives.at(0).toObject().value(QStringLiteral("state1")).toObject();
    QCOMPARE(state.value(QStringLiteral("low_voltage")).toBool(), true);
    QCOMPARE(state.value(QStringLiteral("over_temperature")).toBool(), true);
    QCOMPARE(drives.at(1).toObject().value(QStringLiteral("answered")).toBool(), false);
    QCOMPARE(drives.at(1).toObject().value(QStringLiteral("problems")).toArray().size(), 1);

    const QString html = r.toHtml();
    QVERIFY(html.contains(QStringLiteral("MS5005")));
    QVERIFY(html.contains(QStringLiteral("low voltage, over-temperature"))); // V2.3 names
    QVERIFY(html.contains(QStringLiteral("read_pid: timeout")));
    QVERIFY(html.contains(QStringLiteral("&lt;bus&gt; &amp; co"))); // escaped
    QVERIFY(!html.contains(QStringLiteral("<bus>")));

    QTemporaryDir dir;
    QCOMPARE(r.save(dir.filePath(QStringLiteral("r.json")), dir.filePath(QStringLiteral("r.html"))),
             QString());
    QVERIFY(QFile::exists(dir.filePath(QStringLiteral("r.html"))));
}

QTEST_APPLESS_MAIN(tst_ParameterSet)
#include "tst_parameterset.moc"
