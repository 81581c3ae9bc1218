#include "sim/SimDrive.h"

#include "SimDriveTestUtil.h"

#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::test;
using lk::protocol::Command;
using lk::protocol::Series;
using lk::protocol::SpinDirection;
using lk::sim::SimDrive;
namespace build = lk::protocol::build;

Q_DECLARE_METATYPE(Series)

namespace {
constexpr int kId = kDriveId;
} // namespace

/// One simulated drive's state: heating, protection, RAM/ROM, restart, angles, readouts.
class tst_SimDriveState : public QObject {
    Q_OBJECT
private slots:
    void temperatureRisesWithCurrent();
    void overTemperatureProtection();
    void lowVoltageProtection();
    void restartReloadsRom();
    void writeZeroRomAppliedAfterRestart();
    void clearAngleZeroesUntilRestart();
    void encoderOffsetAndWrap();
    void firmwareQuirksAcknowledgeWithoutEffect();
    void readReplies_data();
    void readReplies();
    void gearedSingleTurnSpansTheOutputTurn();
};

void tst_SimDriveState::temperatureRisesWithCurrent()
{
    SimDrive d = makeDrive(Series::MF);
    d.setRotorLocked(true);
    QCOMPARE(qRound(d.temperatureC()), 25);
    send(d, build::torque(kId, 3.0, {}));
    d.advance(2.0);
    const double lowCurrent = d.temperatureC() - 25.0;
    QVERIFY(lowCurrent > 0.1);

    SimDrive h = makeDrive(Series::MF);
    h.setRotorLocked(true);
    send(h, build::torque(kId, 6.0, {}));
    h.advance(2.0);
    const double highCurrent = h.temperatureC() - 25.0;
    // Heating goes with current squared: twice the current, about four times the rise.
    QVERIFY2(highCurrent > lowCurrent * 3.5 && highCurrent < lowCurrent * 4.5,
             qPrintable(QStringLiteral("%1 vs %2").arg(highCurrent).arg(lowCurrent)));

    plain(h, Command::MotorOff);
    const double hot = h.temperatureC();
    h.advance(30.0);
    QVERIFY(h.temperatureC() < hot - 1.0);
    QVERIFY(h.temperatureC() > 25.0);
    h.advance(3600.0); // capped catch-up: still cools towards ambient, never below
    QVERIFY(h.temperatureC() >= 25.0);
}

void tst_SimDriveState::overTemperatureProtection()
{
    SimDrive d = makeDrive(Series::MF);
    d.setRotorLocked(true);
    send(d, build::torque(kId, 9.0, {}));
    const double t = runUntil(
        d, 120.0, [&] { return d.errorState() != 0; }, 0.05);
    QVERIFY(t < 120.0);
    QCOMPARE(d.errorState(), quint8(0x08));
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    d.advance(0.01);
    QCOMPARE(d.iqA(), 0.0);
    const auto s1 = readBack<protocol::State1>(d, Command::ReadState1);
    QVERIFY(s1.overTemperature());
    QVERIFY(s1.temperatureC >= 85);

    // Still hot: 0x9B cannot clear it, and motion commands are answered but not run.
    auto cleared = readBack<protocol::State1>(d, Command::ClearErrors);
    QCOMPARE(cleared.errorState, quint8(0x08));
    QVERIFY(send(d, build::torque(kId, 1.0, {})));
    QCOMPARE(d.runState(), SimDrive::RunState::Off);

    runUntil(
        d, 600.0, [&] { return d.temperatureC() < 79.0; }, 0.5);
    QCOMPARE(d.errorState(), quint8(0x08)); // latched until cleared
    cleared = readBack<protocol::State1>(d, Command::ClearErrors);
    QCOMPARE(cleared.errorState, quint8(0));
    send(d, build::torque(kId, 1.0, {}));
    QCOMPARE(d.runState(), SimDrive::RunState::Running);
}

