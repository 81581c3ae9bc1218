#include "protocol/Reply.h"

#include "ProtocolTestUtil.h"
#include "ReplyFields.h"

#include <QtTest/QTest>

using lk::protocol::Command;
using lk::protocol::DecodeContext;
using lk::protocol::DecodeError;
using lk::protocol::Frame;
using lk::protocol::Reply;
using lk::protocol::Series;
using lk::test::fields;
using lk::test::hex;
using lk::test::map;
using lk::test::mismatch;
using lk::test::spaced;
namespace proto = lk::protocol;

Q_DECLARE_METATYPE(lk::protocol::Reply)

/// decodeReply: hand-made reply vectors of every command decoded to physical units and raw
/// values; short, long and wrong-direction frames refused; Reply::toFrame round trips.
class tst_Reply : public QObject {
    Q_OBJECT

private slots:
    void decode_data();
    void decode();
    void refused_data();
    void refused();
    void throughParser_data();
    void throughParser();
    void roundTrip_data();
    void roundTrip();
};

namespace {
/// A name field of the 0x12 reply: Latin-1, NUL padded to 20 bytes.
QByteArray nameField(const char *name)
{
    QByteArray b(name);
    b.append(QByteArray(20 - b.size(), '\0'));
    return b;
}

QByteArray le16(quint16 v)
{
    return QByteArray(1, char(v & 0xFF)) + QByteArray(1, char(v >> 8));
}

void addDecode(const char *name, const QByteArray &wire, Series series, bool canonical,
               const QVariantMap &expected)
{
    QTest::newRow(name) << wire << int(series) << canonical << expected;
}

void addSetupDecodeRows()
{
    const Series mf = Series::MF;
    addDecode("read_pid", hex("3E 30 01 06 75 64 32 28 1E 32 32 40"), mf, true,
              map({{"kind", "pid"},
                   {"angle_kp", 100},
                   {"angle_ki", 50},
                   {"speed_kp", 40},
                   {"speed_ki", 30},
                   {"iq_kp", 50},
                   {"iq_ki", 50}}));
    addDecode("read_pid 255 and 0", hex("3E 30 20 06 94 FF 00 FF 00 FF 01 FE"), mf, true,
              map({{"kind", "pid"},
                   {"id", 32},
                   {"angle_kp", 255},
                   {"angle_ki", 0},
                   {"speed_kp", 255},
                   {"speed_ki", 0},
                   {"iq_kp", 255},
                   {"iq_ki", 1}}));
    addDecode("write_pid_ram echo", hex("3E 31 01 06 76 0A 14 1E 28 32 3C D2"), mf, true,
              map({{"kind", "pid"},
                   {"angle_kp", 10},
                   {"angle_ki", 20},
                   {"speed_kp", 30},
                   {"speed_ki", 40},
                   {"iq_kp", 50},
                   {"iq_ki", 60}}));
    addDecode("write_pid_rom echo", hex("3E 32 01 06 77 C8 C9 CA CB CC CD BF"), mf, true,
              map({{"kind", "pid"}, {"angle_kp", 200}, {"iq_ki", 205}}));
    addDecode("read_accel 10000", hex("3E 33 01 04 76 10 27 00 00 37"), mf, true,
              map({{"kind", "accel"}, {"accel_dps2", 10000}}));
    addDecode("read_accel -10000 (int32)", hex("3E 33 01 04 76 F0 D8 FF FF C6"), mf, true,
              map({{"kind", "accel"}, {"accel_dps2", -10000}}));
    addDecode("read_accel int32 min", hex("3E 33 01 04 76 00 00 00 80 80"), mf, true,
              map({{"kind", "accel"}, {"accel_dps2", qlonglong(-2147483648LL)}}));
    addDecode("write_accel_ram echo", hex("3E 34 01 04 77 FF FF FF 7F 7C"), mf, true,
              map({{"kind", "accel"}, {"accel_dps2", 2147483647}}));
    addDecode("read_encoder", hex("3E 90 01 06 D5 FF 3F 34 12 FF FF 82"), mf, true,
              map({{"kind", "encoder"},
                   {"encoder", 16383},
                   {"encoder_raw", 0x1234},
                   {"encoder_offset", 65535}}));
    addDecode("write_encoder_offset echo", hex("3E 91 01 02 D2 00 80 80"), mf, true,
              map({{"kind", "offset"}, {"encoder_offset", 0x8000}}));
    addDecode("write_zero_rom LEN 0", hex("3E 19 01 00 58"), mf, true,
              map({{"kind", "zero"}, {"has_offset", false}}));
    addDecode("write_zero_rom LEN 2", hex("3E 19 01 02 5A 45 23 68"), mf, true,
              map({{"kind", "zero"}, {"has_offset", true}, {"encoder_offset", 0x2345}}));
}

void addAngleDecodeRows()
{
    const Series mf = Series::MF;
    addDecode("read_multi_turn -36000.00 deg", hex("3E 92 01 08 D9 80 11 C9 FF FF FF FF FF 55"), mf,
              true,
              map({{"kind", "multi_turn"}, {"angle_raw", -3600000}, {"angle_deg", -36000.0}}));
    addDecode("read_multi_turn -0.01 deg", hex("3E 92 01 08 D9 FF FF FF FF FF FF FF FF F8"), mf,
              true, map({{"kind", "multi_turn"}, {"angle_raw", -1}, {"angle_deg", -0.01}}));
    // All 8 bytes are the int64, the last one included (ERRATA: byte +7, not +6).
    addDecode("read_multi_turn byte +7", hex("3E 92 01 08 D9 08 07 06 05 04 03 02 01 24"), mf, true,
              map({{"kind", "multi_turn"}, {"angle_raw", qlonglong(0x0102030405060708LL)}}));
    addDecode("read_multi_turn int64 min (sign in byte +7)",
              hex("3E 92 01 08 D9 00 00 00 00 00 00 00 80 80"), mf, true,
              map({{"kind", "multi_turn"},
                   {"angle_raw", qlonglong(std::numeric_limits<qint64>::min())}}));
    addDecode("read_single_turn 359.99", hex("3E 94 01 04 D7 9F 8C 00 00 2B"), mf, true,
              map({{"kind", "single_turn"}, {"angle_raw", 35999}, {"angle_deg", 359.99}}));
    addDecode("read_single_turn geared 3599.99", hex("3E 94 01 04 D7 3F 7E 05 00 C2"), mf, true,
              map({{"kind", "single_turn"}, {"angle_raw", 359999}, {"angle_deg", 3599.99}}));
}

void addStateDecodeRows()
{
    const Series mf = Series::MF;
    addDecode("read_state1 25 C 12.0 V no error", hex("3E 9A 01 07 E0 19 00 78 00 00 00 00 91"), mf,
              true,
              map({{"kind", "state1"},
                   {"temperature_c", 25},
                   {"voltage_raw", 120},
                   {"voltage_v", 12.0},
                   {"error_state", 0},
                   {"low_voltage", false},
                   {"over_temperature", false}}));
    addDecode("read_state1 -10 C, bits 0 and 3", hex("3E 9A 01 07 E0 F6 00 F0 00 00 00 09 EF"), mf,
              true,
              map({{"kind", "state1"},
                   {"temperature_c", -10},
                   {"voltage_v", 24.0},
                   {"error_state", 9},
                   {"low_voltage", true},
                   {"over_temperature", true}}));
    addDecode("read_state1 bit 3 only", hex("3E 9A 01 07 E0 50 00 F1 00 00 00 08 49"), mf, true,
              map({{"kind", "state1"},
                   {"temperature_c", 80},
                   {"voltage_v", 24.1},
                   {"low_voltage", false},
                   {"over_temperature", true}}));
    addDecode("read_state1 NULL bytes not zero are ignored",
              hex("3E 9A 01 07 E0 1E AA 7D 00 AA AA 01 9A"), mf, false,
              map({{"kind", "state1"},
                   {"temperature_c", 30},
                   {"voltage_raw", 125},
                   {"voltage_v", 12.5},
                   {"low_voltage", true},
                   {"over_temperature", false}}));
    addDecode("clear_errors", hex("3E 9B 01 07 E1 D8 00 FF FF 00 00 00 D6"), mf, true,
              map({{"kind", "state1"},
                   {"temperature_c", -40},
                   {"voltage_raw", 65535},
                   {"voltage_v", 6553.5},
                   {"error_state", 0}}));
    addDecode("read_state2 MF iq 2048 = 33 A", hex("3E 9C 01 07 E2 1E 00 08 0C FE FF 3F 6E"), mf,
              true,
              map({{"kind", "state2"},
                   {"temperature_c", 30},
                   {"is_power", false},
                   {"iq_raw", 2048},
                   {"iq_a", 33.0},
                   {"speed_dps", -500},
                   {"encoder", 16383}}));
    addDecode("read_state2 MG iq -2048 = -33 A", hex("3E 9C 01 07 E2 FB 00 F8 FF 7F 00 00 71"),
              Series::MG, true,
              map({{"kind", "state2"},
                   {"temperature_c", -5},
                   {"iq_raw", -2048},
                   {"iq_a", -33.0},
                   {"speed_dps", 32767},
                   {"encoder", 0}}));
    addDecode("read_state2 MS power -1000", hex("3E 9C 01 07 E2 2D 18 FC 00 80 FF FF BF"),
              Series::MS, true,
              map({{"kind", "state2"},
                   {"temperature_c", 45},
                   {"is_power", true},
                   {"power", -1000},
                   {"speed_dps", -32768},
                   {"encoder", 65535}}));
    addDecode("read_state3 1/64 A", hex("3E 9D 01 07 E3 32 40 00 80 FF 20 00 11"), Series::MH, true,
              map({{"kind", "state3"},
                   {"temperature_c", 50},
                   {"ia_raw", 64},
                   {"ia_a", 1.0},
                   {"ib_raw", -128},
                   {"ib_a", -2.0},
                   {"ic_raw", 32},
                   {"ic_a", 0.5}}));
}

void addMotionDecodeRows()
{
    const Series mf = Series::MF, ms = Series::MS;
    for (const char *wire :
         {"3E 80 01 00 BF", "3E 81 01 00 C0", "3E 88 01 00 C7", "3E 95 01 00 D4"})
        addDecode(qPrintable(QStringLiteral("echo ") + QLatin1String(wire)), hex(wire), mf, true,
                  map({{"kind", "ack"}}));
    addDecode("open_loop reply: always power", hex("3E A0 01 07 E6 28 0C FE 64 00 E8 03 81"), mf,
              true,
              map({{"kind", "state2"},
                   {"temperature_c", 40},
                   {"is_power", true},
                   {"power", -500},
                   {"speed_dps", 100},
                   {"encoder", 1000}}));
    addDecode("open_loop reply MS", hex("3E A0 01 07 E6 28 0C FE 64 00 E8 03 81"), ms, true,
              map({{"kind", "state2"}, {"is_power", true}, {"power", -500}}));
    addDecode("torque reply iq 1024 = 16.5 A", hex("3E A1 01 07 E7 29 00 04 9C FF D0 07 9F"), mf,
              true,
              map({{"kind", "state2"},
                   {"temperature_c", 41},
                   {"iq_raw", 1024},
                   {"iq_a", 16.5},
                   {"speed_dps", -100},
                   {"encoder", 2000}}));
    addDecode("speed reply MF iq -1", hex("3E A2 01 07 E8 2A FF FF 68 01 B8 0B 54"), mf, true,
              map({{"kind", "state2"},
                   {"temperature_c", 42},
                   {"iq_raw", -1},
                   {"iq_a", -33.0 / 2048.0},
                   {"speed_dps", 360},
                   {"encoder", 3000}}));
    addDecode("speed reply MS power 999", hex("3E A2 01 07 E8 2A E7 03 68 01 B8 0B 40"), ms, true,
              map({{"kind", "state2"}, {"is_power", true}, {"power", 999}, {"speed_dps", 360}}));
}

void addPositionReplyRows()
{
    const Series mf = Series::MF;
    addDecode("multi_position reply", hex("3E A3 01 07 E9 2B 64 00 00 00 A0 0F 3E"), mf, true,
              map({{"kind", "state2"},
                   {"temperature_c", 43},
                   {"iq_raw", 100},
                   {"speed_dps", 0},
                   {"encoder", 4000}}));
    addDecode("multi_position_limited reply (CLI.md frame, good checksum)",
              hex("3E A4 01 07 EA 2C 9C FF FF FF 88 13 60"), mf, true,
              map({{"kind", "state2"},
                   {"temperature_c", 44},
                   {"iq_raw", -100},
                   {"speed_dps", -1},
                   {"encoder", 5000}}));
    addDecode("single_position reply", hex("3E A5 01 07 EB 2D C8 00 0A 00 70 17 86"), mf, true,
              map({{"kind", "state2"},
                   {"temperature_c", 45},
                   {"iq_raw", 200},
                   {"speed_dps", 10},
                   {"encoder", 6000}}));
    addDecode("single_position_limited reply", hex("3E A6 01 07 EC 2E 38 FF F6 FF 58 1B CD"), mf,
              true,
              map({{"kind", "state2"},
                   {"temperature_c", 46},
                   {"iq_raw", -200},
                   {"speed_dps", -10},
                   {"encoder", 7000}}));
    addDecode("increment_position reply", hex("3E A7 01 07 ED 2F 2C 01 14 00 40 1F CF"), mf, true,
              map({{"kind", "state2"},
                   {"temperature_c", 47},
                   {"iq_raw", 300},
                   {"speed_dps", 20},
                   {"encoder", 8000}}));
    addDecode("increment_position_limited reply LEN 7 (ERRATA)",
              hex("3E A8 20 07 0D 30 D4 FE EC FF 28 23 38"), mf, true,
              map({{"kind", "state2"},
                   {"id", 32},
                   {"temperature_c", 48},
                   {"iq_raw", -300},
                   {"speed_dps", -20},
                   {"encoder", 9000}}));
}

void addModelDecodeRows()
{
    // 0x12 V2.3: driverName[20] motorName[20] u8 hw u8 fw, versions / 10.
    const QByteArray v23 =
        nameField("LK-DRV-MF") + nameField("MF4015v2-i10") + QByteArray(1, 13) + QByteArray(1, 23);
    QVERIFY(v23.size() == 42);
    addDecode("read_model V2.3 42 bytes", hex("3E 12 01 2A 7B") + v23 + hex("90"), Series::MF, true,
              map({{"kind", "model"},
                   {"generation", "V2.3"},
                   {"driver_name", "LK-DRV-MF"},
                   {"motor_name", "MF4015v2-i10"},
                   {"hardware_raw", 13},
                   {"hardware_version", 1.3},
                   {"firmware_raw", 23},
                   {"firmware_version", 2.3}}));
    // Names that fill all 20 bytes (no NUL), and a name with bytes after its NUL.
    QByteArray full = QByteArray("ABCDEFGHIJKLMNOPQRST") + nameField("MG") + QByteArray(1, 10) +
                      QByteArray(1, char(255));
    full[20 + 3] = char(0xFF); // after the NUL that ends "MG"
    const Frame fullFrame{0x12, 5, full};
    addDecode("read_model V2.3 20-char name, junk after NUL", fullFrame.encode(), Series::MF, false,
              map({{"kind", "model"},
                   {"id", 5},
                   {"driver_name", "ABCDEFGHIJKLMNOPQRST"},
                   {"motor_name", "MG"},
                   {"hardware_version", 1.0},
                   {"firmware_raw", 255},
                   {"firmware_version", 25.5}}));
    // 0x12 V2.35: driverName[20] motorName[20] motorId[12] u16 hw u16 motorVersion u16 fw,
    // versions / 100 (a real fw 2.35 drive reports hw 300, fw 235).
    const QByteArray v235 = nameField("LKDriver") + nameField("MS4015") +
                            QByteArray("MID123456789") + le16(300) + le16(101) + le16(235);
    QVERIFY(v235.size() == 58);
    addDecode("read_model V2.35 58 bytes", hex("3E 12 01 3A 8B") + v235 + hex("A1"), Series::MS,
              true,
              map({{"kind", "model"},
                   {"generation", "V2.35"},
                   {"driver_name", "LKDriver"},
                   {"motor_name", "MS4015"},
                   {"motor_id", "MID123456789"},
                   {"hardware_raw", 300},
                   {"hardware_version", 3.0},
                   {"motor_version_raw", 101},
                   {"firmware_raw", 235},
                   {"firmware_version", 2.35}}));
}
} // namespace

