// The scan estimate: stable for the same bus (it followed the adaptive timeout margin, which
// moves with the host's load, and jumped between 272 ms and 1.7 s while scans took 207 ms),
// and, once a scan at that baud completed, what that scan took. The counts are of drives.

#include <bus/BusConfig.h>
#include <bus/BusTiming.h>
#include <bus/LinkTiming.h>
#include <bus/ScanTypes.h>
#include <bus/Scanner.h>
#include <panels/ScanControls.h>

#include <QtTest/QtTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QLabel>

using lk::bus::BusTiming;
using lk::bus::Scanner;
using lk::ui::ScanControls;

class tst_ScanControls : public QObject {
    Q_OBJECT
private slots:
    void estimateIsTheScannersPerBaud();
    void sweepCountsDrivesNotAnswers();
    void lastScanTimesTheBus();
    void canHasNoBaudSweep();
    void canEstimateUsesCanTiming_data();
    void canEstimateUsesCanTiming();
};

void tst_ScanControls::estimateIsTheScannersPerBaud()
{
    lk::bus::ScanOptions o;
    o.firstId = 1;
    o.lastId = 32;
    QCOMPARE(ScanControls::estimateSeconds(o, 1000000),
             Scanner::estimatedSeconds(32, 1000000, lk::bus::BusConfig{}));
    o.sweepBauds = true;
    o.bauds = {115200, 1000000};
    o.lastId = 1;
    lk::bus::ScanOptions one = o;
    one.sweepBauds = false;
    QCOMPARE(ScanControls::estimateSeconds(o, 0), ScanControls::estimateSeconds(one, 115200) +
                                                      ScanControls::estimateSeconds(one, 1000000));
    // Every baud of the sweep, the slowest costing the most.
    o.bauds.clear();
    o.lastId = 32;
    QVERIFY(ScanControls::estimateSeconds(o, 115200) >
            ScanControls::estimateSeconds(one, 9600) * 32);
}

// The built-in bus answers at every baud: a sweep hears its four drives forty times. The
// summary counts drives, and the next sweep's estimate counts their answers' wire time.
void tst_ScanControls::sweepCountsDrivesNotAnswers()
{
    ScanControls controls;
    controls.setRange(1, 32, true);
    controls.setBaud(115200);
    auto *status = controls.findChild<QLabel *>(QStringLiteral("scanStatus"));
    const double silent = controls.expectedSeconds(controls.options());
    controls.onScanStarted();
    lk::bus::ScanSummary done;
    done.finalBaud = 115200;
    done.elapsedS = 3.4;
    for (int baud : BusTiming::standardBauds()) {
        for (int id = 1; id <= 4; ++id) {
            lk::bus::FoundMotor m;
            m.id = id;
            m.baud = baud;
            m.modelKnown = true;
            m.model.motorName = QStringLiteral("MF4015");
            done.motors << m;
        }
    }
    lk::bus::ScanProgress p;
    p.baud = 4000000;
    p.id = 32;
    p.done = 319;
    p.total = 320;
    p.found = Scanner::driveCount(done.motors);
    controls.onScanProgress(p);
    QVERIFY2(status->text().contains(QStringLiteral("4 drive(s) found")),
             qPrintable(status->text()));
    controls.onScanFinished(done);
    QCOMPARE(status->text(), QStringLiteral("Scan done in 3.4 s: 4 drive(s) found"));
    // Four drives at each baud: at 9600 baud their replies take longer than a silent ID.
    QVERIFY(controls.expectedSeconds(controls.options()) > silent);
}