void tst_SimDriveState::lowVoltageProtection()
{
    SimDrive d = makeDrive(Series::MF);
    QCOMPARE(d.busVoltage(), 24.0);
    send(d, build::speed(kId, 360.0));
    d.setSupplyVoltage(10.0); // MF minimum is 12 V
    QCOMPARE(d.errorState(), quint8(0x01));
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    auto s1 = readBack<protocol::State1>(d, Command::ReadState1);
    QCOMPARE(s1.voltageRaw, quint16(100));
    QVERIFY(s1.lowVoltage());
    s1 = readBack<protocol::State1>(d, Command::ClearErrors);
    QCOMPARE(s1.errorState, quint8(0x01)); // cause still there
    d.setSupplyVoltage(24.0);
    d.advance(0.1);
    QCOMPARE(d.errorState(), quint8(0x01)); // latched
    s1 = readBack<protocol::State1>(d, Command::ClearErrors);
    QCOMPARE(s1.errorState, quint8(0));
    QCOMPARE(s1.voltageRaw, quint16(240));
}

void tst_SimDriveState::restartReloadsRom()
{
    SimDrive d = makeDrive(Series::MF);
    const protocol::PidGains defaults{100, 100, 50, 40, 50, 50};
    QCOMPARE(d.ramPid(), defaults);
    const protocol::PidGains ram{1, 2, 3, 4, 5, 6};
    auto reply = send(d, build::writePid(kId, ram, false));
    QCOMPARE(payloadOf<protocol::PidGains>(reply), ram); // echo
    QCOMPARE(d.ramPid(), ram);
    send(d, build::writeAcceleration(kId, 1234));
    QCOMPARE(readBack<protocol::Acceleration>(d, Command::ReadAccel).dps2, 1234);
    send(d, build::speed(kId, 100));

    d.restart();
    QCOMPARE(d.ramPid(), defaults); // RAM lost
    QCOMPARE(d.accelerationDps2(), d.rom().accelDps2);
    QCOMPARE(d.runState(), SimDrive::RunState::Off);
    QVERIFY(!d.activeCommand());

    int romWrites = 0;
    d.setRomWrittenHandler([&](int, Series, const sim::SimRom &) { ++romWrites; });
    const protocol::PidGains rom{10, 20, 30, 40, 50, 60};
    reply = send(d, build::writePid(kId, rom, true));
    QCOMPARE(payloadOf<protocol::PidGains>(reply), rom);
    QCOMPARE(romWrites, 1);
    QCOMPARE(d.ramPid(), rom); // 0x32 writes RAM too
    d.restart();
    QCOMPARE(d.ramPid(), rom); // ROM kept
    QCOMPARE(readBack<protocol::PidGains>(d, Command::ReadPid), rom);
}

void tst_SimDriveState::writeZeroRomAppliedAfterRestart()
{
    SimDrive d = makeDrive(Series::MF);
    const quint16 offsetBefore = d.encoderOffset();
    const quint16 raw = d.encoderRaw();
    QVERIFY(raw != 0); // drive 1 starts at 137.5 deg
    const qint64 angleBefore = d.multiTurnRaw();
    const auto reply = send(d, build::plain(Command::WriteZeroRom, kId));
    QVERIFY(reply);
    QVERIFY(!payloadOf<protocol::ZeroWritten>(reply).encoderOffset); // V2.3: echo
    QCOMPARE(reply ? reply->encode().size() : 0, 5);
    QCOMPARE(d.rom().encoderZero, raw);
    // Not effective before a power cycle.
    QCOMPARE(d.encoderOffset(), offsetBefore);
    QCOMPARE(d.multiTurnRaw(), angleBefore);

    d.restart();
    QCOMPARE(d.encoderOffset(), raw);
    QCOMPARE(d.encoder(), quint16(0));
    QVERIFY(std::abs(d.multiTurnRaw()) < 3); // within one 14-bit count (0.022 deg)

    d.setZeroReplyCarriesOffset(true); // newer firmware: LEN 2 with the new zero
    const auto newer = send(d, build::plain(Command::WriteZeroRom, kId));
    QCOMPARE(payloadOf<protocol::ZeroWritten>(newer).encoderOffset, std::optional<quint16>(raw));
}

