#include "FleetRig.h"

#include <fleet/BackupFile.h>
#include <sim/SimParamsSeed.h>

#include <QtTest/QTest>

using namespace lk;
using fleet::DriveReport;
using fleet::FleetRestore;
using fleettest::FleetRig;
using fleettest::kWaitMs;
using protocol::Command;

namespace {

const QString kSpec = QStringLiteral("1:MF,2:MF,3:MS4015@2.35,4:MS4015@2.35");

/// The restorable values of a snapshot (the encoder offset is each motor's own).
fleet::ValueMap restorable(const fleet::DriveSnapshot &d)
{
    fleet::ValueMap out = d.valueMap();
    for (const fleet::FleetParam &p :
         fleet::FleetCatalog::params(d.identity.generation, d.identity.link)) {
        if (!p.restorable)
            out.remove(p.key);
    }
    return out;
}

bool openSeeded(FleetRig &rig, quint32 seed = 7)
{
    int seeded = 0;
    const bool open = rig.open(); // the simulated bus exists once the link is open
    rig.withBus([&](sim::SimBus &bus) { seeded = sim::SimParamsSeed::apply(bus, seed); });
    return open && seeded == 4;
}

QVector<FleetRestore::Job> jobs(const QVector<QPair<fleet::DriveSnapshot, int>> &pairs)
{
    QVector<FleetRestore::Job> out;
    for (const auto &p : pairs)
        out << FleetRestore::Job{p.first, p.second};
    return out;
}

} // namespace

class tst_FleetBus : public QObject {
    Q_OBJECT
private slots:
    void readsEveryParameterOfEveryDrive();
    void backupRestoreRoundTripLeavesDrivesIdentical();
    void idMapPutsTheOldDrivesValuesOnTheNewOne();
    void failedReadOfTargetBlocksItsWrite();
    void otherGenerationIsRefusedAndNothingSent();
    void romIsWrittenAfterRamAndReadBack();
    void romIsSentOnceWhenItsReplyIsLost_data();
    void romIsSentOnceWhenItsReplyIsLost();
    void cancelStopsAfterTheDriveBeingRead();
    void canReadsTheDeclaredIdentityNeverTheModel();
    void canV236RestoreIsRamOnly();
};

void tst_FleetBus::readsEveryParameterOfEveryDrive()
{
    FleetRig rig(kSpec);
    QVERIFY(openSeeded(rig));
    const QVector<fleet::DriveSnapshot> read = rig.read({1, 3, 9});
    QCOMPARE(read.size(), 3);
    QVERIFY2(read.at(0).complete(), qPrintable(read.at(0).failure));
    QVERIFY2(read.at(1).complete(), qPrintable(read.at(1).failure));
    protocol::PidGains pid;
    sim::SimParams params;
    quint16 zero = 0;
    rig.withDrive(1, [&](sim::SimDrive &d) {
        pid = d.ramPid();
        zero = d.rom().encoderZero;
    });
    rig.withDrive(3, [&](sim::SimDrive &d) { params = d.ramParams(); });
    const fleet::ValueMap one = read.at(0).valueMap();
    QCOMPARE(one.value(QStringLiteral("angle_kp")), pid.angleKp);
    QCOMPARE(one.value(QStringLiteral("iq_ki")), pid.iqKi);
    QVERIFY(one.contains(QStringLiteral("encoder_offset")));
    Q_UNUSED(zero);
    const fleet::ValueMap three = read.at(1).valueMap();
    QCOMPARE(read.at(1).identity.generation, protocol::Generation::V2_35);
    QCOMPARE(read.at(1).identity.uniqueId.size(), 12);
    QCOMPARE(three.value(QStringLiteral("speed_kd")), params.speedPid[2]);
    QCOMPARE(three.value(QStringLiteral("max_torque")), params.maxTorque);
    QCOMPARE(three.value(QStringLiteral("max_angle_raw")), params.maxAngleRaw);
    QCOMPARE(three.value(QStringLiteral("speed_ramp_dps2")), params.speedRampDps2);
    // Drive 9 is not on the bus: failed, nothing guessed.
    QVERIFY(!read.at(2).identified);
    QVERIFY(read.at(2).values.isEmpty());
    QVERIFY(read.at(2).failure.contains(QStringLiteral("read_model")));
    // The seeds give the drives of one series different values to compare.
    QVERIFY(restorable(rig.read({2}).value(0)) != restorable(read.at(0)));
}

