// The CAN layouts of both CAN generations against the example frames of docs/CAN.md (the
// spec's section 9, written by hand from the vendor tables, never produced by the code under
// test), both ways: typed value -> frame, and frame -> typed value -> the same frame.

#include "CanTestUtil.h"
#include "ProtocolTestUtil.h"

#include <protocol/CanLayout.h>
#include <protocol/FieldJson.h>
#include <protocol/LinkCodec.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QtEndian>
#include <QtTest/QTest>

#include <functional>
#include <vector>

using namespace lk::test::cantest;
using lk::test::hex;

namespace {

struct RequestVector {
    const char *name;
    Generation generation;
    std::function<proto::Request()> request;
    const char *frame;
};

const std::vector<RequestVector> &requestVectors()
{
    using G = Generation;
    static const std::vector<RequestVector> v{
        // Held vectors of the spec's section 9.
        {"read_state2 old", G::V2_3, [] { return req(Command::ReadState2); },
         "141#9C00000000000000"},
        {"read_state2 V2.36", G::V2_35, [] { return req(Command::ReadState2); },
         "141#9C00000000000000"},
        {"0xA4 90 deg at 360 dps old", G::V2_3,
         [] {
             return req(Command::MultiPositionLimited, proto::MultiPositionCommand{9000, 36000});
         },
         "141#A400680128230000"},
        {"0xA4 90 deg at 360 dps V2.36", G::V2_35,
         [] {
             return req(Command::MultiPositionLimited, proto::MultiPositionCommand{9000, 36000});
         },
         "141#A400680128230000"},
        {"0xA2 V2.36 iq limit 512, 100 dps", G::V2_35,
         [] {
             return req(Command::Speed, proto::SpeedCommand{10000, qint16(512)});
         },
         "141#A200000210270000"},
        {"0x8C V2.36 read brake", G::V2_35,
         [] { return req(Command::Brake, proto::BrakeCommand{proto::BrakeAction::Read}); },
         "141#8C10000000000000"},
        // The other layouts of the spec's sections 3 and 4.
        {"0xA2 old, no limit field", G::V2_3,
         [] { return req(Command::Speed, proto::SpeedCommand{10000}); }, "141#A200000010270000"},
        {"0xA1 old iq 100", G::V2_3, [] { return req(Command::Torque, proto::TorqueCommand{100}); },
         "141#A100000064000000"},
        {"0xA1 V2.36 iq -2048", G::V2_35,
         [] { return req(Command::Torque, proto::TorqueCommand{-2048}); }, "141#A100000000F80000"},
        {"0xA0 V2.36 power -850", G::V2_35,
         [] { return req(Command::OpenLoop, proto::OpenLoopCommand{-850}); },
         "141#A0000000AEFC0000"},
        {"0xA3 -1 deg", G::V2_3,
         [] {
             return req(Command::MultiPosition, proto::MultiPositionCommand{-100, {}});
         },
         "141#A30000009CFFFFFF"},
        {"0xA5 old 180 deg CCW", G::V2_3,
         [] {
             return req(
                 Command::SinglePosition,
                 proto::SinglePositionCommand{proto::SpinDirection::CounterClockwise, 18000, {}});
         },
         "141#A501000050460000"},
        {"0xA5 V2.36 angle beyond 16 bits", G::V2_35,
         [] {
             return req(Command::SinglePosition,
                        proto::SinglePositionCommand{proto::SpinDirection::Clockwise, 100000, {}});
         },
         "141#A5000000A0860100"},
        {"0xA6 V2.36 180 deg at 90 dps", G::V2_35,
         [] {
             return req(Command::SinglePositionLimited,
                        proto::SinglePositionCommand{proto::SpinDirection::CounterClockwise, 18000,
                                                     9000u});
         },
         "141#A6015A0050460000"},
        {"0xA8 -90 deg at 30 dps", G::V2_3,
         [] {
             return req(Command::IncrementPositionLimited,
                        proto::IncrementPositionCommand{-9000, 3000u});
         },
         "141#A8001E00D8DCFFFF"},
        {"0xA7 +10 deg", G::V2_35,
         [] {
             return req(Command::IncrementPosition, proto::IncrementPositionCommand{1000, {}});
         },
         "141#A7000000E8030000"},
        {"0x31 PID RAM old", G::V2_3,
         [] {
             return req(Command::WritePidRam, proto::PidGains{1, 2, 3, 4, 5, 6});
         },
         "141#3100010203040506"},
        {"0x34 accel old", G::V2_3,
         [] { return req(Command::WriteAccelRam, proto::Acceleration{1000}); },
         "141#34000000E8030000"},
        {"0x91 offset old", G::V2_3,
         [] { return req(Command::WriteEncoderOffset, proto::EncoderOffset{0x1234}); },
         "141#9100000000003412"},
        {"0x95 V2.36 clear_angle = position 0", G::V2_35, [] { return req(Command::ClearAngle); },
         "141#9500000000000000"},
        {"0x80 motor_off old", G::V2_3, [] { return req(Command::MotorOff); },
         "141#8000000000000000"},
    };
    return v;
}

struct ReplyVector {
    const char *name;
    Generation generation;
    std::function<proto::Reply()> reply;
    const char *frame;
};

proto::Reply rep(Command c, proto::ReplyPayload p)
{
    return proto::Reply{c, 1, std::move(p)};
}

proto::State2 state2(qint8 t, qint16 iq, qint16 speed, quint16 enc)
{
    proto::State2 s;
    s.temperatureC = t;
    s.torqueRaw = iq;
    s.speedDps = speed;
    s.encoder = enc;
    return s;
}

proto::State1 state1V236()
{
    proto::State1 s;
    s.generation = Generation::V2_35;
    s.temperatureC = 30;
    s.voltageRaw = 2400;
    s.busCurrentRaw = 150;
    s.motorStateRaw = 0x10;
    s.errorState = 0x02;
    return s;
}

const std::vector<ReplyVector> &replyVectors()
{
    using G = Generation;
    static const std::vector<ReplyVector> v{
        {"read_state2 old on 0x141", G::V2_3,
         [] { return rep(Command::ReadState2, state2(50, 100, 500, 0x2000)); },
         "141#9C326400F4010020"},
        {"read_state2 V2.36 on 0x181", G::V2_35,
         [] { return rep(Command::ReadState2, state2(50, -100, -500, 0x2000)); },
         "181#9C329CFF0CFE0020"},
        {"0x92 -360.00 deg old", G::V2_3,
         [] { return rep(Command::ReadMultiTurn, proto::MultiTurnAngle{-36000}); },
         "141#926073FFFFFFFFFF"},
        {"0x92 -360.00 deg V2.36", G::V2_35,
         [] { return rep(Command::ReadMultiTurn, proto::MultiTurnAngle{-36000}); },
         "181#926073FFFFFFFFFF"},
        {"0x92 +360.00 deg", G::V2_3,
         [] { return rep(Command::ReadMultiTurn, proto::MultiTurnAngle{36000}); },
         "141#92A08C0000000000"},
        {"0x9A old 24.0 V", G::V2_3,
         [] { return rep(Command::ReadState1, proto::State1(30, 240, 0x08)); },
         "141#9A1E00F000000008"},
        {"0x9A V2.36 24.00 V 1.50 A off", G::V2_35,
         [] { return rep(Command::ReadState1, state1V236()); }, "181#9A1E600996001002"},
        {"0x94 180 deg", G::V2_3,
         [] { return rep(Command::ReadSingleTurn, proto::SingleTurnAngle{18000}); },
         "141#9400000050460000"},
        {"0x90 encoder", G::V2_35,
         [] {
             return rep(Command::ReadEncoder, proto::EncoderReading{0x1000, 0x1100, 0x0100});
         },
         "181#9000001000110001"},
        {"0x8C V2.36 released", G::V2_35,
         [] { return rep(Command::Brake, proto::BrakeState{0x01}); }, "181#8C01000000000000"},
        {"0x30 PID old", G::V2_3,
         [] {
             return rep(Command::ReadPid, proto::PidGains{1, 2, 3, 4, 5, 6});
         },
         "141#3000010203040506"},
        {"0x33 accel old", G::V2_3,
         [] { return rep(Command::ReadAccel, proto::Acceleration{1000}); }, "141#33000000E8030000"},
        {"0x19 new zero old", G::V2_3,
         [] { return rep(Command::WriteZeroRom, proto::ZeroWritten{quint16(0x2345)}); },
         "141#1900000000004523"},
        {"0x81 echo V2.36", G::V2_35, [] { return rep(Command::MotorStop, proto::Acknowledged{}); },
         "181#8100000000000000"},
    };
    return v;
}

} // namespace

