#include "CanLksim.h"
#include "E2eUtil.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtTest/QTest>

using namespace lk::e2e;

/// lkctl --can against lksim --can over Qt's virtualcan: both CAN generations, one old CAN MG
/// (replies on 0x141) and one V2.36 MF (replies on 0x182), through real QCanBusDevices.
class tst_E2eCan : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void scanFindsBothGenerations();
    void readsDecodeInEachGeneration();
    void speedOnV236NeedsSoftLimitsAndCarriesThem();
    void stopReachesEveryId();
    void badOptionsAreNamed();

private:
    QStringList can() const { return m_bus.can(); }

    CanLksim m_bus;
};

void tst_E2eCan::init()
{
    const QString failed =
        m_bus.start(QStringLiteral("1:MG@can,2:MF@can236"), {QStringLiteral("--wire-time")});
    QVERIFY2(failed.isEmpty(), qPrintable(failed));
}

void tst_E2eCan::cleanup()
{
    m_bus.stop();
}

void tst_E2eCan::scanFindsBothGenerations()
{
    const CtlResult r = lkctl(QStringList{"scan", "--json", "--retries", "1"} + can());
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray drives = QJsonDocument::fromJson(r.out).array();
    QCOMPARE(drives.size(), 2);
    QCOMPARE(drives.at(0).toObject().value("id").toInt(), 1);
    QCOMPARE(drives.at(0).toObject().value("generation").toString(), QStringLiteral("v2.3"));
    QCOMPARE(drives.at(0).toObject().value("dialect").toString(), QStringLiteral("CAN (old)"));
    QCOMPARE(drives.at(1).toObject().value("id").toInt(), 2);
    QCOMPARE(drives.at(1).toObject().value("generation").toString(), QStringLiteral("v2.35"));
    QCOMPARE(drives.at(1).toObject().value("dialect").toString(), QStringLiteral("CAN V2.36"));
    // CAN has no model read: nothing is claimed.
    QVERIFY(drives.at(0).toObject().value("motor_name").isNull());
}

void tst_E2eCan::readsDecodeInEachGeneration()
{
    for (const QString &who : {QStringLiteral("1:MG@can"), QStringLiteral("2:MF@can236")}) {
        const QString id = who.left(1);
        const CtlResult r =
            lkctl(QStringList{"read", id, "state1", "--json", "--drives", who} + can());
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = jsonOf(r.out.trimmed());
        // A V2.36 drive's 0.01 V read as the old 0.1 V field would be ten times too high.
        const double volts = o.value("fields").toObject().value("voltage_v").toDouble();
        QVERIFY2(volts > 5 && volts < 60, r.out.constData());
    }
}

void tst_E2eCan::speedOnV236NeedsSoftLimitsAndCarriesThem()
{
    const CtlResult r = lkctl(QStringList{"control", "2", "speed", "30", "--drives", "2:MF@can236",
                                          "--max-torque-a", "1.5", "--json"} +
                              can());
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    const CtlResult off = lkctl(QStringList{"off", "2"} + can());
    QVERIFY2(off.exitCode == 0, off.err.constData());
}

void tst_E2eCan::stopReachesEveryId()
{
    const CtlResult r = lkctl(QStringList{"off", "all", "--json"} + can());
    QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
    QVERIFY2(r.out.contains("1") && r.out.contains("2"), r.out.constData());
}

void tst_E2eCan::badOptionsAreNamed()
{
    CtlResult r = lkctl(QStringList{"scan", "--can", "nosuchplugin:can0"});
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains("nosuchplugin"), r.err.constData());
    r = lkctl(QStringList{"scan", "--bitrate", "123"} + can());
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains("--bitrate"), r.err.constData());
    r = lkctl(QStringList{"read", "2", "state1", "--drives", "2:MF"} + can());
    QVERIFY(r.exitCode != 0);
    QVERIFY2(r.err.contains("--drives"), r.err.constData());
}

QTEST_GUILESS_MAIN(tst_E2eCan)
#include "tst_e2ecan.moc"
