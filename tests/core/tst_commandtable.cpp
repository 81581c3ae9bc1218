#include "protocol/Command.h"

#include <QtCore/QSet>
#include <QtTest/QTest>

using lk::protocol::Command;
using lk::protocol::CommandInfo;
using lk::protocol::CommandTable;

/// The command table against CLI.md (names, codes) and docs/ERRATA.md (lengths, flags).
class tst_CommandTable : public QObject {
    Q_OBJECT

private slots:
    void everyCommand_data();
    void everyCommand();
    void tableHasExactly33DistinctEntries();
    void unknownCodes_data();
    void unknownCodes();
    void onlyTheTableCodesAreKnown();
    void unknownNames_data();
    void unknownNames();
    void codeText_data();
    void codeText();
    void availabilityByLink_data();
    void availabilityByLink();
};

namespace {
// The V2.3 command set as written in CLI.md, docs/ERRATA.md and the vendor spec, by hand, and the
// five commands V2.35 added (docs/V2.35.md section 4).
// Columns: code, name, request LEN, reply LEN, alt reply LEN, echo, moves motor, writes flash.
struct Expected {
    int code;
    const char *name;
    int req, reply, alt;
    bool echo, moves, flash;
};
const Expected kExpected[] = {
    {0x30, "read_pid", 0, 6, -1, false, false, false},
    {0x31, "write_pid_ram", 6, 6, -1, true, false, false},
    {0x32, "write_pid_rom", 6, 6, -1, true, false, true},
    {0x33, "read_accel", 0, 4, -1, false, false, false},
    {0x34, "write_accel_ram", 4, 4, -1, true, false, false},
    {0x90, "read_encoder", 0, 6, -1, false, false, false},
    {0x91, "write_encoder_offset", 2, 2, -1, true, false, true}, // the spec's table: "到 ROM"
    {0x19, "write_zero_rom", 0, 0, 2, true, false, true},
    {0x92, "read_multi_turn", 0, 8, -1, false, false, false},
    {0x94, "read_single_turn", 0, 4, -1, false, false, false},
    {0x95, "clear_angle", 0, 0, -1, true, false, false},
    {0x9A, "read_state1", 0, 7, -1, false, false, false},
    {0x9B, "clear_errors", 0, 7, -1, false, false, false},
    {0x9C, "read_state2", 0, 7, -1, false, false, false},
    {0x9D, "read_state3", 0, 7, -1, false, false, false},
    {0x80, "motor_off", 0, 0, -1, true, false, false},
    {0x81, "motor_stop", 0, 0, -1, true, false, false},
    {0x88, "motor_run", 0, 0, -1, true, true, false},
    {0xA0, "open_loop", 2, 7, -1, false, true, false},
    {0xA1, "torque", 2, 7, -1, false, true, false},
    {0xA2, "speed", 4, 7, -1, false, true, false},
    {0xA3, "multi_position", 8, 7, -1, false, true, false},
    {0xA4, "multi_position_limited", 12, 7, -1, false, true, false},
    {0xA5, "single_position", 4, 7, -1, false, true, false},
    {0xA6, "single_position_limited", 8, 7, -1, false, true, false},
    {0xA7, "increment_position", 4, 7, -1, false, true, false},         // ERRATA: LEN 4, not 3
    {0xA8, "increment_position_limited", 8, 7, -1, false, true, false}, // ERRATA: reply LEN 7
    {0x12, "read_model", 0, 42, 58, false, false, false},
    {0x40, "read_param", 2, 7, -1, false, false, false},
    {0x42, "write_param_ram", 7, 2, -1, false, false, false},
    {0x44, "write_param_rom", 7, 2, -1, false, false, true},
    {0x8C, "brake", 1, 1, -1, false, false, false},
    {0x93, "clear_turn_count", 0, 0, -1, true, false, false}, // PDF "8 byte" is a typo
    // CAN V2.36 only (docs/CAN.md section 4.1): lengths of a CAN frame's B1..B7, RAM only.
    {0xC0, "read_control_param", 7, 7, -1, false, false, false},
    {0xC1, "write_control_param", 7, 7, -1, false, false, false},
};
constexpr int kRs485Commands = 33;
constexpr int kCanOnlyCommands = 2;

bool isExpectedCode(int code)
{
    for (const Expected &e : kExpected) {
        if (e.code == code)
            return true;
    }
    return false;
}
} // namespace