void tst_FleetBus::backupRestoreRoundTripLeavesDrivesIdentical()
{
    FleetRig rig(kSpec);
    QVERIFY(openSeeded(rig));
    fleet::BackupFile backup;
    backup.savedAt = QDateTime::currentDateTimeUtc();
    backup.drives = rig.read({1, 2, 3, 4});
    const std::optional<fleet::BackupFile> file = fleet::BackupFile::fromJson(backup.toJsonBytes());
    QVERIFY(file);

    // Someone changes the machine: 1 is cloned onto 2, 3 onto 4.
    FleetRestore clone(&rig.session);
    QVERIFY(rig.restore(clone, jobs({{backup.drives.at(0), 2}, {backup.drives.at(2), 4}}), true));
    for (const DriveReport &r : clone.reports())
        QCOMPARE(DriveReport::outcomeName(r.outcome), "verified");
    QCOMPARE(restorable(rig.read({2}).value(0)), restorable(backup.drives.at(0)));

    // The backup restores every drive to what it held.
    FleetRestore restore(&rig.session);
    QVector<FleetRestore::Job> all;
    for (const fleet::DriveSnapshot &d : file->drives)
        all << FleetRestore::Job{d, d.id()};
    QVERIFY(rig.restore(restore, all, true));
    QCOMPARE(restore.undo().size(), 4);
    QCOMPARE(restorable(restore.undo().at(1)), restorable(backup.drives.at(0))); // 2 as cloned
    const QVector<fleet::DriveSnapshot> after = rig.read({1, 2, 3, 4});
    for (int i = 0; i < 4; ++i) {
        QCOMPARE(after.at(i).valueMap(), backup.drives.at(i).valueMap());
        const char *expected = i == 0 || i == 2 ? "unchanged" : "verified";
        QCOMPARE(DriveReport::outcomeName(restore.reports().at(i).outcome), expected);
    }
}

void tst_FleetBus::idMapPutsTheOldDrivesValuesOnTheNewOne()
{
    FleetRig rig(kSpec);
    QVERIFY(openSeeded(rig));
    fleet::BackupFile backup;
    backup.drives = rig.read({3});
    // Old drive 3 -> new drive 4.
    FleetRestore restore(&rig.session);
    QVERIFY(rig.restore(restore, jobs({{*backup.drive(3), 4}}), false));
    QCOMPARE(restore.plans().size(), 1);
    QVERIFY(!restore.plans().at(0).changes.isEmpty());
    QCOMPARE(rig.count(4, Command::WriteParamRam), 0); // prepare writes nothing
    QSignalSpy finished(&restore, &FleetRestore::finished);
    restore.execute(false);
    QVERIFY(!finished.isEmpty() || finished.wait(kWaitMs));
    QCOMPARE(DriveReport::outcomeName(restore.reports().at(0).outcome), "verified");
    QCOMPARE(restorable(rig.read({4}).value(0)), restorable(*backup.drive(3)));
    QCOMPARE(rig.count(4, Command::WriteParamRom), 0); // RAM only: no ROM asked
    QCOMPARE(rig.count(3, Command::WriteParamRam), 0);
}

void tst_FleetBus::failedReadOfTargetBlocksItsWrite()
{
    FleetRig rig(kSpec);
    QVERIFY(openSeeded(rig));
    const fleet::DriveSnapshot source = rig.read({1}).value(0);
    rig.withBus([](sim::SimBus &bus) { bus.faults().setSilenced(2, true); });
    FleetRestore restore(&rig.session);
    QVERIFY(rig.restore(restore, jobs({{source, 2}}), true, true));
    const DriveReport &r = restore.reports().at(0);
    QCOMPARE(DriveReport::outcomeName(r.outcome), "refused");
    QCOMPARE(r.refusal->key, QStringLiteral("read"));
    QCOMPARE(rig.count(2, Command::WritePidRam), 0);
    QCOMPARE(rig.count(2, Command::WritePidRom), 0);
    QCOMPARE(rig.count(2, Command::WriteAccelRam), 0);
}

void tst_FleetBus::otherGenerationIsRefusedAndNothingSent()
{
    FleetRig rig(kSpec);
    QVERIFY(openSeeded(rig));
    const fleet::DriveSnapshot source = rig.read({1}).value(0);
    FleetRestore restore(&rig.session);
    QVERIFY(rig.restore(restore, jobs({{source, 3}}), true, true));
    const DriveReport &r = restore.reports().at(0);
    QCOMPARE(DriveReport::outcomeName(r.outcome), "refused");
    QCOMPARE(r.refusal->key, QStringLiteral("generation"));
    QCOMPARE(rig.count(3, Command::WriteParamRam), 0);
    QCOMPARE(rig.count(3, Command::WriteParamRom), 0);
}

