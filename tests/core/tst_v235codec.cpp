// Firmware 2.35 (protocol V2.35) codec: the example frames of docs/V2.35.md section 13 and the
// real captures of section 7 and 12, both directions, and what the same bytes mean to a V2.3
// decoder (the cross-decoding that made a 24 V supply read 308 V).
#include "ProtocolTestUtil.h"
#include "RequestText.h"

#include "protocol/ErrorFlags.h"
#include "protocol/FieldJson.h"
#include "protocol/ProtocolFields.h"
#include "protocol/Reply.h"
#include "protocol/RequestBuilder.h"

#include <QtTest/QtTest>

using namespace lk::protocol;
using lk::lkctl::FieldBuildResult;
using lk::lkctl::RequestText;
using lk::test::hex;
using lk::test::spaced;

namespace {
const DecodeContext kV235Ms{Series::MS, Generation::V2_35};
const DecodeContext kV235Mf{Series::MF, Generation::V2_35};
const DecodeContext kV235Mg{Series::MG, Generation::V2_35};
const DecodeContext kV23Mf{Series::MF, Generation::V2_3};

Frame frameOf(const QByteArray &bytes)
{
    const lk::test::EventLog log = lk::test::parseAll(bytes);
    if (log.events.size() != 1 || !log.events.front().isFrame)
        qFatal("not one valid frame: %s", qPrintable(spaced(bytes)));
    return log.events.front().frame;
}

Reply replyOf(const char *text, const DecodeContext &ctx)
{
    const ReplyDecodeResult r = decodeReply(frameOf(hex(text)), ctx);
    if (!r.reply)
        qFatal("no reply: %s", text);
    return *r.reply;
}

QString json(const QJsonObject &o)
{
    return QString::fromUtf8(FieldJson::toJsonLine(o));
}
} // namespace

class tst_V235Codec : public QObject {
    Q_OBJECT
private slots:
    void commandsByGeneration_data();
    void commandsByGeneration();
    void requestsEncode_data();
    void requestsEncode();
    void state1V235();
    void state1CrossDecodesWrongly();
    void errorFlagsNamed();
    void parameterReplies();
    void parameterWriteResult();
    void brakeDirectionAndReply();
    void modelCapture();
    void zeroReplyWithEncoderZero();
    void currentScales();
    void torqueBuilderScale();
    void maxTorqueParamNamedPerSeries();
    void openLoopStricterRange();
    void singleTurnThreeBytes();
    void badDataChecksumCaptureCounted();
    void encodeTextParams();
};

void tst_V235Codec::commandsByGeneration_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<bool>("onV23");
    QTest::addColumn<bool>("onV235");
    for (int c : {0x30, 0x31, 0x32, 0x33, 0x34, 0x91})
        QTest::addRow("0x%02X V2.3 only", c) << c << true << false;
    for (int c : {0x40, 0x42, 0x44, 0x8C, 0x93})
        QTest::addRow("0x%02X V2.35 only", c) << c << false << true;
    for (int c : {0x12, 0x19, 0x80, 0x81, 0x88, 0x90, 0x92, 0x94, 0x95, 0x9A, 0x9B,
                  0x9C, 0x9D, 0xA0, 0xA1, 0xA2, 0xA3, 0xA4, 0xA5, 0xA6, 0xA7, 0xA8})
        QTest::addRow("0x%02X both", c) << c << true << true;
}

void tst_V235Codec::commandsByGeneration()
{
    QFETCH(int, code);
    QFETCH(bool, onV23);
    QFETCH(bool, onV235);
    const auto cmd = static_cast<Command>(code);
    QVERIFY(CommandTable::find(quint8(code)));
    QCOMPARE(CommandTable::availableOn(cmd, Generation::V2_3), onV23);
    QCOMPARE(CommandTable::availableOn(cmd, Generation::V2_35), onV235);
    QCOMPARE(CommandTable::info(Command::WriteParamRom).writesFlash, true);
    QCOMPARE(CommandTable::info(Command::WriteParamRam).writesFlash, false);
}

