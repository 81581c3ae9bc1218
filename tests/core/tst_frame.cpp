#include "protocol/Checksum.h"
#include "protocol/Frame.h"

#include "ProtocolTestUtil.h"

#include <QtTest/QTest>

using lk::protocol::Frame;
using lk::protocol::FrameDirection;
using lk::test::hex;

/// Frame encoding, checksums (& 0xFF, bytes >= 0x80) and direction from the layout.
class tst_Frame : public QObject {
    Q_OBJECT

private slots:
    void encode_data();
    void encode();
    void checksums_data();
    void checksums();
    void direction_data();
    void direction();
    void directionName_data();
    void directionName();
    void equality();

private:
    static void addEveryCommandRows();
};

void tst_Frame::encode_data()
{
    QTest::addColumn<int>("command");
    QTest::addColumn<int>("id");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<QByteArray>("wire");

    // Worked examples of the spec and CLI.md.
    QTest::newRow("motor_off id 1") << 0x80 << 1 << QByteArray() << hex("3E 80 01 00 BF");
    QTest::newRow("motor_stop id 1") << 0x81 << 1 << QByteArray() << hex("3E 81 01 00 C0");
    QTest::newRow("motor_run id 1") << 0x88 << 1 << QByteArray() << hex("3E 88 01 00 C7");
    QTest::newRow("write_zero_rom id 1") << 0x19 << 1 << QByteArray() << hex("3E 19 01 00 58");
    QTest::newRow("read_model id 1") << 0x12 << 1 << QByteArray() << hex("3E 12 01 00 51");
    // Header checksum that wraps: 3E + A8 + 20 + 08 = 0x10E.
    QTest::newRow("header sum wraps") << 0xA8 << 32 << hex("00 00 00 00 FF FF FF FF")
                                      << hex("3E A8 20 08 0E 00 00 00 00 FF FF FF FF FC");
    // iq -1 = FF FF: sum 0x1FE; & 0xFF = FE, while % 255 would give 00.
    QTest::newRow("negative iq, & not % 255")
        << 0xA1 << 1 << hex("FF FF") << hex("3E A1 01 02 E2 FF FF FE");
    QTest::newRow("torque -32 A") << 0xA1 << 1 << hex("30 F8") << hex("3E A1 01 02 E2 30 F8 28");
    QTest::newRow("speed -100 dps")
        << 0xA2 << 1 << hex("F0 D8 FF FF") << hex("3E A2 01 04 E5 F0 D8 FF FF C6");
    QTest::newRow("multi_position -90 deg") << 0xA3 << 1 << hex("D8 DC FF FF FF FF FF FF")
                                            << hex("3E A3 01 08 EA D8 DC FF FF FF FF FF FF AE");
    // Sum of 6 x 0xFF = 0x5FA; % 255 would give 0.
    QTest::newRow("pid 6 x 255") << 0x32 << 32 << hex("FF FF FF FF FF FF")
                                 << hex("3E 32 20 06 96 FF FF FF FF FF FF FA");
    QTest::newRow("all-zero data keeps its checksum byte")
        << 0x31 << 1 << QByteArray(6, '\0') << hex("3E 31 01 06 76 00 00 00 00 00 00 00");
    // 60 bytes of 0xFF: data sum 60 * 255 = 0x3BC4; header 3E + 9C + 01 + 3C = 0x117.
    QByteArray longData(60, char(0xFF));
    QTest::newRow("60 bytes of 0xFF")
        << 0x9C << 1 << longData << hex("3E 9C 01 3C 17") + longData + hex("C4");
    addEveryCommandRows();
    QTest::newRow("unknown command still encodes")
        << 0x89 << 1 << QByteArray() << hex("3E 89 01 00 C8");
}

