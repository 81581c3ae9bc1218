// Protection faults a simulated drive raises by itself (SimFault): the syntax of lksim's
// --fault and of "+fault=" in a bus spec, by generation; what the drive does when one trips
// (it stops, its flags latch, 0x9B clears them once the cause has gone); the built-in bus.
#include "SimDriveTestUtil.h"

#include "protocol/RequestBuilder.h"
#include "sim/SimBus.h"
#include "sim/SimBusSpec.h"
#include "sim/SimFault.h"

using namespace lk;
using namespace lk::test;
using protocol::Command;
using protocol::Generation;
using sim::SimDrive;
using sim::SimFault;

namespace {
SimDrive makeDrive(const QString &spec)
{
    const auto parsed = sim::SimBusSpec::parse(spec);
    if (!parsed)
        qFatal("bad spec %s", qPrintable(spec));
    return SimDrive(kDriveId, parsed->drives.first().model);
}

quint8 clearErrors(SimDrive &d)
{
    return readBack<protocol::State1>(d, Command::ClearErrors).errorState;
}
} // namespace

class tst_SimFault : public QObject {
    Q_OBJECT
private slots:
    void parse_data();
    void parse();
    void refused_data();
    void refused();
    void specCarriesFaults();
    void lksimFaultOptionAddsToTheSpec();
    void scheduledFaultStopsTheDriveAndLatches();
    void v235TripLeavesTheMotorOffUntilRun();
    void lowVoltageShowsInTheSupply();
    void overTemperatureShowsInTheTemperature();
    void builtInBusRaisesFaults();
};

void tst_SimFault::parse_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("generation");
    QTest::addColumn<int>("bit");
    QTest::addColumn<double>("start");
    QTest::addColumn<double>("end"); // -1: none
    QTest::addColumn<QString>("back");
    const int v23 = int(Generation::V2_3);
    const int v235 = int(Generation::V2_35);
    QTest::newRow("V2.3 low voltage from power-up")
        << "low_voltage" << v23 << 0 << 0.0 << -1.0 << "low_voltage";
    QTest::newRow("V2.3 over-temperature at 5 s")
        << "over_temperature@5s" << v23 << 3 << 5.0 << -1.0 << "over_temperature@5s";
    QTest::newRow("seconds without s")
        << "over_temperature@5" << v23 << 3 << 5.0 << -1.0 << "over_temperature@5s";
    QTest::newRow("V2.35 motor over-temperature by its V2.3 name")
        << "over_temperature@1.5s" << v235 << 3 << 1.5 << -1.0 << "motor_over_temperature@1.5s";
    QTest::newRow("V2.35 stall window")
        << "stall@2-4.5s" << v235 << 6 << 2.0 << 4.5 << "stall@2s-4.5s";
    QTest::newRow("V2.35 every bit: over_voltage")
        << "over_voltage" << v235 << 1 << 0.0 << -1.0 << "over_voltage";
    QTest::newRow("driver over-temperature") << "driver_over_temperature@0s-1s" << v235 << 2 << 0.0
                                             << 1.0 << "driver_over_temperature@0s-1s";
    QTest::newRow("over current") << "OVER_CURRENT" << v235 << 4 << 0.0 << -1.0 << "over_current";
    QTest::newRow("short circuit")
        << "short_circuit" << v235 << 5 << 0.0 << -1.0 << "short_circuit";
    QTest::newRow("input timeout")
        << "input_timeout@10s" << v235 << 7 << 10.0 << -1.0 << "input_timeout@10s";
}

void tst_SimFault::parse()
{
    QFETCH(QString, text);
    QFETCH(int, generation);
    QFETCH(int, bit);
    QFETCH(double, start);
    QFETCH(double, end);
    QFETCH(QString, back);
    QString error;
    const auto f = SimFault::parse(text, Generation(generation), &error);
    QVERIFY2(f, qPrintable(error));
    QCOMPARE(f->bit, bit);
    QCOMPARE(f->startS, start);
    QCOMPARE(f->endS.value_or(-1.0), end);
    QCOMPARE(f->toString(Generation(generation)), back);
    QCOMPARE(SimFault::parse(back, Generation(generation)), f);
}

