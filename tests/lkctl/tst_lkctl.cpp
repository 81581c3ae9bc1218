#include "E2eUtil.h"
#include "protocol/Command.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QProcess>
#include <QtTest/QtTest>

// Runs the built lkctl binary (path from CMake) and checks what a script would see: standard
// output, standard error and the exit status. Frame vectors were computed by hand from the
// spec (checksums = byte sums & 0xFF), not with the code under test.

namespace {

using Result = lk::e2e::CtlResult;

Result lkctl(const QStringList &args, const QByteArray &input = {})
{
    return lk::e2e::runProgram(QStringLiteral(LKCTL_PATH), args,
                               QProcessEnvironment::systemEnvironment(), 120000, input);
}

QStringList words(const char *text)
{
    return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

QByteArray lines(const QList<QByteArray> &ls)
{
    QByteArray out;
    for (const QByteArray &l : ls)
        out += l + '\n';
    return out;
}

// Hand-computed frames (see the row names for what they hold).
const char kReadState2[] = "3E 9C 01 00 DB";
const char kState2Reply[] = "3E 9C 01 07 E2 1F F4 01 68 01 00 30 AD"; // 31 C, 500, 360 dps, 12288
const char kSpeedNeg[] = "3E A2 07 04 EB BE D8 FF FF 94";             // id 7, -100.50 dps
const char kSpeedReply[] = "3E A2 01 07 E8 21 9C FF 63 00 90 01 B0";  // 33 C, -100, 99 dps, 400
const char kPidEcho[] = "3E 31 01 06 76 64 64 32 28 32 32 86";
const char kState1Reply[] = "3E 9A 01 07 E0 28 00 F3 00 00 00 09 24"; // 40 C, 24.3 V, flags 9
const char kState3Reply[] = "3E 9D 01 07 E3 1E 40 00 E0 FF E0 FF 1C"; // 30 C, 64, -32, -32
const char kEncoderReply[] = "3E 90 01 06 D5 FF 3F E0 2E 1F 11 7C";
const char kMultiReply[] = "3E 92 01 08 D9 4E 11 C9 FF FF FF FF FF 23"; // -3600050
const char kSingleReply[] = "3E 94 01 04 D7 9F 8C 00 00 2B";            // 35999
const char kModelReply[] = "3E 12 01 2A 7B 4C 4B 44 52 56 30 31 00 00 00 00 00 00 00 00 00 00 00 "
                           "00 00 4D 47 34 30 31 30 45 2D 69 31 30 00 00 00 00 00 00 00 00 00 0A "
                           "15 98";
const char kZeroReply[] = "3E 19 01 02 5A D2 04 D6";
const char kZeroEcho[] = "3E 19 01 00 58";
const char kSingleRequest[] = "3E A5 01 04 E8 01 9F 8C 00 2C";
const char kIncrementLimited[] = "3E A8 01 08 EF 94 11 00 00 A0 8C 00 00 D1";
const char kBadDataChecksum[] = "3E A4 01 07 EA 21 00 00 0A 00 2C 19 73";
const char kBadLength[] = "3E 9C 01 03 DE 01 02 03 06";
const char kUnknown[] = "3E 55 01 00 94";
const char kBadHeader[] = "3E 9C 01 00 00";
const char kOpenLoopReply[] = "3E A0 01 07 E6 21 9C FF 63 00 90 01 B0";
const char kTorqueReply[] = "3E A1 01 07 E7 21 9C FF 63 00 90 01 B0";

QByteArray frameLine(const char *direction, const char *command, const char *code, int id,
                     const char *fields)
{
    return QStringLiteral(R"({"direction":"%1","command":"%2","code":"%3","id":%4,"fields":%5})")
        .arg(QLatin1String(direction), QLatin1String(command), QLatin1String(code))
        .arg(id)
        .arg(QLatin1String(fields))
        .toUtf8();
}

QByteArray errorLine(const char *error, const char *bytes)
{
    return QStringLiteral(R"({"error":"%1","bytes":"%2"})")
        .arg(QLatin1String(error), QLatin1String(bytes))
        .toUtf8();
}

const char kState2Fields[] =
    R"({"temperature_c":31,"iq_a":8.056640625,"iq_raw":500,"speed_dps":360.0,"encoder":12288})";
const char kState2PowerFields[] =
    R"({"temperature_c":31,"power":500,"speed_dps":360.0,"encoder":12288})";

} // namespace

class tst_Lkctl : public QObject {
    Q_OBJECT
private slots:
    void encode_data();
    void encode();
    void encodeRefused_data();
    void encodeRefused();
    void encodeThenDecode_data();
    void encodeThenDecode();
    void decode_data();
    void decode();
    void decodeStdinText();
    void decodeStdinBinary();
    void decodeStdinMatchesArguments();
    void decodeBadHex_data();
    void decodeBadHex();
    void decodeBadHexOnStdinKeepsEarlierLines();
    void decodeUsageErrors_data();
    void decodeUsageErrors();
    void help_data();
    void help();
    void helpListsEveryCommand();
    void dispatcherErrors_data();
    void dispatcherErrors();
    void version();
};

void tst_Lkctl::encode_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QByteArray>("expected");
    const auto row = [](const char *name, const char *args, const char *hex) {
        QTest::newRow(name) << QString::fromLatin1(args) << QByteArray(hex) + '\n';
    };
    row("motor_off (CLI.md)", "motor_off --id 1", "3E 80 01 00 BF");
    row("motor_stop", "motor_stop --id 5", "3E 81 05 00 C4");
    row("motor_run", "motor_run --id 32", "3E 88 20 00 E6");
    row("read_pid", "read_pid --id 1", "3E 30 01 00 6F");
    row("write_pid_ram",
        "write_pid_ram --id 1 --angle-kp 100 --angle-ki 100 --speed-kp 50 --speed-ki 40 "
        "--iq-kp 50 --iq-ki 50",
        "3E 31 01 06 76 64 64 32 28 32 32 86");
    row("write_pid_rom",
        "write_pid_rom --id 32 --angle-kp 255 --angle-ki 0 --speed-kp 128 --speed-ki 1 "
        "--iq-kp 200 --iq-ki 7",
        "3E 32 20 06 96 FF 00 80 01 C8 07 4F");
    row("read_accel", "read_accel --id 2", "3E 33 02 00 73");
    row("write_accel_ram", "write_accel_ram --id 1 --accel-dps2 10000",
        "3E 34 01 04 77 10 27 00 00 37");
    row("read_encoder", "read_encoder --id 3", "3E 90 03 00 D1");
    row("write_encoder_offset", "write_encoder_offset --id 1 --encoder-offset 40000",
        "3E 91 01 02 D2 40 9C DC");
    row("write_zero_rom", "write_zero_rom --id 1", "3E 19 01 00 58");
    row("read_multi_turn", "read_multi_turn --id 1", "3E 92 01 00 D1");
    row("read_single_turn", "read_single_turn --id 1", "3E 94 01 00 D3");
    row("clear_angle", "clear_angle --id 1", "3E 95 01 00 D4");
    row("read_state1", "read_state1 --id 1", "3E 9A 01 00 D9");
    row("clear_errors", "clear_errors --id 1", "3E 9B 01 00 DA");
    row("read_state2", "read_state2 --id 1", "3E 9C 01 00 DB");
    row("read_state3", "read_state3 --id 1", "3E 9D 01 00 DC");
    row("read_model", "read_model --id 1", "3E 12 01 00 51");
    row("open_loop", "open_loop --id 1 --power -500", "3E A0 01 02 E1 0C FE 0A");
    row("torque", "torque --id 1 --iq-a -32", "3E A1 01 02 E2 30 F8 28");
    row("speed (CLI.md)", "speed --id 1 --speed-dps 100", "3E A2 01 04 E5 10 27 00 00 37");
    row("speed negative", "speed --id 7 --speed-dps -100.5", "3E A2 07 04 EB BE D8 FF FF 94");
    row("speed --field=value", "speed --id=7 --speed-dps=-100.5", "3E A2 07 04 EB BE D8 FF FF 94");
    row("multi_position", "multi_position --id 1 --angle-deg 360",
        "3E A3 01 08 EA A0 8C 00 00 00 00 00 00 2C");
    row("multi_position negative", "multi_position --id 1 --angle-deg -720",
        "3E A3 01 08 EA C0 E6 FE FF FF FF FF FF 9F");
    row("multi_position_limited",
        "multi_position_limited --id 1 --angle-deg 90 --max-speed-dps 500",
        "3E A4 01 0C EF 28 23 00 00 00 00 00 00 50 C3 00 00 5E");
    row("single_position", "single_position --id 1 --direction ccw --angle-deg 359.99",
        "3E A5 01 04 E8 01 9F 8C 00 2C");
    row("single_position CCW upper case",
        "single_position --id 1 --direction CCW --angle-deg 359.99",
        "3E A5 01 04 E8 01 9F 8C 00 2C");
    row("single_position_limited",
        "single_position_limited --id 1 --direction cw --angle-deg 0 --max-speed-dps 42949672.95",
        "3E A6 01 08 ED 00 00 00 00 FF FF FF FF FC");
    row("increment_position", "increment_position --id 1 --angle-deg -90",
        "3E A7 01 04 EA D8 DC FF FF B2");
    row("increment_position_limited",
        "increment_position_limited --id 1 --angle-deg 45 --max-speed-dps 360",
        "3E A8 01 08 EF 94 11 00 00 A0 8C 00 00 D1");
    row("options before the name", "--id 1 motor_off", "3E 80 01 00 BF");
}

