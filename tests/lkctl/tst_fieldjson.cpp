#include "RequestText.h"
#include "protocol/FieldJson.h"
#include "protocol/ProtocolFields.h"
#include "protocol/RequestBuilder.h"
#include "protocol/StreamParser.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QRegularExpression>
#include <QtTest/QtTest>

using namespace lk::protocol;
using lk::lkctl::FieldBuildResult;
using lk::lkctl::FieldValues;
using lk::lkctl::RequestText;

Q_DECLARE_METATYPE(lk::protocol::Request)
Q_DECLARE_METATYPE(lk::protocol::Reply)
Q_DECLARE_METATYPE(lk::protocol::Command)

namespace {

Request req(const BuildResult &r)
{
    if (!r.ok())
        qFatal("test vector refused: %s", qPrintable(r.error.message()));
    return *r.request;
}

Reply reply(Command c, ReplyPayload payload, quint8 id = 1)
{
    return Reply{c, id, std::move(payload)};
}

State2 state2(qint8 t, qint16 torque, bool isPower, qint16 speed, quint16 enc)
{
    State2 s;
    s.temperatureC = t;
    s.torqueRaw = torque;
    s.isPower = isPower;
    s.speedDps = speed;
    s.encoder = enc;
    return s;
}

QByteArray line(const QJsonObject &o)
{
    return FieldJson::toJsonLine(o);
}

QByteArray fromHex(const char *hex)
{
    return QByteArray::fromHex(QByteArray(hex));
}

/// Every JSON line the parser makes of the bytes.
QList<QByteArray> decodeAll(const QByteArray &bytes, const DecodeContext &ctx = {})
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
bool sameJson(const QJsonValue &a, const QJsonValue &b)
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

const char kPidFields[] = R"({"angle_kp":100,"angle_ki":100,"speed_kp":50,"speed_ki":40,)"
                          R"("iq_kp":50,"iq_ki":50})";

} // namespace

class tst_FieldJson : public QObject {
    Q_OBJECT
private slots:
    void requestFields_data();
    void requestFields();
    void requestFieldsCoverEveryCommand();
    void replyFields_data();
    void replyFields();
    void replyFieldsCoverEveryCommand();
    void roundTripThroughText_data();
    void roundTripThroughText();
    void buildRequestRefuses_data();
    void buildRequestRefuses();
    void specRangesMatchBuilders();
    void eventLines_data();
    void eventLines();
    void jsonLineFormatting_data();
    void jsonLineFormatting();
    void hexText();
};

void tst_FieldJson::requestFields_data()
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
    QTest::newRow("torque") << req(build::torque(1, 1.6))
                            << QByteArray(R"({"iq_a":1.6,"iq_raw":100})");
    QTest::newRow("torque -32") << req(build::torque(1, -32))
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

void tst_FieldJson::requestFields()
{
    QFETCH(Request, request);
    QFETCH(QByteArray, expected);
    QCOMPARE(line(FieldJson::requestFields(request)), expected);
}

namespace {
// A value every spec accepts: "cw" for a direction, the first word of a choice, else "1".
QString validText(const FieldSpec &s)
{
    if (s.kind == FieldKind::Direction)
        return QStringLiteral("cw");
    if (s.kind == FieldKind::Choice)
        return s.range.section(QLatin1Char('|'), 0, 0);
    return QStringLiteral("1");
}

// The specs of a command with valid values; a parameter write takes angle_pid's fields.
QList<FieldSpec> specsWithParam(Command command)
{
    QList<FieldSpec> specs = ProtocolFields::ofCommand(command);
    if (command == Command::WriteParamRam || command == Command::WriteParamRom)
        specs.append(ProtocolFields::ofParam(lk::protocol::ParamId::AnglePid));
    return specs;
}
} // namespace

