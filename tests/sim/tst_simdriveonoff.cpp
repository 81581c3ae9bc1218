// A simulated firmware-2.35 drive's motor on/off and brake, as docs/V2.35.md sections 3, 8 and
// 11 state them, and its identity against the real MS4015 / DS40R7 of the captures.
#include "SimDriveTestUtil.h"

#include "protocol/RequestBuilder.h"
#include "sim/SimBus.h"
#include "sim/SimBusSpec.h"
#include "sim/SimRomStore.h"

using namespace lk;
using namespace lk::test;
using protocol::Command;
using sim::SimDrive;

namespace {
sim::SimDrive makeDrive(const char *spec)
{
    const auto parsed = sim::SimBusSpec::parse(QString::fromLatin1(spec));
    if (!parsed)
        qFatal("bad spec %s", spec);
    return sim::SimDrive(kDriveId, parsed->drives.first().model);
}

bool brakeReleased(SimDrive &d)
{
    return payloadOf<protocol::BrakeState>(
               d.handle(req(protocol::build::brake(kDriveId, protocol::BrakeAction::Read))))
        .released();
}

std::optional<bool> motorOn(SimDrive &d)
{
    return readBack<protocol::State1>(d, Command::ReadState1).motorOn();
}
} // namespace

class tst_SimDriveOnOff : public QObject {
    Q_OBJECT
private slots:
    void v235PowersUpOnAndUnbraked();
    void offStaysOffUntilMotorRun();
    void runDoesNotLeaveAStop();
    void v23ControlCommandTurnsTheMotorOn();
    void engagedBrakeHoldsTheShaft();
    void ms4015IsTheCapturedDrive();
    void factoryRomOnlyWhereNothingWasStored();
};

void tst_SimDriveOnOff::v235PowersUpOnAndUnbraked()
{
    SimDrive d = makeDrive("1:MS4015@2.35");
    QCOMPARE(motorOn(d), std::optional<bool>(true));
    QVERIFY(brakeReleased(d));
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    d.advance(1.0);
    QVERIFY(d.speedDps() > 300);
    // A power cycle: on and unbraked again, whatever was set before.
    plain(d, Command::MotorOff);
    QVERIFY(send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Engage)));
    d.restart();
    QCOMPARE(motorOn(d), std::optional<bool>(true));
    QVERIFY(brakeReleased(d));
}

void tst_SimDriveOnOff::offStaysOffUntilMotorRun()
{
    SimDrive d = makeDrive("1:MF4015@2.35");
    plain(d, Command::MotorOff);
    QCOMPARE(motorOn(d), std::optional<bool>(false));
    // A control command is answered with the motion reply, but does not turn it on.
    const auto reply = d.handle(req(protocol::build::speed(kDriveId, 360)));
    QVERIFY(reply);
    QVERIFY(std::holds_alternative<protocol::State2>(reply->payload));
    d.advance(1.0);
    QCOMPARE(d.speedDps(), 0.0);
    QCOMPARE(motorOn(d), std::optional<bool>(false));
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    // 0x88 turns it on with no command (0x80 cleared it, the ignored one was not kept)...
    plain(d, Command::MotorRun);
    QCOMPARE(motorOn(d), std::optional<bool>(true));
    d.advance(1.0);
    QCOMPARE(d.speedDps(), 0.0);
    // ... and a control command then runs.
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    d.advance(1.0);
    QVERIFY(d.speedDps() > 300);
}

void tst_SimDriveOnOff::runDoesNotLeaveAStop()
{
    // V2.35: 0x88 turns a motor that is off on; a stop is left by a new control command.
    SimDrive d = makeDrive("1:MF4015@2.35");
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    d.advance(1.0);
    plain(d, Command::MotorStop);
    QCOMPARE(motorOn(d), std::optional<bool>(true));
    plain(d, Command::MotorRun);
    d.advance(2.0);
    QCOMPARE(d.runState(), SimDrive::RunState::Stopped); // not resumed
    QVERIFY2(d.speedDps() < 300, qPrintable(QString::number(d.speedDps())));
    QVERIFY(send(d, protocol::build::speed(kDriveId, -360)));
    d.advance(1.0);
    QVERIFY(d.speedDps() < -300);
}