void tst_Lkctl::encode()
{
    QFETCH(QString, args);
    QFETCH(QByteArray, expected);
    const Result r = lkctl(QStringList{"encode"} + args.split(' '));
    QCOMPARE(r.err, QByteArray());
    QCOMPARE(r.out, expected);
    QCOMPARE(r.exitCode, 0);
}

void tst_Lkctl::encodeRefused_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QStringList>("mentions"); // each must appear in the message
    const auto row = [](const char *name, const char *args, QStringList mentions) {
        QTest::newRow(name) << QString::fromLatin1(args) << mentions;
    };
    row("speed too high", "speed --id 1 --speed-dps 21474836.48",
        {"speed_dps", "-21474836.48..21474836.47 dps", "21474836.48"});
    row("torque over 32 A", "torque --id 1 --iq-a 32.01", {"iq_a", "-32..32 A", "32.01"});
    row("power", "open_loop --id 1 --power -851", {"power", "-850..850", "-851"});
    row("power not integer", "open_loop --id 1 --power 2.5", {"power", "-850..850", "integer"});
    row("pid gain",
        "write_pid_ram --id 1 --angle-kp 256 --angle-ki 0 --speed-kp 0 --speed-ki 0 "
        "--iq-kp 0 --iq-ki 0",
        {"angle_kp", "0..255", "256"});
    row("accel negative", "write_accel_ram --id 1 --accel-dps2 -1",
        {"accel_dps2", "0..2147483647 dps/s"});
    row("encoder offset", "write_encoder_offset --id 1 --encoder-offset 65536",
        {"encoder_offset", "0..65535", "65536"});
    row("single angle", "single_position --id 1 --direction cw --angle-deg 360",
        {"angle_deg", "0..359.99 deg", "360"});
    row("direction", "single_position --id 1 --direction up --angle-deg 1",
        {"direction", "cw|ccw", "up"});
    row("increment", "increment_position --id 1 --angle-deg -21474836.49",
        {"angle_deg", "-21474836.48..21474836.47 deg"});
    row("max speed", "multi_position_limited --id 1 --angle-deg 1 --max-speed-dps -1",
        {"max_speed_dps", "0..42949672.95 dps"});
    row("multi angle", "multi_position --id 1 --angle-deg 1e17", {"angle_deg", "-9e16..9e16 deg"});
    row("id 33", "motor_off --id 33", {"id", "1..32", "33"});
    row("id 0", "motor_off --id 0", {"id", "1..32"});
    row("missing id", "motor_off", {"id", "missing", "1..32"});
    row("missing field", "speed --id 1", {"speed_dps", "missing", "dps"});
    row("not a number", "speed --id 1 --speed-dps fast", {"speed_dps", "not a number", "dps"});
    row("nan", "speed --id 1 --speed-dps nan", {"speed_dps", "-21474836.48..21474836.47 dps"});
    row("unknown field", "speed --id 1 --speed-dps 1 --rpm 5", {"unknown field rpm", "speed_dps"});
    row("limit on the unlimited command", "multi_position --id 1 --angle-deg 1 --max-speed-dps 5",
        {"max_speed_dps", "multi_position"});
    row("unknown command", "spin --id 1", {"unknown command 'spin'"});
    row("no command", "--id 1", {"missing the command NAME"});
    row("value missing at the end", "speed --id 1 --speed-dps", {"--speed-dps needs a value"});
    row("option given twice", "motor_off --id 1 --id 2", {"--id given twice"});
    row("two names", "motor_off motor_stop --id 1", {"unexpected argument 'motor_stop'"});
}

