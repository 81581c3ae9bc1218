#include "protocol/Request.h"
#include "protocol/RequestBuilder.h"

#include "ProtocolTestUtil.h"

#include <QtTest/QTest>

#include <functional>

using lk::protocol::BuildResult;
using lk::protocol::Command;
using lk::protocol::DecodeError;
using lk::protocol::Frame;
using lk::protocol::Request;
using lk::protocol::RequestPayload;
using lk::protocol::SpinDirection;
using lk::test::hex;
using lk::test::spaced;
namespace build = lk::protocol::build;
namespace proto = lk::protocol;

using BuildFn = std::function<BuildResult()>;
Q_DECLARE_METATYPE(BuildFn)

/// decodeRequest: build -> encode -> parse -> decode gives the original back; frames of the
/// wrong direction, bad length or unknown command are refused with the right error.
class tst_RequestDecode : public QObject {
    Q_OBJECT

private slots:
    void roundTrip_data();
    void roundTrip();
    void fromWire_data();
    void fromWire();
    void refused_data();
    void refused();
    void physicalUnits();
};

namespace {
// Every field of a payload in one string: equal strings mean equal payloads, and a failure
// shows what differs.
struct Describe {
    QString operator()(const proto::NoPayload &) const { return QStringLiteral("none"); }
    QString operator()(const proto::PidGains &g) const
    {
        return QStringLiteral("pid %1 %2 %3 %4 %5 %6")
            .arg(g.angleKp)
            .arg(g.angleKi)
            .arg(g.speedKp)
            .arg(g.speedKi)
            .arg(g.iqKp)
            .arg(g.iqKi);
    }
    QString operator()(const proto::Acceleration &a) const
    {
        return QStringLiteral("accel %1").arg(a.dps2);
    }
    QString operator()(const proto::EncoderOffset &o) const
    {
        return QStringLiteral("offset %1").arg(o.offset);
    }
    QString operator()(const proto::OpenLoopCommand &c) const
    {
        return QStringLiteral("power %1").arg(c.power);
    }
    QString operator()(const proto::TorqueCommand &c) const
    {
        return QStringLiteral("iq %1").arg(c.iqRaw);
    }
    QString operator()(const proto::SpeedCommand &c) const
    {
        return QStringLiteral("speed %1").arg(c.speedRaw);
    }
    static QString maxSpeed(const std::optional<quint32> &m)
    {
        return m ? QStringLiteral(" max %1").arg(*m) : QString();
    }
    QString operator()(const proto::MultiPositionCommand &c) const
    {
        return QStringLiteral("multi %1").arg(c.angleRaw) + maxSpeed(c.maxSpeedRaw);
    }
    QString operator()(const proto::SinglePositionCommand &c) const
    {
        return QStringLiteral("single dir %1 %2").arg(int(c.direction)).arg(c.angleRaw) +
               maxSpeed(c.maxSpeedRaw);
    }
    QString operator()(const proto::IncrementPositionCommand &c) const
    {
        return QStringLiteral("increment %1").arg(c.angleRaw) + maxSpeed(c.maxSpeedRaw);
    }
    QString operator()(const proto::ParamRead &p) const
    {
        return QStringLiteral("read param %1").arg(p.paramId);
    }
    QString operator()(const proto::ParameterValue &v) const
    {
        return QStringLiteral("param %1 = %2").arg(v.paramId).arg(v.asInt32());
    }
    QString operator()(const proto::BrakeCommand &b) const
    {
        return QStringLiteral("brake %1").arg(int(b.action));
    }
    QString operator()(const proto::ControlParamRead &p) const
    {
        return QStringLiteral("read control param %1").arg(p.paramId);
    }
    QString operator()(const proto::ControlParameter &v) const
    {
        return QStringLiteral("control param %1 = %2").arg(v.paramId).arg(v.value());
    }
    QString operator()(const proto::PositionSet &p) const
    {
        return QStringLiteral("position := %1").arg(p.angleRaw);
    }
};

QString describe(const Request &r)
{
    return QStringLiteral("%1 id %2 [%3] ")
               .arg(proto::CommandTable::codeText(quint8(r.command)))
               .arg(r.id)
               .arg(r.payload.index()) +
           std::visit(Describe{}, r.payload);
}

void addRoundTrip(const char *name, const BuildFn &fn)
{
    QTest::newRow(name) << fn;
}
} // namespace