void tst_SimDriveOnOff::v23ControlCommandTurnsTheMotorOn()
{
    // V2.3 has no motor-on flag: a control command after 0x80 runs at once.
    SimDrive d = makeDrive("1:MF");
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    QVERIFY(!motorOn(d).has_value());
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    d.advance(1.0);
    QVERIFY(d.speedDps() > 300);
    plain(d, Command::MotorOff);
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    QCOMPARE(d.runState(), SimDrive::RunState::Running);
}

void tst_SimDriveOnOff::engagedBrakeHoldsTheShaft()
{
    SimDrive d = makeDrive("1:MS4015@2.35");
    QVERIFY(send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Engage)));
    const quint16 encoder = d.encoder();
    QVERIFY(send(d, protocol::build::speed(kDriveId, 360)));
    d.advance(1.0);
    QCOMPARE(d.speedDps(), 0.0);
    QCOMPARE(d.encoder(), encoder);
    QVERIFY(send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Release)));
    d.advance(1.0);
    QVERIFY(d.speedDps() > 300);
    // The bench's blocked rotor is its own: releasing the brake does not free it.
    d.setRotorLocked(true);
    d.advance(0.5);
    QCOMPARE(d.speedDps(), 0.0);
}

void tst_SimDriveOnOff::ms4015IsTheCapturedDrive()
{
    // docs/V2.35.md sections 7 and 12: "DS40R7" + "MS4015", an encoder zero away from 0, and
    // Max Power (ParamID 0x99 on MS) within the series' -1000..1000.
    SimDrive d = makeDrive("1:MS4015@2.35");
    const auto model = readBack<protocol::ModelInfo>(d, Command::ReadModel);
    QCOMPARE(model.driverName, QStringLiteral("DS40R7"));
    QCOMPARE(model.motorName, QStringLiteral("MS4015"));
    const auto encoder = readBack<protocol::EncoderReading>(d, Command::ReadEncoder);
    QVERIFY(encoder.encoderOffset != 0);
    QCOMPARE(encoder.encoder,
             quint16((encoder.encoderRaw - encoder.encoderOffset + 65536) % 65536));
    const auto power = payloadOf<protocol::ParameterValue>(
        d.handle(req(protocol::build::readParam(kDriveId, protocol::ParamId::MaxTorqueCurrent))));
    QVERIFY2(std::abs(power.asInt16()) <= 1000, qPrintable(QString::number(power.asInt16())));
    // Another ID's factory zero lies elsewhere; a V2.3 drive's stays 0.
    const auto spec = sim::SimBusSpec::parse(QStringLiteral("2:MS4015@2.35"));
    SimDrive other(2, spec->drives.first().model);
    QVERIFY(other.encoderOffset() != d.encoderOffset());
    QCOMPARE(makeDrive("1:MS").encoderOffset(), quint16(0));
    QCOMPARE(makeDrive("1:MF4015@2.35").modelInfo().driverName, QStringLiteral("LK-MF4015-DRV"));
}

void tst_SimDriveOnOff::factoryRomOnlyWhereNothingWasStored()
{
    // A zero written with 0x19 (stored in ROM) wins over the factory zero after a restart.
    sim::SimBus bus;
    auto spec = sim::SimBusSpec::parse(QStringLiteral("1:MS4015@2.35"));
    SimDrive *d = bus.addDrive(1, spec->drives.first().model);
    QVERIFY(d);
    const quint16 factory = d->encoderOffset();
    QVERIFY(d->handle(req(protocol::build::plain(Command::WriteZeroRom, 1))));
    const quint16 written = d->rom().encoderZero;
    QVERIFY(bus.removeDrive(1));
    d = bus.addDrive(1, spec->drives.first().model);
    QCOMPARE(d->encoderOffset(), quint16(written % d->encoderCountsPerTurn()));
    QVERIFY(factory != 0);
}

QTEST_APPLESS_MAIN(tst_SimDriveOnOff)
#include "tst_simdriveonoff.moc"