void tst_Lkctl::encodeRefused()
{
    QFETCH(QString, args);
    QFETCH(QStringList, mentions);
    const Result r = lkctl(QStringList{"encode"} + args.split(' '));
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, QByteArray()); // nothing clamped, nothing printed
    QVERIFY(r.err.startsWith("lkctl encode: "));
    QCOMPARE(r.err.count('\n'), 1);
    for (const QString &m : mentions)
        QVERIFY2(r.err.contains(m.toUtf8()), r.err.constData());
}

void tst_Lkctl::encodeThenDecode_data()
{
    encode_data();
}

void tst_Lkctl::encodeThenDecode()
{
    // What encode prints, decode reads back as that command (request, or echo when the
    // drive's reply repeats it), with exit status 0.
    QFETCH(QString, args);
    QFETCH(QByteArray, expected);
    const Result r = lkctl(QStringList{"decode"} + QString::fromLatin1(expected).split(' '));
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out.count('\n'), 1);
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    const QStringList a = args.split(' ');
    const QString name = a.first().startsWith("--") ? a.at(2) : a.first();
    QCOMPARE(o.value("command").toString(), name);
    const auto info = lk::protocol::CommandTable::fromName(name);
    QVERIFY(info);
    QCOMPARE(o.value("direction").toString(),
             lk::protocol::CommandTable::info(*info).replyEchoesRequest ? "echo" : "request");
    QCOMPARE(o.value("code").toString(), lk::protocol::CommandTable::codeText(quint8(*info)));
}

