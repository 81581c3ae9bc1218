// The CAN frames outside the request/reply codec: the old generation's multi-motor torque
// frame (0x280), V2.36 control parameters (0xC0/0xC1) and V2.36 0x95 set position.
#include "CanTestUtil.h"

#include <protocol/CanLayout.h>
#include <protocol/Command.h>
#include <protocol/FieldJson.h>
#include <protocol/FieldText.h>
#include <protocol/LinkCodec.h>
#include <protocol/Request.h>

#include <QtTest/QTest>

#include <array>
#include <optional>

using namespace lk::test::cantest;

class tst_CanFrames : public QObject {
    Q_OBJECT
private slots:
    void multiMotorTorque();
    void controlParameters();
    void setPosition();
};

void tst_CanFrames::multiMotorTorque()
{
    const can::CanEncodeResult r = can::encodeMultiMotorTorque({100, -100, 0, 0});
    QVERIFY(r.ok());
    QCOMPARE(candump(*r.data), candump(canFrame("280#64009CFF00000000")));
    const auto iq = can::decodeMultiMotorTorque(canFrame("280#64009CFF00000000"));
    QVERIFY(iq);
    QCOMPARE((*iq)[0], qint16(100));
    QCOMPARE((*iq)[1], qint16(-100));
    QCOMPARE((*iq)[2], qint16(0));
    QVERIFY(!can::encodeMultiMotorTorque({0, 0, 2001, 0}).ok());
    QCOMPARE(can::encodeMultiMotorTorque({0, 0, 0, -2001}).error.field, QStringLiteral("iq_raw"));
    QVERIFY(!can::decodeMultiMotorTorque(canFrame("141#64009CFF00000000")));
}

void tst_CanFrames::controlParameters()
{
    using can::ControlParamId;
    // Held vectors: 0xC1 torque limit 2000, 0xC0 read angle PID.
    const can::ControlParameter limit =
        can::ControlParameter::ofValue(ControlParamId::InputTorqueLimit, 2000);
    QCOMPARE(candump(can::encodeControlParamWrite(1, limit)),
             candump(canFrame("141#C11E0000D0070000")));
    QCOMPARE(candump(can::encodeControlParamRead(1, ControlParamId::AnglePid)),
             candump(canFrame("141#C00A000000000000")));
    const auto back = can::decodeControlParam(canFrame("141#C11E0000D0070000"));
    QVERIFY(back);
    QCOMPARE(*back, limit);
    QCOMPARE(back->value(), 2000);
    // PID: three uint16 in value bytes 1-2, 3-4, 5-6 (B2..B7).
    const auto pid = can::decodeControlParam(canFrame("181#C00B0A0014001E00"));
    QVERIFY(pid);
    QCOMPARE(pid->paramId, quint8(0x0B));
    QCOMPARE(pid->pid(), (std::array<quint16, 3>{10, 20, 30}));
    QCOMPARE(can::ControlParameter::ofPid(ControlParamId::SpeedPid, 10, 20, 30), *pid);
    // int32 parameters: value bytes 3-6 (B4..B7).
    const auto speed = can::ControlParameter::ofValue(ControlParamId::InputSpeedLimit, -36000);
    QCOMPARE(candump(can::encodeControlParamWrite(2, speed)),
             candump(canFrame("142#C12000006073FFFF")));
    QVERIFY(!can::decodeControlParam(canFrame("141#9C00000000000000")));
}

void tst_CanFrames::setPosition()
{
    // Held vector: V2.36 0x95, current position := 360.00 deg.
    QCOMPARE(candump(can::encodeSetPosition(1, 36000)), candump(canFrame("141#95000000A08C0000")));
    QCOMPARE(can::decodeSetPosition(canFrame("141#95000000A08C0000")),
             std::optional<qint32>(36000));
    QCOMPARE(can::decodeSetPosition(canFrame("141#950000006073FFFF")),
             std::optional<qint32>(-36000));
    QVERIFY(!can::decodeSetPosition(canFrame("141#9400000000000000")));
    // clear_angle is the same frame with 0; another position is not read as a clear: it
    // decodes with its angle (another master's, heard while listening) and encodes back.
    const DecodeContext v236 = canCtx(Generation::V2_35);
    QCOMPARE(candump(*can::encodeRequest(req(Command::ClearAngle), v236).data),
             candump(can::encodeSetPosition(1, 0)));
    QVERIFY(std::holds_alternative<proto::NoPayload>(
        proto::decodeRequest(*can::frameOf(canFrame("141#9500000000000000")), v236)
            .request->payload));
    const proto::RequestDecodeResult set =
        proto::decodeRequest(*can::frameOf(canFrame("141#95000000A08C0000")), v236);
    QVERIFY(set.request);
    QCOMPARE(set.request->command, Command::ClearAngle);
    QCOMPARE(std::get<proto::PositionSet>(set.request->payload).angleRaw, 36000);
    QCOMPARE(candump(*can::encodeRequest(*set.request, v236).data),
             candump(canFrame("141#95000000A08C0000")));
    QCOMPARE(proto::FieldText::request(*set.request, v236),
             QStringLiteral("position := 360.00 deg")); // the Traffic view's words
    QCOMPARE(proto::FieldJson::requestFields(*set.request, v236).value(QStringLiteral("angle_deg")),
             QJsonValue(360.0)); // lkctl decode's
    // The old generation's 0x95 carries no angle; RS485's only zeroes.
    const DecodeContext old = canCtx(Generation::V2_3);
    QVERIFY(!can::encodeRequest(*set.request, old).data);
    QVERIFY(!proto::encodeRequest(
                 *set.request,
                 proto::DecodeContext{proto::Series::MG, Generation::V2_35, proto::Link::Rs485})
                 .ok());
}

QTEST_APPLESS_MAIN(tst_CanFrames)
#include "tst_canframes.moc"
