#include <record/BusReport.h>
#include <record/ParameterSet.h>

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::record::BusReport;
using lk::record::BusReportDrive;
using lk::record::ParameterSet;

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
    void refused_data();
    void refused();
    void saveIsAtomic();
    void busReportJsonAndHtml();
};

void tst_ParameterSet::roundTrip()
{
    const ParameterSet s = sample();
    QString error;
    const auto back = ParameterSet::fromJson(s.toJsonBytes(), &error);
    QVERIFY2(back, qPrintable(error));
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

void tst_ParameterSet::refused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("mentions");
    const QByteArray good = sample().toJsonBytes();
    auto replace = [&](const char *from, const char *to) {
        QByteArray b = good;
        return b.replace(from, to);
    };
    QTest::newRow("empty") << QByteArray() << "JSON";
    QTest::newRow("array") << QByteArray("[1,2]") << "object";
    QTest::newRow("garbage") << QByteArray("\x01\x02\xff") << "JSON";
    QTest::newRow("wrong format") << replace("lkstudio-parameters", "other") << "format";
    QTest::newRow("newer version") << replace("\"version\": 1", "\"version\": 9") << "newer";
    QTest::newRow("gain 256") << replace("\"iq_kp\": 255", "\"iq_kp\": 256") << "iq_kp";
    QTest::newRow("gain negative") << replace("\"angle_kp\": 1", "\"angle_kp\": -1") << "angle_kp";
    QTest::newRow("gain fraction") << replace("\"angle_ki\": 2", "\"angle_ki\": 2.5") << "angle_ki";
    QTest::newRow("gain text") << replace("\"speed_kp\": 3", "\"speed_kp\": \"3\"") << "speed_kp";
    QTest::newRow("gain missing") << replace("\"speed_ki\": 4,", "") << "speed_ki";
    QTest::newRow("accel negative")
        << replace("\"accel_dps2\": 2147483647", "\"accel_dps2\": -5") << "accel_dps2";
    QTest::newRow("accel too big")
        << replace("\"accel_dps2\": 2147483647", "\"accel_dps2\": 2147483648") << "accel_dps2";
    QTest::newRow("id 0") << replace("\"id\": 7", "\"id\": 0") << "id";
    QTest::newRow("bad series") << replace("\"MF\"", "\"MX\"") << "series";
}

void tst_ParameterSet::refused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, mentions);
    QString error;
    QVERIFY(!ParameterSet::fromJson(json, &error));
    QVERIFY2(error.contains(mentions), qPrintable(error));
}

void tst_ParameterSet::saveIsAtomic()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    QCOMPARE(sample().save(path), QString());
    QString error;
    QVERIFY(ParameterSet::load(path, &error));
    QVERIFY(!ParameterSet::load(dir.filePath(QStringLiteral("missing.json")), &error));
    QVERIFY(error.contains(QStringLiteral("cannot read")));
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
    QVERIFY(html.contains(QStringLiteral("LOW VOLTAGE")));
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