void tst_Lkctl::decode_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("expected");
    QTest::addColumn<int>("exitCode");
    QTest::newRow("CLI.md request")
        << words("3E A2 01 04 E5 10 27 00 00 37")
        << lines({frameLine("request", "speed", "0xA2", 1,
                            R"({"speed_dps":100.0,"speed_raw":10000})")})
        << 0;
    QTest::newRow("CLI.md reply") << words(kState2Reply)
                                  << lines({frameLine("reply", "read_state2", "0x9C", 1,
                                                      kState2Fields)})
                                  << 0;
    QTest::newRow("CLI.md echo") << words("3E 80 01 00 BF")
                                 << lines({frameLine("echo", "motor_off", "0x80", 1, "{}")}) << 0;
    QTest::newRow("CLI.md bad data checksum")
        << words(kBadDataChecksum) << lines({errorLine("bad_data_checksum", kBadDataChecksum)})
        << 3;
    QTest::newRow("one argument, no spaces")
        << QStringList{"3E800100BF3E9C0100DB"}
        << lines({frameLine("echo", "motor_off", "0x80", 1, "{}"),
                  frameLine("request", "read_state2", "0x9C", 1, "{}")})
        << 0;
    QTest::newRow("0x prefixes and commas")
        << QStringList{"0x3E,0x80,0x01,0x00,0xbf"}
        << lines({frameLine("echo", "motor_off", "0x80", 1, "{}")}) << 0;
    QTest::newRow("garbage only") << words("00 11 22") << lines({errorLine("garbage", "00 11 22")})
                                  << 3;
    QTest::newRow("garbage around a frame")
        << words("AA 3E 80 01 00 BF 55")
        << lines({errorLine("garbage", "AA"), frameLine("echo", "motor_off", "0x80", 1, "{}"),
                  errorLine("garbage", "55")})
        << 3;
    QTest::newRow("truncated") << words("3E A2 01") << lines({errorLine("truncated", "3E A2 01")})
                               << 3;
    QTest::newRow("--series MS gives power")
        << (QStringList{"--series", "MS"} + words(kState2Reply))
        << lines({frameLine("reply", "read_state2", "0x9C", 1, kState2PowerFields)}) << 0;
    QTest::newRow("--series=ms after the bytes")
        << (words(kState2Reply) + QStringList{"--series=ms"})
        << lines({frameLine("reply", "read_state2", "0x9C", 1, kState2PowerFields)}) << 0;
    const char speedIq[] =
        R"({"temperature_c":33,"iq_a":-1.611328125,"iq_raw":-100,"speed_dps":99.0,"encoder":400})";
    const char speedPower[] = R"({"temperature_c":33,"power":-100,"speed_dps":99.0,"encoder":400})";
    QTest::newRow("MS: motion replies carry power, open loop always, torque never")
        << (QStringList{"--series", "MS"} + words(kSpeedReply) + words(kOpenLoopReply) +
            words(kTorqueReply))
        << lines({frameLine("reply", "speed", "0xA2", 1, speedPower),
                  frameLine("reply", "open_loop", "0xA0", 1, speedPower),
                  frameLine("reply", "torque", "0xA1", 1, speedIq)})
        << 0;
    QTest::newRow("mixed bus capture")
        << (words(kReadState2) + words(kState2Reply) + words("AA 55") + words(kSpeedNeg) +
            words(kSpeedReply) + words(kPidEcho) + words(kState1Reply) + words(kState3Reply) +
            words(kEncoderReply) + words(kMultiReply) + words(kSingleReply) + words(kModelReply) +
            words(kZeroReply) + words(kZeroEcho) + words(kSingleRequest) +
            words(kIncrementLimited) + words(kBadDataChecksum) + words(kBadLength) +
            words(kUnknown) + words(kBadHeader) + words("3E A2 01"))
        << lines({
               frameLine("request", "read_state2", "0x9C", 1, "{}"),
               frameLine("reply", "read_state2", "0x9C", 1, kState2Fields),
               errorLine("garbage", "AA 55"),
               frameLine("request", "speed", "0xA2", 7,
                         R"({"speed_dps":-100.5,"speed_raw":-10050})"),
               frameLine("reply", "speed", "0xA2", 1, speedIq),
               frameLine("echo", "write_pid_ram", "0x31", 1,
                         R"({"angle_kp":100,"angle_ki":100,"speed_kp":50,"speed_ki":40,)"
                         R"("iq_kp":50,"iq_ki":50})"),
               frameLine("reply", "read_state1", "0x9A", 1,
                         R"({"temperature_c":40,"voltage_v":24.3,"voltage_raw":243,)"
                         R"("error_state":9,"low_voltage":true,"over_temperature":true})"),
               frameLine("reply", "read_state3", "0x9D", 1,
                         R"({"temperature_c":30,"ia_a":1.0,"ia_raw":64,"ib_a":-0.5,)"
                         R"("ib_raw":-32,"ic_a":-0.5,"ic_raw":-32})"),
               frameLine("reply", "read_encoder", "0x90", 1,
                         R"({"encoder":16383,"encoder_raw":12000,"encoder_offset":4383})"),
               frameLine("reply", "read_multi_turn", "0x92", 1,
                         R"({"angle_deg":-36000.5,"angle_raw":-3600050})"),
               frameLine("reply", "read_single_turn", "0x94", 1,
                         R"({"angle_deg":359.99,"angle_raw":35999})"),
               frameLine("reply", "read_model", "0x12", 1,
                         R"({"driver_name":"LKDRV01","motor_name":"MG4010E-i10",)"
                         R"("hardware_version":1.0,"hardware_version_raw":10,)"
                         R"("firmware_version":2.1,"firmware_version_raw":21})"),
               frameLine("reply", "write_zero_rom", "0x19", 1, R"({"encoder_offset":1234})"),
               frameLine("echo", "write_zero_rom", "0x19", 1, "{}"),
               frameLine("request", "single_position", "0xA5", 1,
                         R"({"direction":"ccw","angle_deg":359.99,"angle_raw":35999})"),
               frameLine("request", "increment_position_limited", "0xA8", 1,
                         R"({"angle_deg":45.0,"angle_raw":4500,"max_speed_dps":360.0,)"
                         R"("max_speed_raw":36000})"),
               errorLine("bad_data_checksum", kBadDataChecksum),
               errorLine("bad_length", kBadLength),
               errorLine("unknown_command", kUnknown),
               errorLine("bad_header_checksum", kBadHeader),
               errorLine("truncated", "3E A2 01"),
           })
        << 3;
}

