// Every live lkctl command on CAN, both generations, against lksim --can over Qt's virtualcan
// (a port per test): what lkctl prints is checked against the frames lksim put on the wire,
// decoded here by docs/CAN.md's layouts, and what the protocol lacks is refused with nothing
// sent. A listening third node (CanSniffer) sees every frame. Drive 1 is an old CAN MG
// (request and reply on 0x141), drive 2 a V2.36 MF (request 0x142, reply 0x182).

#include "CanSniffer.h"
#include "E2eUtil.h"
#include "LksimProcess.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtTest/QTest>

#include <memory>

using namespace lk::e2e;

namespace {
const QString kOld = QStringLiteral("1:MG@can");
const QString kNew = QStringLiteral("2:MF@can236");
const QString kBoth = QStringLiteral("1:MG@can,2:MF@can236");
constexpr quint32 kOldReq = 0x141, kOldRep = 0x141, kNewReq = 0x142, kNewRep = 0x182;
} // namespace

class tst_E2eCanCommands : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void readMatchesTheWire_data();
    void readMatchesTheWire();
    void modelIsNeverReadOnCan_data();
    void modelIsNeverReadOnCan();
    void infoOnOldCanMatchesTheWire();
    void infoClaimsNoModel();
    void whatTheGenerationLacksIsRefusedUnsent_data();
    void whatTheGenerationLacksIsRefusedUnsent();
    void refusalOfAMissingCommandSaysNothingWasSent_data();
    void refusalOfAMissingCommandSaysNothingWasSent();
    void oldCanWritesGainsAndAccel_data();
    void oldCanWritesGainsAndAccel();
    void controlModesReachTheWire_data();
    void controlModesReachTheWire();
    void beyondTheSoftLimitsNothingIsSent_data();
    void beyondTheSoftLimitsNothingIsSent();
    void v236SpeedCarriesTheTorqueLimit();
    void v236SpeedWithoutSeriesSendsNoGuessedLimit();
    void v236ZeroInRamIsSetAngleZero();
    void zeroInRomIsSentOnce_data();
    void zeroInRomIsSentOnce();
    void brakeOnV236_data();
    void brakeOnV236();
    void clearErrorsOnBoth_data();
    void clearErrorsOnBoth();
    void motorStateCommandsOnBoth_data();
    void motorStateCommandsOnBoth();
    void v236InfoReadsGainsWithC0();
    void v236PidWriteGoesOutAsC1KeepingKd();
    void v236ParamWriteGoesOutAsC1();
    void v236RomWriteIsRefusedAsRamOnly_data();
    void v236RomWriteIsRefusedAsRamOnly();

private:
    CtlResult run(const QStringList &args) { return m_bus.run(args); }
    /// Waits until a marker read of drive 1 has passed the sniffer: frames an earlier lkctl
    /// sent are then all seen.
    void settle();

    CanE2eBus m_bus;
    CanSniffer &m_wire = m_bus.wire();
};

void tst_E2eCanCommands::init()
{
    const QString error = m_bus.start(kBoth, kOld);
    QVERIFY2(error.isEmpty(), qPrintable(error));
}

void tst_E2eCanCommands::cleanup()
{
    m_bus.stop();
}