void tst_FieldJson::requestFieldsCoverEveryCommand()
{
    // Every command's request names exactly its specs plus, where scaled, "<field>_raw".
    QSet<int> seen;
    for (const CommandInfo &info : CommandTable::all()) {
        FieldValues values{{QStringLiteral("id"), QStringLiteral("1")}};
        QStringList expectedKeys;
        for (const FieldSpec &s : specsWithParam(info.command)) {
            values.insert(s.name, validText(s));
            expectedKeys << s.name;
            if (s.name == QLatin1String("param"))
                expectedKeys << QStringLiteral("param_id"); // the ParamID byte beside its name
            if (s.kind == FieldKind::Number)
                expectedKeys << QString(s.name).replace(QRegularExpression("_[a-z0-9]+$"),
                                                        QStringLiteral("_raw"));
        }
        const FieldBuildResult r = RequestText::build(info.command, values);
        QVERIFY2(r.ok(), qPrintable(r.message));
        QStringList keys = FieldJson::requestFields(*r.request).keys();
        keys.sort();
        expectedKeys.sort();
        QCOMPARE(keys, expectedKeys);
        seen.insert(int(info.command));
    }
    QCOMPARE(seen.size(), CommandTable::kCount);
}

void tst_FieldJson::replyFields_data()
{
    QTest::addColumn<Reply>("reply");
    QTest::addColumn<QByteArray>("expected");
    const auto pid = PidGains{100, 100, 50, 40, 50, 50};
    QTest::newRow("read_pid") << reply(Command::ReadPid, pid) << QByteArray(kPidFields);
    QTest::newRow("write_pid_rom") << reply(Command::WritePidRom, pid) << QByteArray(kPidFields);
    QTest::newRow("read_accel") << reply(Command::ReadAccel, Acceleration{1000})
                                << QByteArray(R"({"accel_dps2":1000})");
    QTest::newRow("read_encoder")
        << reply(Command::ReadEncoder, EncoderReading{16383, 12000, 4383})
        << QByteArray(R"({"encoder":16383,"encoder_raw":12000,"encoder_offset":4383})");
    QTest::newRow("write_encoder_offset") << reply(Command::WriteEncoderOffset, EncoderOffset{7})
                                          << QByteArray(R"({"encoder_offset":7})");
    QTest::newRow("write_zero_rom echo")
        << reply(Command::WriteZeroRom, ZeroWritten{}) << QByteArray("{}");
    QTest::newRow("write_zero_rom with data") << reply(Command::WriteZeroRom, ZeroWritten{1234})
                                              << QByteArray(R"({"encoder_offset":1234})");
    QTest::newRow("read_multi_turn")
        << reply(Command::ReadMultiTurn, MultiTurnAngle{-3600050})
        << QByteArray(R"({"angle_deg":-36000.5,"angle_raw":-3600050})");
    QTest::newRow("read_single_turn") << reply(Command::ReadSingleTurn, SingleTurnAngle{35999})
                                      << QByteArray(R"({"angle_deg":359.99,"angle_raw":35999})");
    State1 s1;
    s1.temperatureC = 40;
    s1.voltageRaw = 243;
    s1.errorState = 0x09;
    QTest::newRow("read_state1")
        << reply(Command::ReadState1, s1)
        << QByteArray(R"({"temperature_c":40,"voltage_v":24.3,"voltage_raw":243,)"
                      R"("error_state":9,"low_voltage":true,"over_temperature":true})");
    s1.voltageRaw = 120;
    s1.errorState = 0x00;
    QTest::newRow("clear_errors")
        << reply(Command::ClearErrors, s1)
        << QByteArray(R"({"temperature_c":40,"voltage_v":12.0,"voltage_raw":120,)"
                      R"("error_state":0,"low_voltage":false,"over_temperature":false})");
    QTest::newRow("read_state2 iq")
        << reply(Command::ReadState2, state2(31, 500, false, 360, 12288))
        << QByteArray(R"({"temperature_c":31,"iq_a":8.056640625,"iq_raw":500,)"
                      R"("speed_dps":360.0,"encoder":12288})");
    QTest::newRow("read_state2 power")
        << reply(Command::ReadState2, state2(31, 500, true, 360, 12288))
        << QByteArray(R"({"temperature_c":31,"power":500,"speed_dps":360.0,"encoder":12288})");
    QTest::newRow("speed reply negative")
        << reply(Command::Speed, state2(-5, -2048, false, -100, 65535))
        << QByteArray(R"({"temperature_c":-5,"iq_a":-33.0,"iq_raw":-2048,)"
                      R"("speed_dps":-100.0,"encoder":65535})");
    QTest::newRow("read_state3")
        << reply(Command::ReadState3, State3{30, 64, -32, -1, lk::protocol::kPhaseAmpsPerLsb})
        << QByteArray(R"({"temperature_c":30,"ia_a":1.0,"ia_raw":64,"ib_a":-0.5,"ib_raw":-32,)"
                      R"("ic_a":-0.015625,"ic_raw":-1})");
    ModelInfo m;
    m.driverName = QStringLiteral("LKDRV01");
    m.motorName = QStringLiteral("MG4010E-i10");
    m.hardwareRaw = 10;
    m.firmwareRaw = 21;
    QTest::newRow("read_model V2.3")
        << reply(Command::ReadModel, m)
        << QByteArray(R"({"driver_name":"LKDRV01","motor_name":"MG4010E-i10",)"
                      R"("hardware_version":1.0,"hardware_version_raw":10,)"
                      R"("firmware_version":2.1,"firmware_version_raw":21})");
    m.generation = Generation::V2_35;
    m.hardwareRaw = 300;
    m.firmwareRaw = 235;
    m.motorVersionRaw = 7;
    m.motorId = QByteArray::fromHex("0102030405060708090A0BFF");
    QTest::newRow("read_model V2.35")
        << reply(Command::ReadModel, m)
        << QByteArray(R"({"driver_name":"LKDRV01","motor_name":"MG4010E-i10",)"
                      R"("hardware_version":3.0,"hardware_version_raw":300,)"
                      R"("firmware_version":2.35,"firmware_version_raw":235,)"
                      R"("motor_id":"01 02 03 04 05 06 07 08 09 0A 0B FF","motor_version_raw":7})");
    for (Command c :
         {Command::MotorOff, Command::MotorStop, Command::MotorRun, Command::ClearAngle})
        QTest::newRow(qPrintable(CommandTable::name(c)))
            << reply(c, Acknowledged{}) << QByteArray("{}");
}

