#include "protocol/RequestBuilder.h"

#include "ProtocolTestUtil.h"

#include <QtTest/QTest>

#include <cmath>
#include <functional>
#include <limits>

using lk::protocol::BuildResult;
using lk::protocol::Command;
using lk::protocol::CommandTable;
using lk::protocol::SpinDirection;
using lk::test::hex;
using lk::test::spaced;
namespace build = lk::protocol::build;

using BuildFn = std::function<BuildResult()>;
Q_DECLARE_METATYPE(BuildFn)

/// Request builders: wire vectors for every command (by hand from the spec and docs/ERRATA.md),
/// range edges accepted, just-outside values refused with the right field name.
class tst_RequestBuilder : public QObject {
    Q_OBJECT

private slots:
    void vectors_data();
    void vectors();
    void refused_data();
    void refused();
    void plainRefusesCommandsWithData_data();
    void plainRefusesCommandsWithData();
    void checkId_data();
    void checkId();
    void pidOverloadsAgree();
    void fieldErrorMessage();
    // Last on purpose: it exercises a command value outside the enum's named values.
    void plainRefusesUnknownCommandValue();
};

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr auto kCw = SpinDirection::Clockwise;
constexpr auto kCcw = SpinDirection::CounterClockwise;

void addVector(const char *name, const BuildFn &fn, const char *wire)
{
    QTest::newRow(name) << fn << hex(wire);
}

void addPlainVectors()
{
    const auto plain = [](Command c, int id) {
        return BuildFn([=] { return build::plain(c, id); });
    };
    addVector("read_pid", plain(Command::ReadPid, 1), "3E 30 01 00 6F");
    addVector("read_accel", plain(Command::ReadAccel, 1), "3E 33 01 00 72");
    addVector("read_encoder", plain(Command::ReadEncoder, 1), "3E 90 01 00 CF");
    addVector("write_zero_rom (spec example)", plain(Command::WriteZeroRom, 1), "3E 19 01 00 58");
    addVector("read_multi_turn", plain(Command::ReadMultiTurn, 1), "3E 92 01 00 D1");
    addVector("read_single_turn", plain(Command::ReadSingleTurn, 1), "3E 94 01 00 D3");
    addVector("clear_angle", plain(Command::ClearAngle, 1), "3E 95 01 00 D4");
    addVector("read_state1", plain(Command::ReadState1, 1), "3E 9A 01 00 D9");
    addVector("clear_errors", plain(Command::ClearErrors, 1), "3E 9B 01 00 DA");
    addVector("read_state2", plain(Command::ReadState2, 1), "3E 9C 01 00 DB");
    addVector("read_state3", plain(Command::ReadState3, 1), "3E 9D 01 00 DC");
    addVector("motor_off (spec example)", plain(Command::MotorOff, 1), "3E 80 01 00 BF");
    addVector("motor_stop (spec example)", plain(Command::MotorStop, 1), "3E 81 01 00 C0");
    addVector("motor_run (spec example)", plain(Command::MotorRun, 1), "3E 88 01 00 C7");
    addVector("read_model (spec example)", plain(Command::ReadModel, 1), "3E 12 01 00 51");
    addVector("read_state2 id 32", plain(Command::ReadState2, 32), "3E 9C 20 00 FA");
    addVector("motor_off id 32", plain(Command::MotorOff, 32), "3E 80 20 00 DE");
    addVector("read_model id 32", plain(Command::ReadModel, 32), "3E 12 20 00 70");
}

