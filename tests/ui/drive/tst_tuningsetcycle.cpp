#include "DriveTestRig.h"

#include <drive/ConfirmDialog.h>
#include <drive/DriveView.h>
#include <drive/ParameterTable.h>
#include <drive/RequestTracker.h>
#include <drive/TuningSetCycle.h>
#include <drive/TuningSetV23.h>
#include <sim/FaultInjector.h>

#include <QtTest/QtTest>

#include <functional>

using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::DriveView;
using lk::ui::ParamValues;
using lk::ui::TuningSetCycle;
using V23 = lk::ui::TuningSetV23;
using Kind = TuningSetCycle::WriteKind;

namespace {

/// The least a cycle needs of a drive view: a session, a drive, a link and a tracker. What
/// the Tuning view does on a change of context is left to the test (`onContext`).
class BareView : public DriveView {
public:
    using DriveView::tracker;
    std::function<void(Changes)> onContext;

protected:
    void contextChanged(Changes changes) override
    {
        if (onContext)
            onContext(changes);
    }
};

/// A cycle on drive `id` of a scanned simulated bus, V2.3 set.
struct CycleRig {
    SimRig sim;
    BareView view;
    lk::ui::ParameterTable table;
    V23 spec;
    TuningSetCycle cycle{&view, view.tracker(), &table};
    QSignalSpy reads{&cycle, &TuningSetCycle::readFinished};
    QSignalSpy mismatches{&cycle, &TuningSetCycle::mismatchChanged};
    QSignalSpy acknowledged{&cycle, &TuningSetCycle::writeAcknowledged};

    explicit CycleRig(const QString &drives = QStringLiteral("1:MF,2:MG")) : sim(drives)
    {
        table.setFields(spec.fields());
        cycle.setSpec(&spec);
        // As the Tuning view does (its spec stays V2.3 here).
        view.onContext = [this](DriveView::Changes changes) {
            cycle.contextChanged(changes);
            if (changes & (DriveView::Change::Session | DriveView::Change::Drive))
                cycle.startOver();
            cycle.showDrive();
        };
    }

    /// Opens the bus, selects drive `id` and reads it (`dropped` replies lost first).
    bool openOn(int id, int dropped = 0)
    {
        if (!sim.open())
            return false;
        view.setSession(&sim.session);
        view.setConnected(true);
        view.setDrive(id, sim.motor(id));
        return readNow(dropped);
    }
    bool readNow(int dropped = 0)
    {
        if (dropped > 0)
            dropNext(dropped);
        const qsizetype before = reads.size();
        cycle.read(true);
        return QTest::qWaitFor([&] { return reads.size() > before && !cycle.isBusy(); }, kWaitMs);
    }
    /// The next `count` replies are lost; the drives still act on the requests.
    void dropNext(int count)
    {
        sim.sim->withBus([count](lk::sim::SimBus &bus) {
            bus.faults().injectNext(lk::sim::Fault::DropReply, count);
        });
    }
    /// The pending edit with field `f` set to `value`.
    void editTo(int f, qint64 value)
    {
        ParamValues values = *table.pending();
        values[f] = value;
        table.setPending(values);
    }
    int writes(int id)
    {
        return sim.count(id, Command::WritePidRam) + sim.count(id, Command::WritePidRom) +
               sim.count(id, Command::WriteAccelRam);
    }
    bool waitIdle()
    {
        return QTest::qWaitFor([&] { return !cycle.isBusy(); }, kWaitMs);
    }
};

} // namespace

class tst_TuningSetCycle : public QObject {
    Q_OBJECT
private slots:
    void nothingIsWrittenBeforeACompleteRead_data();
    void nothingIsWrittenBeforeACompleteRead();
    void ramWriteIsReadBack();
    void romWriteAsksAndIsNeverRetried();
    void declinedWriteSendsNothing_data();
    void declinedWriteSendsNothing();
    void driveChangedDuringTheQuestionSendsNothing();
    void readBackDifferenceIsReported();
    void restoreWritesTheFirstRead();
    void unsentEditWaitsForItsDrive();
};

void tst_TuningSetCycle::nothingIsWrittenBeforeACompleteRead_data()
{
    QTest::addColumn<int>("kind");
    QTest::newRow("RAM") << int(Kind::Ram);
    QTest::newRow("ROM") << int(Kind::Rom);
    QTest::newRow("restore") << int(Kind::RestoreFirstRead);
}