void tst_Reply::decode_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<int>("series");
    QTest::addColumn<bool>("canonical"); ///< toFrame() gives the same bytes back
    QTest::addColumn<QVariantMap>("expected");
    addSetupDecodeRows();
    addAngleDecodeRows();
    addStateDecodeRows();
    addMotionDecodeRows();
    addPositionReplyRows();
    addModelDecodeRows();
}

void tst_Reply::decode()
{
    QFETCH(QByteArray, wire);
    QFETCH(int, series);
    QFETCH(bool, canonical);
    QFETCH(QVariantMap, expected);

    const lk::test::EventLog log = lk::test::parseAll(wire);
    QCOMPARE(int(log.events.size()), 1);
    QVERIFY2(log.events.front().isFrame, qPrintable(lk::test::describe(log.events.front())));
    QVERIFY(log.events.front().direction != proto::FrameDirection::Request);

    DecodeContext ctx;
    ctx.series = static_cast<Series>(series);
    const proto::ReplyDecodeResult r = proto::decodeReply(log.events.front().frame, ctx);
    QVERIFY(r.error == DecodeError::None);
    QVERIFY(r.reply.has_value());
    QCOMPARE(int(r.reply->command), int(quint8(wire[1])));
    QCOMPARE(int(r.reply->id), int(quint8(wire[2])));
    const QString diff = mismatch(fields(*r.reply), expected, false);
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
    if (canonical)
        QCOMPARE(spaced(r.reply->encode()), spaced(wire));
}