void tst_V235Codec::requestsEncode_data()
{
    QTest::addColumn<QByteArray>("built");
    QTest::addColumn<QByteArray>("expected");
    const auto row = [](const char *name, const BuildResult &b, const char *text) {
        if (!b.ok())
            qFatal("%s: %s", name, qPrintable(b.error.message()));
        QTest::newRow(name) << b.request->encode() << hex(text);
    };
    using namespace build;
    row("read 0x96", readParam(1, ParamId::AnglePid), "3E 40 01 02 81 96 00 96");
    row("0x97 Kp50 Ki20 RAM [cap]", writeParamPid(1, ParamId::SpeedPid, 50, 20, 0, false),
        "3E 42 01 07 88 97 32 00 14 00 00 00 DD");
    row("0x97 ROM", writeParamPid(1, ParamId::SpeedPid, 50, 20, 0, true),
        "3E 44 01 07 8A 97 32 00 14 00 00 00 DD");
    row("0x99 max torque 1000", writeParam(1, ParamId::MaxTorqueCurrent, 1000, false),
        "3E 42 01 07 88 99 E8 03 00 00 00 00 84");
    row("0x9A max speed 360 dps", writeParam(1, ParamId::MaxSpeed, 360, false),
        "3E 42 01 07 88 9A A0 8C 00 00 00 00 C6");
    row("brake read", brake(1, BrakeAction::Read), "3E 8C 01 01 CC 10 10");
    row("brake release", brake(1, BrakeAction::Release), "3E 8C 01 01 CC 01 01");
    row("brake apply", brake(1, BrakeAction::Engage), "3E 8C 01 01 CC 00 00");
    row("clear turns", plain(Command::ClearTurnCount, 1), "3E 93 01 00 D2");
    row("zero in RAM", plain(Command::ClearAngle, 1), "3E 95 01 00 D4");
    row("0xA6 CCW 90 at 360", singlePosition(1, SpinDirection::CounterClockwise, 90.0, 360.0),
        "3E A6 01 08 ED 01 28 23 00 A0 8C 00 00 78");
    row("0xA8 +90 at 360", incrementPosition(1, 90.0, 360.0),
        "3E A8 01 08 EF 28 23 00 00 A0 8C 00 00 77");
    row("0xA0 -500", openLoop(1, -500), "3E A0 01 02 E1 0C FE 0A");
}

void tst_V235Codec::requestsEncode()
{
    QFETCH(QByteArray, built);
    QFETCH(QByteArray, expected);
    QCOMPARE(spaced(built), spaced(expected));
    // And back: the bytes decode to a request that encodes to the same bytes.
    const RequestDecodeResult back = decodeRequest(frameOf(expected));
    QVERIFY(back.request);
    QCOMPARE(spaced(back.request->encode()), spaced(expected));
}

void tst_V235Codec::state1V235()
{
    // 30 C, 24.00 V, -0.20 A, motor off, low voltage (docs/V2.35.md section 13).
    const Reply r = replyOf("3E 9A 01 07 E0 1E 60 09 EC FF 10 01 83", kV235Ms);
    const auto &s = std::get<State1>(r.payload);
    QCOMPARE(int(s.temperatureC), 30);
    QCOMPARE(s.voltageV(), 24.0);
    QCOMPARE(*s.busCurrentA(), -0.2);
    QCOMPARE(*s.motorOn(), false);
    QVERIFY(s.lowVoltage());
    QCOMPARE(json(FieldJson::replyFields(r)),
             QStringLiteral("{\"temperature_c\":30,\"voltage_v\":24.0,\"voltage_raw\":2400,"
                            "\"bus_current_a\":-0.2,\"bus_current_raw\":-20,\"motor_on\":false,"
                            "\"motor_state_raw\":16,\"error_state\":1,\"low_voltage\":true,"
                            "\"over_voltage\":false,\"driver_over_temperature\":false,"
                            "\"motor_over_temperature\":false,\"over_current\":false,"
                            "\"short_circuit\":false,\"stall\":false,\"input_timeout\":false}"));
    // The simulator's side writes the same bytes.
    QCOMPARE(spaced(r.encode()), QStringLiteral("3E 9A 01 07 E0 1E 60 09 EC FF 10 01 83"));
}

void tst_V235Codec::state1CrossDecodesWrongly()
{
    // 24.00 V, 1.50 A, on (docs/V2.35.md section 5). Read as V2.3, D2-D3 = 09 96 is 0x9609 =
    // 38409 x 0.1 V = 3840.9 V, as docs/V2.35.md works it out. The generation must come from
    // the drive, never from a default.
    const char *frame = "3E 9A 01 07 E0 1E 60 09 96 00 00 00 1D";
    QCOMPARE(std::get<State1>(replyOf(frame, kV235Mf).payload).voltageV(), 24.0);
    QCOMPARE(*std::get<State1>(replyOf(frame, kV235Mf).payload).motorOn(), true);
    QCOMPARE(std::get<State1>(replyOf(frame, kV23Mf).payload).voltageV(), 3840.9);
    QVERIFY(!std::get<State1>(replyOf(frame, kV23Mf).payload).busCurrentA());
    QVERIFY(!std::get<State1>(replyOf(frame, kV23Mf).payload).motorOn());
}