void tst_FieldJson::replyFields()
{
    QFETCH(Reply, reply);
    QFETCH(QByteArray, expected);
    QCOMPARE(line(FieldJson::replyFields(reply)), expected);
}

void tst_FieldJson::replyFieldsCoverEveryCommand()
{
    // The fields of every command's reply, as decoded from the wire, carry the CLI.md names.
    const QMap<QString, QStringList> names{
        {QStringLiteral("state2"), {"temperature_c", "iq_a", "iq_raw", "speed_dps", "encoder"}},
        {QStringLiteral("state1"),
         {"temperature_c", "voltage_v", "voltage_raw", "error_state", "low_voltage",
          "over_temperature"}},
    };
    for (const CommandInfo &info : CommandTable::all()) {
        const Frame f{quint8(info.command), 1, QByteArray(info.replyLength, '\x01')};
        const ReplyDecodeResult r = decodeReply(f);
        QVERIFY2(r.reply, info.name);
        QStringList keys = FieldJson::replyFields(*r.reply).keys();
        keys.sort();
        QStringList expected;
        const quint8 code = quint8(info.command);
        if (code == 0x9C || (code >= 0xA1 && code <= 0xA8))
            expected = names.value(QStringLiteral("state2"));
        else if (code == 0xA0)
            expected = {"temperature_c", "power", "speed_dps", "encoder"};
        else if (code == 0x9A || code == 0x9B)
            expected = names.value(QStringLiteral("state1"));
        else if (code == 0x9D)
            expected = {"temperature_c", "ia_a", "ia_raw", "ib_a", "ib_raw", "ic_a", "ic_raw"};
        else if (code >= 0x30 && code <= 0x32)
            expected = {"angle_kp", "angle_ki", "speed_kp", "speed_ki", "iq_kp", "iq_ki"};
        else if (code == 0x33 || code == 0x34)
            expected = {"accel_dps2"};
        else if (code == 0x90)
            expected = {"encoder", "encoder_raw", "encoder_offset"};
        else if (code == 0x91)
            expected = {"encoder_offset"};
        else if (code == 0x92 || code == 0x94)
            expected = {"angle_deg", "angle_raw"};
        else if (code == 0x12)
            expected = {"driver_name",          "motor_name",       "hardware_version",
                        "hardware_version_raw", "firmware_version", "firmware_version_raw"};
        else if (code == 0x40) // ParamID 0x01 is not in the table: its bytes are shown raw
            expected = {"param", "param_id", "value_bytes"};
        else if (code == 0x42 || code == 0x44)
            expected = {"param", "param_id", "success", "success_flag"};
        else if (code == 0x8C)
            expected = {"brake_released", "brake_raw"};
        expected.sort();
        QCOMPARE(keys, expected);
    }
}

