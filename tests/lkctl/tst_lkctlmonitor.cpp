#include "E2eUtil.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QRegularExpression>
#include <QtTest/QtTest>

// lkctl monitor on the in-process simulated bus: a --what set a drive's series lacks is refused
// at once (exit 2, nothing polled, no header) instead of printing a header and waiting for
// rows that never come; V2.35 voltages keep their 0.01 V.

using lk::e2e::CtlResult;

namespace {
QStringList words(const char *text)
{
    return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}
} // namespace

class tst_LkctlMonitor : public QObject {
    Q_OBJECT
private slots:
    void setTheSeriesLacksIsRefused_data();
    void setTheSeriesLacksIsRefused();
    void voltageKeepsItsResolution_data();
    void voltageKeepsItsResolution();
};

void tst_LkctlMonitor::setTheSeriesLacksIsRefused_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QString>("said");
    QTest::newRow("MS, state3 alone")
        << "monitor 17 --what state3 --count 2 --sim 17:MS"
        << "drive 17 is MS, and the MS series has no read_state3 (--what state3)";
    QTest::newRow("V2.35 MS, state3")
        << "monitor 1 --what state2,state3 --count 2 --sim 1:MS4015@2.35"
        << "drive 1 is MS, and the MS series has no read_state3 (--what state3)";
    QTest::newRow("MS beside an MF, state3 alone")
        << "monitor 3 17 --what state3 --count 2 --json --sim 3:MF,17:MS"
        << "drive 17 is MS, and the MS series has no read_state3 (--what state3)";
}

void tst_LkctlMonitor::setTheSeriesLacksIsRefused()
{
    QFETCH(QString, args);
    QFETCH(QString, said);
    QElapsedTimer clock;
    clock.start();
    const CtlResult r = lk::e2e::lkctl(args.split(QLatin1Char(' ')), 60000);
    QVERIFY2(clock.elapsed() < 50000, "refused at once, not after a wait");
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, QByteArray()); // not even the header
    QVERIFY2(r.err.startsWith("lkctl monitor: "), r.err.constData());
    QVERIFY2(r.err.contains(said.toUtf8()), r.err.constData());
    QVERIFY2(r.err.contains("nothing was polled"), r.err.constData());
    // With something to poll for every drive, a set some of them lack is fine: an MS beside
    // an MF goes without the phase currents.
    const CtlResult ok = lk::e2e::lkctl(
        words("monitor 3 17 --what state2,state3 --count 2 --sim 3:MF,17:MS --json"), 60000);
    QCOMPARE(ok.exitCode, 0);
    QCOMPARE(ok.out.count('\n'), 2); // --count counts JSON lines: a round of two drives
    QVERIFY(ok.out.contains("\"id\":3,") && ok.out.contains("\"ia_a\""));
}

void tst_LkctlMonitor::voltageKeepsItsResolution_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QString>("pattern");
    // V2.35 sends 0.01 V: a value such as 24.37 must not read 24.4. One column, one
    // resolution: V2.3's 0.1 V values read with a trailing 0.
    QTest::newRow("V2.35 JSON") << "monitor 1 --what state1 --count 2 --json --sim 1:MS4015@2.35"
                                << R"("voltage_v":\d+\.\d\d[,}])";
    QTest::newRow("V2.35 CSV") << "monitor 1 --what state1 --count 2 --csv-layout long "
                                  "--sim 1:MS4015@2.35"
                               << R"(^[0-9.]+,1,\d+,\d+\.\d\d,)";
    QTest::newRow("V2.3 JSON") << "monitor 3 --what state1 --count 2 --json --sim 3:MF"
                               << R"("voltage_v":\d+\.\d0[,}])";
}

void tst_LkctlMonitor::voltageKeepsItsResolution()
{
    QFETCH(QString, args);
    QFETCH(QString, pattern);
    const CtlResult r = lk::e2e::lkctl(args.split(QLatin1Char(' ')), 60000);
    QCOMPARE(r.exitCode, 0);
    const QRegularExpression re(pattern, QRegularExpression::MultilineOption);
    QVERIFY2(re.match(QString::fromUtf8(r.out)).hasMatch(), r.out.constData());
}

QTEST_GUILESS_MAIN(tst_LkctlMonitor)
#include "tst_lkctlmonitor.moc"