void tst_E2eCanCommands::settle()
{
    const int before = m_wire.count(kOldReq, 0x94);
    const CtlResult r = run({"read", "1", "single-turn", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(m_wire.waitFor(kOldReq, 0x94, before + 2));
}

void tst_E2eCanCommands::readMatchesTheWire_data()
{
    QTest::addColumn<QString>("drive");
    QTest::addColumn<QString>("what");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("field");
    QTest::addColumn<int>("from"); // the field's first byte in the reply, its length, sign
    QTest::addColumn<int>("len");
    QTest::addColumn<bool>("isSigned");
    QTest::addColumn<double>("scale");
    // Old CAN: voltage uint16 0.1 V in B3-B4; V2.36: int16 0.01 V in B2-B3 (CAN.md 3, 4).
    QTest::newRow("old state1") << kOld << "state1" << 0x9A << "voltage_v" << 3 << 2 << false
                                << 0.1;
    QTest::newRow("v236 state1") << kNew << "state1" << 0x9A << "voltage_v" << 2 << 2 << true
                                 << 0.01;
    QTest::newRow("v236 bus current")
        << kNew << "state1" << 0x9A << "bus_current_a" << 4 << 2 << true << 0.01;
    QTest::newRow("old state2") << kOld << "state2" << 0x9C << "encoder" << 6 << 2 << false << 1.0;
    QTest::newRow("v236 state2") << kNew << "state2" << 0x9C << "encoder" << 6 << 2 << false << 1.0;
    QTest::newRow("old state3") << kOld << "state3" << 0x9D << "ia_raw" << 2 << 2 << true << 1.0;
    QTest::newRow("v236 state3") << kNew << "state3" << 0x9D << "ia_raw" << 2 << 2 << true << 1.0;
    QTest::newRow("old encoder") << kOld << "encoder" << 0x90 << "encoder_raw" << 4 << 2 << false
                                 << 1.0;
    QTest::newRow("v236 encoder offset")
        << kNew << "encoder" << 0x90 << "encoder_offset" << 6 << 2 << false << 1.0;
    // 0x92: seven bytes, sign from bit 55.
    QTest::newRow("old multi-turn")
        << kOld << "multi-turn" << 0x92 << "angle_deg" << 1 << 7 << true << 0.01;
    QTest::newRow("v236 multi-turn")
        << kNew << "multi-turn" << 0x92 << "angle_deg" << 1 << 7 << true << 0.01;
    QTest::newRow("old single-turn")
        << kOld << "single-turn" << 0x94 << "angle_deg" << 4 << 4 << false << 0.01;
    QTest::newRow("v236 single-turn")
        << kNew << "single-turn" << 0x94 << "angle_deg" << 4 << 4 << false << 0.01;
    QTest::newRow("old pid") << kOld << "pid" << 0x30 << "speed_kp" << 4 << 1 << false << 1.0;
    QTest::newRow("old accel") << kOld << "accel" << 0x33 << "accel_dps2" << 4 << 4 << true << 1.0;
}

void tst_E2eCanCommands::readMatchesTheWire()
{
    QFETCH(QString, drive);
    QFETCH(QString, what);
    QFETCH(int, code);
    QFETCH(QString, field);
    QFETCH(int, from);
    QFETCH(int, len);
    QFETCH(bool, isSigned);
    QFETCH(double, scale);
    const CtlResult r = run({"read", drive.left(1), what, "--json", "--drives", drive});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const quint32 replyId = drive == kOld ? kOldRep : kNewRep;
    QVERIFY(m_wire.waitFor(replyId, quint8(code), drive == kOld ? 2 : 1));
    const QByteArray reply = m_wire.last(replyId, quint8(code)).data;
    const QJsonObject fields = jsonOf(r.out.trimmed()).value("fields").toObject();
    QVERIFY2(fields.contains(field), r.out.constData());
    QCOMPARE(fields.value(field).toDouble(), leBytes(reply, from, len, isSigned) * scale);
}

void tst_E2eCanCommands::modelIsNeverReadOnCan_data()
{
    QTest::addColumn<QString>("drive");
    QTest::newRow("old") << kOld;
    QTest::newRow("v236") << kNew;
}

void tst_E2eCanCommands::modelIsNeverReadOnCan()
{
    // CAN has no 0x12 (CAN.md 2): `read ID model` is refused, exit 1, nothing sent; it must
    // never print another reply's fields as the model.
    QFETCH(QString, drive);
    const CtlResult r = run({"read", drive.left(1), "model", "--json", "--drives", drive});
    settle();
    QCOMPARE(m_wire.count(drive == kOld ? kOldReq : kNewReq, 0x12), 0);
    QVERIFY2(!r.out.contains("read_model"), qPrintable(describeRun(r)));
    QVERIFY2(r.exitCode == 1, qPrintable(describeRun(r)));
    QVERIFY2(r.err.contains("nothing was sent"), r.err.constData());
}

void tst_E2eCanCommands::infoOnOldCanMatchesTheWire()
{
    const CtlResult r = run({"info", "1", "--json", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out.trimmed());
    QCOMPARE(o.value("generation").toString(), QStringLiteral("v2.3"));
    QVERIFY(m_wire.waitFor(kOldRep, 0x30, 2) && m_wire.waitFor(kOldRep, 0x33, 2));
    const QByteArray pid = m_wire.last(kOldRep, 0x30).data;
    const QJsonObject gains = o.value("pid").toObject();
    const char *names[] = {"angle_kp", "angle_ki", "speed_kp", "speed_ki", "iq_kp", "iq_ki"};
    for (int i = 0; i < 6; ++i)
        QCOMPARE(gains.value(names[i]).toInt(), int(quint8(pid.at(2 + i))));
    QCOMPARE(o.value("accel").toObject().value("accel_dps2").toInt(),
             int(leBytes(m_wire.last(kOldRep, 0x33).data, 4, 4, true)));
    QCOMPARE(m_wire.count(kOldReq, 0x12), 0);
}

void tst_E2eCanCommands::infoClaimsNoModel()
{
    // Nothing was read of the model: it is null, not a model of empty names and version 0.0
    // ("never show an unknown value as 0").
    const CtlResult r = run({"info", "1", "--json", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out.trimmed());
    QVERIFY2(o.value("model").isNull(), r.out.constData());
}

void tst_E2eCanCommands::whatTheGenerationLacksIsRefusedUnsent_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<int>("forbidden"); // the command that must not reach the wire
    QTest::newRow("v236 read accel")
        << QStringList{"read", "2", "accel", "--drives", kNew} << 1 << 0x33;
    QTest::newRow("v236 write accel")
        << QStringList{"write", "2", "accel", "100", "--ram", "--drives", kNew} << 1 << 0x34;
    QTest::newRow("v236 write pid rom")
        << QStringList{"write", "2", "pid",   "1",     "2",        "3", "4",
                       "5",     "6", "--rom", "--yes", "--drives", kNew}
        << 1 << 0x32;
    QTest::newRow("old read params")
        << QStringList{"read", "1", "params", "--drives", kOld} << 1 << 0x40;
    QTest::newRow("old brake") << QStringList{"brake", "1", "status", "--drives", kOld} << 1
                               << 0x8C;
    QTest::newRow("old zero ram") << QStringList{"zero", "1", "--ram", "--yes", "--drives", kOld}
                                  << 1 << 0x95;
    QTest::newRow("v236 clear-turns")
        << QStringList{"clear-turns", "2", "--yes", "--drives", kNew} << 1 << 0x93;
    QTest::newRow("old open loop (MG)")
        << QStringList{"control", "1", "open-loop", "10", "--drives", kOld} << 4 << 0xA0;
    QTest::newRow("torque, series unknown")
        << QStringList{"control", "2", "torque", "0.2"} << 4 << 0xA1;
}

void tst_E2eCanCommands::whatTheGenerationLacksIsRefusedUnsent()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(int, forbidden);
    const CtlResult r = run(args);
    QVERIFY2(r.exitCode == exitCode, qPrintable(describeRun(r)));
    QVERIFY2(r.err.contains("nothing was sent"), r.err.constData());
    settle();
    const quint32 req = args.at(1) == QLatin1String("1") ? kOldReq : kNewReq;
    QCOMPARE(m_wire.count(req, quint8(forbidden)), 0);
}

void tst_E2eCanCommands::refusalOfAMissingCommandSaysNothingWasSent_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("old zero ram") << QStringList{"zero", "1", "--ram", "--yes", "--drives", kOld};
    QTest::newRow("v236 clear-turns") << QStringList{"clear-turns", "2", "--yes", "--drives", kNew};
    QTest::newRow("old brake") << QStringList{"brake", "1", "status", "--drives", kOld};
    QTest::newRow("v236 write pid rom") << QStringList{
        "write", "2", "pid", "1", "2", "3", "4", "5", "6", "--rom", "--yes", "--drives", kNew};
}

void tst_E2eCanCommands::refusalOfAMissingCommandSaysNothingWasSent()
{
    // A command the CAN generation lacks is refused in CAN's words, and nothing after that
    // suggests it may have been applied, nor points to RS485 firmware or V2.35 parameters.
    QFETCH(QStringList, args);
    const CtlResult r = run(args);
    QVERIFY2(r.exitCode == 1, qPrintable(describeRun(r)));
    QVERIFY2(r.err.contains("speaks CAN"), r.err.constData());
    QVERIFY2(!r.err.contains("is not known"), r.err.constData());
    QVERIFY2(!r.err.contains("RS485") && !r.err.contains("write 2 param"), r.err.constData());
}

void tst_E2eCanCommands::oldCanWritesGainsAndAccel_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("code");
    QTest::addColumn<QByteArray>("frame"); // the request's bytes, B0..B7
    QTest::newRow("pid ram") << QStringList{"pid", "90", "80", "70", "60", "50", "40", "--ram"}
                             << 0x31 << QByteArray::fromHex("31005a50463c3228");
    QTest::newRow("pid rom") << QStringList{"pid", "90", "80",    "70",   "60",
                                            "50",  "40", "--rom", "--yes"}
                             << 0x32 << QByteArray::fromHex("32005a50463c3228");
    QTest::newRow("accel ram") << QStringList{"accel", "12345", "--ram"} << 0x34
                               << QByteArray::fromHex("3400000039300000");
}