/// CanLayout: every held vector both ways in both CAN generations, the 0x92 sign extension,
/// the V2.36 0xA2 torque limit (never 0, from the soft limits), max speeds rounded down to
/// whole dps, and what each generation refuses.
class tst_CanLayout : public QObject {
    Q_OBJECT
private slots:
    void requestVectors_data();
    void requestVectors();
    void replyVectors_data();
    void replyVectors();
    void multiTurnSignExtension_data();
    void multiTurnSignExtension();
    void refusals_data();
    void refusals();
    void maxSpeedRoundsDown_data();
    void maxSpeedRoundsDown();
    void speedTorqueLimitFromSoftLimits_data();
    void speedTorqueLimitFromSoftLimits();
    void addresses();
    void generationHints_data();
    void generationHints();
    void replyDecodeFaults();
    void linkCodecKeepsRs485();
};

void tst_CanLayout::requestVectors_data()
{
    QTest::addColumn<int>("index");
    for (size_t i = 0; i < ::requestVectors().size(); ++i)
        QTest::newRow(::requestVectors()[i].name) << int(i);
}

void tst_CanLayout::requestVectors()
{
    QFETCH(int, index);
    const RequestVector &v = ::requestVectors()[size_t(index)];
    const DecodeContext ctx = canCtx(v.generation);
    const proto::Request request = v.request();
    const can::CanData expected = canFrame(v.frame);

    // typed -> frame
    const can::CanEncodeResult enc = can::encodeRequest(request, ctx);
    QVERIFY2(enc.ok(), qPrintable(enc.error.message()));
    QCOMPARE(candump(*enc.data), candump(expected));

    // frame -> typed -> the same frame, with the same fields
    const std::optional<proto::Frame> frame = can::frameOf(expected);
    QVERIFY(frame);
    QCOMPARE(frame->id, quint8(1));
    const proto::RequestDecodeResult dec = proto::decodeRequest(*frame, ctx);
    QVERIFY(dec.request);
    QCOMPARE(int(dec.request->command), int(request.command));
    QCOMPARE(proto::FieldJson::requestFields(*dec.request, ctx),
             proto::FieldJson::requestFields(request, ctx));
    if (const auto *s = std::get_if<proto::SpeedCommand>(&request.payload))
        QCOMPARE(std::get<proto::SpeedCommand>(dec.request->payload).iqLimitRaw, s->iqLimitRaw);
    QCOMPARE(candump(*can::encodeRequest(*dec.request, ctx).data), candump(expected));
}