void addSetupVectors()
{
    addVector(
        "write_pid_ram", [] { return build::writePid(1, 100, 50, 40, 30, 50, 50, false); },
        "3E 31 01 06 76 64 32 28 1E 32 32 40");
    addVector(
        "write_pid_ram all 0", [] { return build::writePid(1, 0, 0, 0, 0, 0, 0, false); },
        "3E 31 01 06 76 00 00 00 00 00 00 00");
    addVector(
        "write_pid_rom all 255 id 32",
        [] { return build::writePid(32, 255, 255, 255, 255, 255, 255, true); },
        "3E 32 20 06 96 FF FF FF FF FF FF FA");
    addVector(
        "write_pid_rom field order", [] { return build::writePid(7, 1, 2, 3, 4, 5, 254, true); },
        "3E 32 07 06 7D 01 02 03 04 05 FE 0D");
    // 0x34: 10 bytes on the wire, data checksum at DATA[9] (ERRATA).
    addVector(
        "write_accel_ram 0", [] { return build::writeAcceleration(1, 0); },
        "3E 34 01 04 77 00 00 00 00 00");
    addVector(
        "write_accel_ram 2147483647", [] { return build::writeAcceleration(1, 2147483647); },
        "3E 34 01 04 77 FF FF FF 7F 7C");
    addVector(
        "write_accel_ram 10000 id 32", [] { return build::writeAcceleration(32, 10000); },
        "3E 34 20 04 96 10 27 00 00 37");
    // 0x91: the data checksum covers DATA[5..6] (ERRATA).
    addVector(
        "write_encoder_offset 0", [] { return build::writeEncoderOffset(1, 0); },
        "3E 91 01 02 D2 00 00 00");
    addVector(
        "write_encoder_offset 65535", [] { return build::writeEncoderOffset(1, 65535); },
        "3E 91 01 02 D2 FF FF FE");
    addVector(
        "write_encoder_offset 0x1234 id 32", [] { return build::writeEncoderOffset(32, 0x1234); },
        "3E 91 20 02 F1 34 12 46");
}

void addCurrentAndSpeedVectors()
{
    addVector(
        "open_loop -850", [] { return build::openLoop(1, -850); }, "3E A0 01 02 E1 AE FC AA");
    addVector(
        "open_loop 850", [] { return build::openLoop(1, 850); }, "3E A0 01 02 E1 52 03 55");
    addVector(
        "open_loop -1", [] { return build::openLoop(1, -1); }, "3E A0 01 02 E1 FF FF FE");
    addVector(
        "open_loop 0 id 32", [] { return build::openLoop(32, 0); }, "3E A0 20 02 00 00 00 00");
    addVector(
        "torque -32 A = -2000", [] { return build::torque(1, -32.0, {}); },
        "3E A1 01 02 E2 30 F8 28");
    addVector(
        "torque 32 A = 2000", [] { return build::torque(1, 32.0, {}); }, "3E A1 01 02 E2 D0 07 D7");
    addVector(
        "torque -16 A = -1000", [] { return build::torque(1, -16.0, {}); },
        "3E A1 01 02 E2 18 FC 14");
    addVector(
        "torque 0.5 A rounds to 31", [] { return build::torque(1, 0.5, {}); },
        "3E A1 01 02 E2 1F 00 1F");
    addVector(
        "torque 1.6 A id 32 = 100", [] { return build::torque(32, 1.6, {}); },
        "3E A1 20 02 01 64 00 64");
    addVector(
        "speed 100 dps", [] { return build::speed(1, 100.0); }, "3E A2 01 04 E5 10 27 00 00 37");
    addVector(
        "speed -100 dps", [] { return build::speed(1, -100.0); }, "3E A2 01 04 E5 F0 D8 FF FF C6");
    addVector(
        "speed int32 max", [] { return build::speed(1, 21474836.47); },
        "3E A2 01 04 E5 FF FF FF 7F 7C");
    addVector(
        "speed int32 min", [] { return build::speed(1, -21474836.48); },
        "3E A2 01 04 E5 00 00 00 80 80");
    addVector(
        "speed 0 id 32", [] { return build::speed(32, 0.0); }, "3E A2 20 04 04 00 00 00 00 00");
}