void tst_FleetBus::romIsWrittenAfterRamAndReadBack()
{
    FleetRig rig(kSpec);
    QVERIFY(openSeeded(rig));
    const QVector<fleet::DriveSnapshot> sources = rig.read({1, 3});
    FleetRestore restore(&rig.session);
    QVERIFY(rig.restore(restore, jobs({{sources.at(0), 2}, {sources.at(1), 4}}), true, true));
    const DriveReport &v23 = restore.reports().at(0);
    QCOMPARE(DriveReport::outcomeName(v23.outcome), "written"); // V2.3 cannot read ROM
    QVERIFY(v23.notVerified.join(' ').contains(QStringLiteral("V2.3")));
    QCOMPARE(rig.count(2, Command::WritePidRom), 1);
    protocol::PidGains rom;
    rig.withDrive(2, [&](sim::SimDrive &d) { rom = d.rom().pid; });
    QCOMPARE(int(rom.speedKi), int(sources.at(0).valueMap().value(QStringLiteral("speed_ki"))));
    const DriveReport &v235 = restore.reports().at(1);
    QCOMPARE(DriveReport::outcomeName(v235.outcome), "verified");
    QCOMPARE(rig.count(4, Command::WriteParamRom), 9); // 3 loops, 4 limits, the angle's pair
    sim::SimParams romParams;
    rig.withDrive(4, [&](sim::SimDrive &d) { romParams = d.rom().params; });
    QCOMPARE(romParams.maxTorque, sources.at(1).valueMap().value(QStringLiteral("max_torque")));
}

void tst_FleetBus::romIsSentOnceWhenItsReplyIsLost_data()
{
    QTest::addColumn<int>("source");
    QTest::addColumn<int>("target");
    QTest::addColumn<int>("romCommand");
    QTest::newRow("v2.3") << 1 << 2 << int(Command::WritePidRom);
    QTest::newRow("v2.35") << 3 << 4 << int(Command::WriteParamRom);
}

void tst_FleetBus::romIsSentOnceWhenItsReplyIsLost()
{
    QFETCH(int, source);
    QFETCH(int, target);
    QFETCH(int, romCommand);
    FleetRig rig(kSpec);
    QVERIFY(openSeeded(rig));
    const fleet::DriveSnapshot from = rig.read({source}).value(0);
    FleetRestore ram(&rig.session);
    QVERIFY(rig.restore(ram, jobs({{from, target}}), true)); // RAM now equal: ROM comes first
    FleetRestore rom(&rig.session);
    QVERIFY(rig.restore(rom, jobs({{from, target}}), false));
    QVERIFY(rom.plans().at(0).changes.isEmpty());
    rig.withBus([](sim::SimBus &bus) { bus.faults().injectNext(sim::Fault::DropReply, 1); });
    QSignalSpy finished(&rom, &FleetRestore::finished);
    rom.execute(true);
    QVERIFY(!finished.isEmpty() || finished.wait(kWaitMs));
    const DriveReport &r = rom.reports().at(0);
    QCOMPARE(DriveReport::outcomeName(r.outcome), "failed");
    QCOMPARE(r.romFramesSent, 1);
    QVERIFY(r.reason.contains(QStringLiteral("not repeated")));
    QCOMPARE(rig.count(target, Command(romCommand)), 1); // once, and no further ROM frame
}

void tst_FleetBus::cancelStopsAfterTheDriveBeingRead()
{
    FleetRig rig(kSpec);
    QVERIFY(openSeeded(rig));
    fleet::FleetReader reader(&rig.session);
    QSignalSpy done(&reader, &fleet::FleetReader::finished);
    connect(&reader, &fleet::FleetReader::driveRead, &reader,
            [&reader](const fleet::DriveSnapshot &, int n, int) {
                if (n == 1)
                    reader.cancel();
            });
    reader.start({1, 2, 3, 4});
    QVERIFY(!done.isEmpty() || done.wait(kWaitMs));
    QVERIFY(reader.cancelled());
    QCOMPARE(reader.snapshots().size(), 1);
    QCOMPARE(rig.count(2, Command::ReadModel), 0);
}

namespace {
/// Drive 1 an old CAN MG, drive 2 a V2.36 MF, drive 3 a V2.36 MF nobody declares.
bool openCan(FleetRig &rig)
{
    using protocol::Generation;
    rig.session.setDriveIdentity({1, protocol::Series::MG, Generation::V2_3, std::nullopt});
    rig.session.setDriveIdentity({2, protocol::Series::MF, Generation::V2_35, 36.0});
    return rig.open();
}
} // namespace