void tst_CanLayout::replyVectors_data()
{
    QTest::addColumn<int>("index");
    for (size_t i = 0; i < ::replyVectors().size(); ++i)
        QTest::newRow(::replyVectors()[i].name) << int(i);
}

void tst_CanLayout::replyVectors()
{
    QFETCH(int, index);
    const ReplyVector &v = ::replyVectors()[size_t(index)];
    const DecodeContext ctx = canCtx(v.generation);
    const proto::Reply reply = v.reply();
    const can::CanData expected = canFrame(v.frame);

    const can::CanEncodeResult enc = can::encodeReply(reply, ctx);
    QVERIFY2(enc.ok(), qPrintable(enc.error.message()));
    QCOMPARE(candump(*enc.data), candump(expected));

    const std::optional<proto::Frame> frame = can::frameOf(expected);
    QVERIFY(frame);
    const proto::ReplyDecodeResult dec = proto::decodeReply(*frame, ctx);
    QVERIFY(dec.reply);
    QCOMPARE(int(dec.reply->command), int(reply.command));
    QCOMPARE(proto::FieldJson::replyFields(*dec.reply), proto::FieldJson::replyFields(reply));
    QCOMPARE(candump(*can::encodeReply(*dec.reply, ctx).data), candump(expected));
}

void tst_CanLayout::multiTurnSignExtension_data()
{
    QTest::addColumn<QByteArray>("b1to7");
    QTest::addColumn<qint64>("raw");
    QTest::newRow("-360.00 deg (spec)") << hex("6073FFFFFFFFFF") << qint64(-36000);
    QTest::newRow("-0.01 deg") << hex("FFFFFFFFFFFFFF") << qint64(-1);
    QTest::newRow("0") << hex("00000000000000") << qint64(0);
    QTest::newRow("largest positive") << hex("FFFFFFFFFFFF7F") << qint64((1LL << 55) - 1);
    QTest::newRow("most negative") << hex("00000000000080") << qint64(-(1LL << 55));
    QTest::newRow("bit 54 alone is positive") << hex("00000000000040") << qint64(1LL << 54);
}