void tst_FieldJson::roundTripThroughText_data()
{
    requestFields_data();
}

void tst_FieldJson::roundTripThroughText()
{
    // Request -> fields -> text values (as typed on a command line) -> the same request.
    QFETCH(Request, request);
    const QJsonObject fields = FieldJson::requestFields(request);
    FieldValues values{{QStringLiteral("id"), QString::number(request.id)}};
    for (auto it = fields.begin(); it != fields.end(); ++it) {
        if (it.key().endsWith(QLatin1String("_raw")))
            continue;
        values.insert(it.key(), it.value().isString()
                                    ? it.value().toString()
                                    : QString::number(it.value().toDouble(), 'g', 17));
    }
    const FieldBuildResult r = RequestText::build(request.command, values);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.request->encode().toHex(' '), request.encode().toHex(' '));
}

void tst_FieldJson::buildRequestRefuses_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<FieldValues>("values");
    QTest::addColumn<QString>("field"); // empty: not a field's value (unknown name)
    QTest::addColumn<QString>("message");
    const auto id = [](FieldValues v) {
        v.insert(QStringLiteral("id"), QStringLiteral("1"));
        return v;
    };
    QTest::newRow("out of range") << "speed" << id({{"speed_dps", "21474836.48"}}) << "speed_dps"
                                  << "speed_dps must be in -21474836.48..21474836.47 dps "
                                     "(got 21474836.48)";
    QTest::newRow("torque over 32 A") << "torque" << id({{"iq_a", "32.01"}}) << "iq_a"
                                      << "iq_a must be in -32..32 A (got 32.01)";
    QTest::newRow("power") << "open_loop" << id({{"power", "851"}}) << "power"
                           << "power must be in -850..850 (got 851)";
    QTest::newRow("power not integer") << "open_loop" << id({{"power", "1.5"}}) << "power"
                                       << "power must be in -850..850 (got 1.5, not an integer)";
    QTest::newRow("not a number") << "speed" << id({{"speed_dps", "fast"}}) << "speed_dps"
                                  << "speed_dps must be in -21474836.48..21474836.47 dps "
                                     "(got 'fast', not a number)";
    QTest::newRow("nan") << "speed" << id({{"speed_dps", "nan"}}) << "speed_dps"
                         << "speed_dps must be in -21474836.48..21474836.47 dps (got nan)";
    QTest::newRow("missing") << "speed" << id({}) << "speed_dps"
                             << "speed_dps is missing; it must be in -21474836.48..21474836.47 dps";
    QTest::newRow("missing id") << "motor_off" << FieldValues{} << "id"
                                << "id is missing; it must be in 1..32";
    QTest::newRow("id 33") << "motor_off" << FieldValues{{"id", "33"}} << "id"
                           << "id must be in 1..32 (got 33)";
    QTest::newRow("id beyond int") << "motor_off" << FieldValues{{"id", "4294967297"}} << "id"
                                   << "id must be in 1..32 (got 4294967297)";
    QTest::newRow("pid gain beyond int") << "write_pid_ram"
                                         << id({{"angle_kp", "1"},
                                                {"angle_ki", "1"},
                                                {"speed_kp", "1"},
                                                {"speed_ki", "1"},
                                                {"iq_kp", "1"},
                                                {"iq_ki", "-4294967295"}})
                                         << "iq_ki"
                                         << "iq_ki must be in 0..255 (got -4294967295)";
    QTest::newRow("direction") << "single_position" << id({{"direction", "up"}, {"angle_deg", "1"}})
                               << "direction"
                               << "direction must be in cw|ccw (got 'up')";
    QTest::newRow("single angle 360")
        << "single_position" << id({{"direction", "cw"}, {"angle_deg", "360"}}) << "angle_deg"
        << "angle_deg must be in 0..359.99 deg (got 360)";
    QTest::newRow("negative max speed")
        << "multi_position_limited" << id({{"angle_deg", "1"}, {"max_speed_dps", "-1"}})
        << "max_speed_dps"
        << "max_speed_dps must be in 0..42949672.95 dps (got -1)";
    QTest::newRow("unknown field") << "speed" << id({{"speed_dps", "1"}, {"rpm", "5"}}) << ""
                                   << "unknown field rpm for speed (it takes: id, speed_dps)";
    QTest::newRow("max speed on the unlimited command")
        << "multi_position" << id({{"angle_deg", "1"}, {"max_speed_dps", "5"}}) << ""
        << "unknown field max_speed_dps for multi_position (it takes: id, angle_deg)";
    QTest::newRow("unknown command") << "spin" << id({}) << ""
                                     << "unknown command 'spin'";
}

