// lkctl's live commands on CAN take each drive's identity from --drives ID:SERIES@GEN/GEAR,
// gear ratio included, as `control` does: CAN has no model read, so a command that bounds a
// move by the gearbox (one output turn) has only the user's word for it. Against lksim --can
// over Qt's virtualcan, on a TCP port of this test's own (the virtualcan server is
// system-wide).

#include "CanLksim.h"
#include "E2eUtil.h"

#include <QtCore/QJsonObject>
#include <QtTest/QTest>

using namespace lk::e2e;

class tst_LkctlCan : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void stepTakesTheGearRatioOfDrives_data();
    void stepTakesTheGearRatioOfDrives();

private:
    QStringList can() const { return m_bus.can(); }

    CanLksim m_bus;
};

void tst_LkctlCan::init()
{
    const QString failed = m_bus.start(QStringLiteral("1:MG@can"));
    QVERIFY2(failed.isEmpty(), qPrintable(failed));
}

void tst_LkctlCan::cleanup()
{
    if (m_bus.isRunning())
        lkctl(QStringList{"off", "1"} + can());
    m_bus.stop();
}

void tst_LkctlCan::stepTakesTheGearRatioOfDrives_data()
{
    QTest::addColumn<QString>("drives");
    QTest::addColumn<int>("exitCode");
    // 0 -> 720 rotor deg is two rotor turns: one output turn of a 1:36 gearbox allows it,
    // a drive without a gearbox refuses it (more than one output turn), nothing sent.
    QTest::newRow("1:36 gearbox") << QStringLiteral("1:MG@can/36") << 0;
    QTest::newRow("no gearbox") << QStringLiteral("1:MG@can") << 4;
}

void tst_LkctlCan::stepTakesTheGearRatioOfDrives()
{
    QFETCH(QString, drives);
    QFETCH(int, exitCode);
    const CtlResult r =
        lkctl(QStringList{"step", "1", "position", "0", "720", "--duration", "0.2", "--pre-roll",
                          "0.1", "--max-speed", "3600", "--json", "--drives", drives} +
              can());
    QVERIFY2(r.exitCode == exitCode, (r.out + r.err).constData());
    if (exitCode == 4)
        QVERIFY2(r.err.contains("output turn"), r.err.constData());
    else
        QVERIFY2(jsonOf(r.out.trimmed()).value("loop").toString() == QStringLiteral("position"),
                 r.out.constData());
}

QTEST_GUILESS_MAIN(tst_LkctlCan)
#include "tst_lkctlcan.moc"