void tst_TuningSetCycle::nothingIsWrittenBeforeACompleteRead()
{
    QFETCH(int, kind);
    CycleRig rig;
    QVERIFY(rig.openOn(1, 2)); // both tries of read_pid lost; read_accel answers
    QVERIFY(!rig.cycle.readComplete());
    QVERIFY(!rig.table.pending()); // unknown, never 0
    QVERIFY2(rig.cycle.status().contains(QStringLiteral("Could not read drive 1")),
             qPrintable(rig.cycle.status()));
    int asked = 0;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &) { return ++asked > 0; });
    rig.cycle.write(Kind(kind));
    QCOMPARE(asked, 0);
    QVERIFY2(rig.cycle.status().contains(QStringLiteral("Nothing was sent")),
             qPrintable(rig.cycle.status()));
    QVERIFY(rig.sim.barrier(1));
    QCOMPARE(rig.writes(1), 0);
}

void tst_TuningSetCycle::ramWriteIsReadBack()
{
    CycleRig rig;
    QVERIFY(rig.openOn(1));
    QVERIFY(rig.cycle.readComplete());
    const int kp = rig.sim.ramPid(1).speedKp == 77 ? 78 : 77;
    rig.editTo(V23::SpeedKp, kp);
    const qsizetype before = rig.reads.size();
    rig.cycle.write(Kind::Ram);
    QTRY_VERIFY_WITH_TIMEOUT(rig.reads.size() > before && !rig.cycle.isBusy(), kWaitMs);
    QCOMPARE(int(rig.sim.ramPid(1).speedKp), kp);
    QCOMPARE(rig.cycle.held().value(V23::SpeedKp), std::optional<qint64>(kp)); // read back
    QCOMPARE(rig.acknowledged.size(), 1);
    QCOMPARE(rig.acknowledged.first().first().toBool(), false);
    QCOMPARE(rig.sim.count(1, Command::WritePidRam), 1);
    QCOMPARE(rig.sim.count(1, Command::WritePidRom), 0);
    QVERIFY(rig.cycle.ramRomNote().warning); // changed in RAM only: lost at power-off
}

void tst_TuningSetCycle::romWriteAsksAndIsNeverRetried()
{
    CycleRig rig;
    QVERIFY(rig.openOn(2));
    QList<ConfirmRequest> asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q;
        return true;
    });
    const int kp = rig.sim.romPid(2).angleKp == 88 ? 89 : 88;
    rig.editTo(V23::AngleKp, kp);
    rig.dropNext(1); // the drive writes its flash, its acknowledgement is lost
    const qsizetype before = rig.reads.size();
    rig.cycle.write(Kind::Rom);
    QCOMPARE(asked.size(), 1);
    QCOMPARE(asked.first().key, QStringLiteral("write_pid_rom"));
    QTRY_VERIFY_WITH_TIMEOUT(rig.reads.size() > before && !rig.cycle.isBusy(), kWaitMs);
    QVERIFY(rig.sim.barrier(2));
    QCOMPARE(rig.sim.count(2, Command::WritePidRom), 1); // sent once, not again
    QCOMPARE(int(rig.sim.romPid(2).angleKp), kp);
    QVERIFY2(rig.cycle.status().startsWith(QStringLiteral("The write failed")),
             qPrintable(rig.cycle.status()));
    QVERIFY(rig.acknowledged.isEmpty());
    // The read-back still shows what the drive holds now.
    QCOMPARE(rig.cycle.held().value(V23::AngleKp), std::optional<qint64>(kp));
}

void tst_TuningSetCycle::declinedWriteSendsNothing_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("status");
    QTest::newRow("ROM") << int(Kind::Rom) << QStringLiteral("ROM write cancelled");
    QTest::newRow("restore") << int(Kind::RestoreFirstRead) << QStringLiteral("Restore cancelled");
}

void tst_TuningSetCycle::declinedWriteSendsNothing()
{
    QFETCH(int, kind);
    QFETCH(QString, status);
    CycleRig rig;
    QVERIFY(rig.openOn(1));
    rig.editTo(V23::IqKi, rig.sim.ramPid(1).iqKi == 12 ? 13 : 12);
    int asked = 0;
    ConfirmDialog::ScopedPolicy no([&](const ConfirmRequest &) {
        ++asked;
        return false;
    });
    rig.cycle.write(Kind(kind));
    QCOMPARE(asked, 1);
    QVERIFY2(rig.cycle.status().startsWith(status), qPrintable(rig.cycle.status()));
    QVERIFY(rig.sim.barrier(1));
    QCOMPARE(rig.writes(1), 0);
    QVERIFY(rig.table.anyChanged()); // the edit is kept
}

