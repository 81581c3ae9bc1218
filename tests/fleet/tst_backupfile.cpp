#include "FleetData.h"

#include <fleet/BackupFile.h>

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <functional>

using namespace lk;
using fleet::BackupFile;
using Kind = record::ParameterFileError::Kind;
using protocol::Generation;

namespace {

BackupFile sample()
{
    BackupFile file;
    file.savedAt = QDateTime(QDate(2026, 11, 27), QTime(10, 5), Qt::UTC);
    file.drives << fleettest::snapshot(3, Generation::V2_3)
                << fleettest::snapshot(7, Generation::V2_35, protocol::Series::MS, 100);
    fleet::DriveSnapshot failed;
    failed.identity.id = 5;
    failed.readAt = file.savedAt;
    failed.failure = QStringLiteral("read_model: timeout");
    file.drives << failed;
    return file;
}

/// `o` with the value at the dotted `path` replaced by `v` (removed when undefined).
QJsonObject edited(QJsonObject o, const QStringList &path, const QJsonValue &v)
{
    if (path.size() == 1) {
        if (v.isUndefined())
            o.remove(path.first());
        else
            o.insert(path.first(), v);
        return o;
    }
    o.insert(path.first(), edited(o.value(path.first()).toObject(), path.mid(1), v));
    return o;
}

QByteArray bytesWith(const QString &path, const QJsonValue &v)
{
    const QJsonObject o = edited(sample().toJson(), path.split(QLatin1Char('.')), v);
    return QJsonDocument(o).toJson();
}

} // namespace

class tst_BackupFile : public QObject {
    Q_OBJECT
private slots:
    void roundTripKeepsEveryDriveAndValue();
    void failedDriveHasNoValues();
    void refusedNamingTheKey_data();
    void refusedNamingTheKey();
    void canDrivesAreDeclaredNotRead();
    void canDriveRefusedNamingTheKey_data();
    void canDriveRefusedNamingTheKey();
    void directoryIsRefusedUnopened();
    void documentedExampleIsAccepted();
};

void tst_BackupFile::roundTripKeepsEveryDriveAndValue()
{
    const BackupFile file = sample();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bus.json"));
    QCOMPARE(file.save(path), QString());
    record::ParameterFileError error;
    const std::optional<BackupFile> back = BackupFile::load(path, &error);
    QVERIFY2(back, qPrintable(BackupFile::errorText(error)));
    QCOMPARE(back->savedAt, file.savedAt);
    QCOMPARE(back->drives.size(), 3);
    for (int id : {3, 7}) {
        const fleet::DriveSnapshot *a = file.drive(id);
        const fleet::DriveSnapshot *b = back->drive(id);
        QVERIFY(a && b);
        QCOMPARE(b->identity.generation, a->identity.generation);
        QCOMPARE(b->identity.series, a->identity.series);
        QCOMPARE(b->identity.motorName, a->identity.motorName);
        QCOMPARE(b->identity.firmwareRaw, a->identity.firmwareRaw);
        QCOMPARE(b->identity.uniqueId, a->identity.uniqueId);
        QCOMPARE(b->readAt, a->readAt);
        QCOMPARE(b->valueMap(), a->valueMap());
        for (auto it = a->values.begin(); it != a->values.end(); ++it)
            QCOMPARE(b->values.value(it.key()).readAt, it.value().readAt);
        QVERIFY(b->complete());
        QVERIFY(b->failure.isEmpty());
    }
}

void tst_BackupFile::failedDriveHasNoValues()
{
    const QJsonObject five = sample()
                                 .toJson()
                                 .value(QStringLiteral("drives"))
                                 .toObject()
                                 .value(QStringLiteral("5"))
                                 .toObject();
    QCOMPARE(five.value(QStringLiteral("status")).toString(), QStringLiteral("failed"));
    QCOMPARE(five.value(QStringLiteral("failure")).toString(),
             QStringLiteral("read_model: timeout"));
    QVERIFY(!five.contains(QStringLiteral("params")));
    const std::optional<BackupFile> back = BackupFile::fromJson(sample().toJsonBytes());
    QVERIFY(back);
    QVERIFY(!back->drive(5)->complete());
    QVERIFY(back->drive(5)->values.isEmpty());
}