void tst_FleetBus::canReadsTheDeclaredIdentityNeverTheModel()
{
    FleetRig rig(QStringLiteral("1:MG,2:MF@2.35,3:MF@2.35"), protocol::Link::Can);
    QVERIFY(openCan(rig));
    const QVector<fleet::DriveSnapshot> read = rig.read({1, 2, 3});
    QCOMPARE(read.size(), 3);
    for (int i = 0; i < 2; ++i) {
        const fleet::DriveIdentity &who = read.at(i).identity;
        QVERIFY2(read.at(i).complete(), qPrintable(read.at(i).failure));
        QVERIFY(who.declared);
        QCOMPARE(who.link, protocol::Link::Can);
        QVERIFY(who.motorName.isEmpty() && who.driverName.isEmpty());
    }
    QCOMPARE(read.at(1).identity.gearRatio, std::optional<double>(36.0));
    // What was read is a valid backup: every value with the time its reply came.
    fleet::BackupFile file;
    file.savedAt = QDateTime::currentDateTimeUtc();
    file.drives = read.mid(0, 2);
    record::ParameterFileError error;
    QVERIFY2(fleet::BackupFile::fromJson(file.toJsonBytes(), &error),
             qPrintable(fleet::BackupFile::errorText(error)));
    sim::SimParams params;
    protocol::PidGains pid;
    rig.withDrive(1, [&](sim::SimDrive &d) { pid = d.ramPid(); });
    rig.withDrive(2, [&](sim::SimDrive &d) { params = d.ramParams(); });
    QCOMPARE(read.at(0).valueMap().value(QStringLiteral("speed_kp")), pid.speedKp);
    const fleet::ValueMap two = read.at(1).valueMap();
    QCOMPARE(two.value(QStringLiteral("speed_kd")), params.speedPid[2]);
    QCOMPARE(two.value(QStringLiteral("max_torque")), params.maxTorque);
    QCOMPARE(two.value(QStringLiteral("speed_ramp_dps2")), params.speedRampDps2);
    QCOMPARE(rig.count(2, Command::ReadControlParam), 8);
    // Drive 3 is not declared: nothing was guessed and nothing sent to it.
    QVERIFY(!read.at(2).identified);
    QVERIFY2(read.at(2).failure.contains(QStringLiteral("not declared")),
             qPrintable(read.at(2).failure));
    QVERIFY(rig.barrier(1));
    for (int id : {1, 2, 3})
        QCOMPARE(rig.count(id, Command::ReadModel), 0);
    QCOMPARE(rig.count(3, Command::ReadControlParam), 0);
    QCOMPARE(rig.count(3, Command::ReadEncoder), 0);
}

void tst_FleetBus::canV236RestoreIsRamOnly()
{
    FleetRig rig(QStringLiteral("1:MG,2:MF@2.35"), protocol::Link::Can);
    QVERIFY(openCan(rig));
    fleet::DriveSnapshot source = rig.read({2}).value(0);
    QVERIFY2(source.complete(), qPrintable(source.failure));
    source.values[QStringLiteral("speed_ki")].value += 7;
    const qint64 wanted = source.values.value(QStringLiteral("speed_ki")).value;

    FleetRestore rom(&rig.session);
    QVERIFY(rig.restore(rom, jobs({{source, 2}}), true, true));
    QCOMPARE(DriveReport::outcomeName(rom.reports().at(0).outcome), "refused");
    QCOMPARE(rom.reports().at(0).refusal->key, QStringLiteral("rom"));
    QVERIFY(rig.barrier(2));
    QCOMPARE(rig.count(2, Command::WriteControlParam), 0);

    FleetRestore ram(&rig.session);
    QVERIFY(rig.restore(ram, jobs({{source, 2}}), true));
    const DriveReport &r = ram.reports().at(0);
    QCOMPARE(DriveReport::outcomeName(r.outcome), "verified");
    QVERIFY(r.notes.join(' ').contains(QStringLiteral("RAM only")));
    QCOMPARE(rig.count(2, Command::WriteControlParam), 1); // the speed loop, once
    sim::SimParams params;
    rig.withDrive(2, [&](sim::SimDrive &d) { params = d.ramParams(); });
    QCOMPARE(qint64(params.speedPid[1]), wanted);
}

QTEST_GUILESS_MAIN(tst_FleetBus)
#include "tst_fleetbus.moc"