void tst_TuningSetCycle::driveChangedDuringTheQuestionSendsNothing()
{
    CycleRig rig;
    QVERIFY(rig.openOn(1));
    rig.editTo(V23::AngleKp, rig.sim.ramPid(1).angleKp == 50 ? 51 : 50);
    // The dialog runs an event loop: meanwhile the operator selects drive 2.
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &) {
        rig.view.setDrive(2, rig.sim.motor(2));
        return true;
    });
    rig.cycle.write(Kind::Rom);
    QVERIFY2(rig.cycle.status().contains(QStringLiteral("nothing was sent")),
             qPrintable(rig.cycle.status()));
    QVERIFY(!rig.cycle.readComplete());
    QVERIFY(rig.sim.barrier(1));
    QVERIFY(rig.sim.barrier(2));
    QCOMPARE(rig.writes(1), 0);
    QCOMPARE(rig.writes(2), 0);
}

void tst_TuningSetCycle::readBackDifferenceIsReported()
{
    // Firmware that acknowledges 0x34 and reads 0 with 0x33 (docs/ERRATA.md).
    CycleRig rig(QStringLiteral("1:MF+accel-ignored"));
    QVERIFY(rig.openOn(1));
    rig.editTo(V23::Accel, 15000);
    const qsizetype before = rig.reads.size();
    rig.cycle.write(Kind::Ram);
    QTRY_VERIFY_WITH_TIMEOUT(rig.reads.size() > before && !rig.cycle.isBusy(), kWaitMs);
    QVERIFY(!rig.mismatches.isEmpty());
    const QString text = rig.mismatches.last().first().toString();
    QVERIFY2(text.contains(QStringLiteral("acceleration 0 dps/s after 15000 dps/s")),
             qPrintable(text));
    QVERIFY2(rig.cycle.status().contains(QStringLiteral("read-back differs")),
             qPrintable(rig.cycle.status()));
}

void tst_TuningSetCycle::restoreWritesTheFirstRead()
{
    CycleRig rig;
    QVERIFY(rig.openOn(1));
    QVERIFY(rig.cycle.firstReadAt());
    const lk::protocol::PidGains first = rig.sim.ramPid(1);
    rig.editTo(V23::SpeedKi, first.speedKi == 5 ? 6 : 5);
    rig.cycle.write(Kind::Ram);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim.ramPid(1).speedKi != first.speedKi, kWaitMs);
    QVERIFY(rig.waitIdle());

    QList<ConfirmRequest> asked;
    ConfirmDialog::ScopedPolicy yes([&](const ConfirmRequest &q) {
        asked << q;
        return true;
    });
    rig.cycle.write(Kind::RestoreFirstRead);
    QCOMPARE(asked.size(), 1);
    QTRY_COMPARE_WITH_TIMEOUT(rig.sim.ramPid(1), first, kWaitMs);
    QVERIFY(rig.waitIdle());
    QCOMPARE(V23::pidOf(*rig.table.pending()), first); // the pending edit is what was restored
}

void tst_TuningSetCycle::unsentEditWaitsForItsDrive()
{
    CycleRig rig;
    QVERIFY(rig.openOn(1));
    const int mine = rig.sim.ramPid(1).speedKp == 40 ? 41 : 40;
    rig.editTo(V23::SpeedKp, mine);
    rig.view.setDrive(2, rig.sim.motor(2));
    QVERIFY(!rig.table.pending()); // drive 1's edit is not drive 2's
    QVERIFY(rig.readNow());
    QVERIFY(!rig.table.anyChanged());

    rig.view.setDrive(1, rig.sim.motor(1));
    QVERIFY(rig.readNow());
    QCOMPARE(rig.table.pending()->value(V23::SpeedKp), qint64(mine));
    QVERIFY(rig.cycle.status().contains(QStringLiteral("unsent edit of drive 1")));
    QCOMPARE(rig.writes(1), 0);
}

QTEST_MAIN(tst_TuningSetCycle)
#include "tst_tuningsetcycle.moc"
