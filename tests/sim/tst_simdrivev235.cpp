// A simulated drive on firmware 2.35 (docs/V2.35.md): what it answers, what it ignores, its
// parameter table in RAM and ROM, brake, turn count, and the layouts of its replies.
#include "SimDriveTestUtil.h"

#include "protocol/RequestBuilder.h"
#include "sim/SimBusSpec.h"
#include "sim/SimRomStore.h"

#include <QtCore/QTemporaryDir>

using namespace lk;
using namespace lk::test;
using protocol::Command;
using protocol::ParamId;

namespace {
sim::SimDrive makeV235(const char *spec = "1:MS4015@2.35")
{
    const auto parsed = sim::SimBusSpec::parse(QString::fromLatin1(spec));
    if (!parsed)
        qFatal("bad spec %s", spec);
    return sim::SimDrive(kDriveId, parsed->drives.first().model);
}

protocol::ParameterValue readParam(sim::SimDrive &d, ParamId p)
{
    return payloadOf<protocol::ParameterValue>(
        d.handle(req(protocol::build::readParam(kDriveId, p))));
}
} // namespace

class tst_SimDriveV235 : public QObject {
    Q_OBJECT
private slots:
    void specNamesTheFirmware();
    void silentToWhatTheGenerationLacks();
    void v23DriveSilentToV235Commands();
    void modelReplyIs58Bytes();
    void state1HasV235Layout();
    void parametersRamAndRom();
    void paramGainsDriveThePhysics();
    void romSurvivesTheStore();
    void brakeStateRemembered();
    void clearTurnCountKeepsTheAngleInTheTurn();
    void zeroReplyCarriesEncoderZero();
};

void tst_SimDriveV235::specNamesTheFirmware()
{
    const auto spec = sim::SimBusSpec::parse(QStringLiteral("1:MS4015@2.35,2:MF,3:MG@2.3"));
    QVERIFY(spec);
    QCOMPARE(spec->drives[0].model.generation, protocol::Generation::V2_35);
    QCOMPARE(spec->drives[1].model.generation, protocol::Generation::V2_3);
    QCOMPARE(spec->drives[2].model.generation, protocol::Generation::V2_3);
    QCOMPARE(spec->toString(), QStringLiteral("1:MS4015@2.35,2:MF,3:MG"));
    QString error;
    QVERIFY(!sim::SimBusSpec::parse(QStringLiteral("1:MF@3.0"), &error));
    QVERIFY2(error.contains(QLatin1String("3.0")), qPrintable(error));
}

void tst_SimDriveV235::silentToWhatTheGenerationLacks()
{
    sim::SimDrive d = makeV235();
    for (Command c : {Command::ReadPid, Command::ReadAccel})
        QVERIFY(!d.handle(req(protocol::build::plain(c, kDriveId))));
    QVERIFY(!send(d, protocol::build::writePid(kDriveId, 1, 2, 3, 4, 5, 6, false)));
    QVERIFY(!send(d, protocol::build::writeAcceleration(kDriveId, 100)));
    QVERIFY(!send(d, protocol::build::writeEncoderOffset(kDriveId, 100)));
}

void tst_SimDriveV235::v23DriveSilentToV235Commands()
{
    sim::SimDrive d = makeDrive(protocol::Series::MF);
    QVERIFY(!send(d, protocol::build::readParam(kDriveId, ParamId::SpeedPid)));
    QVERIFY(!send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Read)));
    QVERIFY(!send(d, protocol::build::plain(Command::ClearTurnCount, kDriveId)));
}

void tst_SimDriveV235::modelReplyIs58Bytes()
{
    sim::SimDrive d = makeV235();
    const auto reply = d.handle(req(protocol::build::plain(Command::ReadModel, kDriveId)));
    QVERIFY(reply);
    QCOMPARE(reply->toFrame().data.size(), 58);
    const auto m = std::get<protocol::ModelInfo>(reply->payload);
    QCOMPARE(m.firmwareVersion(), 2.35);
    QCOMPARE(m.hardwareVersion(), 3.0);
    QCOMPARE(m.motorId.size(), 12);
}

void tst_SimDriveV235::state1HasV235Layout()
{
    sim::SimDrive d = makeV235();
    const auto reply = d.handle(req(protocol::build::plain(Command::ReadState1, kDriveId)));
    QVERIFY(reply);
    const protocol::DecodeContext ctx{protocol::Series::MS, protocol::Generation::V2_35};
    const auto back = protocol::decodeReply(protocol::Frame{0x9A, 1, reply->toFrame().data}, ctx);
    const auto s = std::get<protocol::State1>(back.reply->payload);
    QCOMPARE(s.voltageV(), d.busVoltage());
    QCOMPARE(*s.motorOn(), true); // a real drive powers up with its motor on
    plain(d, Command::MotorOff);
    QCOMPARE(*readBack<protocol::State1>(d, Command::ReadState1).motorOn(), false);
    plain(d, Command::MotorRun);
    QCOMPARE(*readBack<protocol::State1>(d, Command::ReadState1).motorOn(), true);
}