void tst_SimFault::refused_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("generation");
    QTest::addColumn<QString>("says");
    const int v23 = int(Generation::V2_3);
    // V2.3 names only bit 0 and bit 3 (docs/V2.35.md section 5).
    QTest::newRow("stall on V2.3") << "stall" << v23 << "low_voltage, over_temperature";
    QTest::newRow("over-voltage on V2.3") << "over_voltage@1s" << v23 << "over_voltage";
    QTest::newRow("unknown") << "meltdown" << int(Generation::V2_35) << "input_timeout";
    QTest::newRow("bad time") << "stall@soon" << int(Generation::V2_35) << "@START";
    QTest::newRow("end before start") << "stall@5-2" << int(Generation::V2_35) << "END after";
    QTest::newRow("negative") << "stall@-1" << int(Generation::V2_35) << "@START";
    QTest::newRow("empty time") << "stall@" << int(Generation::V2_35) << "@START";
}

void tst_SimFault::refused()
{
    QFETCH(QString, text);
    QFETCH(int, generation);
    QFETCH(QString, says);
    QString error;
    QVERIFY(!SimFault::parse(text, Generation(generation), &error));
    QVERIFY2(error.contains(says), qPrintable(error));
}

void tst_SimFault::specCarriesFaults()
{
    QString error;
    const auto spec = sim::SimBusSpec::parse(
        QStringLiteral("1:MF+fault=over_temperature@5s,2:MS4015@2.35+accel-ignored+fault=stall@1-2"
                       "+fault=low_voltage"),
        &error);
    QVERIFY2(spec, qPrintable(error));
    QCOMPARE(spec->drives[0].model.faults.size(), 1);
    QCOMPARE(spec->drives[1].model.faults.size(), 2);
    QVERIFY(spec->drives[1].model.quirks.accelIgnored);
    const QString text = spec->toString();
    QCOMPARE(text, QStringLiteral("1:MF+fault=over_temperature@5s,2:MS4015@2.35+accel-ignored+"
                                  "fault=stall@1s-2s+fault=low_voltage"));
    QCOMPARE(sim::SimBusSpec::parse(text)->toString(), text);
    // A V2.3 drive has no stall flag: the entry and the names it has are given.
    QVERIFY(!sim::SimBusSpec::parse(QStringLiteral("3:MF+fault=stall"), &error));
    QVERIFY2(error.contains("'3:MF+fault=stall'") && error.contains("over_temperature"),
             qPrintable(error));
}

void tst_SimFault::lksimFaultOptionAddsToTheSpec()
{
    auto spec = sim::SimBusSpec::parse(QStringLiteral("1:MF4015,2:MG@2.35"));
    QString error;
    QVERIFY2(spec->addFaults(QStringLiteral("1:over_temperature@5s, 2:over_current@1s-3s"), &error),
             qPrintable(error));
    QCOMPARE(spec->toString(), QStringLiteral("1:MF+fault=over_temperature@5s,2:MG@2.35+fault="
                                              "over_current@1s-3s"));
    QVERIFY(!spec->addFaults(QStringLiteral("7:stall"), &error));
    QVERIFY2(error.contains("no drive 7"), qPrintable(error));
    QVERIFY(!spec->addFaults(QStringLiteral("1:stall"), &error));
    QVERIFY2(error.contains("v2.3"), qPrintable(error));
    QVERIFY(!spec->addFaults(QStringLiteral("stall"), &error));
    QVERIFY2(error.contains("ID:FAULT"), qPrintable(error));
}

void tst_SimFault::scheduledFaultStopsTheDriveAndLatches()
{
    // V2.35 stall from 1 s to 2 s after power-up.
    SimDrive d = makeDrive(QStringLiteral("1:MF4015@2.35+fault=stall@1-2"));
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    d.advance(0.9);
    QCOMPARE(d.errorState(), quint8(0));
    QVERIFY(d.speedDps() > 300);
    d.advance(0.2); // 1.1 s: tripped
    QCOMPARE(d.errorState(), quint8(0x40));
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    QVERIFY(!d.activeCommand());
    d.advance(3.0); // the drive stopped itself: the rotor coasts to rest, nothing drives it
    QVERIFY2(std::abs(d.speedDps()) < 1, qPrintable(QString::number(d.speedDps())));
    QCOMPARE(d.iqA(), 0.0);
    // 4.1 s: the cause has gone, the flag stays until 0x9B clears it.
    QCOMPARE(d.errorState(), quint8(0x40));
    QCOMPARE(clearErrors(d), quint8(0));
}