void tst_Lkctl::decode()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, expected);
    QFETCH(int, exitCode);
    const Result r = lkctl(QStringList{"decode"} + args);
    QCOMPARE(r.err, QByteArray());
    QCOMPARE(r.out, expected);
    QCOMPARE(r.exitCode, exitCode);
}

void tst_Lkctl::decodeStdinText()
{
    // Separators, 0x prefixes, CRLF, '#' comments (GUI export style) and blank lines.
    const QByteArray text = "# lkstudio traffic export\r\n"
                            "3E 9C 01 00 DB   # 12:00:00.001 TX read_state2\r\n"
                            "\n"
                            "0x3E,0x9C,0x01,0x07,0xE2 # reply split over two lines\n"
                            "1f:f4:01:68:01:00:30:ad\n"
                            "3E800100BF"; // no newline at the end
    const Result r = lkctl({"decode", "-"}, text);
    QCOMPARE(r.err, QByteArray());
    QCOMPARE(r.out, lines({frameLine("request", "read_state2", "0x9C", 1, "{}"),
                           frameLine("reply", "read_state2", "0x9C", 1, kState2Fields),
                           frameLine("echo", "motor_off", "0x80", 1, "{}")}));
    QCOMPARE(r.exitCode, 0);
}

void tst_Lkctl::decodeStdinBinary()
{
    QByteArray bytes = QByteArray::fromHex(QByteArray(kState2Reply).replace(' ', ""));
    bytes.prepend('\x00');
    bytes += QByteArray::fromHex("3E800100BF3E");
    const Result r = lkctl({"decode", "--series", "MS", "--binary", "-"}, bytes);
    QCOMPARE(r.err, QByteArray());
    QCOMPARE(r.out, lines({errorLine("garbage", "00"),
                           frameLine("reply", "read_state2", "0x9C", 1, kState2PowerFields),
                           frameLine("echo", "motor_off", "0x80", 1, "{}"),
                           errorLine("truncated", "3E")}));
    QCOMPARE(r.exitCode, 3);
    // --binary alone reads standard input too; empty input is no fault.
    const Result empty = lkctl({"decode", "--binary"});
    QCOMPARE(empty.out, QByteArray());
    QCOMPARE(empty.exitCode, 0);
}