void tst_SimDriveV235::parametersRamAndRom()
{
    sim::SimDrive d = makeV235();
    auto ack =
        send(d, protocol::build::writeParamPid(kDriveId, ParamId::SpeedPid, 70, 30, 5, false));
    QVERIFY(ack);
    QVERIFY(std::get<protocol::ParamWriteResult>(ack->payload).succeeded());
    QCOMPARE(int(readParam(d, ParamId::SpeedPid).pidKp()), 70);
    QCOMPARE(int(readParam(d, ParamId::SpeedPid).pidKd()), 5);
    QCOMPARE(int(d.rom().params.speedPid[0]), 50); // RAM only
    d.restart();
    QCOMPARE(int(readParam(d, ParamId::SpeedPid).pidKp()), 50); // lost at power-off
    ack = send(d, protocol::build::writeParam(kDriveId, ParamId::MaxSpeed, 360, true));
    QVERIFY(std::get<protocol::ParamWriteResult>(ack->payload).succeeded());
    d.restart();
    QCOMPARE(readParam(d, ParamId::MaxSpeed).asInt32(), 36000); // ROM survives
    // The max angle is written as two halves and reads back as the same int64.
    QVERIFY(send(d, protocol::build::writeParam(kDriveId, ParamId::MaxAngleLow, 1.0e8, false)));
    QVERIFY(send(d, protocol::build::writeParam(kDriveId, ParamId::MaxAngleHigh, 1.0e8, false)));
    QCOMPARE(protocol::joinMaxAngle(readParam(d, ParamId::MaxAngleLow),
                                    readParam(d, ParamId::MaxAngleHigh)),
             qint64(1.0e10));
}

void tst_SimDriveV235::paramGainsDriveThePhysics()
{
    sim::SimDrive d = makeV235();
    QVERIFY(send(d, protocol::build::writeParam(kDriveId, ParamId::SpeedRamp, 1234, false)));
    QCOMPARE(d.accelerationDps2(), 1234);
    QVERIFY(
        send(d, protocol::build::writeParamPid(kDriveId, ParamId::AnglePid, 300, 20, 0, false)));
    QCOMPARE(int(d.ramPid().angleKp), 255); // the physics' gains saturate at 255
    QCOMPARE(int(d.ramPid().angleKi), 20);
}

void tst_SimDriveV235::romSurvivesTheStore()
{
    QTemporaryDir dir;
    sim::SimRom rom;
    rom.params.speedPid = {11, 22, 33};
    rom.params.maxAngleRaw = 123456789012LL;
    {
        sim::SimRomStore store(dir.path());
        QVERIFY(store.save(kDriveId, protocol::Series::MS, rom));
    }
    sim::SimRomStore again(dir.path());
    QVERIFY2(again.errors().isEmpty(), qPrintable(again.errors().join('\n')));
    const auto back = again.rom(kDriveId, protocol::Series::MS);
    QVERIFY(back);
    QVERIFY(back->params == rom.params);
}

void tst_SimDriveV235::brakeStateRemembered()
{
    sim::SimDrive d = makeV235();
    auto r = send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Read));
    QVERIFY(std::get<protocol::BrakeState>(r->payload).released()); // released at power-up
    r = send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Engage));
    QVERIFY(!std::get<protocol::BrakeState>(r->payload).released());
    r = send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Release));
    QVERIFY(std::get<protocol::BrakeState>(r->payload).released());
    r = send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Read));
    QVERIFY(std::get<protocol::BrakeState>(r->payload).released());
    r = send(d, protocol::build::brake(kDriveId, protocol::BrakeAction::Engage));
    QVERIFY(!std::get<protocol::BrakeState>(r->payload).released());
}

void tst_SimDriveV235::clearTurnCountKeepsTheAngleInTheTurn()
{
    sim::SimDrive d = makeV235();
    plain(d, Command::MotorRun);
    QVERIFY(send(d, protocol::build::multiPosition(kDriveId, 1000.0, 720.0)));
    d.advance(5.0);
    const double before = angleDeg(d);
    QVERIFY(before > 900);
    plain(d, Command::ClearTurnCount);
    const double after = angleDeg(d);
    QVERIFY2(after >= 0 && after < 360, qPrintable(QString::number(after)));
    QCOMPARE(std::fmod(before, 360.0), after);
}

void tst_SimDriveV235::zeroReplyCarriesEncoderZero()
{
    sim::SimDrive d = makeV235();
    const auto r = d.handle(req(protocol::build::plain(Command::WriteZeroRom, kDriveId)));
    QVERIFY(r);
    QVERIFY(std::get<protocol::ZeroWritten>(r->payload).encoderOffset.has_value());
    QCOMPARE(r->toFrame().data.size(), 2);
}

QTEST_APPLESS_MAIN(tst_SimDriveV235)
#include "tst_simdrivev235.moc"