void tst_SimDriveState::clearAngleZeroesUntilRestart()
{
    SimDrive d = makeDrive(Series::MF);
    send(d, build::multiPosition(kId, 1000.0));
    d.advance(3.0);
    QVERIFY(std::abs(angleDeg(d) - 1000.0) < 0.1);
    const auto ack = send(d, build::plain(Command::ClearAngle, kId));
    QVERIFY(ack && std::holds_alternative<protocol::Acknowledged>(ack->payload));
    QCOMPARE(d.multiTurnRaw(), qint64(0));
    QCOMPARE(d.singleTurnRaw(), 0u);
    d.advance(1.0); // the held position does not move when the zero moves
    QVERIFY(std::abs(angleDeg(d)) < 0.1);

    d.restart(); // angles come back from the encoder: within one turn of its zero
    QVERIFY(d.multiTurnRaw() >= 0 && d.multiTurnRaw() < 36000);
    QVERIFY(std::abs(d.multiTurnRaw() * 0.01 - d.encoder() * 360.0 / 16384) < 0.05);
}

void tst_SimDriveState::firmwareQuirksAcknowledgeWithoutEffect()
{
    // ERRATA: some firmware acknowledges 0x34 and 0x95 without applying them, and reads 0x33
    // as 0. The reply is the normal acknowledgement: only a read-back tells.
    sim::SimDriveModel model = sim::SimDriveModel::forSeries(Series::MF);
    model.quirks.accelIgnored = true;
    model.quirks.clearAngleIgnored = true;
    SimDrive d(kId, model);
    const auto echo = send(d, build::writeAcceleration(kId, 1234));
    QVERIFY(echo);
    QCOMPARE(payloadOf<protocol::Acceleration>(echo).dps2, 1234);
    QCOMPARE(readBack<protocol::Acceleration>(d, Command::ReadAccel).dps2, 0);

    send(d, build::multiPosition(kId, 1000.0));
    d.advance(3.0);
    const auto ack = send(d, build::plain(Command::ClearAngle, kId));
    QVERIFY(ack && std::holds_alternative<protocol::Acknowledged>(ack->payload));
    QVERIFY(std::abs(angleDeg(d) - 1000.0) < 0.1);

    SimDrive plainDrive = makeDrive(Series::MF); // the same requests on normal firmware
    send(plainDrive, build::writeAcceleration(kId, 1234));
    QCOMPARE(readBack<protocol::Acceleration>(plainDrive, Command::ReadAccel).dps2, 1234);
}

void tst_SimDriveState::encoderOffsetAndWrap()
{
    SimDrive d = makeDrive(Series::MF);
    const int counts = d.encoderCountsPerTurn();
    QCOMPARE(counts, 16384);
    const auto echo = send(d, build::writeEncoderOffset(kId, 1000));
    QCOMPARE(payloadOf<protocol::EncoderOffset>(echo).offset, quint16(1000));
    auto e = readBack<protocol::EncoderReading>(d, Command::ReadEncoder);
    QCOMPARE(e.encoderOffset, quint16(1000));
    QCOMPARE(e.encoder, quint16((e.encoderRaw - 1000 + counts) % counts));

    send(d, build::speed(kId, 3600.0)); // 10 turns a second
    d.advance(0.5);
    const qint64 startAngle = d.multiTurnRaw();
    int wraps = 0;
    quint16 last = d.encoderRaw();
    for (int i = 0; i < 200; ++i) {
        d.advance(0.002);
        const quint16 now = d.encoderRaw();
        QVERIFY(now < counts);
        if (now < last)
            ++wraps;
        last = now;
    }
    QVERIFY(wraps >= 3);                                // 0.4 s at 3600 dps = 4 turns
    QVERIFY(d.multiTurnRaw() - startAngle > 3 * 36000); // multi-turn keeps counting
}