void tst_Lkctl::decodeStdinMatchesArguments()
{
    // A large capture (many chunks on the pipe) decodes the same from stdin as binary and as
    // hex text.
    QByteArray bytes;
    for (int i = 0; i < 3000; ++i)
        bytes += QByteArray::fromHex(QByteArray(kState2Reply).replace(' ', "")) +
                 QByteArray::fromHex("3E800100BF");
    QByteArray hex;
    for (qsizetype i = 0; i < bytes.size(); i += 40)
        hex += bytes.mid(i, 40).toHex(' ') + '\n';
    const Result binary = lkctl({"decode", "--binary", "-"}, bytes);
    const Result text = lkctl({"decode", "-"}, hex);
    QCOMPARE(binary.exitCode, 0);
    QCOMPARE(text.exitCode, 0);
    QCOMPARE(binary.out.count('\n'), 6000);
    QCOMPARE(text.out, binary.out);
}

void tst_Lkctl::decodeBadHex_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("input");
    QTest::addColumn<QByteArray>("message");
    QTest::newRow("odd digits") << QStringList{"3E", "80 1", "00"} << QByteArray()
                                << QByteArray("argument 2, column 4: odd number of hex digits "
                                              "in '1'");
    QTest::newRow("odd run") << QStringList{"3E800"} << QByteArray()
                             << QByteArray("argument 1, column 1: odd number of hex digits");
    QTest::newRow("non-hex") << QStringList{"3E 8G"} << QByteArray()
                             << QByteArray("argument 1, column 5: 'G' is not a hex digit");
    QTest::newRow("bare 0x") << QStringList{"0x"} << QByteArray()
                             << QByteArray("argument 1, column 1: '0x' has no hex digits");
    QTest::newRow("stdin line and column")
        << QStringList{"-"} << QByteArray("3E 80 01 00 BF\n# note\n  3E zz\n")
        << QByteArray("standard input, line 3, column 6: 'z' is not a hex digit");
    QTest::newRow("stdin odd") << QStringList{"-"} << QByteArray("3E8\n")
                               << QByteArray("line 1, column 1: odd number of hex digits");
}