void tst_CanLayout::multiTurnSignExtension()
{
    QFETCH(QByteArray, b1to7);
    QFETCH(qint64, raw);
    for (Generation g : {Generation::V2_3, Generation::V2_35}) {
        const proto::ReplyDecodeResult r =
            proto::decodeReply(proto::Frame{0x92, 1, b1to7}, canCtx(g));
        QVERIFY(r.reply);
        QCOMPARE(std::get<proto::MultiTurnAngle>(r.reply->payload).raw, raw);
    }
}

void tst_CanLayout::refusals_data()
{
    QTest::addColumn<int>("generation");
    QTest::addColumn<int>("index"); ///< into the requests below
    QTest::addColumn<QString>("field");
    QTest::newRow("V2.36 0xA2 without a torque limit")
        << int(Generation::V2_35) << 0 << "iq_limit_raw";
    QTest::newRow("V2.36 0xA2 with limit 0") << int(Generation::V2_35) << 1 << "iq_limit_raw";
    QTest::newRow("V2.36 0xA2 with limit 2049") << int(Generation::V2_35) << 2 << "iq_limit_raw";
    QTest::newRow("V2.36 0xA2 with a negative limit")
        << int(Generation::V2_35) << 3 << "iq_limit_raw";
    QTest::newRow("0x12 old") << int(Generation::V2_3) << 4 << "command";
    QTest::newRow("0x12 V2.36") << int(Generation::V2_35) << 4 << "command";
    QTest::newRow("0x93 V2.36") << int(Generation::V2_35) << 5 << "command";
    QTest::newRow("0x8C old") << int(Generation::V2_3) << 6 << "command";
    QTest::newRow("0x95 old (not implemented)") << int(Generation::V2_3) << 7 << "command";
    QTest::newRow("0x31 V2.36") << int(Generation::V2_35) << 8 << "command";
    QTest::newRow("0x40 V2.36") << int(Generation::V2_35) << 9 << "command";
    QTest::newRow("0xA3 beyond int32") << int(Generation::V2_3) << 10 << "angle_deg";
    QTest::newRow("0xA5 old beyond 359.99 deg") << int(Generation::V2_3) << 11 << "angle_deg";
    QTest::newRow("0xA4 max speed under 1 dps") << int(Generation::V2_35) << 12 << "max_speed_dps";
    QTest::newRow("0xA0 V2.36 power 900") << int(Generation::V2_35) << 13 << "power";
    QTest::newRow("0xA1 old iq 2048") << int(Generation::V2_3) << 14 << "iq_raw";
}

void tst_CanLayout::refusals()
{
    QFETCH(int, generation);
    QFETCH(int, index);
    QFETCH(QString, field);
    const std::vector<proto::Request> requests{
        req(Command::Speed, proto::SpeedCommand{10000}),
        req(Command::Speed, proto::SpeedCommand{10000, qint16(0)}),
        req(Command::Speed, proto::SpeedCommand{10000, qint16(2049)}),
        req(Command::Speed, proto::SpeedCommand{10000, qint16(-5)}),
        req(Command::ReadModel),
        req(Command::ClearTurnCount),
        req(Command::Brake, proto::BrakeCommand{proto::BrakeAction::Read}),
        req(Command::ClearAngle),
        req(Command::WritePidRam, proto::PidGains{}),
        req(Command::ReadParam, proto::ParamRead{0x96}),
        req(Command::MultiPosition, proto::MultiPositionCommand{(1LL << 31), {}}),
        req(Command::SinglePosition, proto::SinglePositionCommand{{}, 36000, {}}),
        req(Command::MultiPositionLimited, proto::MultiPositionCommand{0, 99u}),
        req(Command::OpenLoop, proto::OpenLoopCommand{900}),
        req(Command::Torque, proto::TorqueCommand{2048}),
    };
    const DecodeContext ctx = canCtx(Generation(generation));
    const can::CanEncodeResult r = can::encodeRequest(requests[size_t(index)], ctx);
    QVERIFY(!r.ok());
    QCOMPARE(r.error.field, field);
    const proto::WireEncodeResult w = proto::encodeRequest(requests[size_t(index)], ctx);
    QVERIFY(!w.ok());
    QVERIFY(w.bytes.isEmpty()); // nothing to send
}