namespace {
DecodeError expectedError(const lk::test::CommandLengths &l, int len)
{
    return len == l.request ? DecodeError::WrongDirection : DecodeError::BadLength;
}
} // namespace

void tst_Reply::refused_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<int>("len");
    QTest::addColumn<int>("error");
    for (const lk::test::CommandLengths &l : lk::test::kCommandLengths) {
        const auto add = [&l](const char *what, int len) {
            if (len < 0 || l.replies.contains(len))
                return; // a valid reply length, decoded in decode()
            QTest::addRow("%s %s LEN %d", l.name, what, len)
                << l.code << len << int(expectedError(l, len));
        };
        add("empty", 0);
        add("one byte", 1);
        for (int len : l.replies) {
            add("truncated", len - 1);
            add("one too long", len + 1);
        }
        add("wrong direction", l.request);
        add("max", 60);
    }
    for (int len : {0, 7, 42})
        QTest::addRow("unknown 0x89 LEN %d", len)
            << 0x89 << len << int(DecodeError::UnknownCommand);
    QTest::newRow("unknown 0x00") << 0x00 << 0 << int(DecodeError::UnknownCommand);
    QTest::newRow("unknown 0xFF") << 0xFF << 7 << int(DecodeError::UnknownCommand);
}

void tst_Reply::refused()
{
    QFETCH(int, code);
    QFETCH(int, len);
    QFETCH(int, error);
    // Data bytes >= 0x80 so a decoder that reads past the end or decodes zeros shows up.
    const Frame frame{quint8(code), 1, QByteArray(len, char(0xE7))};
    for (Series s : {Series::MS, Series::MF}) {
        DecodeContext ctx;
        ctx.series = s;
        const proto::ReplyDecodeResult r = proto::decodeReply(frame, ctx);
        QCOMPARE(int(r.error), error);
        QVERIFY(!r.reply.has_value());
    }
}