void addPositionVectors()
{
    addVector(
        "multi_position 90", [] { return build::multiPosition(1, 90.0); },
        "3E A3 01 08 EA 28 23 00 00 00 00 00 00 4B");
    addVector(
        "multi_position -90", [] { return build::multiPosition(1, -90.0); },
        "3E A3 01 08 EA D8 DC FF FF FF FF FF FF AE");
    addVector(
        "multi_position 0 id 32", [] { return build::multiPosition(32, 0.0); },
        "3E A3 20 08 09 00 00 00 00 00 00 00 00 00");
    addVector(
        "multi_position 9e16 deg", [] { return build::multiPosition(1, 9.0e16); },
        "3E A3 01 08 EA 00 00 84 E2 50 6C E6 7C 84");
    addVector(
        "multi_position -9e16 deg", [] { return build::multiPosition(1, -9.0e16); },
        "3E A3 01 08 EA 00 00 7C 1D AF 93 19 83 77");
    addVector(
        "multi_position_limited 360 / 500", [] { return build::multiPosition(1, 360.0, 500.0); },
        "3E A4 01 0C EF A0 8C 00 00 00 00 00 00 50 C3 00 00 3F");
    addVector(
        "multi_position_limited -720 / max speed 0",
        [] { return build::multiPosition(1, -720.0, 0.0); },
        "3E A4 01 0C EF C0 E6 FE FF FF FF FF FF 00 00 00 00 9F");
    addVector(
        "multi_position_limited uint32 max speed",
        [] { return build::multiPosition(1, 0.01, 42949672.95); },
        "3E A4 01 0C EF 01 00 00 00 00 00 00 00 FF FF FF FF FD");
}

void addSingleAndIncrementVectors()
{
    // 0xA5/0xA6: direction byte, uint16 angle, one 0x00 pad [, uint32 max speed] (ERRATA).
    addVector(
        "single_position cw 0", [] { return build::singlePosition(1, kCw, 0.0); },
        "3E A5 01 04 E8 00 00 00 00 00");
    addVector(
        "single_position ccw 359.99", [] { return build::singlePosition(1, kCcw, 359.99); },
        "3E A5 01 04 E8 01 9F 8C 00 2C");
    addVector(
        "single_position cw 90.5 id 32", [] { return build::singlePosition(32, kCw, 90.5); },
        "3E A5 20 04 07 00 5A 23 00 7D");
    addVector(
        "single_position_limited cw 180 / 100",
        [] { return build::singlePosition(1, kCw, 180.0, 100.0); },
        "3E A6 01 08 ED 00 50 46 00 10 27 00 00 CD");
    addVector(
        "single_position_limited ccw 359.99 / 0",
        [] { return build::singlePosition(1, kCcw, 359.99, 0.0); },
        "3E A6 01 08 ED 01 9F 8C 00 00 00 00 00 2C");
    // 0xA7: LEN 4 (ERRATA; the V2.3 spec says 3).
    addVector(
        "increment_position 90", [] { return build::incrementPosition(1, 90.0); },
        "3E A7 01 04 EA 28 23 00 00 4B");
    addVector(
        "increment_position -90", [] { return build::incrementPosition(1, -90.0); },
        "3E A7 01 04 EA D8 DC FF FF B2");
    addVector(
        "increment_position int32 max", [] { return build::incrementPosition(1, 21474836.47); },
        "3E A7 01 04 EA FF FF FF 7F 7C");
    addVector(
        "increment_position int32 min id 32",
        [] { return build::incrementPosition(32, -21474836.48); }, "3E A7 20 04 09 00 00 00 80 80");
    addVector(
        "increment_position_limited -45 / 200",
        [] { return build::incrementPosition(1, -45.0, 200.0); },
        "3E A8 01 08 EF 6C EE FF FF 20 4E 00 00 C6");
    addVector(
        "increment_position_limited 0 / uint32 max id 32",
        [] { return build::incrementPosition(32, 0.0, 42949672.95); },
        "3E A8 20 08 0E 00 00 00 00 FF FF FF FF FC");
}
} // namespace

void tst_RequestBuilder::vectors_data()
{
    QTest::addColumn<BuildFn>("buildFn");
    QTest::addColumn<QByteArray>("wire");
    addPlainVectors();
    addSetupVectors();
    addCurrentAndSpeedVectors();
    addPositionVectors();
    addSingleAndIncrementVectors();
}