void tst_RequestDecode::roundTrip_data()
{
    QTest::addColumn<BuildFn>("buildFn");
    const Command plainCommands[] = {
        Command::ReadPid,      Command::ReadAccel,     Command::ReadEncoder,
        Command::WriteZeroRom, Command::ReadMultiTurn, Command::ReadSingleTurn,
        Command::ClearAngle,   Command::ReadState1,    Command::ClearErrors,
        Command::ReadState2,   Command::ReadState3,    Command::MotorOff,
        Command::MotorStop,    Command::MotorRun,      Command::ReadModel};
    for (Command c : plainCommands) {
        for (int id : {1, 32}) {
            QTest::addRow("%s id %d", proto::CommandTable::info(c).name, id)
                << BuildFn([c, id] { return build::plain(c, id); });
        }
    }
    const auto cw = SpinDirection::Clockwise;
    const auto ccw = SpinDirection::CounterClockwise;
    addRoundTrip("write_pid_ram", [] { return build::writePid(3, 1, 2, 3, 4, 5, 6, false); });
    addRoundTrip("write_pid_rom 255",
                 [] { return build::writePid(32, 255, 0, 255, 0, 255, 0, true); });
    addRoundTrip("write_accel_ram max", [] { return build::writeAcceleration(1, 2147483647); });
    addRoundTrip("write_accel_ram 0", [] { return build::writeAcceleration(2, 0); });
    addRoundTrip("write_encoder_offset 65535", [] { return build::writeEncoderOffset(1, 65535); });
    addRoundTrip("write_encoder_offset 0x8000",
                 [] { return build::writeEncoderOffset(5, 0x8000); });
    addRoundTrip("open_loop -850", [] { return build::openLoop(1, -850); });
    addRoundTrip("open_loop 850", [] { return build::openLoop(32, 850); });
    addRoundTrip("torque -32", [] { return build::torque(1, -32.0, {}); });
    addRoundTrip("torque 31.5", [] { return build::torque(9, 31.5, {}); });
    addRoundTrip("speed int32 min", [] { return build::speed(1, -21474836.48); });
    addRoundTrip("speed int32 max", [] { return build::speed(1, 21474836.47); });
    addRoundTrip("multi_position -123456.78", [] { return build::multiPosition(1, -123456.78); });
    addRoundTrip("multi_position 9e16", [] { return build::multiPosition(1, 9e16); });
    addRoundTrip("multi_position_limited", [] { return build::multiPosition(4, -720.0, 360.0); });
    addRoundTrip("multi_position_limited max 0", [] { return build::multiPosition(4, 1.0, 0.0); });
    addRoundTrip("single_position cw 0", [cw] { return build::singlePosition(1, cw, 0.0); });
    addRoundTrip("single_position ccw 359.99",
                 [ccw] { return build::singlePosition(1, ccw, 359.99); });
    addRoundTrip("single_position_limited ccw",
                 [ccw] { return build::singlePosition(6, ccw, 123.45, 42949672.95); });
    addRoundTrip("single_position_limited cw",
                 [cw] { return build::singlePosition(6, cw, 359.99, 0.01); });
    addRoundTrip("increment_position -90", [] { return build::incrementPosition(1, -90.0); });
    addRoundTrip("increment_position int32 min",
                 [] { return build::incrementPosition(1, -21474836.48); });
    addRoundTrip("increment_position_limited",
                 [] { return build::incrementPosition(32, 21474836.47, 42949672.95); });
}

void tst_RequestDecode::roundTrip()
{
    QFETCH(BuildFn, buildFn);
    const BuildResult built = buildFn();
    QVERIFY2(built.ok(), qPrintable(built.error.message()));
    const Request &original = *built.request;
    const QByteArray wire = original.encode();

    const lk::test::EventLog log = lk::test::parseAll(wire);
    QCOMPARE(int(log.events.size()), 1);
    const proto::ParseEvent &ev = log.events.front();
    QVERIFY2(ev.isFrame, qPrintable(lk::test::describe(ev)));
    QCOMPARE(ev.bytes, wire);
    QVERIFY(ev.direction == proto::FrameDirection::Request ||
            ev.direction == proto::FrameDirection::Echo);

    const proto::RequestDecodeResult decoded = proto::decodeRequest(ev.frame);
    QVERIFY(decoded.error == DecodeError::None);
    QVERIFY(decoded.request.has_value());
    QCOMPARE(describe(*decoded.request), describe(original));
    QCOMPARE(spaced(decoded.request->encode()), spaced(wire));
}