void tst_Frame::addEveryCommandRows()
{
    // One frame of every command, by hand (requests; replies for the read-only answers).
    const struct {
        const char *name;
        int code;
        const char *data;
        const char *wire;
    } every[] = {
        {"read_pid", 0x30, "", "3E 30 01 00 6F"},
        {"write_pid_ram", 0x31, "64 32 28 1E 32 32", "3E 31 01 06 76 64 32 28 1E 32 32 40"},
        {"write_pid_rom", 0x32, "01 02 03 04 05 FE", "3E 32 01 06 77 01 02 03 04 05 FE 0D"},
        {"read_accel", 0x33, "", "3E 33 01 00 72"},
        {"write_accel_ram", 0x34, "FF FF FF 7F", "3E 34 01 04 77 FF FF FF 7F 7C"},
        {"read_encoder", 0x90, "", "3E 90 01 00 CF"},
        {"write_encoder_offset", 0x91, "FF FF", "3E 91 01 02 D2 FF FF FE"},
        {"write_zero_rom reply LEN 2", 0x19, "45 23", "3E 19 01 02 5A 45 23 68"},
        {"read_multi_turn", 0x92, "", "3E 92 01 00 D1"},
        {"read_single_turn", 0x94, "", "3E 94 01 00 D3"},
        {"clear_angle", 0x95, "", "3E 95 01 00 D4"},
        {"read_state1", 0x9A, "", "3E 9A 01 00 D9"},
        {"clear_errors", 0x9B, "", "3E 9B 01 00 DA"},
        {"read_state2", 0x9C, "", "3E 9C 01 00 DB"},
        {"read_state3", 0x9D, "", "3E 9D 01 00 DC"},
        {"open_loop", 0xA0, "18 FC", "3E A0 01 02 E1 18 FC 14"},
        {"torque", 0xA1, "D0 07", "3E A1 01 02 E2 D0 07 D7"},
        {"speed", 0xA2, "FF FF FF 7F", "3E A2 01 04 E5 FF FF FF 7F 7C"},
        {"multi_position", 0xA3, "28 23 00 00 00 00 00 00",
         "3E A3 01 08 EA 28 23 00 00 00 00 00 00 4B"},
        {"multi_position_limited", 0xA4, "A0 8C 00 00 00 00 00 00 50 C3 00 00",
         "3E A4 01 0C EF A0 8C 00 00 00 00 00 00 50 C3 00 00 3F"},
        {"single_position", 0xA5, "01 9F 8C 00", "3E A5 01 04 E8 01 9F 8C 00 2C"},
        {"single_position_limited", 0xA6, "00 50 46 00 10 27 00 00",
         "3E A6 01 08 ED 00 50 46 00 10 27 00 00 CD"},
        {"increment_position", 0xA7, "D8 DC FF FF", "3E A7 01 04 EA D8 DC FF FF B2"},
        {"increment_position_limited", 0xA8, "6C EE FF FF 20 4E 00 00",
         "3E A8 01 08 EF 6C EE FF FF 20 4E 00 00 C6"},
        {"read_state2 reply", 0x9C, "1E 00 08 0C FE FF 3F",
         "3E 9C 01 07 E2 1E 00 08 0C FE FF 3F 6E"},
    };
    for (const auto &e : every)
        QTest::addRow("every: %s", e.name) << e.code << 1 << hex(e.data) << hex(e.wire);
}

void tst_Frame::encode()
{
    QFETCH(int, command);
    QFETCH(int, id);
    QFETCH(QByteArray, data);
    QFETCH(QByteArray, wire);
    const auto cmd = static_cast<quint8>(command);
    const auto fid = static_cast<quint8>(id);
    QCOMPARE(lk::protocol::encodeFrame(cmd, fid, data), wire);
    QCOMPARE((Frame{cmd, fid, data}.encode()), wire);
}

void tst_Frame::checksums_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<int>("sum");
    QTest::newRow("empty") << QByteArray() << 0x00;
    QTest::newRow("one 0x80") << hex("80") << 0x80;
    QTest::newRow("0x80 + 0x80 wraps to 0") << hex("80 80") << 0x00;
    QTest::newRow("0xFF + 0x01 wraps to 0") << hex("FF 01") << 0x00;
    QTest::newRow("two 0xFF: & gives FE, % 255 would give 0") << hex("FF FF") << 0xFE;
    QTest::newRow("255 x 0x01 = 0xFF (% 255 would give 0)") << QByteArray(255, '\1') << 0xFF;
    QTest::newRow("1000 x 0xFF") << QByteArray(1000, char(0xFF)) << ((1000 * 255) & 0xFF);
}