void tst_SimDriveState::readReplies_data()
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<QString>("driver");
    QTest::addColumn<QString>("motor");
    QTest::addColumn<int>("counts");
    QTest::addColumn<int>("voltageRaw");
    QTest::addColumn<quint32>("singleTurnRange");
    QTest::newRow("MS") << Series::MS << "LK-MS5005-DRV"
                        << "MS5005" << 4096 << 120 << 36000u;
    QTest::newRow("MF") << Series::MF << "LK-MF4015-DRV"
                        << "MF4015" << 16384 << 240 << 36000u;
    QTest::newRow("MG") << Series::MG << "LK-MG5010E-DRV"
                        << "MG5010E-i10" << 65536 << 480 << 360000u;
    QTest::newRow("MH") << Series::MH << "LK-MH7015-DRV"
                        << "MH7015" << 16384 << 240 << 36000u;
}

void tst_SimDriveState::readReplies()
{
    QFETCH(Series, series);
    QFETCH(QString, driver);
    QFETCH(QString, motor);
    QFETCH(int, counts);
    QFETCH(int, voltageRaw);
    QFETCH(quint32, singleTurnRange);
    SimDrive d = makeDrive(series);
    const auto model = readBack<protocol::ModelInfo>(d, Command::ReadModel);
    QCOMPARE(model.driverName, driver);
    QCOMPARE(model.motorName, motor);
    QCOMPARE(model.hardwareVersion(), 1.0);
    QCOMPARE(model.firmwareVersion(), 2.3);
    const auto modelReply = d.handle(req(build::plain(Command::ReadModel, kId)));
    QVERIFY(modelReply);
    QCOMPARE(modelReply->encode().size(), 48);
    QCOMPARE(d.encoderCountsPerTurn(), counts);
    QCOMPARE(int(d.state1().voltageRaw), voltageRaw);
    QCOMPARE(d.state1().temperatureC, qint8(25));
    QCOMPARE(d.state2().isPower, series == Series::MS);

    // Over several output turns the single-turn angle stays in 0 .. 36000 x ratio - 1.
    send(d, build::speed(kId, 2000.0));
    quint32 highest = 0;
    for (int i = 0; i < 500; ++i) {
        d.advance(0.01);
        QVERIFY(d.singleTurnRaw() < singleTurnRange);
        highest = std::max(highest, d.singleTurnRaw());
    }
    QVERIFY(highest > singleTurnRange * 0.9 || singleTurnRange > 36000);
    if (singleTurnRange > 36000)
        QVERIFY(highest > 36000); // geared: more than one rotor turn
}

// A geared drive's single-turn target lies within its output turn (0..36000 x ratio - 1), as
// its single-turn angle does: from 400 deg, "350 deg clockwise" on an i10 drive ends at 3950.
void tst_SimDriveState::gearedSingleTurnSpansTheOutputTurn()
{
    SimDrive d = makeDrive(Series::MG); // MG5010E-i10
    d.setMultiTurnAngle(40000);
    QCOMPARE(d.singleTurnRaw(), 40000u);
    send(d, build::singlePosition(kId, protocol::SpinDirection::Clockwise, 350));
    for (int i = 0; i < 800; ++i)
        d.advance(0.01);
    QVERIFY2(std::abs(d.multiTurnRaw() - 395000) < 50,
             qPrintable(QString::number(d.multiTurnRaw())));
    QVERIFY2(std::abs(int(d.singleTurnRaw()) - 35000) < 50,
             qPrintable(QString::number(d.singleTurnRaw())));
}

QTEST_APPLESS_MAIN(tst_SimDriveState)
#include "tst_simdrivestate.moc"