void tst_RequestBuilder::vectors()
{
    QFETCH(BuildFn, buildFn);
    QFETCH(QByteArray, wire);
    const BuildResult r = buildFn();
    QVERIFY2(r.ok(), qPrintable(r.error.message()));
    QCOMPARE(spaced(r.request->encode()), spaced(wire));
    // The typed request agrees with the wire: command code, id and LEN.
    QCOMPARE(int(r.request->command), int(quint8(wire[1])));
    QCOMPARE(int(r.request->id), int(quint8(wire[2])));
    const lk::protocol::Frame f = r.request->toFrame();
    QCOMPARE(f.data.size(), qsizetype(quint8(wire[3])));
    QCOMPARE(int(CommandTable::info(r.request->command).requestLength), int(quint8(wire[3])));
}

namespace {
void addRefused(const char *name, const BuildFn &fn, const char *field)
{
    QTest::newRow(name) << fn << QString::fromLatin1(field);
}

void addIdRefusals()
{
    const int badIds[] = {0, 33, -1, 255, 256, 257, std::numeric_limits<int>::min()};
    for (int id : badIds) {
        QTest::addRow("plain id %d", id)
            << BuildFn([id] { return build::plain(Command::MotorOff, id); }) << "id";
        QTest::addRow("torque id %d", id)
            << BuildFn([id] { return build::torque(id, 1.0, {}); }) << "id";
    }
    addRefused(
        "pid id 0", [] { return build::writePid(0, 1, 1, 1, 1, 1, 1, false); }, "id");
    addRefused(
        "accel id 33", [] { return build::writeAcceleration(33, 1); }, "id");
    addRefused(
        "encoder offset id 0", [] { return build::writeEncoderOffset(0, 1); }, "id");
    addRefused(
        "open_loop id 33", [] { return build::openLoop(33, 1); }, "id");
    addRefused(
        "speed id 0", [] { return build::speed(0, 1); }, "id");
    addRefused(
        "multi id 33", [] { return build::multiPosition(33, 1); }, "id");
    addRefused(
        "multi limited id 0", [] { return build::multiPosition(0, 1, 1); }, "id");
    addRefused(
        "single id 33", [] { return build::singlePosition(33, kCw, 1); }, "id");
    addRefused(
        "single limited id 0", [] { return build::singlePosition(0, kCw, 1, 1); }, "id");
    addRefused(
        "increment id 33", [] { return build::incrementPosition(33, 1); }, "id");
    addRefused(
        "increment limited id 0", [] { return build::incrementPosition(0, 1, 1); }, "id");
    // The id is checked before the value: both bad names the id.
    addRefused(
        "torque id 0 and 99 A", [] { return build::torque(0, 99.0, {}); }, "id");
}

void addValueRefusals()
{
    addRefused(
        "torque 32.02 A", [] { return build::torque(1, 32.02, {}); }, "iq_a");
    addRefused(
        "torque -32.02 A", [] { return build::torque(1, -32.02, {}); }, "iq_a");
    addRefused(
        "torque NaN", [] { return build::torque(1, kNaN, {}); }, "iq_a");
    addRefused(
        "torque +inf", [] { return build::torque(1, kInf, {}); }, "iq_a");
    addRefused(
        "torque -inf", [] { return build::torque(1, -kInf, {}); }, "iq_a");
    addRefused(
        "open_loop 851 (V2.35 allows +-850)", [] { return build::openLoop(1, 851); }, "power");
    addRefused(
        "open_loop -1000 (V2.3 allowed it)", [] { return build::openLoop(1, -1000); }, "power");
    addRefused(
        "open_loop 65536 (wraps to 0 in int16)", [] { return build::openLoop(1, 65536); }, "power");
    addRefused(
        "speed int32 max + 0.01", [] { return build::speed(1, 21474836.48); }, "speed_dps");
    addRefused(
        "speed int32 min - 0.01", [] { return build::speed(1, -21474836.49); }, "speed_dps");
    addRefused(
        "speed NaN", [] { return build::speed(1, kNaN); }, "speed_dps");
    addRefused(
        "speed inf", [] { return build::speed(1, kInf); }, "speed_dps");
    addRefused(
        "accel -1", [] { return build::writeAcceleration(1, -1); }, "accel_dps2");
    addRefused(
        "accel 2147483648", [] { return build::writeAcceleration(1, 2147483648LL); }, "accel_dps2");
    addRefused(
        "encoder offset -1", [] { return build::writeEncoderOffset(1, -1); }, "encoder_offset");
    addRefused(
        "encoder offset 65536", [] { return build::writeEncoderOffset(1, 65536); },
        "encoder_offset");
    const char *pidFields[] = {"angle_kp", "angle_ki", "speed_kp", "speed_ki", "iq_kp", "iq_ki"};
    for (int field = 0; field < 6; ++field) {
        for (int bad : {256, -1}) {
            QTest::addRow("pid %s %d", pidFields[field], bad) << BuildFn([field, bad] {
                int g[6] = {10, 20, 30, 40, 50, 60};
                g[field] = bad;
                return build::writePid(1, g[0], g[1], g[2], g[3], g[4], g[5], field % 2);
            }) << pidFields[field];
        }
    }
}

void addPositionRefusals()
{
    addRefused(
        "single 360", [] { return build::singlePosition(1, kCw, 360.0); }, "angle_deg");
    addRefused(
        "single -0.01", [] { return build::singlePosition(1, kCw, -0.01); }, "angle_deg");
    addRefused(
        "single NaN", [] { return build::singlePosition(1, kCcw, kNaN); }, "angle_deg");
    addRefused(
        "single inf", [] { return build::singlePosition(1, kCcw, kInf); }, "angle_deg");
    addRefused(
        "single limited 360", [] { return build::singlePosition(1, kCw, 360.0, 10.0); },
        "angle_deg");
    addRefused(
        "single limited max speed -1", [] { return build::singlePosition(1, kCw, 10.0, -1.0); },
        "max_speed_dps");
    addRefused(
        "single limited max speed NaN", [] { return build::singlePosition(1, kCw, 10.0, kNaN); },
        "max_speed_dps");
    addRefused(
        "multi NaN", [] { return build::multiPosition(1, kNaN); }, "angle_deg");
    addRefused(
        "multi -inf", [] { return build::multiPosition(1, -kInf); }, "angle_deg");
    addRefused(
        "multi 1e17 deg overflows int64 of 0.01 deg",
        [] { return build::multiPosition(1, 1.0e17); }, "angle_deg");
    addRefused(
        "multi limited max speed -0.01", [] { return build::multiPosition(1, 10.0, -0.01); },
        "max_speed_dps");
    addRefused(
        "multi limited max speed -1", [] { return build::multiPosition(1, 10.0, -1.0); },
        "max_speed_dps");
    addRefused(
        "multi limited max speed inf", [] { return build::multiPosition(1, 10.0, kInf); },
        "max_speed_dps");
    addRefused(
        "multi limited max speed uint32 max + 0.01",
        [] { return build::multiPosition(1, 10.0, 42949672.96); }, "max_speed_dps");
    addRefused(
        "increment NaN", [] { return build::incrementPosition(1, kNaN); }, "angle_deg");
    addRefused(
        "increment int32 max + 0.01", [] { return build::incrementPosition(1, 21474836.48); },
        "angle_deg");
    addRefused(
        "increment int32 min - 0.01", [] { return build::incrementPosition(1, -21474836.49); },
        "angle_deg");
    addRefused(
        "increment limited max speed -1", [] { return build::incrementPosition(1, 10.0, -1.0); },
        "max_speed_dps");
    addRefused(
        "increment limited max speed NaN", [] { return build::incrementPosition(1, 10.0, kNaN); },
        "max_speed_dps");
}
} // namespace