void tst_BackupFile::refusedNamingTheKey_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("key");
    const QByteArray good = sample().toJsonBytes();
    QTest::newRow("truncated") << good.left(good.size() / 2) << int(Kind::NotJson) << QString();
    QByteArray damaged = good;
    damaged[damaged.indexOf(':')] = '=';
    QTest::newRow("damaged") << damaged << int(Kind::NotJson) << QString();
    QTest::newRow("gain out of range")
        << bytesWith(QStringLiteral("drives.3.params.angle_kp.value"), 256) << int(Kind::OutOfRange)
        << QStringLiteral("drives.3.params.angle_kp.value");
    QTest::newRow("v2.35 torque out of range")
        << bytesWith(QStringLiteral("drives.7.params.max_torque.value"), 2049)
        << int(Kind::OutOfRange) << QStringLiteral("drives.7.params.max_torque.value");
    QTest::newRow("negative accel")
        << bytesWith(QStringLiteral("drives.3.params.accel_dps2.value"), -1)
        << int(Kind::OutOfRange) << QStringLiteral("drives.3.params.accel_dps2.value");
    QTest::newRow("other generation's key")
        << bytesWith(QStringLiteral("drives.3.params.angle_kd"),
                     QJsonObject{{"value", 1}, {"read_at", "2026-11-27T10:00:00.000Z"}})
        << int(Kind::UnknownKey) << QStringLiteral("drives.3.params.angle_kd");
    QTest::newRow("v2.3 values marked v2.35")
        << bytesWith(QStringLiteral("drives.3.generation"), QStringLiteral("v2.35"))
        << int(Kind::UnknownKey) << QStringLiteral("drives.3.params.accel_dps2");
    QTest::newRow("unknown generation")
        << bytesWith(QStringLiteral("drives.3.generation"), QStringLiteral("v3"))
        << int(Kind::UnknownGeneration) << QStringLiteral("drives.3.generation");
    QTest::newRow("value missing")
        << bytesWith(QStringLiteral("drives.3.params.iq_ki"), QJsonValue::Undefined)
        << int(Kind::MissingKey) << QStringLiteral("drives.3.params.iq_ki");
    QTest::newRow("value as text")
        << bytesWith(QStringLiteral("drives.3.params.iq_ki.value"), QStringLiteral("12"))
        << int(Kind::WrongType) << QStringLiteral("drives.3.params.iq_ki.value");
    QTest::newRow("failed drive with values")
        << bytesWith(QStringLiteral("drives.5.params"),
                     QJsonObject{{"iq_ki", QJsonObject{{"value", 1}}}})
        << int(Kind::UnknownKey) << QStringLiteral("drives.5.params");
    QTest::newRow("bad status") << bytesWith(QStringLiteral("drives.3.status"),
                                             QStringLiteral("maybe"))
                                << int(Kind::WrongType) << QStringLiteral("drives.3.status");
    QTest::newRow("id out of range")
        << bytesWith(QStringLiteral("drives.40"),
                     sample().toJson().value("drives").toObject().value("3"))
        << int(Kind::OutOfRange) << QStringLiteral("drives.40");
    QTest::newRow("unknown series")
        << bytesWith(QStringLiteral("drives.3.series"), QStringLiteral("MX"))
        << int(Kind::UnknownSeries) << QStringLiteral("drives.3.series");
    QTest::newRow("bad time") << bytesWith(QStringLiteral("drives.3.params.iq_kp.read_at"),
                                           QStringLiteral("yesterday"))
                              << int(Kind::BadTimestamp)
                              << QStringLiteral("drives.3.params.iq_kp.read_at");
    QTest::newRow("other format") << bytesWith(QStringLiteral("format"),
                                               QStringLiteral("lkstudio-parameters"))
                                  << int(Kind::WrongFormat) << QStringLiteral("format");
    QTest::newRow("newer version") << bytesWith(QStringLiteral("version"), 3)
                                   << int(Kind::NewerVersion) << QStringLiteral("version");
    QByteArray twice = good;
    twice.replace("\"angle_ki\"", "\"angle_kp\"");
    QTest::newRow("key given twice")
        << twice << int(Kind::DuplicateKey) << QStringLiteral("drives.3.params.angle_kp");
}

void tst_BackupFile::refusedNamingTheKey()
{
    QFETCH(QByteArray, bytes);
    QFETCH(int, kind);
    QFETCH(QString, key);
    record::ParameterFileError error;
    QVERIFY(!BackupFile::fromJson(bytes, &error));
    QCOMPARE(int(error.kind), kind);
    QCOMPARE(error.key, key);
    const QString text = BackupFile::errorText(error);
    QVERIFY2(key.isEmpty() || text.contains(key), qPrintable(text));
}

namespace {
BackupFile canSample()
{
    BackupFile file;
    file.savedAt = QDateTime(QDate(2026, 11, 27), QTime(10, 5), Qt::UTC);
    file.drives << fleettest::snapshot(1, Generation::V2_3, protocol::Series::MG, 10,
                                       protocol::Link::Can)
                << fleettest::snapshot(2, Generation::V2_35, protocol::Series::MF, 100,
                                       protocol::Link::Can);
    file.drives[1].identity.gearRatio = 36;
    return file;
}
} // namespace