void tst_Reply::throughParser_data()
{
    QTest::addColumn<QByteArray>("wire");
    // One good reply per command; each gets a garbage prefix and a corrupted copy.
    const char *replies[] = {
        "3E 30 01 06 75 64 32 28 1E 32 32 40",
        "3E 31 01 06 76 0A 14 1E 28 32 3C D2",
        "3E 32 01 06 77 C8 C9 CA CB CC CD BF",
        "3E 33 01 04 76 F0 D8 FF FF C6",
        "3E 34 01 04 77 FF FF FF 7F 7C",
        "3E 90 01 06 D5 FF 3F 34 12 FF FF 82",
        "3E 91 01 02 D2 00 80 80",
        "3E 19 01 00 58",
        "3E 19 01 02 5A 45 23 68",
        "3E 92 01 08 D9 80 11 C9 FF FF FF FF FF 55",
        "3E 94 01 04 D7 9F 8C 00 00 2B",
        "3E 95 01 00 D4",
        "3E 9A 01 07 E0 F6 00 F0 00 00 00 09 EF",
        "3E 9B 01 07 E1 D8 00 FF FF 00 00 00 D6",
        "3E 9C 01 07 E2 1E 00 08 0C FE FF 3F 6E",
        "3E 9D 01 07 E3 32 40 00 80 FF 20 00 11",
        "3E 80 01 00 BF",
        "3E 81 01 00 C0",
        "3E 88 01 00 C7",
        "3E A0 01 07 E6 28 0C FE 64 00 E8 03 81",
        "3E A1 01 07 E7 29 00 04 9C FF D0 07 9F",
        "3E A2 01 07 E8 2A FF FF 68 01 B8 0B 54",
        "3E A3 01 07 E9 2B 64 00 00 00 A0 0F 3E",
        "3E A4 01 07 EA 2C 9C FF FF FF 88 13 60",
        "3E A5 01 07 EB 2D C8 00 0A 00 70 17 86",
        "3E A6 01 07 EC 2E 38 FF F6 FF 58 1B CD",
        "3E A7 01 07 ED 2F 2C 01 14 00 40 1F CF",
        "3E A8 20 07 0D 30 D4 FE EC FF 28 23 38",
    };
    for (const char *w : replies)
        QTest::newRow(w) << hex(w);
}