void tst_FieldJson::buildRequestRefuses()
{
    QFETCH(QString, command);
    QFETCH(FieldValues, values);
    QFETCH(QString, field);
    QFETCH(QString, message);
    const FieldBuildResult r = RequestText::build(command, values);
    QVERIFY(!r.ok());
    QCOMPARE(r.message, message);
    QCOMPARE(r.fieldError ? r.fieldError->field : QString(), field);
}

void tst_FieldJson::specRangesMatchBuilders()
{
    // The ranges in the specs (help, "missing" messages) are the builders' own: push each
    // field out of range through the builder and compare what it says.
    const QStringList badIntegers{"-1", "256", "1001", "-1001", "65536"};
    int checked = 0;
    for (const CommandInfo &info : CommandTable::all()) {
        QList<FieldSpec> specs = specsWithParam(info.command);
        specs.prepend(ProtocolFields::idSpec());
        FieldValues valid;
        for (const FieldSpec &s : specs)
            valid.insert(s.name, validText(s));
        QVERIFY2(RequestText::build(info.command, valid).ok(), info.name);
        for (const FieldSpec &s : specs) {
            if (s.kind == FieldKind::Direction || s.kind == FieldKind::Choice)
                continue; // not builder arguments: the builders take enums
            const QStringList bad =
                s.kind == FieldKind::Integer ? badIntegers : QStringList{"1e30", "-1e30"};
            bool refused = false;
            for (const QString &v : bad) {
                FieldValues values = valid;
                values.insert(s.name, v);
                const FieldBuildResult r = RequestText::build(info.command, values);
                if (r.ok())
                    continue;
                refused = true;
                QVERIFY(r.fieldError);
                QCOMPARE(r.fieldError->field, s.name);
                QCOMPARE(r.fieldError->range, s.range);
            }
            QVERIFY2(refused, qPrintable(s.name));
            ++checked;
        }
    }
    // 33 ids, 12 PID gains, accel, offset, power, iq, speed, 1 + 2 multi-position, 1 + 2
    // single-position (direction aside), 1 + 2 increment, 2 x 3 parameter gains (param and
    // brake action aside).
    QCOMPARE(checked, 33 + 12 + 5 + 3 + 3 + 3 + 6);
}

void tst_FieldJson::eventLines_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<bool>("ms");
    QTest::addColumn<QList<QByteArray>>("expected");
    QTest::newRow("CLI.md speed request")
        << fromHex("3EA20104E51027000037") << false
        << QList<QByteArray>{R"({"direction":"request","command":"speed","code":"0xA2","id":1,)"
                             R"("fields":{"speed_dps":100.0,"speed_raw":10000}})"};
    QTest::newRow("CLI.md echo")
        << fromHex("3E800100BF") << false
        << QList<QByteArray>{R"({"direction":"echo","command":"motor_off","code":"0x80","id":1,)"
                             R"("fields":{}})"};
    QTest::newRow("CLI.md bad data checksum")
        << fromHex("3EA40107EA2100000A002C1973") << false
        << QList<QByteArray>{R"({"error":"bad_data_checksum",)"
                             R"("bytes":"3E A4 01 07 EA 21 00 00 0A 00 2C 19 73"})"};
    QTest::newRow("reply MF") << fromHex("3E9C0107E21FF40168010030AD") << false
                              << QList<QByteArray>{
                                     R"({"direction":"reply","command":"read_state2",)"
                                     R"("code":"0x9C","id":1,"fields":{"temperature_c":31,)"
                                     R"("iq_a":8.056640625,"iq_raw":500,"speed_dps":360.0,)"
                                     R"("encoder":12288}})"};
    QTest::newRow("reply MS") << fromHex("3E9C0107E21FF40168010030AD") << true
                              << QList<QByteArray>{
                                     R"({"direction":"reply","command":"read_state2",)"
                                     R"("code":"0x9C","id":1,"fields":{"temperature_c":31,)"
                                     R"("power":500,"speed_dps":360.0,"encoder":12288}})"};
    QTest::newRow("write echo carries the values")
        << fromHex("3E910102D2409CDC") << false
        << QList<QByteArray>{R"({"direction":"echo","command":"write_encoder_offset",)"
                             R"("code":"0x91","id":1,"fields":{"encoder_offset":40000}})"};
    QTest::newRow("faults") << fromHex("00113E9C0100003E550100943E") << false
                            << QList<QByteArray>{R"({"error":"garbage","bytes":"00 11"})",
                                                 R"({"error":"bad_header_checksum",)"
                                                 R"("bytes":"3E 9C 01 00 00"})",
                                                 R"({"error":"unknown_command",)"
                                                 R"("bytes":"3E 55 01 00 94"})",
                                                 R"({"error":"truncated","bytes":"3E"})"};
}

