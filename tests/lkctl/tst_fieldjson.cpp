// FieldJson: the fields of every request and reply as JSON (the lkctl --json contract).

#include "FieldJsonTestUtil.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QRegularExpression>
#include <QtTest/QtTest>

using namespace lk::protocol;
using namespace lk::fieldjsontest;

class tst_FieldJson : public QObject {
    Q_OBJECT
private slots:
    void requestFields_data();
    void requestFields();
    void replyFields_data();
    void replyFields();
    void replyFieldsCoverEveryCommand();
};

void tst_FieldJson::requestFields_data()
{
    addRequestRows();
}

void tst_FieldJson::requestFields()
{
    QFETCH(Request, request);
    QFETCH(QByteArray, expected);
    QCOMPARE(line(FieldJson::requestFields(request)), expected);
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
        if (info.canOnly) // CAN V2.36's 0xC0/0xC1: lkctl encode/decode work on RS485 frames
            continue;
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

QTEST_APPLESS_MAIN(tst_FieldJson)
#include "tst_fieldjson.moc"