void tst_CommandTable::everyCommand_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("codeText");
    QTest::addColumn<int>("requestLength");
    QTest::addColumn<int>("replyLength");
    QTest::addColumn<int>("altReplyLength");
    QTest::addColumn<bool>("echo");
    QTest::addColumn<bool>("moves");
    QTest::addColumn<bool>("flash");
    for (const Expected &e : kExpected) {
        const QString text = QStringLiteral("0x") +
                             QStringLiteral("%1").arg(e.code, 2, 16, QLatin1Char('0')).toUpper();
        QTest::newRow(e.name) << e.code << QString::fromLatin1(e.name) << text << e.req << e.reply
                              << e.alt << e.echo << e.moves << e.flash;
    }
}

void tst_CommandTable::everyCommand()
{
    QFETCH(int, code);
    QFETCH(QString, name);
    QFETCH(QString, codeText);
    QFETCH(int, requestLength);
    QFETCH(int, replyLength);
    QFETCH(int, altReplyLength);
    QFETCH(bool, echo);
    QFETCH(bool, moves);
    QFETCH(bool, flash);

    const CommandInfo *info = CommandTable::find(static_cast<quint8>(code));
    QVERIFY(info);
    QCOMPARE(static_cast<int>(info->command), code);
    QCOMPARE(QString::fromLatin1(info->name), name);
    QCOMPARE(int(info->requestLength), requestLength);
    QCOMPARE(int(info->replyLength), replyLength);
    QCOMPARE(int(info->altReplyLength), altReplyLength);
    QCOMPARE(info->replyEchoesRequest, echo);
    QCOMPARE(info->movesMotor, moves);
    QCOMPARE(info->writesFlash, flash);

    const auto command = static_cast<Command>(code);
    QCOMPARE(&CommandTable::info(command), info);
    QCOMPARE(CommandTable::name(command), name);
    const std::optional<Command> byName = CommandTable::fromName(name);
    QVERIFY(byName.has_value());
    QCOMPARE(static_cast<int>(*byName), code);
    QCOMPARE(CommandTable::codeText(static_cast<quint8>(code)), codeText);
}

void tst_CommandTable::tableHasExactly33DistinctEntries()
{
    QCOMPARE(CommandTable::kCount, kRs485Commands + kCanOnlyCommands);
    QCOMPARE(int(CommandTable::all().size()), CommandTable::kCount);
    int rs485 = 0;
    QSet<int> codes;
    QSet<QString> names;
    for (const CommandInfo &c : CommandTable::all()) {
        codes.insert(static_cast<int>(c.command));
        names.insert(QString::fromLatin1(c.name));
        QVERIFY2(isExpectedCode(static_cast<int>(c.command)), c.name);
        QCOMPARE(CommandTable::find(static_cast<quint8>(c.command)), &c);
        // An RS485 frame never carries a CAN-only code: the stream parser calls it unknown.
        QCOMPARE(CommandTable::findOnRs485(static_cast<quint8>(c.command)),
                 c.canOnly ? nullptr : &c);
        rs485 += c.canOnly ? 0 : 1;
    }
    QCOMPARE(rs485, kRs485Commands);
    QCOMPARE(codes.size(), CommandTable::kCount);
    QCOMPARE(names.size(), CommandTable::kCount);
}

void tst_CommandTable::unknownCodes_data()
{
    QTest::addColumn<int>("code");
    // Neighbours of real codes (0x41/0x43 between the parameter commands, 0x89 which the
    // vendor tool uses but no document defines, 0x07 the undocumented reboot), the frame head
    // and the extremes.
    const int codes[] = {0x00, 0x01, 0x07, 0x11, 0x13, 0x18, 0x1A, 0x2F, 0x35, 0x3E,
                         0x41, 0x43, 0x45, 0x7F, 0x82, 0x87, 0x89, 0x8B, 0x8D, 0x8F,
                         0x96, 0x99, 0x9E, 0x9F, 0xA9, 0xAF, 0xB0, 0xFE, 0xFF};
    for (int c : codes)
        QTest::newRow(qPrintable(CommandTable::codeText(static_cast<quint8>(c)))) << c;
}

void tst_CommandTable::unknownCodes()
{
    QFETCH(int, code);
    QVERIFY(CommandTable::find(static_cast<quint8>(code)) == nullptr);
}

void tst_CommandTable::onlyTheTableCodesAreKnown()
{
    int known = 0;
    for (int code = 0; code < 256; ++code) {
        const bool found = CommandTable::find(static_cast<quint8>(code)) != nullptr;
        QVERIFY2(found == isExpectedCode(code), qPrintable(QString::number(code, 16)));
        known += found ? 1 : 0;
    }
    QCOMPARE(known, CommandTable::kCount);
}