void tst_FieldJson::eventLines()
{
    QFETCH(QByteArray, bytes);
    QFETCH(bool, ms);
    QFETCH(QList<QByteArray>, expected);
    DecodeContext ctx;
    ctx.series = ms ? Series::MS : Series::MF;
    const QList<QByteArray> lines = decodeAll(bytes, ctx);
    QCOMPARE(lines, expected);
    for (const QByteArray &l : lines) {
        // Whatever the writer does with order and decimals, it is JSON a parser reads back.
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(l, &error);
        QCOMPARE(error.error, QJsonParseError::NoError);
        QCOMPARE(FieldJson::isError(doc.object()), l.startsWith(R"({"error")"));
    }
}

void tst_FieldJson::jsonLineFormatting_data()
{
    QTest::addColumn<QJsonObject>("object");
    QTest::addColumn<QByteArray>("expected");
    QTest::newRow("CLI.md key order")
        << QJsonObject{{"fields", QJsonObject{}},
                       {"id", 3},
                       {"code", "0x80"},
                       {"command", "motor_off"},
                       {"direction", "echo"}}
        << QByteArray(R"({"direction":"echo","command":"motor_off","code":"0x80","id":3,)"
                      R"("fields":{}})");
    QTest::newRow("error first") << QJsonObject{{"bytes", "00"}, {"error", "garbage"}}
                                 << QByteArray(R"({"error":"garbage","bytes":"00"})");
    QTest::newRow("reals keep a decimal point, integers do not")
        << QJsonObject{{"speed_dps", 100.0}, {"speed_raw", 10000}, {"angle_deg", -0.01}}
        << QByteArray(R"({"speed_dps":100.0,"speed_raw":10000,"angle_deg":-0.01})");
    QTest::newRow("large real") << QJsonObject{{"angle_deg", 9.0e16}}
                                << QByteArray(R"({"angle_deg":9e+16})");
    QTest::newRow("int64 raw exact") << QJsonObject{{"angle_raw", qint64(-9000000000000000000LL)}}
                                     << QByteArray(R"({"angle_raw":-9000000000000000000})");
    QTest::newRow("unknown keys sorted after known")
        << QJsonObject{{"zeta", 1}, {"alpha", true}, {"encoder", 5}}
        << QByteArray(R"({"encoder":5,"alpha":true,"zeta":1})");
    QTest::newRow("string escaping")
        << QJsonObject{{"driver_name", QString::fromUtf8("a\"b\\c\n\x01é")}}
        << QByteArray(R"({"driver_name":"a\"b\\c\n\u0001)") + QByteArray("\xc3\xa9\"}");
    QTest::newRow("arrays and null") << QJsonObject{{"x", QJsonArray{1, QJsonValue(), "s"}}}
                                     << QByteArray(R"({"x":[1,null,"s"]})");
}

void tst_FieldJson::jsonLineFormatting()
{
    QFETCH(QJsonObject, object);
    QFETCH(QByteArray, expected);
    const QByteArray got = FieldJson::toJsonLine(object);
    QCOMPARE(got, expected);
    QVERIFY(sameJson(QJsonDocument::fromJson(got).object(), object));
}

void tst_FieldJson::hexText()
{
    QCOMPARE(FieldJson::hexText(QByteArray()), QString());
    QCOMPARE(FieldJson::hexText(fromHex("3ea4ff00")), QStringLiteral("3E A4 FF 00"));
    QCOMPARE(FieldJson::errorObject(ParseError::Truncated, fromHex("3e9c")),
             (QJsonObject{{"error", "truncated"}, {"bytes", "3E 9C"}}));
}

QTEST_APPLESS_MAIN(tst_FieldJson)
#include "tst_fieldjson.moc"