void tst_Frame::checksums()
{
    QFETCH(QByteArray, bytes);
    QFETCH(int, sum);
    QCOMPARE(int(lk::protocol::byteSum(bytes.constData(), bytes.size())), sum);
    // Header checksum: the same rule over 3E CMD ID LEN.
    QCOMPARE(int(lk::protocol::headerChecksum(0xA8, 0x20, 0x08)), 0x0E);
    QCOMPARE(int(lk::protocol::headerChecksum(0xFF, 0xFF, 0xFF)), (0x3E + 3 * 0xFF) & 0xFF);
}

namespace {
// Expected direction: 0 request, 1 reply, 2 echo, -1 none.
constexpr int kReq = 0, kRep = 1, kEcho = 2, kNone = -1;

struct DirRow {
    const char *name;
    int code;
    int len;
    int dir;
};
// By hand from CLI.md/ERRATA: reads are LEN 0 out and LEN n back; writes of PID, accel and
// encoder offset, off/stop/run, clear_angle and write_zero_rom (LEN 0) are echoes.
const DirRow kDirRows[] = {
    {"read_pid", 0x30, 0, kReq},
    {"read_pid", 0x30, 6, kRep},
    {"read_pid", 0x30, 4, kNone},
    {"write_pid_ram", 0x31, 6, kEcho},
    {"write_pid_ram", 0x31, 0, kNone},
    {"write_pid_rom", 0x32, 6, kEcho},
    {"write_pid_rom", 0x32, 7, kNone},
    {"read_accel", 0x33, 0, kReq},
    {"read_accel", 0x33, 4, kRep},
    {"read_accel", 0x33, 8, kNone},
    {"write_accel_ram", 0x34, 4, kEcho},
    {"write_accel_ram", 0x34, 0, kNone},
    {"read_encoder", 0x90, 0, kReq},
    {"read_encoder", 0x90, 6, kRep},
    {"read_encoder", 0x90, 2, kNone},
    {"write_encoder_offset", 0x91, 2, kEcho},
    {"write_encoder_offset", 0x91, 0, kNone},
    {"write_zero_rom", 0x19, 0, kEcho},
    {"write_zero_rom", 0x19, 2, kRep},
    {"write_zero_rom", 0x19, 26, kNone},
    {"read_multi_turn", 0x92, 0, kReq},
    {"read_multi_turn", 0x92, 8, kRep},
    {"read_multi_turn", 0x92, 7, kNone},
    {"read_single_turn", 0x94, 0, kReq},
    {"read_single_turn", 0x94, 4, kRep},
    {"read_single_turn", 0x94, 2, kNone},
    {"clear_angle", 0x95, 0, kEcho},
    {"clear_angle", 0x95, 7, kNone},
    {"read_state1", 0x9A, 0, kReq},
    {"read_state1", 0x9A, 7, kRep},
    {"read_state1", 0x9A, 8, kNone},
    {"clear_errors", 0x9B, 0, kReq},
    {"clear_errors", 0x9B, 7, kRep},
    {"clear_errors", 0x9B, 6, kNone},
    {"read_state2", 0x9C, 0, kReq},
    {"read_state2", 0x9C, 7, kRep},
    {"read_state2", 0x9C, 1, kNone},
    {"read_state3", 0x9D, 0, kReq},
    {"read_state3", 0x9D, 7, kRep},
    {"read_state3", 0x9D, 60, kNone},
    {"motor_off", 0x80, 0, kEcho},
    {"motor_off", 0x80, 7, kNone},
    {"motor_stop", 0x81, 0, kEcho},
    {"motor_stop", 0x81, 1, kNone},
    {"motor_run", 0x88, 0, kEcho},
    {"motor_run", 0x88, 2, kNone},
    {"open_loop", 0xA0, 2, kReq},
    {"open_loop", 0xA0, 7, kRep},
    {"open_loop", 0xA0, 0, kNone},
    {"torque", 0xA1, 2, kReq},
    {"torque", 0xA1, 7, kRep},
    {"torque", 0xA1, 4, kNone},
    {"speed", 0xA2, 4, kReq},
    {"speed", 0xA2, 7, kRep},
    {"speed", 0xA2, 8, kNone},
    {"multi_position", 0xA3, 8, kReq},
    {"multi_position", 0xA3, 7, kRep},
    {"multi_position", 0xA3, 12, kNone},
    {"multi_position_limited", 0xA4, 12, kReq},
    {"multi_position_limited", 0xA4, 7, kRep},
    {"multi_position_limited", 0xA4, 8, kNone},
    {"single_position", 0xA5, 4, kReq},
    {"single_position", 0xA5, 7, kRep},
    {"single_position", 0xA5, 3, kNone},
    {"single_position_limited", 0xA6, 8, kReq},
    {"single_position_limited", 0xA6, 7, kRep},
    {"single_position_limited", 0xA6, 4, kNone},
    {"increment_position", 0xA7, 4, kReq},
    {"increment_position", 0xA7, 7, kRep},
    {"increment_position", 0xA7, 3, kNone},
    {"increment_position_limited", 0xA8, 8, kReq},
    {"increment_position_limited", 0xA8, 7, kRep},
    {"increment_position_limited", 0xA8, 13, kNone},
    {"read_model", 0x12, 0, kReq},
    {"read_model", 0x12, 42, kRep},
    {"read_model", 0x12, 58, kRep},
    {"read_model", 0x12, 41, kNone},
    {"read_model", 0x12, 26, kNone},
    {"unknown 0x89", 0x89, 0, kNone},
    {"unknown 0x00", 0x00, 7, kNone},
    {"unknown 0xFF", 0xFF, 2, kNone},
};
} // namespace