void tst_BackupFile::canDrivesAreDeclaredNotRead()
{
    const BackupFile file = canSample();
    const QJsonObject root = file.toJson();
    QCOMPARE(root.value("version").toInt(), 2); // CAN drives: version 2; RS485 only stays 1
    QCOMPARE(sample().toJson().value("version").toInt(), 1);
    const QJsonObject two = root.value("drives").toObject().value("2").toObject();
    QCOMPARE(two.value("link").toString(), QStringLiteral("can"));
    QCOMPARE(two.value("identity").toString(), QStringLiteral("declared"));
    QCOMPARE(two.value("generation").toString(), QStringLiteral("can236"));
    QCOMPARE(root.value("drives").toObject().value("1").toObject().value("generation"),
             QJsonValue("can"));
    // Nothing only read_model could tell is written, not even as empty or 0.
    for (const char *key :
         {"driver_name", "motor_name", "hardware_version_raw", "firmware_version_raw", "unique_id"})
        QVERIFY2(!two.contains(key), key);
    QStringList keys = two.value("params").toObject().keys();
    QVERIFY(keys.contains("angle_kd") && keys.contains("current_ramp_raw"));
    QVERIFY(!keys.contains("current_ramp")); // V2.35's int16 ramp is not V2.36's
    record::ParameterFileError error;
    const std::optional<BackupFile> back = BackupFile::fromJson(file.toJsonBytes(), &error);
    QVERIFY2(back, qPrintable(BackupFile::errorText(error)));
    for (int id : {1, 2}) {
        const fleet::DriveSnapshot *a = file.drive(id);
        const fleet::DriveSnapshot *b = back->drive(id);
        QVERIFY(b->identity.declared);
        QCOMPARE(b->identity.link, protocol::Link::Can);
        QCOMPARE(b->identity.generation, a->identity.generation);
        QCOMPARE(b->identity.series, a->identity.series);
        QCOMPARE(b->identity.gearRatio, a->identity.gearRatio);
        QCOMPARE(b->valueMap(), a->valueMap());
        QVERIFY(b->complete());
    }
}

void tst_BackupFile::canDriveRefusedNamingTheKey_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("key");
    QTest::newRow("a CAN identity claimed read")
        << "drives.2.identity" << QJsonValue("read") << int(Kind::WrongType) << "drives.2.identity";
    QTest::newRow("CAN without identity")
        << "drives.2.identity" << QJsonValue() << int(Kind::WrongType) << "drives.2.identity";
    QTest::newRow("RS485 generation word on CAN")
        << "drives.2.generation" << QJsonValue("v2.35") << int(Kind::UnknownGeneration)
        << "drives.2.generation";
    QTest::newRow("unknown link") << "drives.2.link" << QJsonValue("usb") << int(Kind::WrongType)
                                  << "drives.2.link";
    QTest::newRow("old CAN holding V2.36 values")
        << "drives.2.generation" << QJsonValue("can") << int(Kind::UnknownKey)
        << "drives.2.params.angle_kd";
    QTest::newRow("torque limit beyond 2048")
        << "drives.2.params.max_torque.value" << QJsonValue(2049) << int(Kind::OutOfRange)
        << "drives.2.params.max_torque.value";
    QTest::newRow("negative speed limit")
        << "drives.2.params.max_speed_raw.value" << QJsonValue(-1) << int(Kind::OutOfRange)
        << "drives.2.params.max_speed_raw.value";
}

void tst_BackupFile::canDriveRefusedNamingTheKey()
{
    QFETCH(QString, path);
    QFETCH(QJsonValue, value);
    QFETCH(int, kind);
    QFETCH(QString, key);
    const QJsonObject o = edited(canSample().toJson(), path.split(QLatin1Char('.')),
                                 value.isNull() ? QJsonValue(QJsonValue::Undefined) : value);
    record::ParameterFileError error;
    QVERIFY(!BackupFile::fromJson(QJsonDocument(o).toJson(), &error));
    QCOMPARE(int(error.kind), kind);
    QCOMPARE(error.key, key);
    QVERIFY2(BackupFile::errorText(error).contains(key), qPrintable(BackupFile::errorText(error)));
}

void tst_BackupFile::directoryIsRefusedUnopened()
{
    QTemporaryDir dir;
    record::ParameterFileError error;
    QVERIFY(!BackupFile::load(dir.path(), &error));
    QCOMPARE(error.kind, Kind::CannotRead);
    QVERIFY(BackupFile::errorText(error).contains(dir.path()));
}

void tst_BackupFile::documentedExampleIsAccepted()
{
    QFile doc(QStringLiteral(LK_SOURCE_DIR "/docs/BACKUP.md"));
    QVERIFY(doc.open(QIODevice::ReadOnly));
    const QByteArray text = doc.readAll();
    const qsizetype from = text.indexOf("```json\n");
    QVERIFY(from >= 0);
    const qsizetype to = text.indexOf("```", from + 8);
    record::ParameterFileError error;
    const std::optional<BackupFile> file =
        BackupFile::fromJson(text.mid(from + 8, to - from - 8), &error);
    QVERIFY2(file, qPrintable(BackupFile::errorText(error)));
    QVERIFY(file->drive(3)->complete());
    QVERIFY(!file->drive(5)->complete());
}

QTEST_GUILESS_MAIN(tst_BackupFile)
#include "tst_backupfile.moc"