void tst_RequestBuilder::refused_data()
{
    QTest::addColumn<BuildFn>("buildFn");
    QTest::addColumn<QString>("field");
    addIdRefusals();
    addValueRefusals();
    addPositionRefusals();
}

void tst_RequestBuilder::refused()
{
    QFETCH(BuildFn, buildFn);
    QFETCH(QString, field);
    const BuildResult r = buildFn();
    if (r.ok())
        QFAIL(qPrintable(QStringLiteral("accepted, built ") + spaced(r.request->encode())));
    QCOMPARE(r.error.field, field);
    QVERIFY(!r.error.range.isEmpty());
    QVERIFY(r.error.message().contains(field));
}

void tst_RequestBuilder::plainRefusesCommandsWithData_data()
{
    QTest::addColumn<int>("code");
    // Every command whose request carries data (CLI.md / ERRATA lengths).
    const int withData[] = {0x31, 0x32, 0x34, 0x91, 0xA0, 0xA1, 0xA2,
                            0xA3, 0xA4, 0xA5, 0xA6, 0xA7, 0xA8};
    for (int c : withData)
        QTest::newRow(qPrintable(CommandTable::codeText(quint8(c)))) << c;
}

void tst_RequestBuilder::plainRefusesCommandsWithData()
{
    QFETCH(int, code);
    const BuildResult r = build::plain(static_cast<Command>(code), 1);
    QVERIFY(!r.ok());
    QCOMPARE(r.error.field, QStringLiteral("command"));
}

