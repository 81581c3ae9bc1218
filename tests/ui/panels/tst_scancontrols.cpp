// The scan estimate: stable for the same bus (it followed the adaptive timeout margin, which
// moves with the host's load, and jumped between 272 ms and 1.7 s while scans took 207 ms),
// and, once a scan at that baud completed, what that scan took.

#include <bus/BusConfig.h>
#include <bus/BusTiming.h>
#include <bus/ScanTypes.h>
#include <panels/ScanControls.h>

#include <QtTest/QtTest>
#include <QtWidgets/QLabel>

using lk::bus::BusTiming;
using lk::ui::ScanControls;

class tst_ScanControls : public QObject {
    Q_OBJECT
private slots:
    void estimateIsProbePlusQuietPerId();
    void lastScanTimesTheBus();
};

void tst_ScanControls::estimateIsProbePlusQuietPerId()
{
    lk::bus::ScanOptions o;
    o.firstId = 1;
    o.lastId = 32;
    const lk::bus::BusConfig config;
    const double probe = BusTiming::replyTimeoutS(lk::protocol::Command::ReadState1, 1000000,
                                                  config.minMarginMs / 1000);
    const double quiet =
        BusTiming::kTurnaroundS +
        BusTiming::wireTimeS(0, BusTiming::maxReplyBytes(lk::protocol::Command::ReadState1),
                             1000000) +
        config.initialMarginMs / 1000;
    QCOMPARE(ScanControls::estimateSeconds(o, 1000000), 32 * (probe + quiet));
    o.sweepBauds = true;
    o.bauds = {115200, 1000000};
    o.lastId = 1;
    lk::bus::ScanOptions one = o;
    one.sweepBauds = false;
    QCOMPARE(ScanControls::estimateSeconds(o, 0), ScanControls::estimateSeconds(one, 115200) +
                                                      ScanControls::estimateSeconds(one, 1000000));
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

QTEST_MAIN(tst_ScanControls)
#include "tst_scancontrols.moc"