void tst_Lkctl::decodeBadHex()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, input);
    QFETCH(QByteArray, message);
    const Result r = lkctl(QStringList{"decode"} + args, input);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.startsWith("lkctl decode: bad hex"), r.err.constData());
    QVERIFY2(r.err.contains(message), r.err.constData());
    if (args.first() != QLatin1String("-")) {
        QCOMPARE(r.out, QByteArray()); // arguments are checked before anything is printed
    }
}

void tst_Lkctl::decodeBadHexOnStdinKeepsEarlierLines()
{
    const Result r = lkctl({"decode", "-"}, "3E 80 01 00 BF\nnot hex\n3E 80 01 00 BF\n");
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, lines({frameLine("echo", "motor_off", "0x80", 1, "{}")}));
    QVERIFY(r.err.contains("line 2, column 1: 'n' is not a hex digit"));
}

void tst_Lkctl::decodeUsageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("message");
    QTest::newRow("no input") << QStringList{} << QByteArray("no input");
    QTest::newRow("unknown series")
        << QStringList{"--series", "MX", "3E"} << QByteArray("unknown series 'MX'");
    QTest::newRow("series without value")
        << QStringList{"--series"} << QByteArray("--series needs a value");
    QTest::newRow("unknown option")
        << QStringList{"--fast", "3E"} << QByteArray("unknown option '--fast'");
    QTest::newRow("hex and stdin") << QStringList{"3E", "-"} << QByteArray("not both");
    QTest::newRow("binary and hex") << QStringList{"--binary", "3E"} << QByteArray("not both");
}