void tst_RequestDecode::fromWire_data()
{
    // Hand-made request frames (spec + ERRATA) and what they must decode to.
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<QString>("expected");
    QTest::newRow("motor_off") << hex("3E 80 01 00 BF") << QStringLiteral("0x80 id 1 [0] none");
    QTest::newRow("write_pid_rom") << hex("3E 32 07 06 7D 01 02 03 04 05 FE 0D")
                                   << QStringLiteral("0x32 id 7 [1] pid 1 2 3 4 5 254");
    QTest::newRow("write_accel_ram 10-byte frame, checksum at DATA[9]")
        << hex("3E 34 20 04 96 10 27 00 00 37") << QStringLiteral("0x34 id 32 [2] accel 10000");
    QTest::newRow("write_accel_ram negative int32")
        << hex("3E 34 01 04 77 F0 D8 FF FF C6") << QStringLiteral("0x34 id 1 [2] accel -10000");
    QTest::newRow("write_encoder_offset")
        << hex("3E 91 20 02 F1 34 12 46") << QStringLiteral("0x91 id 32 [3] offset 4660");
    QTest::newRow("open_loop -1000")
        << hex("3E A0 01 02 E1 18 FC 14") << QStringLiteral("0xA0 id 1 [4] power -1000");
    QTest::newRow("torque -2000") << hex("3E A1 01 02 E2 30 F8 28")
                                  << QStringLiteral("0xA1 id 1 [5] iq -2000");
    QTest::newRow("speed -10000") << hex("3E A2 01 04 E5 F0 D8 FF FF C6")
                                  << QStringLiteral("0xA2 id 1 [6] speed -10000");
    QTest::newRow("multi_position -9000") << hex("3E A3 01 08 EA D8 DC FF FF FF FF FF FF AE")
                                          << QStringLiteral("0xA3 id 1 [7] multi -9000");
    QTest::newRow("multi_position_limited")
        << hex("3E A4 01 0C EF A0 8C 00 00 00 00 00 00 50 C3 00 00 3F")
        << QStringLiteral("0xA4 id 1 [7] multi 36000 max 50000");
    QTest::newRow("single_position ccw 35999")
        << hex("3E A5 01 04 E8 01 9F 8C 00 2C")
        << QStringLiteral("0xA5 id 1 [8] single dir 1 35999");
    QTest::newRow("single_position_limited cw 18000")
        << hex("3E A6 01 08 ED 00 50 46 00 10 27 00 00 CD")
        << QStringLiteral("0xA6 id 1 [8] single dir 0 18000 max 10000");
    QTest::newRow("increment_position LEN 4")
        << hex("3E A7 01 04 EA D8 DC FF FF B2") << QStringLiteral("0xA7 id 1 [9] increment -9000");
    QTest::newRow("increment_position_limited")
        << hex("3E A8 01 08 EF 6C EE FF FF 20 4E 00 00 C6")
        << QStringLiteral("0xA8 id 1 [9] increment -4500 max 20000");
}

void tst_RequestDecode::fromWire()
{
    QFETCH(QByteArray, wire);
    QFETCH(QString, expected);
    const lk::test::EventLog log = lk::test::parseAll(wire);
    QCOMPARE(int(log.events.size()), 1);
    QVERIFY2(log.events.front().isFrame, qPrintable(lk::test::describe(log.events.front())));
    const proto::RequestDecodeResult decoded = proto::decodeRequest(log.events.front().frame);
    QVERIFY(decoded.error == DecodeError::None);
    QVERIFY(decoded.request.has_value());
    QCOMPARE(describe(*decoded.request), expected);
}

void tst_RequestDecode::refused_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<int>("error");
    const auto add = [](const char *name, const char *what, int code, int len, DecodeError e) {
        // Data bytes >= 0x80: nothing may depend on the content.
        const QByteArray wire = proto::encodeFrame(quint8(code), 1, QByteArray(len, char(0xC3)));
        QTest::addRow("%s %s LEN %d", name, what, len) << wire << int(e);
    };
    for (const lk::test::CommandLengths &l : lk::test::kCommandLengths) {
        for (int len : l.replies) {
            if (len != l.request) // an echo is a valid request
                add(l.name, "reply", l.code, len, DecodeError::WrongDirection);
        }
        // Lengths that neither direction carries: one byte, one short, one long, 60.
        for (int len : {1, l.request - 1, l.request + 1, 60}) {
            if (len < 0 || len == l.request || l.replies.contains(len))
                continue;
            add(l.name, "bad length", l.code, len, DecodeError::BadLength);
        }
    }
    for (int code : {0x00, 0x3E, 0x41, 0x89, 0x8D, 0xA9, 0xFF}) {
        for (int len : {0, 2, 7})
            add("unknown", qPrintable(proto::CommandTable::codeText(quint8(code))), code, len,
                DecodeError::UnknownCommand);
    }
}

void tst_RequestDecode::refused()
{
    QFETCH(QByteArray, wire);
    QFETCH(int, error);
    // Through the parser, as the simulator and lkctl decode see frames.
    const lk::test::EventLog log = lk::test::parseAll(wire);
    QCOMPARE(int(log.events.size()), 1);
    const proto::Frame &frame = log.events.front().frame;
    QCOMPARE(spaced(frame.encode()), spaced(wire));
    const proto::RequestDecodeResult decoded = proto::decodeRequest(frame);
    QCOMPARE(int(decoded.error), error);
    QVERIFY(!decoded.request.has_value());
}

void tst_RequestDecode::physicalUnits()
{
    // The accessors of decoded command payloads: 32 A / 2000 and 0.01 dps.
    const auto torque = proto::decodeRequest(Frame{0xA1, 1, hex("30 F8")}).request;
    QVERIFY(torque.has_value());
    QCOMPARE(std::get<proto::TorqueCommand>(torque->payload).iqA(), -32.0);
    const auto half = proto::decodeRequest(Frame{0xA1, 1, hex("1F 00")}).request;
    QVERIFY(half.has_value());
    QCOMPARE(std::get<proto::TorqueCommand>(half->payload).iqA(), 31 * 32.0 / 2000.0);
    const auto speed = proto::decodeRequest(Frame{0xA2, 1, hex("F0 D8 FF FF")}).request;
    QVERIFY(speed.has_value());
    QCOMPARE(std::get<proto::SpeedCommand>(speed->payload).speedDps(), -100.0);
}

QTEST_APPLESS_MAIN(tst_RequestDecode)
#include "tst_requestdecode.moc"