void tst_CanLayout::maxSpeedRoundsDown_data()
{
    QTest::addColumn<quint32>("centiDps");
    QTest::addColumn<quint16>("dps");
    QTest::newRow("360.00") << 36000u << quint16(360);
    QTest::newRow("360.99 -> 360") << 36099u << quint16(360);
    QTest::newRow("1.00") << 100u << quint16(1);
    QTest::newRow("1.99 -> 1") << 199u << quint16(1);
    QTest::newRow("65535.99 -> 65535") << 6553599u << quint16(65535);
    QTest::newRow("above uint16 -> 65535") << 10000000u << quint16(65535);
}

void tst_CanLayout::maxSpeedRoundsDown()
{
    QFETCH(quint32, centiDps);
    QFETCH(quint16, dps);
    const std::vector<proto::Request> limited{
        req(Command::MultiPositionLimited, proto::MultiPositionCommand{100, centiDps}),
        req(Command::SinglePositionLimited, proto::SinglePositionCommand{{}, 100, centiDps}),
        req(Command::IncrementPositionLimited, proto::IncrementPositionCommand{100, centiDps}),
    };
    for (Generation g : {Generation::V2_3, Generation::V2_35}) {
        for (const proto::Request &r : limited) {
            const can::CanEncodeResult enc = can::encodeRequest(r, canCtx(g));
            QVERIFY(enc.ok());
            QCOMPARE(qFromLittleEndian<quint16>(enc.data->bytes.constData() + 2), dps);
        }
    }
}

void tst_CanLayout::speedTorqueLimitFromSoftLimits_data()
{
    QTest::addColumn<int>("series");
    QTest::addColumn<double>("limitA");
    QTest::addColumn<int>("raw"); ///< -1: refused
    // MF on V2.36: 33/4096 A per LSB; MG: 66/4096 A.
    QTest::newRow("MF 1 A -> 124 (124.1 rounded down)") << int(Series::MF) << 1.0 << 124;
    QTest::newRow("MG 1 A -> 62 (62.06 rounded down)") << int(Series::MG) << 1.0 << 62;
    QTest::newRow("MG 33 A -> 2048") << int(Series::MG) << 33.0 << 2048;
    QTest::newRow("MG 100 A -> 2048, the field's top") << int(Series::MG) << 100.0 << 2048;
    QTest::newRow("MF 0.005 A: under one LSB, refused") << int(Series::MF) << 0.005 << -1;
    QTest::newRow("0 A refused") << int(Series::MF) << 0.0 << -1;
    QTest::newRow("NaN refused") << int(Series::MF) << qQNaN() << -1;
}

void tst_CanLayout::speedTorqueLimitFromSoftLimits()
{
    QFETCH(int, series);
    QFETCH(double, limitA);
    QFETCH(int, raw);
    const DecodeContext v236 = canCtx(Generation::V2_35, Series(series));
    const proto::BuildResult b = proto::build::speed(1, 100.0, v236, limitA);
    if (raw < 0) {
        QVERIFY(!b.ok());
        QCOMPARE(b.error.field, QStringLiteral("torque_limit_a"));
        return;
    }
    QVERIFY(b.ok());
    const auto &c = std::get<proto::SpeedCommand>(b.request->payload);
    QCOMPARE(c.iqLimitRaw, std::optional<qint16>(qint16(raw)));
    const can::CanEncodeResult enc = can::encodeRequest(*b.request, v236);
    QVERIFY(enc.ok());
    QCOMPARE(qFromLittleEndian<qint16>(enc.data->bytes.constData() + 2), qint16(raw));
    // The old generation and RS485 have no such field: the same call builds the plain command.
    for (DecodeContext other : {canCtx(Generation::V2_3, Series(series)),
                                DecodeContext{Series(series), Generation::V2_35, Link::Rs485}}) {
        const proto::BuildResult o = proto::build::speed(1, 100.0, other, limitA);
        QVERIFY(o.ok());
        QVERIFY(!std::get<proto::SpeedCommand>(o.request->payload).iqLimitRaw);
    }
}