void tst_Frame::direction_data()
{
    QTest::addColumn<int>("command");
    QTest::addColumn<int>("len");
    QTest::addColumn<int>("expected");
    const char *names[] = {"request", "reply", "echo"};
    for (const DirRow &r : kDirRows) {
        const char *what = r.dir == kNone ? "invalid" : names[r.dir];
        QTest::addRow("%s LEN %d %s", r.name, r.len, what) << r.code << r.len << r.dir;
    }
}

void tst_Frame::direction()
{
    QFETCH(int, command);
    QFETCH(int, len);
    QFETCH(int, expected);
    // Data bytes >= 0x80 so that nothing depends on the content.
    const Frame f{static_cast<quint8>(command), 1, QByteArray(len, char(0xA5))};
    const std::optional<FrameDirection> d = f.direction();
    if (expected == kNone) {
        QVERIFY2(!d.has_value(), d ? lk::protocol::directionName(*d) : "");
        return;
    }
    QVERIFY(d.has_value());
    const FrameDirection want[] = {FrameDirection::Request, FrameDirection::Reply,
                                   FrameDirection::Echo};
    QCOMPARE(lk::protocol::directionName(*d), lk::protocol::directionName(want[expected]));
    QVERIFY(*d == want[expected]);
}

void tst_Frame::directionName_data()
{
    QTest::addColumn<int>("direction");
    QTest::addColumn<QString>("name");
    QTest::newRow("request") << int(FrameDirection::Request) << QStringLiteral("request");
    QTest::newRow("reply") << int(FrameDirection::Reply) << QStringLiteral("reply");
    QTest::newRow("echo") << int(FrameDirection::Echo) << QStringLiteral("echo");
}

void tst_Frame::directionName()
{
    QFETCH(int, direction);
    QFETCH(QString, name);
    QCOMPARE(
        QString::fromLatin1(lk::protocol::directionName(static_cast<FrameDirection>(direction))),
        name);
}

void tst_Frame::equality()
{
    const Frame a{0x9C, 1, hex("01 02")};
    QVERIFY((a == Frame{0x9C, 1, hex("01 02")}));
    QVERIFY(!(a == Frame{0x9D, 1, hex("01 02")}));
    QVERIFY(!(a == Frame{0x9C, 2, hex("01 02")}));
    QVERIFY(!(a == Frame{0x9C, 1, hex("01 03")}));
    QVERIFY(!(a == Frame{0x9C, 1, hex("01")}));
}

QTEST_APPLESS_MAIN(tst_Frame)
#include "tst_frame.moc"