void tst_RequestBuilder::checkId_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<bool>("ok");
    QTest::newRow("min int") << std::numeric_limits<int>::min() << false;
    QTest::newRow("-1") << -1 << false;
    QTest::newRow("0") << 0 << false;
    QTest::newRow("1") << 1 << true;
    QTest::newRow("2") << 2 << true;
    QTest::newRow("31") << 31 << true;
    QTest::newRow("32") << 32 << true;
    QTest::newRow("33") << 33 << false;
    QTest::newRow("256 (0 as a byte)") << 256 << false;
    QTest::newRow("max int") << std::numeric_limits<int>::max() << false;
}

void tst_RequestBuilder::checkId()
{
    QFETCH(int, id);
    QFETCH(bool, ok);
    const std::optional<lk::protocol::FieldError> e = build::checkId(id);
    QCOMPARE(!e.has_value(), ok);
    if (e)
        QCOMPARE(e->field, QStringLiteral("id"));
}

void tst_RequestBuilder::pidOverloadsAgree()
{
    const lk::protocol::PidGains g{1, 2, 3, 4, 5, 254};
    const BuildResult a = build::writePid(7, g, true);
    const BuildResult b = build::writePid(7, 1, 2, 3, 4, 5, 254, true);
    QVERIFY(a.ok() && b.ok());
    QCOMPARE(a.request->encode(), b.request->encode());
    QCOMPARE(spaced(a.request->encode()), spaced(hex("3E 32 07 06 7D 01 02 03 04 05 FE 0D")));
    QCOMPARE(int(build::writePid(7, g, false).request->command), 0x31);
}

void tst_RequestBuilder::fieldErrorMessage()
{
    const BuildResult r = build::torque(1, 40.0, {});
    QVERIFY(!r.ok());
    const QString m = r.error.message();
    QVERIFY2(m.contains(QStringLiteral("iq_a")), qPrintable(m));
    QVERIFY2(m.contains(r.error.range), qPrintable(m));
    QVERIFY2(m.contains(QStringLiteral("40")), qPrintable(m));
}

void tst_RequestBuilder::plainRefusesUnknownCommandValue()
{
    // A byte read from the wire and cast to Command (e.g. 0x89, which the vendor tool uses
    // but no document defines) must be refused like any other bad argument, not dereference
    // a missing table entry.
    const BuildResult r = build::plain(static_cast<Command>(0x89), 1);
    QVERIFY(!r.ok());
    QCOMPARE(r.error.field, QStringLiteral("command"));
}

QTEST_APPLESS_MAIN(tst_RequestBuilder)
#include "tst_requestbuilder.moc"
