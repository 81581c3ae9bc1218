// CAN V2.36 control parameters (0xC0 read, 0xC1 write to RAM) as typed commands of the codec:
// built, encoded per link (refused with the reason where the dialect lacks them), decoded to
// typed values, and described (docs/CAN.md section 4.1).
#include "CanTestUtil.h"

#include <protocol/FieldJson.h>
#include <protocol/FieldText.h>
#include <protocol/LinkCodec.h>
#include <protocol/Reply.h>
#include <protocol/RequestBuilder.h>
#include <protocol/StreamParser.h>

#include <QtTest/QTest>

using namespace lk::test::cantest;
using proto::ControlParameter;
using proto::ControlParamId;

Q_DECLARE_METATYPE(lk::protocol::BuildResult)

namespace {
DecodeContext ctx(Link link, Generation g)
{
    return DecodeContext{Series::MG, g, link};
}

/// The CAN frame a typed request goes out as on `context`, in candump notation; the refusal's
/// field otherwise.
QString wire(const proto::Request &r, const DecodeContext &context)
{
    const can::CanEncodeResult e = can::encodeRequest(r, context);
    return e.ok() ? candump(*e.data) : QStringLiteral("refused:") + e.error.field;
}
} // namespace

class tst_CanControlParam : public QObject {
    Q_OBJECT
private slots:
    void requestsEncodeOnCan236_data();
    void requestsEncodeOnCan236();
    void refusedWhereTheDialectLacksThem();
    void repliesDecodeToTypedValues();
    void buildersCheckRanges();
    void rs485FramesWithTheCodeAreUnknown();
    void describedWithUnitsOrRaw();
};

void tst_CanControlParam::requestsEncodeOnCan236_data()
{
    QTest::addColumn<proto::BuildResult>("built");
    QTest::addColumn<QString>("frame");
    QTest::newRow("read angle pid")
        << proto::build::readControlParam(1, ControlParamId::AnglePid) << "141#C00A000000000000";
    QTest::newRow("read current ramp")
        << proto::build::readControlParam(3, ControlParamId::InputCurrentRamp)
        << "143#C024000000000000";
    QTest::newRow("write speed pid")
        << proto::build::writeControlParamPid(2, ControlParamId::SpeedPid, 10, 20, 30)
        << "142#C10B0A0014001E00";
    // The peer's vector (CAN.md 4.1): torque limit in B4-B5, B2-B3 unused.
    QTest::newRow("write torque limit 2000")
        << proto::build::writeControlParam(1, ControlParamId::InputTorqueLimit, 2000)
        << "141#C11E0000D0070000";
    QTest::newRow("write speed limit 360 dps")
        << proto::build::writeControlParam(1, ControlParamId::InputSpeedLimit, 360.0)
        << "141#C1200000A08C0000";
    QTest::newRow("write angle limit 90 deg")
        << proto::build::writeControlParam(1, ControlParamId::InputAngleLimit, 90.0)
        << "141#C122000028230000";
    QTest::newRow("write current ramp raw 70000")
        << proto::build::writeControlParam(1, ControlParamId::InputCurrentRamp, 70000)
        << "141#C124000070110100";
    QTest::newRow("write speed ramp 10000 dps/s")
        << proto::build::writeControlParam(1, ControlParamId::InputSpeedRamp, 10000)
        << "141#C126000010270000";
}

void tst_CanControlParam::requestsEncodeOnCan236()
{
    QFETCH(proto::BuildResult, built);
    QFETCH(QString, frame);
    QVERIFY2(built.ok(), qPrintable(built.error.message()));
    QCOMPARE(wire(*built.request, ctx(Link::Can, Generation::V2_35)), frame);
    // Read back as the drive does: the same typed request.
    const auto back = proto::decodeRequest(*can::frameOf(canFrame(frame.toLatin1().constData())),
                                           ctx(Link::Can, Generation::V2_35));
    QVERIFY(back.request);
    QCOMPARE(back.request->command, built.request->command);
    QCOMPARE(wire(*back.request, ctx(Link::Can, Generation::V2_35)), frame);
}

void tst_CanControlParam::refusedWhereTheDialectLacksThem()
{
    const proto::Request read =
        *proto::build::readControlParam(1, ControlParamId::AnglePid).request;
    const proto::Request write =
        *proto::build::writeControlParam(1, ControlParamId::InputSpeedRamp, 100).request;
    for (const proto::Request &r : {read, write}) {
        // RS485 (both generations) and the old CAN generation: refused, nothing to send.
        for (const DecodeContext &c :
             {ctx(Link::Rs485, Generation::V2_3), ctx(Link::Rs485, Generation::V2_35),
              ctx(Link::Can, Generation::V2_3)}) {
            const proto::WireEncodeResult e = proto::encodeRequest(r, c);
            QVERIFY(!e.ok());
            QVERIFY(e.bytes.isEmpty());
            QCOMPARE(e.error.field, QStringLiteral("command"));
            QVERIFY2(e.error.message().contains(proto::CommandTable::name(r.command)),
                     qPrintable(e.error.message()));
        }
        QVERIFY(proto::encodeRequest(r, ctx(Link::Can, Generation::V2_35)).ok());
    }
    QVERIFY(!proto::CommandTable::availableOn(Command::ReadControlParam, Generation::V2_35));
    QVERIFY(!proto::CommandTable::availableOn(Command::WriteControlParam,
                                              ctx(Link::Can, Generation::V2_3)));
    QVERIFY(proto::CommandTable::availableOn(Command::WriteControlParam,
                                             ctx(Link::Can, Generation::V2_35)));
    // RAM only: neither writes flash.
    QVERIFY(!proto::CommandTable::info(Command::WriteControlParam).writesFlash);
}

