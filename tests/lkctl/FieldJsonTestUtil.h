#pragma once

// Test vectors and helpers shared by the field tests (FieldJson, RequestText, FieldText).

#include "protocol/FieldJson.h"
#include "protocol/RequestBuilder.h"
#include "protocol/StreamParser.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtTest/QtTest>

Q_DECLARE_METATYPE(lk::protocol::Request)
Q_DECLARE_METATYPE(lk::protocol::Reply)
Q_DECLARE_METATYPE(lk::protocol::Command)

namespace lk::fieldjsontest {

using namespace lk::protocol;

inline Request req(const BuildResult &r)
{
    if (!r.ok())
        qFatal("test vector refused: %s", qPrintable(r.error.message()));
    return *r.request;
}

inline Reply reply(Command c, ReplyPayload payload, quint8 id = 1)
{
    return Reply{c, id, std::move(payload)};
}

inline State2 state2(qint8 t, qint16 torque, bool isPower, qint16 speed, quint16 enc)
{
    State2 s;
    s.temperatureC = t;
    s.torqueRaw = torque;
    s.isPower = isPower;
    s.speedDps = speed;
    s.encoder = enc;
    return s;
}

inline QByteArray line(const QJsonObject &o)
{
    return FieldJson::toJsonLine(o);
}

inline QByteArray fromHex(const char *hex)
{
    return QByteArray::fromHex(QByteArray(hex));
}

/// Every JSON line the parser makes of the bytes.
inline QList<QByteArray> decodeAll(const QByteArray &bytes, const DecodeContext &ctx = {})
{
    QList<QByteArray> lines;
    StreamParser parser;
    const auto sink = [&](const ParseEvent &e) {
        lines << FieldJson::toJsonLine(FieldJson::eventObject(e, ctx));
    };
    parser.feed(bytes, sink);
    parser.finish(sink);
    return lines;
}

/// Equal as JSON: numbers by value (QJsonValue tells integers from doubles in comparisons).
inline bool sameJson(const QJsonValue &a, const QJsonValue &b)
{
    if (a.isDouble() && b.isDouble())
        return a.toDouble() == b.toDouble();
    if (a.type() != b.type())
        return false;
    if (a.isArray()) {
        const QJsonArray x = a.toArray(), y = b.toArray();
        if (x.size() != y.size())
            return false;
        for (qsizetype i = 0; i < x.size(); ++i) {
            if (!sameJson(x.at(i), y.at(i)))
                return false;
        }
        return true;
    }
    if (a.isObject()) {
        const QJsonObject x = a.toObject(), y = b.toObject();
        if (x.keys() != y.keys())
            return false;
        for (const QString &k : x.keys()) {
            if (!sameJson(x.value(k), y.value(k)))
                return false;
        }
        return true;
    }
    return a == b;
}

inline const char kPidFields[] = R"({"angle_kp":100,"angle_ki":100,"speed_kp":50,"speed_ki":40,)"
                                 R"("iq_kp":50,"iq_ki":50})";

/// The rows of tst_FieldJson::requestFields: a request of every command with its fields as
/// JSON (tst_FieldJsonText round-trips the same requests through text).
inline void addRequestRows()
{
    QTest::addColumn<Request>("request");
    QTest::addColumn<QByteArray>("expected");
    const auto pid = PidGains{100, 100, 50, 40, 50, 50};
    QTest::newRow("read_pid") << req(build::plain(Command::ReadPid, 1)) << QByteArray("{}");
    QTest::newRow("write_pid_ram") << req(build::writePid(1, pid, false)) << QByteArray(kPidFields);
    QTest::newRow("write_pid_rom") << req(build::writePid(1, pid, true)) << QByteArray(kPidFields);
    QTest::newRow("write_accel_ram")
        << req(build::writeAcceleration(1, 10000)) << QByteArray(R"({"accel_dps2":10000})");
    QTest::newRow("write_encoder_offset")
        << req(build::writeEncoderOffset(1, 40000)) << QByteArray(R"({"encoder_offset":40000})");
    QTest::newRow("open_loop") << req(build::openLoop(1, -500)) << QByteArray(R"({"power":-500})");
    QTest::newRow("torque") << req(build::torque(1, 1.6, {}))
                            << QByteArray(R"({"iq_a":1.6,"iq_raw":100})");
    QTest::newRow("torque -32") << req(build::torque(1, -32, {}))
                                << QByteArray(R"({"iq_a":-32.0,"iq_raw":-2000})");
    QTest::newRow("speed (CLI.md)")
        << req(build::speed(1, 100)) << QByteArray(R"({"speed_dps":100.0,"speed_raw":10000})");
    QTest::newRow("speed negative") << req(build::speed(1, -123.45))
                                    << QByteArray(R"({"speed_dps":-123.45,"speed_raw":-12345})");
    QTest::newRow("multi_position") << req(build::multiPosition(1, -720))
                                    << QByteArray(R"({"angle_deg":-720.0,"angle_raw":-72000})");
    QTest::newRow("multi_position_limited")
        << req(build::multiPosition(1, 90, 500))
        << QByteArray(R"({"angle_deg":90.0,"angle_raw":9000,"max_speed_dps":500.0,)"
                      R"("max_speed_raw":50000})");
    QTest::newRow("single_position")
        << req(build::singlePosition(1, SpinDirection::CounterClockwise, 359.99))
        << QByteArray(R"({"direction":"ccw","angle_deg":359.99,"angle_raw":35999})");
    QTest::newRow("single_position_limited")
        << req(build::singlePosition(1, SpinDirection::Clockwise, 0, 42949672.95))
        << QByteArray(R"({"direction":"cw","angle_deg":0.0,"angle_raw":0,)"
                      R"("max_speed_dps":42949672.95,"max_speed_raw":4294967295})");
    QTest::newRow("increment_position") << req(build::incrementPosition(1, -90))
                                        << QByteArray(R"({"angle_deg":-90.0,"angle_raw":-9000})");
    QTest::newRow("increment_position_limited")
        << req(build::incrementPosition(1, 45, 360))
        << QByteArray(R"({"angle_deg":45.0,"angle_raw":4500,"max_speed_dps":360.0,)"
                      R"("max_speed_raw":36000})");
    for (Command c :
         {Command::ReadAccel, Command::ReadEncoder, Command::WriteZeroRom, Command::ReadMultiTurn,
          Command::ReadSingleTurn, Command::ClearAngle, Command::ReadState1, Command::ClearErrors,
          Command::ReadState2, Command::ReadState3, Command::MotorOff, Command::MotorStop,
          Command::MotorRun, Command::ReadModel})
        QTest::newRow(qPrintable(CommandTable::name(c)))
            << req(build::plain(c, 1)) << QByteArray("{}");
}

} // namespace lk::fieldjsontest