void tst_V235Codec::errorFlagsNamed()
{
    // 0x50 = over-current + stall on V2.35; on V2.3 both bits are unnamed.
    QStringList keys;
    for (const ErrorFlag &f : ErrorFlags::set(0x50, Generation::V2_35))
        keys << QLatin1String(f.key);
    QCOMPARE(keys, QStringList({"over_current", "stall"}));
    QCOMPARE(int(ErrorFlags::unnamedBits(0x50, Generation::V2_35)), 0);
    QCOMPARE(int(ErrorFlags::unnamedBits(0x50, Generation::V2_3)), 0x50);
    QCOMPARE(ErrorFlags::of(Generation::V2_35).size(), 8);
    QCOMPARE(ErrorFlags::words(0x09, Generation::V2_3),
             QStringList({"low voltage", "over-temperature"}));
    QCOMPARE(ErrorFlags::words(0x88, Generation::V2_35),
             QStringList({"motor over-temperature", "input signal lost (timeout)"}));
}

void tst_V235Codec::parameterReplies()
{
    const Reply pid = replyOf("3E 40 01 07 86 96 32 00 14 00 00 00 DC", kV235Ms);
    const auto &v = std::get<ParameterValue>(pid.payload);
    QCOMPARE(*v.id(), ParamId::AnglePid);
    QCOMPARE(int(v.pidKp()), 50);
    QCOMPARE(int(v.pidKi()), 20);
    QCOMPARE(int(v.pidKd()), 0);
    QCOMPARE(json(FieldJson::replyFields(pid)),
             QStringLiteral("{\"param\":\"angle_pid\",\"param_id\":150,\"angle_kp\":50,"
                            "\"angle_ki\":20,\"angle_kd\":0}"));
    QCOMPARE(spaced(pid.encode()), QStringLiteral("3E 40 01 07 86 96 32 00 14 00 00 00 DC"));

    // The int64 max angle travels as two halves and is joined back.
    const qint64 raw = 0x123456789ALL;
    const ParameterValue lo = ParameterValue::maxAngleHalf(raw, false);
    const ParameterValue hi = ParameterValue::maxAngleHalf(raw, true);
    QCOMPARE(lo.paramId, quint8(0x9B));
    QCOMPARE(hi.paramId, quint8(0x9C));
    QCOMPARE(joinMaxAngle(lo, hi), raw);
    const BuildResult w = build::writeParam(1, ParamId::MaxAngleHigh, 3600.0 * 1000, false);
    QVERIFY(w.ok());
    QCOMPARE(std::get<ParameterValue>(w.request->payload).asUInt32(),
             quint32(quint64(360000000) >> 32));
}

void tst_V235Codec::parameterWriteResult()
{
    // [cap] 3e 42 01 02 83 97 00 97: D0 the ParamID, D1 the flag (0 = success).
    const Reply ok = replyOf("3e 42 01 02 83 97 00 97", kV235Ms);
    QVERIFY(std::get<ParamWriteResult>(ok.payload).succeeded());
    QCOMPARE(int(std::get<ParamWriteResult>(ok.payload).paramId), 0x97);
    const Reply rom = replyOf("3E 44 01 02 85 97 00 97", kV235Ms);
    QVERIFY(std::get<ParamWriteResult>(rom.payload).succeeded());
    // A flag of 1 is a failure.
    const Reply failed = replyOf("3E 42 01 02 83 97 01 98", kV235Ms);
    QVERIFY(!std::get<ParamWriteResult>(failed.payload).succeeded());
    QCOMPARE(json(FieldJson::replyFields(failed)),
             QStringLiteral("{\"param\":\"speed_pid\",\"param_id\":151,\"success\":false,"
                            "\"success_flag\":1}"));
}

void tst_V235Codec::brakeDirectionAndReply()
{
    QCOMPARE(frameOf(hex("3E 8C 01 01 CC 10 10")).direction(), FrameDirection::Request);
    QCOMPARE(frameOf(hex("3E 8C 01 01 CC 01 01")).direction(), FrameDirection::Echo);
    QCOMPARE(frameOf(hex("3E 8C 01 01 CC 00 00")).direction(), FrameDirection::Echo);
    QVERIFY(std::get<BrakeState>(replyOf("3E 8C 01 01 CC 01 01", kV235Mg).payload).released());
    QVERIFY(!std::get<BrakeState>(replyOf("3E 8C 01 01 CC 00 00", kV235Mg).payload).released());
}