void tst_Reply::throughParser()
{
    QFETCH(QByteArray, wire);
    const QByteArray garbage = hex("00 11 22 FF");
    // Garbage prefix: reported as garbage, the reply still decodes.
    lk::test::EventLog log = lk::test::parseAll(garbage + wire);
    QCOMPARE(int(log.events.size()), 2);
    QVERIFY(!log.events[0].isFrame);
    QCOMPARE(log.events[0].bytes, garbage);
    QVERIFY(log.events[1].isFrame);
    QVERIFY(proto::decodeReply(log.events[1].frame).reply.has_value());

    // Corrupt the last byte (data checksum, or header checksum for LEN 0): no frame at all,
    // so nothing reaches a decoder; the same reply after it is still found.
    QByteArray bad = wire;
    bad[bad.size() - 1] = char(bad.back() ^ 0x01);
    log = lk::test::parseAll(bad + wire);
    QCOMPARE(log.frameCount(), 1);
    QVERIFY(!log.events.front().isFrame);
    const auto want =
        wire.size() > 5 ? proto::ParseError::BadDataChecksum : proto::ParseError::BadHeaderChecksum;
    QCOMPARE(proto::parseErrorName(log.events.front().error), proto::parseErrorName(want));
    QCOMPARE(log.events.back().bytes, wire);
    QVERIFY(proto::decodeReply(log.events.back().frame).reply.has_value());
}

