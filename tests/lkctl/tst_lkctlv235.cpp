#include "E2eUtil.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtTest/QtTest>

// lkctl against a firmware-2.35 drive (protocol V2.35) beside a V2.3 drive on the in-process
// simulated bus: scan, info and read show what each generation really reports, and nothing a
// generation lacks is sent to it.

namespace {

using lk::e2e::lkctl;
using Result = lk::e2e::CtlResult;

QStringList sim(const QString &args)
{
    return args.split(QLatin1Char(' '), Qt::SkipEmptyParts) +
           QStringList{QStringLiteral("--sim"), QStringLiteral("1:MS4015@2.35,2:MF")};
}

QJsonObject objectOf(const QByteArray &json)
{
    return QJsonDocument::fromJson(json).object();
}

} // namespace

class tst_LkctlV235 : public QObject {
    Q_OBJECT
private slots:
    void scanShowsEachGeneration();
    void infoReadsGainsAsParameters();
    void readPidOnV235UsesParameters();
    void commandsAGenerationLacksAreNotSent();
    void decodeGenerationFromModelReply();
};

void tst_LkctlV235::scanShowsEachGeneration()
{
    const Result r = lkctl(sim(QStringLiteral("scan --json")));
    QCOMPARE(r.exitCode, 0);
    const QJsonArray drives = QJsonDocument::fromJson(r.out).array();
    QCOMPARE(drives.size(), 2);
    const QJsonObject v235 = drives.at(0).toObject();
    QCOMPARE(v235.value("generation").toString(), QStringLiteral("v2.35"));
    QCOMPARE(v235.value("firmware_version").toDouble(), 2.35);
    QCOMPARE(v235.value("hardware_version").toDouble(), 3.0);
    // The MS series supply is 7.4-24 V: the simulator runs it at 12 V. A V2.3 reading of the
    // same bytes would be far off (the bug: 308 V for 24 V).
    QCOMPARE(v235.value("voltage_v").toDouble(), 12.0);
    QVERIFY(v235.value("bus_current_a").isDouble());
    QCOMPARE(v235.value("motor_on").toBool(false), true); // on after power-up, as a real drive
    QCOMPARE(v235.value("errors").toArray().size(), 0);
    const QJsonObject v23 = drives.at(1).toObject();
    QCOMPARE(v23.value("generation").toString(), QStringLiteral("v2.3"));
    QVERIFY(v23.value("bus_current_a").isNull());
    QVERIFY(v23.value("motor_on").isNull());
    QCOMPARE(v23.value("voltage_v").toDouble(), 24.0);
}

void tst_LkctlV235::infoReadsGainsAsParameters()
{
    Result r = lkctl(sim(QStringLiteral("info 1 --json")));
    QCOMPARE(r.exitCode, 0);
    QJsonObject o = objectOf(r.out);
    QCOMPARE(o.value("generation").toString(), QStringLiteral("v2.35"));
    QCOMPARE(o.value("state1").toObject().value("voltage_v").toDouble(), 12.0);
    const QJsonObject pid = o.value("pid").toObject();
    for (const char *k : {"angle_kp", "angle_ki", "angle_kd", "speed_kp", "speed_ki", "speed_kd",
                          "iq_kp", "iq_ki", "iq_kd"})
        QVERIFY2(pid.contains(QLatin1String(k)), k);
    QVERIFY(!o.contains("accel"));
    QVERIFY(o.value("params").toObject().contains("max_speed_dps"));
    QVERIFY(r.err.isEmpty());

    r = lkctl(sim(QStringLiteral("info 2 --json")));
    QCOMPARE(r.exitCode, 0);
    o = objectOf(r.out);
    QCOMPARE(o.value("generation").toString(), QStringLiteral("v2.3"));
    QVERIFY(o.contains("accel"));
    QVERIFY(!o.value("pid").toObject().contains("angle_kd"));
}

void tst_LkctlV235::readPidOnV235UsesParameters()
{
    const Result r = lkctl(sim(QStringLiteral("read 1 pid --json")));
    QCOMPARE(r.exitCode, 0);
    const QJsonObject o = objectOf(r.out);
    QCOMPARE(o.value("command").toString(), QStringLiteral("read_param"));
    QCOMPARE(o.value("fields").toObject().value("speed_kp").toInt(), 50);
    QCOMPARE(o.value("fields").toObject().value("speed_kd").toInt(), 0);
}

void tst_LkctlV235::commandsAGenerationLacksAreNotSent()
{
    // read_accel does not exist on V2.35: refused by name, not a timeout blaming the wiring.
    Result r = lkctl(sim(QStringLiteral("read 1 accel")));
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("protocol V2.35") && r.err.contains("nothing was sent"), r.err);
    QVERIFY2(!r.err.contains("wiring"), r.err);
}

void tst_LkctlV235::decodeGenerationFromModelReply()
{
    // Without --generation a read_state1 reply reads as V2.3; after a 58-byte read_model
    // reply from the same ID it reads as V2.35.
    const QString state1 = QStringLiteral("3E 9A 01 07 E0 1E 60 09 96 00 00 00 1D");
    QString model = QStringLiteral("3E 12 01 3A 8B ");
    QByteArray data = QByteArray("DS40R7").leftJustified(20, '\0') +
                      QByteArray("MS4015").leftJustified(20, '\0') +
                      QByteArray::fromHex("353735303032731878034a4b2c01c800eb00");
    model += QString::fromLatin1(data.toHex(' ').toUpper());
    int sum = 0;
    for (char c : data)
        sum += quint8(c);
    model += QStringLiteral(" %1").arg(sum & 0xFF, 2, 16, QLatin1Char('0'));
    const Result r = lkctl({QStringLiteral("decode"), state1, model, state1});
    QCOMPARE(r.exitCode, 0);
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 3);
    QCOMPARE(objectOf(lines[0]).value("fields").toObject().value("voltage_v").toDouble(), 3840.9);
    QCOMPARE(objectOf(lines[2]).value("fields").toObject().value("voltage_v").toDouble(), 24.0);
    const Result forced = lkctl({QStringLiteral("decode"), QStringLiteral("--generation"),
                                 QStringLiteral("v2.35"), state1});
    QCOMPARE(objectOf(forced.out).value("fields").toObject().value("motor_on").toBool(), true);
}

QTEST_GUILESS_MAIN(tst_LkctlV235)
#include "tst_lkctlv235.moc"