void tst_V235Codec::modelCapture()
{
    // [cap] the whole 64-byte 0x12 reply of an MS4015 / DS40R7 on fw 2.35.
    QByteArray frame = hex("3e 12 01 3a 8b");
    QByteArray data = QByteArray("DS40R7").leftJustified(20, '\0');
    data += QByteArray("MS4015").leftJustified(20, '\0');
    data += hex("35 37 35 30 30 32 73 18 78 03 4a 4b 2c 01 c8 00 eb 00");
    QCOMPARE(data.size(), 58);
    frame += data;
    frame += hex("9c");
    const ReplyDecodeResult r = decodeReply(frameOf(frame), {});
    QVERIFY(r.reply);
    const auto &m = std::get<ModelInfo>(r.reply->payload);
    QCOMPARE(m.generation, Generation::V2_35);
    QCOMPARE(m.driverName, QStringLiteral("DS40R7"));
    QCOMPARE(m.motorName, QStringLiteral("MS4015"));
    QCOMPARE(m.hardwareVersion(), 3.0);
    QCOMPARE(m.firmwareVersion(), 2.35);
    QCOMPARE(int(m.motorVersionRaw), 200);
    QCOMPARE(spaced(m.motorId), QStringLiteral("35 37 35 30 30 32 73 18 78 03 4A 4B"));
    QCOMPARE(spaced(r.reply->encode()), spaced(frame));
}

void tst_V235Codec::zeroReplyWithEncoderZero()
{
    const Reply r = replyOf("3E 19 01 02 5A DC 04 E0", kV235Ms);
    QCOMPARE(int(*std::get<ZeroWritten>(r.payload).encoderOffset), 1244);
}

void tst_V235Codec::currentScales()
{
    // 0x9D: 30 C, iA 256, iB -128, iC -128. V2.35 uses the iq scale; V2.3 1/64 A.
    const char *s3 = "3E 9D 01 07 E3 1E 00 01 80 FF 80 FF 1D";
    QCOMPARE(std::get<State3>(replyOf(s3, kV235Mf).payload).iaA(), 256 * 33.0 / 4096.0);
    QCOMPARE(std::get<State3>(replyOf(s3, kV235Mg).payload).ibA(), -128 * 66.0 / 4096.0);
    QCOMPARE(std::get<State3>(replyOf(s3, kV23Mf).payload).iaA(), 4.0);
    // Motion reply iq: MF halves on V2.35, MG unchanged; speed 87 FF = -121 dps [cap].
    const char *s2 = "3E 9C 01 07 E2 1E 00 08 87 FF 7C A9 D1";
    QCOMPARE(std::get<State2>(replyOf(s2, kV235Mf).payload).iqA(), 16.5);
    QCOMPARE(std::get<State2>(replyOf(s2, kV235Mg).payload).iqA(), 33.0);
    QCOMPARE(std::get<State2>(replyOf(s2, kV23Mf).payload).iqA(), 33.0);
    QCOMPARE(int(std::get<State2>(replyOf(s2, kV235Mf).payload).speedDps), -121);
    QCOMPARE(int(std::get<State2>(replyOf(s2, kV235Mf).payload).encoder), 43388);
}

void tst_V235Codec::maxTorqueParamNamedPerSeries()
{
    // One name per series, from the field table: lkctl and lkstudio read it there.
    QCOMPARE(ProtocolFields::paramLabel(ParamId::MaxTorqueCurrent, Series::MS),
             QStringLiteral("max power"));
    for (Series s : {Series::MF, Series::MG, Series::MH})
        QCOMPARE(ProtocolFields::paramLabel(ParamId::MaxTorqueCurrent, s),
                 QStringLiteral("max torque current"));
    QCOMPARE(ProtocolFields::paramLabel(ParamId::MaxTorqueCurrent, std::nullopt),
             QStringLiteral("max torque current"));
    QCOMPARE(ProtocolFields::paramLabel(ParamId::MaxSpeed, Series::MS),
             QStringLiteral("max speed"));
}