void tst_CanLayout::addresses()
{
    QCOMPARE(can::requestCanId(1), quint32(0x141));
    QCOMPARE(can::requestCanId(32), quint32(0x160));
    QCOMPARE(can::replyCanId(1, Generation::V2_3), quint32(0x141));
    QCOMPARE(can::replyCanId(32, Generation::V2_35), quint32(0x1A0));
    QVERIFY(!can::driveAddressOf(0x140));
    QVERIFY(!can::driveAddressOf(0x161));
    QVERIFY(!can::driveAddressOf(0x180));
    QVERIFY(!can::driveAddressOf(0x1A1));
    QVERIFY(!can::driveAddressOf(0x280));
    QCOMPARE(can::driveAddressOf(0x160)->driveId, quint8(32));
    QCOMPARE(int(can::driveAddressOf(0x181)->base), int(can::IdBase::Base180));
    QCOMPARE(can::driveAddressOf(0x181)->driveId, quint8(1));
    QVERIFY(!can::frameOf(can::CanData{0x141, hex("9C00")})); // DLC 2
}

void tst_CanLayout::generationHints_data()
{
    QTest::addColumn<QString>("frame");
    QTest::addColumn<int>("generation"); ///< -1: cannot tell
    QTest::newRow("any reply on 0x181") << "181#9C326400F4010020" << int(Generation::V2_35);
    QTest::newRow("old 0x9A, 24.0 V") << "141#9A1E00F000000008" << int(Generation::V2_3);
    QTest::newRow("V2.36 0x9A, 24.00 V, off") << "141#9A1E600996001002" << int(Generation::V2_35);
    QTest::newRow("V2.36 0x9A, 25.60 V, on, 0 A")
        << "141#9A1E000A00000000" << int(Generation::V2_35);
    QTest::newRow("old 0x9B, 48.0 V") << "141#9B2800E001000000" << int(Generation::V2_3);
    QTest::newRow("0x9C on 0x141 cannot tell") << "141#9C326400F4010020" << -1;
    QTest::newRow("0x9A, no plausible voltage") << "141#9A1E000000000000" << -1;
    QTest::newRow("not a drive's ID") << "280#9A1E00F000000008" << -1;
}

void tst_CanLayout::generationHints()
{
    QFETCH(QString, frame);
    QFETCH(int, generation);
    frame.remove(QLatin1Char(' '));
    const std::optional<Generation> g = can::generationHint(canFrame(qPrintable(frame)));
    if (generation < 0)
        QVERIFY(!g);
    else
        QCOMPARE(g, std::optional<Generation>(Generation(generation)));
}

void tst_CanLayout::replyDecodeFaults()
{
    const DecodeContext ctx = canCtx(Generation::V2_35);
    QCOMPARE(int(proto::decodeReply(proto::Frame{0x9C, 1, hex("3264")}, ctx).error),
             int(proto::DecodeError::BadLength));
    QCOMPARE(int(proto::decodeReply(proto::Frame{0x12, 1, QByteArray(7, 0)}, ctx).error),
             int(proto::DecodeError::UnknownCommand));
    QCOMPARE(int(proto::decodeReply(proto::Frame{0xEE, 1, QByteArray(7, 0)}, ctx).error),
             int(proto::DecodeError::UnknownCommand));
    // V2.36 0x9D reads its phase currents at the iq scale, the old generation at 1/64 A.
    const proto::Frame f{0x9D, 1, hex("1E000140000000")};
    const auto v236 = std::get<proto::State3>(proto::decodeReply(f, ctx).reply->payload);
    const auto old =
        std::get<proto::State3>(proto::decodeReply(f, canCtx(Generation::V2_3)).reply->payload);
    QCOMPARE(v236.iaRaw, qint16(256));
    QCOMPARE(old.iaA(), 4.0);
    QCOMPARE(v236.iaA(), 256 * 66.0 / 4096);
}

void tst_CanLayout::linkCodecKeepsRs485()
{
    const proto::Request r = req(Command::MotorOff);
    const proto::WireEncodeResult w = proto::encodeRequest(r, DecodeContext{});
    QVERIFY(w.ok());
    QCOMPARE(w.bytes, hex("3E 80 01 00 BF"));
    QCOMPARE(w.bytes, r.encode());
}

QTEST_APPLESS_MAIN(tst_CanLayout)
#include "tst_canlayout.moc"
