#include "E2eUtil.h"

#include <QtCore/QDir>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

// Options lkctl checks before it moves anything: every --max-* limit within its key's range
// (refused at once, naming the flag) and within what the drive's series can do (refused after
// read_model, naming the flag and the series); and a --port with a slash taken as a path.

using lk::e2e::CtlResult;

class tst_LkctlOptions : public QObject {
    Q_OBJECT
private slots:
    void limitFlagsAreRangeChecked_data();
    void limitFlagsAreRangeChecked();
    void portWithASlashIsAPath_data();
    void portWithASlashIsAPath();
};

void tst_LkctlOptions::limitFlagsAreRangeChecked_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QString>("said");
    QTest::newRow("torque 1e9") << "control 3 speed 10 --max-torque-a 1e9 --sim 3:MF"
                                << "--max-torque-a must be in 0..32 (got 1e9)";
    QTest::newRow("torque over MF") << "control 3 speed 10 --max-torque-a 20 --sim 3:MF"
                                    << "--max-torque-a 20 A is above 9 A, the current limit of "
                                       "the MF series";
    QTest::newRow("speed 0") << "control 3 speed 10 --max-speed-dps 0 --sim 3:MF"
                             << "--max-speed-dps must be in 0.01..18000 (got 0)";
    QTest::newRow("speed 1e6") << "step 3 speed 0 10 --max-speed-dps 1e6 --sim 3:MF"
                               << "--max-speed-dps must be in 0.01..18000 (got 1e6)";
    QTest::newRow("speed over MG") << "control 32 speed 10 --max-speed-dps 15000 --sim 32:MG"
                                   << "--max-speed-dps 15000 dps is above 12000 dps, the top "
                                      "speed of the MG series";
    QTest::newRow("step torque over MH") << "step 4 speed 0 10 --max-torque-a 5 --sim 4:MH"
                                         << "--max-torque-a 5 A is above 4 A";
    QTest::newRow("power") << "control 17 open-loop 10 --max-power 1001 --sim 17:MS"
                           << "--max-power must be an integer in 0..1000";
}

void tst_LkctlOptions::limitFlagsAreRangeChecked()
{
    QFETCH(QString, args);
    QFETCH(QString, said);
    const CtlResult r = lk::e2e::lkctl(args.split(QLatin1Char(' ')));
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, QByteArray()); // no motion reply: nothing moved
    QVERIFY2(r.err.contains(said.toUtf8()), r.err.constData());
}

void tst_LkctlOptions::portWithASlashIsAPath_data()
{
    QTest::addColumn<QString>("port");
    QTest::addColumn<QString>("shown"); // relative to the working directory, or /dev
    QTest::newRow("./name") << "./bus"
                            << "WD/bus";
    QTest::newRow("folder/name") << "sub/bus"
                                 << "WD/sub/bus";
    QTest::newRow("../name") << "sub/../bus"
                             << "WD/bus";
    QTest::newRow("bare name") << "ttyLKnothere"
                               << "/dev/ttyLKnothere";
}

void tst_LkctlOptions::portWithASlashIsAPath()
{
    QFETCH(QString, port);
    QFETCH(QString, shown);
    QTemporaryDir dir;
    QProcess p;
    p.setWorkingDirectory(dir.path());
    p.start(QStringLiteral(LKCTL_PATH), {QStringLiteral("scan"), QStringLiteral("--port"), port});
    QVERIFY(p.waitForFinished(60000));
    QCOMPARE(p.exitCode(), 1);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    shown.replace(QStringLiteral("WD"), QDir(dir.path()).canonicalPath());
    QVERIFY2(err.contains(QStringLiteral("No serial port %1.").arg(shown)), qPrintable(err));
    QVERIFY2(!err.contains(QLatin1String("/dev/.")), qPrintable(err));
}

QTEST_GUILESS_MAIN(tst_LkctlOptions)
#include "tst_lkctloptions.moc"
