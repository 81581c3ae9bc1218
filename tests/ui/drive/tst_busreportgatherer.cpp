// The bus report over the built-in simulated bus: each drive read by the generation its model
// names - a V2.35 drive by read_param, with no read_pid or read_accel (which it lacks: two
// spurious problems before), its state with the voltage at 0.01 V; a V2.3 drive as before.

#include "DriveTestRig.h"

#include <drive/BusReportGatherer.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QtTest>

using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::record::BusReport;

class tst_BusReportGatherer : public QObject {
    Q_OBJECT
private slots:
    void readsEachDriveByItsGeneration();
};

void tst_BusReportGatherer::readsEachDriveByItsGeneration()
{
    SimRig rig(QStringLiteral("1:MS4015@2.35,2:MF"));
    QVERIFY(rig.open());
    rig.withDrive(1, [](lk::sim::SimDrive &d) { d.setSupplyVoltage(24.37); });
    lk::ui::BusReportGatherer gatherer;
    QSignalSpy finished(&gatherer, &lk::ui::BusReportGatherer::finished);
    QSignalSpy progress(&gatherer, &lk::ui::BusReportGatherer::progress);
    gatherer.start(&rig.session);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kWaitMs);
    const BusReport report = finished.first().first().value<BusReport>();
    QCOMPARE(report.drives.size(), 2);

    const lk::record::BusReportDrive &v235 = report.drives.at(0);
    QCOMPARE(v235.problems, QStringList());
    QCOMPARE(v235.generation, std::optional(lk::protocol::Generation::V2_35));
    QVERIFY(!v235.pid && !v235.accelDps2);
    QCOMPARE(v235.params.size(), lk::protocol::ParamTable::kCount);
    QVERIFY2(v235.stateText().contains(QStringLiteral("24.37 V")), qPrintable(v235.stateText()));
    QVERIFY2(v235.gainsText().count(QLatin1Char('/')) == 6, qPrintable(v235.gainsText()));
    QVERIFY2(v235.limitsText().contains(QStringLiteral("max speed")),
             qPrintable(v235.limitsText()));

    const lk::record::BusReportDrive &v23 = report.drives.at(1);
    QCOMPARE(v23.problems, QStringList());
    QCOMPARE(v23.generation, std::optional(lk::protocol::Generation::V2_3));
    QVERIFY(v23.pid && v23.accelDps2);
    QVERIFY(v23.params.isEmpty());
    // Progress ends at its total, whatever the generations made of the first estimate.
    QVERIFY(!progress.isEmpty());
    const QList<QVariant> last = progress.last();
    QCOMPARE(last.at(0).toInt(), last.at(1).toInt());
}

QTEST_MAIN(tst_BusReportGatherer)
#include "tst_busreportgatherer.moc"