void tst_E2eCanCommands::oldCanWritesGainsAndAccel()
{
    QFETCH(QStringList, args);
    QFETCH(int, code);
    QFETCH(QByteArray, frame);
    const CtlResult r =
        run(QStringList{"write", "1"} + args + QStringList{"--json", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY2(jsonOf(r.out.trimmed()).value("match").toBool(), r.out.constData());
    QVERIFY(m_wire.waitFor(kOldReq, quint8(code), 2)); // the request and its echo
    QCOMPARE(m_wire.on(kOldReq, quint8(code)).first().data.toHex(), frame.toHex());
    QCOMPARE(m_wire.count(kOldReq, quint8(code)), 2); // a ROM write is never repeated
}

void tst_E2eCanCommands::controlModesReachTheWire_data()
{
    QTest::addColumn<QString>("drive");
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("frame");
    const QStringList lim{"--max-speed-dps", "360.9", "--max-torque-a", "1.5"};
    // Max speeds go out as uint16 whole dps, rounded down (360.9 -> 360 = 0x0168).
    QTest::newRow("old speed") << kOld << QStringList{"speed", "30"} + lim
                               << QByteArray::fromHex("a2000000b80b0000");
    QTest::newRow("old torque") << kOld << QStringList{"torque", "0.5"} + lim
                                << QByteArray::fromHex("a10000001f000000"); // 0.5 A / 0.016 A
    QTest::newRow("v236 torque") << kNew << QStringList{"torque", "0.5"} + lim
                                 << QByteArray::fromHex("a10000003e000000"); // x 4096 / 33
    QTest::newRow("old multi-position") << kOld << QStringList{"multi-position", "10"} + lim
                                        << QByteArray::fromHex("a4006801e8030000");
    QTest::newRow("v236 multi-position") << kNew << QStringList{"multi-position", "10"} + lim
                                         << QByteArray::fromHex("a4006801e8030000");
    QTest::newRow("old single-position")
        << kOld << QStringList{"single-position", "10", "--direction", "ccw"} + lim
        << QByteArray::fromHex("a6016801e8030000"); // uint16 angle in B4-B5
    QTest::newRow("v236 single-position")
        << kNew << QStringList{"single-position", "10", "--direction", "ccw"} + lim
        << QByteArray::fromHex("a6016801e8030000"); // uint32 angle in B4..B7
    QTest::newRow("old increment")
        << kOld << QStringList{"increment", "-10"} + lim << QByteArray::fromHex("a800680118fcffff");
    QTest::newRow("v236 increment")
        << kNew << QStringList{"increment", "-10"} + lim << QByteArray::fromHex("a800680118fcffff");
}

void tst_E2eCanCommands::controlModesReachTheWire()
{
    QFETCH(QString, drive);
    QFETCH(QStringList, args);
    QFETCH(QByteArray, frame);
    const CtlResult r = run(QStringList{"control", drive.left(1)} + args +
                            QStringList{"--json", "--drives", drive});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const quint32 req = drive == kOld ? kOldReq : kNewReq;
    const quint32 rep = drive == kOld ? kOldRep : kNewRep;
    const quint8 code = quint8(frame.at(0));
    QVERIFY(m_wire.waitFor(rep, code, drive == kOld ? 2 : 1));
    QCOMPARE(m_wire.on(req, code).first().data.toHex(), frame.toHex());
    // What lkctl prints of the reply is what the drive sent (encoder in B6-B7).
    const QJsonObject reply = jsonOf(r.out.trimmed()).value("reply").toObject();
    QCOMPARE(reply.value("encoder").toInt(),
             int(leBytes(m_wire.last(rep, code).data, 6, 2, false)));
    QVERIFY(run({"off", drive.left(1)}).exitCode == 0);
}

void tst_E2eCanCommands::beyondTheSoftLimitsNothingIsSent_data()
{
    QTest::addColumn<QString>("drive");
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("code");
    QTest::newRow("old speed") << kOld << QStringList{"speed", "400", "--max-speed-dps", "360"}
                               << 0xA2;
    QTest::newRow("v236 speed") << kNew << QStringList{"speed", "-400", "--max-speed-dps", "360"}
                                << 0xA2;
    QTest::newRow("old torque") << kOld << QStringList{"torque", "2", "--max-torque-a", "1"}
                                << 0xA1;
    QTest::newRow("v236 torque") << kNew << QStringList{"torque", "-2", "--max-torque-a", "1"}
                                 << 0xA1;
    QTest::newRow("v236 multi-position beyond a turn")
        << kNew << QStringList{"multi-position", "100000"} << 0xA4;
    QTest::newRow("old max speed above the limit")
        << kOld << QStringList{"increment", "10", "--max-speed", "500", "--max-speed-dps", "360"}
        << 0xA8;
}

void tst_E2eCanCommands::beyondTheSoftLimitsNothingIsSent()
{
    QFETCH(QString, drive);
    QFETCH(QStringList, args);
    QFETCH(int, code);
    const CtlResult r =
        run(QStringList{"control", drive.left(1)} + args + QStringList{"--drives", drive});
    QVERIFY2(r.exitCode == 4 || r.exitCode == 2, qPrintable(describeRun(r)));
    settle();
    QCOMPARE(m_wire.count(drive == kOld ? kOldReq : kNewReq, quint8(code)), 0);
}

void tst_E2eCanCommands::v236SpeedCarriesTheTorqueLimit()
{
    // 1.5 A at MF's 33/4096 A is 186.2 units, rounded down: 186 (0xBA) in B2-B3, never 0.
    const CtlResult r =
        run({"control", "2", "speed", "100", "--max-torque-a", "1.5", "--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(m_wire.waitFor(kNewRep, 0xA2));
    QCOMPARE(m_wire.on(kNewReq, 0xA2).first().data.toHex(), QByteArray("a200ba0010270000"));
    QVERIFY(run({"off", "2"}).exitCode == 0);
}

void tst_E2eCanCommands::v236SpeedWithoutSeriesSendsNoGuessedLimit()
{
    // Without --drives the series is unknown, so is the iq scale: a torque limit in B2-B3
    // would be a guess. Either the command is refused, or it carries a limit that is right at
    // every scale (the smaller of MF's and MG's units) and never 0.
    const CtlResult r = run({"control", "2", "speed", "30", "--max-torque-a", "1.5", "--json"});
    settle();
    if (r.exitCode != 0) {
        QCOMPARE(m_wire.count(kNewReq, 0xA2), 0);
        return;
    }
    const QList<SniffedFrame> sent = m_wire.on(kNewReq, 0xA2);
    QCOMPARE(sent.size(), 1);
    const qint64 limit = leBytes(sent.first().data, 2, 2, true);
    QVERIFY2(limit > 0 && limit <= 93, qPrintable(sent.first().text())); // 1.5 A at 66/4096 A
    QVERIFY(run({"off", "2"}).exitCode == 0);
}

void tst_E2eCanCommands::v236ZeroInRamIsSetAngleZero()
{
    // V2.36 0x95 sets the position to B4..B7: zero in RAM sends 0 there, once.
    const CtlResult r = run({"zero", "2", "--ram", "--yes", "--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out.trimmed()).value("result").toString(), QStringLiteral("cleared"));
    QVERIFY(m_wire.waitFor(kNewRep, 0x95));
    QCOMPARE(m_wire.on(kNewReq, 0x95).first().data.toHex(), QByteArray("9500000000000000"));
    QCOMPARE(m_wire.count(kNewReq, 0x95), 1);
}

void tst_E2eCanCommands::zeroInRomIsSentOnce_data()
{
    QTest::addColumn<QString>("drive");
    QTest::newRow("old") << kOld;
    QTest::newRow("v236") << kNew;
}

void tst_E2eCanCommands::zeroInRomIsSentOnce()
{
    QFETCH(QString, drive);
    const CtlResult r = run({"zero", drive.left(1), "--rom", "--yes", "--json", "--drives", drive});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const quint32 rep = drive == kOld ? kOldRep : kNewRep;
    QVERIFY(m_wire.waitFor(rep, 0x19, drive == kOld ? 2 : 1));
    settle();
    QCOMPARE(m_wire.count(drive == kOld ? kOldReq : kNewReq, 0x19), drive == kOld ? 2 : 1);
    // The reply's B6-B7 is the offset written (CAN.md 3), printed as encoder_zero.
    QCOMPARE(jsonOf(r.out.trimmed()).value("encoder_zero").toInt(),
             int(leBytes(m_wire.last(rep, 0x19).data, 6, 2, false)));
}

void tst_E2eCanCommands::brakeOnV236_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("frame");
    QTest::addColumn<bool>("released");
    QTest::newRow("status") << QStringList{"status"} << QByteArray::fromHex("8c10000000000000")
                            << true;
    QTest::newRow("engage") << QStringList{"engage"} << QByteArray::fromHex("8c00000000000000")
                            << false;
    QTest::newRow("release") << QStringList{"release", "--yes"}
                             << QByteArray::fromHex("8c01000000000000") << true;
}

void tst_E2eCanCommands::brakeOnV236()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, frame);
    QFETCH(bool, released);
    const CtlResult r =
        run(QStringList{"brake", "2"} + args + QStringList{"--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out.trimmed()).value("brake_released").toBool(), released);
    QVERIFY(m_wire.waitFor(kNewRep, 0x8C));
    QCOMPARE(m_wire.on(kNewReq, 0x8C).first().data.toHex(), frame.toHex());
    QCOMPARE(int(m_wire.last(kNewRep, 0x8C).data.at(1)), released ? 1 : 0);
}

void tst_E2eCanCommands::clearErrorsOnBoth_data()
{
    modelIsNeverReadOnCan_data();
}

void tst_E2eCanCommands::clearErrorsOnBoth()
{
    QFETCH(QString, drive);
    const CtlResult r = run({"clear-errors", drive.left(1), "--json", "--drives", drive});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(jsonOf(r.out.trimmed()).value("cleared").toBool());
    const quint32 rep = drive == kOld ? kOldRep : kNewRep;
    QVERIFY(m_wire.waitFor(rep, 0x9B, drive == kOld ? 2 : 1));
    QCOMPARE(m_wire.count(drive == kOld ? kOldReq : kNewReq, 0x9B), drive == kOld ? 2 : 1);
}

void tst_E2eCanCommands::motorStateCommandsOnBoth_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<int>("code");
    const char *names[] = {"off", "stop", "run"};
    const int codes[] = {0x80, 0x81, 0x88};
    for (int i = 0; i < 3; ++i) {
        QTest::addRow("old %s", names[i]) << QString::fromLatin1(names[i]) << codes[i];
        QTest::addRow("v236 %s", names[i]) << QString::fromLatin1(names[i]) << codes[i];
    }
}

void tst_E2eCanCommands::motorStateCommandsOnBoth()
{
    QFETCH(QString, command);
    QFETCH(int, code);
    const bool old = QString::fromLatin1(QTest::currentDataTag()).startsWith("old");
    const QString drive = old ? kOld : kNew;
    const CtlResult r = run({command, drive.left(1), "--json", "--drives", drive});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out.trimmed()).value("acknowledged").toArray(),
             QJsonArray{drive.left(1).toInt()});
    QVERIFY(m_wire.waitFor(old ? kOldRep : kNewRep, quint8(code), old ? 2 : 1));
    QCOMPARE(m_wire.on(old ? kOldReq : kNewReq, quint8(code)).first().data.toHex(),
             QByteArray::number(code, 16) + QByteArray(14, '0'));
}

void tst_E2eCanCommands::v236InfoReadsGainsWithC0()
{
    const CtlResult r = run({"info", "2", "--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(m_wire.waitFor(kNewRep, 0xC0, 3));
    QCOMPARE(m_wire.on(kNewReq, 0xC0).first().data.toHex(), QByteArray("c00a000000000000"));
    const QByteArray angle = m_wire.on(kNewRep, 0xC0).first().data;
    QCOMPARE(jsonOf(r.out.trimmed()).value("pid").toObject().value("angle_kp").toInt(),
             int(leBytes(angle, 2, 2, false)));
    // read pid takes the same path: 0xC0, never the 0x30 V2.36 lacks.
    const CtlResult pid = run({"read", "2", "pid", "--json", "--drives", kNew});
    QVERIFY2(pid.exitCode == 0, qPrintable(describeRun(pid)));
    QCOMPARE(jsonOf(pid.out.trimmed()).value("fields").toObject().value("angle_kp").toInt(),
             int(leBytes(angle, 2, 2, false)));
    settle();
    QCOMPARE(m_wire.count(kNewReq, 0x30), 0);
}

void tst_E2eCanCommands::v236PidWriteGoesOutAsC1KeepingKd()
{
    // Six gains are Kp and Ki of each loop; V2.36 keeps Kd in the same control parameter, so
    // each loop is read first (0xC0) and its Kd written back as read, in RAM (0xC1), then
    // read back. Nothing goes to ROM, and the V2.3 commands the drive lacks are never sent.
    const CtlResult r = run({"write", "2", "pid", "90", "80", "70", "60", "50", "40", "--ram",
                             "--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out.trimmed());
    QVERIFY2(o.value("match").toBool(), r.out.constData());
    QCOMPARE(o.value("command").toString(), QStringLiteral("write_control_param"));
    QVERIFY(m_wire.waitFor(kNewRep, 0xC1, 3));
    QVERIFY(m_wire.waitFor(kNewRep, 0xC0, 6)); // the Kd reads, then the read-back
    const QList<SniffedFrame> reads = m_wire.on(kNewRep, 0xC0);
    const QList<SniffedFrame> writes = m_wire.on(kNewReq, 0xC1);
    QCOMPARE(writes.size(), 3);
    const quint8 loops[] = {0x0A, 0x0B, 0x0C};
    const int kp[] = {90, 70, 50}, ki[] = {80, 60, 40};
    for (int l = 0; l < 3; ++l) {
        const QByteArray &w = writes.at(l).data;
        QCOMPARE(quint8(w.at(1)), loops[l]);
        QCOMPARE(leBytes(w, 2, 2, false), kp[l]);
        QCOMPARE(leBytes(w, 4, 2, false), ki[l]);
        QCOMPARE(leBytes(w, 6, 2, false), leBytes(reads.at(l).data, 6, 2, false)); // Kd as read
        const QString loop = QStringList{"angle", "speed", "iq"}.at(l);
        QCOMPARE(o.value("holds").toObject().value(loop + "_kd").toInt(),
                 int(leBytes(reads.at(l).data, 6, 2, false)));
    }
    settle();
    for (int code : {0x30, 0x31, 0x32})
        QCOMPARE(m_wire.count(kNewReq, quint8(code)), 0);
}

void tst_E2eCanCommands::v236ParamWriteGoesOutAsC1()
{
    // 500 dps is 50000 of 0.01 dps, an int32 in value bytes 3-6 (B4..B7) of parameter 0x20.
    const CtlResult r =
        run({"write", "2", "param", "max_speed_dps", "500", "--ram", "--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out.trimmed());
    QVERIFY2(o.value("match").toBool(), r.out.constData());
    QVERIFY(o.value("ram_only").toBool());
    QVERIFY(m_wire.waitFor(kNewRep, 0xC1));
    QCOMPARE(m_wire.on(kNewReq, 0xC1).first().data.toHex(), QByteArray("c1200000"
                                                                       "50c30000"));
    QCOMPARE(m_wire.count(kNewReq, 0xC1), 1);
}

void tst_E2eCanCommands::v236RomWriteIsRefusedAsRamOnly_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("pid") << QStringList{"pid", "90", "80", "70", "60", "50", "40"};
    QTest::newRow("param") << QStringList{"param", "speed_pid", "1", "2", "3"};
}

void tst_E2eCanCommands::v236RomWriteIsRefusedAsRamOnly()
{
    QFETCH(QStringList, args);
    const CtlResult r =
        run(QStringList{"write", "2"} + args + QStringList{"--rom", "--yes", "--drives", kNew});
    QVERIFY2(r.exitCode == 1, qPrintable(describeRun(r)));
    QVERIFY2(r.err.contains("RAM only") && r.err.contains("nothing was sent"), r.err.constData());
    settle();
    for (int code : {0xC0, 0xC1, 0x32})
        QCOMPARE(m_wire.count(kNewReq, quint8(code)), 0);
}

QTEST_GUILESS_MAIN(tst_E2eCanCommands)
#include "tst_e2ecancommands.moc"