void tst_SimFault::v235TripLeavesTheMotorOffUntilRun()
{
    SimDrive d = makeDrive(QStringLiteral("1:MF4015@2.35+fault=over_current@0-0.5"));
    QCOMPARE(d.errorState(), quint8(0x10)); // from power-up
    QCOMPARE(readBack<protocol::State1>(d, Command::ReadState1).motorOn(),
             std::optional<bool>(false));
    QCOMPARE(clearErrors(d), quint8(0x10)); // the cause is still there
    plain(d, Command::MotorRun);
    QCOMPARE(d.runState(), SimDrive::RunState::Off); // a drive in protection stays off
    d.advance(1.0);
    QCOMPARE(clearErrors(d), quint8(0));
    // Cleared, but still off: a control command does not turn it on, 0x88 does.
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    plain(d, Command::MotorRun);
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    d.advance(1.0);
    QVERIFY(d.speedDps() > 300);
}

void tst_SimFault::lowVoltageShowsInTheSupply()
{
    SimDrive d = makeDrive(QStringLiteral("1:MF+fault=low_voltage@0.5-1.5"));
    QCOMPARE(d.busVoltage(), 24.0);
    d.advance(0.6);
    QCOMPARE(d.errorState(), quint8(0x01));
    QVERIFY(d.busVoltage() < d.limits().minSupplyV);
    QCOMPARE(clearErrors(d), quint8(0x01));
    d.advance(1.0);
    QCOMPARE(d.busVoltage(), 24.0); // the bench supply is back
    QCOMPARE(clearErrors(d), quint8(0));
    d.setSupplyVoltage(30.0); // the bench's own setting still applies
    QCOMPARE(d.busVoltage(), 30.0);
}

void tst_SimFault::overTemperatureShowsInTheTemperature()
{
    SimDrive d = makeDrive(QStringLiteral("1:MF+fault=over_temperature@1-2"));
    d.advance(1.5);
    QCOMPARE(d.errorState(), quint8(0x08));
    QVERIFY(d.temperatureC() > SimDrive::kOverTemperatureC);
    d.advance(1.0); // the cause has gone, but the motor is still hot: it must cool first
    QCOMPARE(clearErrors(d), quint8(0x08));
    runUntil(
        d, 1200.0, [&] { return d.temperatureC() < SimDrive::kOverTemperatureClearC; }, 1.0);
    QCOMPARE(clearErrors(d), quint8(0));
}

void tst_SimFault::builtInBusRaisesFaults()
{
    // lkstudio's and lkctl's --sim build their bus from the same spec.
    const auto spec = sim::SimBusSpec::parse(QStringLiteral("3:MG@2.35+fault=short_circuit@0.2"));
    QVERIFY(spec);
    const auto bus = sim::SimBus::fromSpec(*spec);
    bus->advanceTo(0);
    bus->advanceTo(0.1);
    QCOMPARE(bus->drive(3)->errorState(), quint8(0));
    bus->advanceTo(0.3);
    QCOMPARE(bus->drive(3)->errorState(), quint8(0x20));
    const QList<sim::SimReply> replies =
        bus->receive(req(protocol::build::plain(Command::ReadState1, 3)).encode(), 0.31);
    QCOMPARE(replies.size(), 1);
    QVERIFY(replies.first().bytes.size() == 13);
    QCOMPARE(quint8(replies.first().bytes.at(11)), quint8(0x20)); // D6: errorState
    QCOMPARE(quint8(replies.first().bytes.at(10)), quint8(0x10)); // D5: motor off
}

QTEST_APPLESS_MAIN(tst_SimFault)
#include "tst_simfault.moc"