void tst_CommandTable::unknownNames_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("empty") << QString();
    QTest::newRow("prefix of a name") << QStringLiteral("motor_of");
    QTest::newRow("longer than a name") << QStringLiteral("motor_offf");
    QTest::newRow("space instead of underscore") << QStringLiteral("motor off");
    QTest::newRow("dash instead of underscore") << QStringLiteral("read-state2");
    QTest::newRow("code text") << QStringLiteral("0x80");
    QTest::newRow("no such state") << QStringLiteral("read_state4");
    QTest::newRow("no such command") << QStringLiteral("brakes");
}

void tst_CommandTable::unknownNames()
{
    QFETCH(QString, name);
    QVERIFY(!CommandTable::fromName(name).has_value());
}

void tst_CommandTable::codeText_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("text");
    QTest::newRow("0x00") << 0x00 << QStringLiteral("0x00");
    QTest::newRow("0x0A: leading zero, upper-case digit") << 0x0A << QStringLiteral("0x0A");
    QTest::newRow("0x12") << 0x12 << QStringLiteral("0x12");
    QTest::newRow("0x3E") << 0x3E << QStringLiteral("0x3E");
    QTest::newRow("0x9C") << 0x9C << QStringLiteral("0x9C");
    QTest::newRow("0xA2") << 0xA2 << QStringLiteral("0xA2");
    QTest::newRow("0xAB: all letters") << 0xAB << QStringLiteral("0xAB");
    QTest::newRow("0xFF") << 0xFF << QStringLiteral("0xFF");
}

void tst_CommandTable::codeText()
{
    QFETCH(int, code);
    QFETCH(QString, text);
    QCOMPARE(CommandTable::codeText(static_cast<quint8>(code)), text);
}

void tst_CommandTable::availabilityByLink_data()
{
    // docs/CAN.md section 3, written out by hand: on RS485 V2.3, RS485 V2.35, CAN old, CAN V2.36.
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("on"); ///< four flags: "1" = available
    QTest::newRow("0x12 read_model") << 0x12 << "1100";
    QTest::newRow("0x30 read_pid") << 0x30 << "1010";
    QTest::newRow("0x32 write_pid_rom") << 0x32 << "1010";
    QTest::newRow("0x34 write_accel_ram") << 0x34 << "1010";
    QTest::newRow("0x40 read_param") << 0x40 << "0100";
    QTest::newRow("0x44 write_param_rom") << 0x44 << "0100";
    QTest::newRow("0x91 write_encoder_offset") << 0x91 << "1010";
    QTest::newRow("0x93 clear_turn_count") << 0x93 << "0100";
    QTest::newRow("0x95 clear_angle") << 0x95 << "1101";
    QTest::newRow("0x8C brake") << 0x8C << "0101";
    QTest::newRow("0x19 write_zero_rom") << 0x19 << "1111";
    QTest::newRow("0x80 motor_off") << 0x80 << "1111";
    QTest::newRow("0x92 read_multi_turn") << 0x92 << "1111";
    QTest::newRow("0x9A read_state1") << 0x9A << "1111";
    QTest::newRow("0xA2 speed") << 0xA2 << "1111";
    QTest::newRow("0xA8 increment_position_limited") << 0xA8 << "1111";
    QTest::newRow("0xC0 read_control_param") << 0xC0 << "0001";
    QTest::newRow("0xC1 write_control_param") << 0xC1 << "0001";
}

void tst_CommandTable::availabilityByLink()
{
    using lk::protocol::DecodeContext;
    using lk::protocol::Generation;
    using lk::protocol::Link;
    using lk::protocol::Series;
    QFETCH(int, code);
    QFETCH(QString, on);
    const Command c = CommandTable::find(quint8(code))->command;
    const DecodeContext contexts[] = {{Series::MF, Generation::V2_3, Link::Rs485},
                                      {Series::MF, Generation::V2_35, Link::Rs485},
                                      {Series::MF, Generation::V2_3, Link::Can},
                                      {Series::MF, Generation::V2_35, Link::Can}};
    for (int i = 0; i < 4; ++i)
        QCOMPARE(CommandTable::availableOn(c, contexts[i]), on[i] == QLatin1Char('1'));
    // On RS485 the context answers as the generation alone.
    QCOMPARE(CommandTable::availableOn(c, contexts[0]),
             CommandTable::availableOn(c, Generation::V2_3));
    QCOMPARE(CommandTable::availableOn(c, contexts[1]),
             CommandTable::availableOn(c, Generation::V2_35));
}

QTEST_APPLESS_MAIN(tst_CommandTable)
#include "tst_commandtable.moc"