void tst_CanControlParam::repliesDecodeToTypedValues()
{
    const DecodeContext v236 = ctx(Link::Can, Generation::V2_35);
    const auto decode = [&](const char *frame) {
        const proto::ReplyDecodeResult r = proto::decodeReply(*can::frameOf(canFrame(frame)), v236);
        return r.reply ? std::get<ControlParameter>(r.reply->payload) : ControlParameter{};
    };
    const ControlParameter pid = decode("181#C00C2C01C8000500");
    QCOMPARE(pid.id(), std::optional<ControlParamId>(ControlParamId::CurrentPid));
    QCOMPARE(pid.pid(), (std::array<quint16, 3>{300, 200, 5}));
    // The torque limit is int16 in B4-B5 whatever B2-B3 hold; the others int32 in B4..B7.
    QCOMPARE(decode("181#C01EFFFF30F8FFFF").value(), -2000);
    QCOMPARE(decode("141#C1206073FFFF0000").value(), 0x0000FFFF);
    QCOMPARE(decode("181#C0220000A0F6FEFF").value(), -67936);
    QCOMPARE(decode("181#C024000070110100").value(), 70000);
    // Not a control parameter reply on the old generation.
    QVERIFY(!proto::decodeReply(*can::frameOf(canFrame("141#C00A000000000000")),
                                ctx(Link::Can, Generation::V2_3))
                 .reply);
    // A reply on the table's own terms, both ways.
    const proto::Reply r{Command::ReadControlParam, 2,
                         ControlParameter::ofValue(ControlParamId::InputSpeedRamp, 12345)};
    QCOMPARE(candump(*can::encodeReply(r, v236).data), QStringLiteral("182#C026000039300000"));
}

void tst_CanControlParam::buildersCheckRanges()
{
    using proto::build::writeControlParam;
    QCOMPARE(writeControlParam(1, ControlParamId::InputTorqueLimit, 2049).error.field,
             QStringLiteral("max_torque"));
    QVERIFY(!writeControlParam(1, ControlParamId::InputTorqueLimit, -1).ok());
    QCOMPARE(writeControlParam(1, ControlParamId::InputAngleLimit, 21474837).error.field,
             QStringLiteral("max_angle_deg"));
    QCOMPARE(writeControlParam(1, ControlParamId::InputCurrentRamp, -5).error.field,
             QStringLiteral("current_ramp_raw"));
    QVERIFY(!writeControlParam(1, ControlParamId::AnglePid, 5).ok());
    QVERIFY(!proto::build::writeControlParamPid(1, ControlParamId::SpeedPid, 65536, 0, 0).ok());
    QVERIFY(!proto::build::writeControlParamPid(1, ControlParamId::InputSpeedRamp, 1, 1, 1).ok());
    QVERIFY(!proto::build::readControlParam(33, ControlParamId::AnglePid).ok());
    ControlParameter unknown;
    unknown.paramId = 0x99;
    QVERIFY(!proto::build::writeControlParam(1, unknown).ok());
}

void tst_CanControlParam::rs485FramesWithTheCodeAreUnknown()
{
    // 0xC0 is no RS485 command: a frame with it is an unknown command, never a parameter.
    QByteArray frame = proto::encodeFrame(0xC0, 1, QByteArray(7, '\0'));
    proto::StreamParser parser;
    QList<proto::ParseEvent> events;
    parser.feed(frame, [&](const proto::ParseEvent &e) { events.append(e); });
    QCOMPARE(events.size(), 1);
    QCOMPARE(events.at(0).error, proto::ParseError::UnknownCommand);
    const proto::Frame f{0xC0, 1, QByteArray(7, '\0')};
    QCOMPARE(proto::decodeRequest(f).error, proto::DecodeError::UnknownCommand);
    QCOMPARE(proto::decodeReply(f).error, proto::DecodeError::UnknownCommand);
}

void tst_CanControlParam::describedWithUnitsOrRaw()
{
    const auto text = [](const ControlParameter &v) {
        return proto::FieldText::reply(proto::Reply{Command::ReadControlParam, 1, v});
    };
    QCOMPARE(text(ControlParameter::ofPid(ControlParamId::AnglePid, 1, 2, 3)),
             QStringLiteral("angle_pid Kp 1 Ki 2 Kd 3"));
    QCOMPARE(text(ControlParameter::ofValue(ControlParamId::InputSpeedLimit, 36000)),
             QStringLiteral("input_speed_limit 360.00 dps"));
    // The current ramp's unit is unknown (CAN.md): the raw number, said so.
    QCOMPARE(text(ControlParameter::ofValue(ControlParamId::InputCurrentRamp, 500)),
             QStringLiteral("input_current_ramp 500 (unit unknown)"));
    const QJsonObject o = proto::FieldJson::replyFields(
        proto::Reply{Command::ReadControlParam, 1,
                     ControlParameter::ofValue(ControlParamId::InputAngleLimit, 9000)});
    QCOMPARE(o.value(QStringLiteral("control_param")).toString(),
             QStringLiteral("input_angle_limit"));
    QCOMPARE(o.value(QStringLiteral("max_angle_deg")).toDouble(), 90.0);
    QCOMPARE(o.value(QStringLiteral("max_angle_raw")).toInt(), 9000);
    const QJsonObject ramp = proto::FieldJson::replyFields(
        proto::Reply{Command::ReadControlParam, 1,
                     ControlParameter::ofValue(ControlParamId::InputCurrentRamp, 7)});
    QCOMPARE(ramp.value(QStringLiteral("current_ramp_raw")).toInt(), 7);
    QVERIFY(!ramp.contains(QStringLiteral("current_ramp")));
}

QTEST_APPLESS_MAIN(tst_CanControlParam)
#include "tst_cancontrolparam.moc"