namespace {
void addRoundTrip(const char *name, Command c, const proto::ReplyPayload &p, Series s = Series::MF)
{
    QTest::newRow(name) << Reply{c, 7, p} << int(s);
}

proto::State2 state2(bool power)
{
    proto::State2 s;
    s.temperatureC = -12;
    s.torqueRaw = power ? -999 : 2047;
    s.isPower = power;
    s.speedDps = -1234;
    s.encoder = 54321;
    return s;
}
} // namespace

void tst_Reply::roundTrip_data()
{
    QTest::addColumn<Reply>("reply");
    QTest::addColumn<int>("series");
    const proto::PidGains pid{1, 2, 3, 254, 255, 0};
    addRoundTrip("read_pid", Command::ReadPid, pid);
    addRoundTrip("write_pid_ram", Command::WritePidRam, pid);
    addRoundTrip("write_pid_rom", Command::WritePidRom, pid);
    addRoundTrip("read_accel", Command::ReadAccel, proto::Acceleration{-123456});
    addRoundTrip("write_accel_ram", Command::WriteAccelRam, proto::Acceleration{2147483647});
    addRoundTrip("read_encoder", Command::ReadEncoder, proto::EncoderReading{1, 65535, 32768});
    addRoundTrip("write_encoder_offset", Command::WriteEncoderOffset, proto::EncoderOffset{65535});
    addRoundTrip("write_zero_rom echo", Command::WriteZeroRom, proto::ZeroWritten{});
    addRoundTrip("write_zero_rom offset", Command::WriteZeroRom, proto::ZeroWritten{0xBEEF});
    addRoundTrip("read_multi_turn", Command::ReadMultiTurn,
                 proto::MultiTurnAngle{-0x123456789ABCDEFLL});
    addRoundTrip("read_single_turn", Command::ReadSingleTurn, proto::SingleTurnAngle{4000000000u});
    addRoundTrip("clear_angle", Command::ClearAngle, proto::Acknowledged{});
    addRoundTrip("read_state1", Command::ReadState1, proto::State1{-128, 65535, 0xFF});
    addRoundTrip("clear_errors", Command::ClearErrors, proto::State1{127, 1, 0x08});
    addRoundTrip("read_state2 MF", Command::ReadState2, state2(false));
    addRoundTrip("read_state2 MS", Command::ReadState2, state2(true), Series::MS);
    addRoundTrip("read_state3", Command::ReadState3,
                 proto::State3{99, -32768, 32767, -1, lk::protocol::kPhaseAmpsPerLsb});
    addRoundTrip("motor_off", Command::MotorOff, proto::Acknowledged{});
    addRoundTrip("motor_stop", Command::MotorStop, proto::Acknowledged{});
    addRoundTrip("motor_run", Command::MotorRun, proto::Acknowledged{});
    addRoundTrip("open_loop MS", Command::OpenLoop, state2(true), Series::MS);
    addRoundTrip("torque MF", Command::Torque, state2(false));
    const Command motion[] = {Command::Speed,
                              Command::MultiPosition,
                              Command::MultiPositionLimited,
                              Command::SinglePosition,
                              Command::SinglePositionLimited,
                              Command::IncrementPosition,
                              Command::IncrementPositionLimited};
    for (Command c : motion) {
        const char *name = proto::CommandTable::info(c).name;
        QTest::addRow("%s MF", name) << Reply{c, 7, state2(false)} << int(Series::MF);
        QTest::addRow("%s MS", name) << Reply{c, 7, state2(true)} << int(Series::MS);
    }
    proto::ModelInfo v23;
    v23.driverName = QStringLiteral("DRIVER-20-CHARS-LONG");
    v23.motorName = QStringLiteral("MF4015");
    v23.hardwareRaw = 255;
    v23.firmwareRaw = 23;
    addRoundTrip("read_model V2.3", Command::ReadModel, v23);
    proto::ModelInfo v235;
    v235.generation = proto::Generation::V2_35;
    v235.driverName = QStringLiteral("LK");
    v235.motorName = QStringLiteral("MS4015");
    v235.motorId = QByteArray("ABCDEFGHIJKL");
    v235.hardwareRaw = 300;
    v235.motorVersionRaw = 65535;
    v235.firmwareRaw = 235;
    addRoundTrip("read_model V2.35", Command::ReadModel, v235);
}

void tst_Reply::roundTrip()
{
    QFETCH(Reply, reply);
    QFETCH(int, series);
    const QByteArray wire = reply.encode();
    const lk::test::EventLog log = lk::test::parseAll(wire);
    QCOMPARE(int(log.events.size()), 1);
    QVERIFY2(log.events.front().isFrame, qPrintable(lk::test::describe(log.events.front())));
    QCOMPARE(log.events.front().bytes, wire);

    DecodeContext ctx;
    ctx.series = static_cast<Series>(series);
    const proto::ReplyDecodeResult r = proto::decodeReply(log.events.front().frame, ctx);
    QVERIFY(r.error == DecodeError::None);
    QVERIFY(r.reply.has_value());
    QCOMPARE(int(r.reply->command), int(reply.command));
    const QString diff = mismatch(fields(*r.reply), fields(reply), true);
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
    QCOMPARE(spaced(r.reply->encode()), spaced(wire));
}

QTEST_APPLESS_MAIN(tst_Reply)
#include "tst_reply.moc"