void tst_ScanControls::lastScanTimesTheBus()
{
    ScanControls controls;
    controls.setRange(1, 32, false);
    controls.setBaud(1000000);
    auto *status = controls.findChild<QLabel *>(QStringLiteral("scanStatus"));
    const QString before = status->text();
    QVERIFY2(before.startsWith(QStringLiteral("Scan takes about")), qPrintable(before));
    controls.setBaud(1000000); // statistics come and go: the text stays
    QCOMPARE(status->text(), before);

    controls.onScanStarted();
    lk::bus::ScanSummary done;
    done.finalBaud = 1000000;
    done.elapsedS = 0.207;
    controls.onScanFinished(done);
    QCOMPARE(controls.expectedSeconds(controls.options()), 0.207);
    controls.setBaud(1000000);
    QCOMPARE(status->text(), QStringLiteral("Scan takes about 207 ms at 1000000 baud"));
    // Another baud has not been timed yet: the formula again.
    controls.setBaud(115200);
    lk::bus::ScanOptions at115200 = controls.options();
    QCOMPARE(controls.expectedSeconds(at115200), ScanControls::estimateSeconds(at115200, 115200));
}

void tst_ScanControls::canHasNoBaudSweep()
{
    // A CAN bus has one bit rate, set on the interface: a baud sweep would reopen it at RS485
    // bauds. The option is hidden there and never asked for; RS485 keeps the user's choice.
    ScanControls controls;
    controls.show();
    controls.setRange(1, 32, true);
    controls.setLink(lk::protocol::Link::Can);
    QVERIFY(!controls.options().sweepBauds);
    QVERIFY(!controls.findChild<QCheckBox *>(QStringLiteral("scanSweepBauds"))->isVisible());
    const auto *status = controls.findChild<QLabel *>(QStringLiteral("scanStatus"));
    QVERIFY2(status->text().endsWith(QStringLiteral("at 1 Mbit/s")), qPrintable(status->text()));
    controls.setBaud(500000);
    QVERIFY2(status->text().endsWith(QStringLiteral("at 500 kbit/s")), qPrintable(status->text()));
    controls.setLink(lk::protocol::Link::Rs485);
    QVERIFY(controls.options().sweepBauds);
    QVERIFY(controls.findChild<QCheckBox *>(QStringLiteral("scanSweepBauds"))->isVisible());
}

void tst_ScanControls::canEstimateUsesCanTiming_data()
{
    QTest::addColumn<int>("bitRate");
    QTest::addColumn<int>("answering");
    QTest::newRow("500 kbit/s, 1 drive") << 500000 << 1;
    QTest::newRow("1 Mbit/s, 4 drives") << 1000000 << 4;
    QTest::newRow("125 kbit/s, 2 drives") << 125000 << 2;
}

// On CAN the estimate is the scanner's for CAN frames at the bit rate (no model read, the
// 0.25 ms reply time), not the RS485 formula at a "baud" of the same number.
void tst_ScanControls::canEstimateUsesCanTiming()
{
    QFETCH(int, bitRate);
    QFETCH(int, answering);
    ScanControls controls;
    controls.setLink(lk::protocol::Link::Can);
    controls.setBaud(bitRate);
    controls.setRange(1, 32, false);
    const double can =
        Scanner::estimatedSeconds(32, lk::bus::LinkTiming::can(bitRate), lk::bus::BusConfig{}, 0);
    QCOMPARE(controls.expectedSeconds(controls.options()), can);
    // A scan's drives are expected again where they answered, with CAN's cost per drive.
    controls.onScanStarted();
    lk::bus::ScanSummary done;
    done.finalBaud = bitRate;
    done.cancelled = true; // not a timing of the bus: the estimate stays computed
    for (int id = 1; id <= answering; ++id) {
        lk::bus::FoundMotor m;
        m.id = id;
        m.baud = bitRate;
        done.motors << m;
    }
    controls.onScanFinished(done);
    done.cancelled = false;
    done.elapsedS = 0; // no time measured: the estimate is computed with the drives found
    controls.onScanStarted();
    controls.onScanFinished(done);
    const double expected = Scanner::estimatedSeconds(32, lk::bus::LinkTiming::can(bitRate),
                                                      lk::bus::BusConfig{}, answering);
    QCOMPARE(controls.expectedSeconds(controls.options()), expected);
    // Not the RS485 figure of a "baud" of the same number (bytes, a model read per drive).
    QVERIFY(expected != Scanner::estimatedSeconds(32, bitRate, lk::bus::BusConfig{}, answering));
}

QTEST_MAIN(tst_ScanControls)
#include "tst_scancontrols.moc"