void tst_V235Codec::torqueBuilderScale()
{
    // The raw range stays +-2000 (the stricter of both generations); the scale follows the
    // drive: on a V2.35 MF drive 8.25 A is 1024 LSB, on V2.3 it would be 516.
    const BuildResult mf = build::torque(1, 8.25, kV235Mf);
    QVERIFY(mf.ok());
    QCOMPARE(int(std::get<TorqueCommand>(mf.request->payload).iqRaw), 1024);
    // The command carries the drive's scale: what the drive makes of it, for the limit checks
    // and every text that shows the torque sent.
    QCOMPARE(std::get<TorqueCommand>(mf.request->payload).iqA(), 8.25);
    // 2 A: V2.35 MF 248 LSB, MG 124 LSB (66/4096 A), V2.3 125 LSB (32/2000 A).
    const auto raw = [](const DecodeContext &c) {
        return int(std::get<TorqueCommand>(build::torque(1, 2.0, c).request->payload).iqRaw);
    };
    QCOMPARE(raw(kV235Mf), 248);
    QCOMPARE(raw(kV235Mg), 124);
    QCOMPARE(raw(kV23Mf), 125);
    QCOMPARE(int(std::get<TorqueCommand>(build::torque(1, 8.25, kV23Mf).request->payload).iqRaw),
             516);
    const BuildResult over = build::torque(1, 16.5, kV235Mf); // 2048 LSB
    QVERIFY(!over.ok());
    QCOMPARE(over.error.range, QStringLiteral("-16.11..16.11 A"));
    QVERIFY(decodeRequest(frameOf(hex("3E A1 01 02 E2 00 08 08"))).request);
}

void tst_V235Codec::openLoopStricterRange()
{
    QVERIFY(build::openLoop(1, 850).ok());
    QVERIFY(!build::openLoop(1, 851).ok());
    QVERIFY(!build::openLoop(1, -1000).ok());
    QCOMPARE(build::openLoop(1, 900).error.range, QStringLiteral("-850..850"));
}

void tst_V235Codec::singleTurnThreeBytes()
{
    // 0xA5 CW to 720.00 deg on a geared drive: the angle's third byte is 0x01.
    const char *text = "3E A5 01 04 E8 00 40 19 01 5A";
    const RequestDecodeResult r = decodeRequest(frameOf(hex(text)));
    QVERIFY(r.request);
    QCOMPARE(std::get<SinglePositionCommand>(r.request->payload).angleRaw, quint32(72000));
    QCOMPARE(spaced(r.request->encode()), QStringLiteral("3E A5 01 04 E8 00 40 19 01 5A"));
}

void tst_V235Codec::badDataChecksumCaptureCounted()
{
    // [cap] one of the 9 in 754 0xA4 replies with a bad data checksum: reported, not decoded,
    // and the stream goes on with the next good frame.
    const QByteArray stream = hex("3E A4 01 07 EA 21 00 00 0A 00 2C 19 73") +
                              hex("3E 9C 01 07 E2 1E 00 08 87 FF 7C A9 D1");
    const lk::test::EventLog log = lk::test::parseAll(stream);
    QCOMPARE(log.events.size(), size_t(2));
    QVERIFY(!log.events[0].isFrame);
    QCOMPARE(log.events[0].error, ParseError::BadDataChecksum);
    QVERIFY(log.events[1].isFrame);
}

void tst_V235Codec::encodeTextParams()
{
    FieldBuildResult r =
        RequestText::build(QStringLiteral("write_param_ram"), {{"id", "1"},
                                                               {"param", "speed_pid"},
                                                               {"speed_kp", "50"},
                                                               {"speed_ki", "20"},
                                                               {"speed_kd", "0"}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(spaced(r.request->encode()), QStringLiteral("3E 42 01 07 88 97 32 00 14 00 00 00 DD"));
    r = RequestText::build(QStringLiteral("write_param_rom"),
                           {{"id", "1"}, {"param", "max_speed"}, {"max_speed_dps", "360"}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(spaced(r.request->encode()), QStringLiteral("3E 44 01 07 8A 9A A0 8C 00 00 00 00 C6"));
    r = RequestText::build(QStringLiteral("write_param_ram"), {{"id", "1"},
                                                               {"param", "speed_pid"},
                                                               {"speed_kp", "70000"},
                                                               {"speed_ki", "0"},
                                                               {"speed_kd", "0"}});
    QVERIFY(!r.ok());
    QVERIFY2(r.message.contains(QLatin1String("speed_kp")) &&
                 r.message.contains(QLatin1String("0..65535")),
             qPrintable(r.message));
    r = RequestText::build(QStringLiteral("brake"), {{"id", "2"}, {"action", "release"}});
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(spaced(r.request->encode()), QStringLiteral("3E 8C 02 01 CD 01 01"));
    r = RequestText::build(QStringLiteral("read_param"), {{"id", "1"}, {"param", "nope"}});
    QVERIFY(!r.ok());
}

QTEST_APPLESS_MAIN(tst_V235Codec)
#include "tst_v235codec.moc"