void tst_Lkctl::decodeUsageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, message);
    const Result r = lkctl(QStringList{"decode"} + args);
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, QByteArray());
    QVERIFY2(r.err.startsWith("lkctl decode: "), r.err.constData());
    QVERIFY2(r.err.contains(message), r.err.constData());
}

void tst_Lkctl::help_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QStringList>("mentions");
    const QStringList overview{"Usage: lkctl COMMAND", "encode", "decode",
                               "Examples:", "lkctl encode speed --id 1 --speed-dps 100"};
    QTest::newRow("--help") << QStringList{"--help"} << overview;
    QTest::newRow("-h") << QStringList{"-h"} << overview;
    QTest::newRow("help") << QStringList{"help"} << overview;
    const QStringList encode{"Usage: lkctl encode NAME --id N",
                             "--speed-dps",
                             "--direction",
                             "--max-speed-dps",
                             "--iq-a",
                             "--power",
                             "--angle-deg",
                             "--accel-dps2",
                             "--encoder-offset",
                             "--angle-kp",
                             "--iq-ki",
                             "Examples:",
                             "3E 80 01 00 BF",
                             "Exit status"};
    QTest::newRow("encode --help") << QStringList{"encode", "--help"} << encode;
    QTest::newRow("help encode") << QStringList{"help", "encode"} << encode;
    QTest::newRow("encode NAME -h") << QStringList{"encode", "speed", "-h"} << encode;
    const QStringList decode{
        "Usage: lkctl decode [--series MS|MF|MG|MH] [--generation v2.3|v2.35] HEX...",
        "--binary",
        "'#' starts a comment",
        "bad_header_checksum",
        "truncated",
        "Examples:",
        "Exit status"};
    QTest::newRow("decode --help") << QStringList{"decode", "--help"} << decode;
    QTest::newRow("decode -h") << QStringList{"decode", "-h"} << decode;
    QTest::newRow("help decode") << QStringList{"help", "decode"} << decode;
}

void tst_Lkctl::help()
{
    QFETCH(QStringList, args);
    QFETCH(QStringList, mentions);
    const Result r = lkctl(args);
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.err, QByteArray());
    for (const QString &m : mentions)
        QVERIFY2(r.out.contains(m.toUtf8()), qPrintable(m));
}

void tst_Lkctl::helpListsEveryCommand()
{
    const Result r = lkctl({"encode", "--help"});
    QCOMPARE(r.exitCode, 0);
    for (const lk::protocol::CommandInfo &info : lk::protocol::CommandTable::all()) {
        const QByteArray entry =
            QByteArray("  ") + info.name + " (" +
            lk::protocol::CommandTable::codeText(quint8(info.command)).toLatin1() + ")";
        // CAN V2.36's 0xC0/0xC1 too (--link can236), marked as such.
        QVERIFY2(r.out.contains(info.canOnly ? entry + " can236" : entry), entry.constData());
    }
}

void tst_Lkctl::dispatcherErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("message");
    QTest::newRow("no arguments") << QStringList{} << QByteArray("Usage: lkctl COMMAND");
    QTest::newRow("unknown command")
        << QStringList{"frobnicate"} << QByteArray("unknown command 'frobnicate'");
    QTest::newRow("unknown option")
        << QStringList{"--frobnicate"} << QByteArray("unknown option '--frobnicate'");
    QTest::newRow("help on unknown")
        << QStringList{"help", "frobnicate"} << QByteArray("no command 'frobnicate'");
}

void tst_Lkctl::dispatcherErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, message);
    const Result r = lkctl(args);
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, QByteArray());
    QVERIFY2(r.err.contains(message), r.err.constData());
}

void tst_Lkctl::version()
{
    const Result r = lkctl({"--version"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out, QByteArray("lkctl " LK_VERSION "\n"));
}

QTEST_GUILESS_MAIN(tst_Lkctl)
#include "tst_lkctl.moc"
