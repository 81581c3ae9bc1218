// The CAN transport's record (CanRecord) and the CAN FrameParser (CanRecordParser): the
// record's bytes written by hand from its documented layout, every split point of a stream of
// records, the direction of frames at the host and the drive end, and what is not a
// ParseEvent (error frames, frames of other devices).

#include "ProtocolTestUtil.h"

#include <protocol/CanRecord.h>
#include <protocol/CanRecordParser.h>
#include <protocol/StreamParser.h>

#include <QtTest/QTest>

namespace proto = lk::protocol;
using lk::test::EventLog;
using lk::test::hex;
using proto::CanRecord;
using proto::CanRecordParser;
using proto::FrameDirection;
using proto::LinkEnd;
using proto::ParseError;

namespace {
CanRecord record(quint32 id, const char *data, quint8 flags = 0, qint64 us = 0)
{
    CanRecord r;
    r.canId = id;
    r.data = hex(data);
    r.flags = flags;
    r.timestampUs = us;
    return r;
}
} // namespace

class tst_CanRecordParser : public QObject {
    Q_OBJECT
private slots:
    void recordLayout();
    void recordRefusesOtherVersionsAndDlc_data();
    void recordRefusesOtherVersionsAndDlc();
    void candumpText();
    void candumpLog_data();
    void candumpLog();
    void candumpRefused_data();
    void candumpRefused();
    void direction_data();
    void direction();
    void everySplitPoint();
    void faults();
    void notParseEvents();
    void factoryChoosesByLink();
};

void tst_CanRecordParser::recordLayout()
{
    // version 1 | id 0x141 LE | flags | DLC 8 | data | timestamp 0x0102030405060708 LE
    const CanRecord r = record(0x141, "9C00000000000000", CanRecord::Echo, 0x0102030405060708);
    const QByteArray expected = hex("01 41010000 01 08 9C00000000000000 0807060504030201");
    QCOMPARE(r.encode(), expected);
    QCOMPARE(r.encode().size(), CanRecord::kSize);
    QCOMPARE(CanRecord::decode(expected), std::optional<CanRecord>(r));
    // A short frame: bytes past the DLC are 0 on the wire and absent once read.
    const CanRecord shortFrame = record(0x7FF, "AABB");
    QCOMPARE(shortFrame.encode(), hex("01 FF070000 00 02 AABB000000000000 0000000000000000"));
    QCOMPARE(CanRecord::decode(shortFrame.encode())->data, hex("AABB"));
}

void tst_CanRecordParser::recordRefusesOtherVersionsAndDlc_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::newRow("version 2") << hex("02 41010000 00 08 9C00000000000000 0000000000000000");
    QTest::newRow("version 0") << hex("00 41010000 00 08 9C00000000000000 0000000000000000");
    QTest::newRow("DLC 9") << hex("01 41010000 00 09 9C00000000000000 0000000000000000");
    QTest::newRow("unknown flag") << hex("01 41010000 80 08 9C00000000000000 0000000000000000");
    QTest::newRow("short") << hex("01 41010000 00 08 9C00000000000000 00000000000000");
    QTest::newRow("empty") << QByteArray();
}

void tst_CanRecordParser::recordRefusesOtherVersionsAndDlc()
{
    QFETCH(QByteArray, bytes);
    QVERIFY(!CanRecord::decode(bytes));
}

void tst_CanRecordParser::candumpText()
{
    QCOMPARE(record(0x141, "9C00000000000000").candumpText(),
             QStringLiteral("141#9C00000000000000"));
    QCOMPARE(record(0x280, "64009CFF00000000").candumpText(),
             QStringLiteral("280#64009CFF00000000"));
    QCOMPARE(record(0x1ABCDEF0, "01", CanRecord::Extended).candumpText(),
             QStringLiteral("1ABCDEF0#01"));
    QCOMPARE(record(0x7, "").candumpText(), QStringLiteral("007#"));
}

void tst_CanRecordParser::candumpLog_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<quint32>("id");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<int>("flags");
    QTest::addColumn<qint64>("us");
    QTest::addColumn<QString>("written"); ///< candumpLogLine("can0") of the record
    QTest::newRow("candump -L") << "(1700000000.123456) can0 141#9C00000000000000" << 0x141u
                                << hex("9C00000000000000") << 0 << qint64(1700000000123456)
                                << "(1700000000.123456) can0 141#9C00000000000000";
    QTest::newRow("bare, lower case") << "181#9c326400f4010020" << 0x181u << hex("9C326400F4010020")
                                      << 0 << qint64(0) << "(0.000000) can0 181#9C326400F4010020";
    QTest::newRow("short fraction")
        << "(12.5) vcan0 280#64009CFF00000000" << 0x280u << hex("64009CFF00000000") << 0
        << qint64(12500000) << "(12.500000) can0 280#64009CFF00000000";
    QTest::newRow("29-bit ID") << "(1.000001) can0 1ABCDEF0#01" << 0x1ABCDEF0u << hex("01")
                               << int(CanRecord::Extended) << qint64(1000001)
                               << "(1.000001) can0 1ABCDEF0#01";
    QTest::newRow("error frame") << "(2.000000) can0 20000040#0000000000000000" << 0x40u
                                 << hex("0000000000000000") << int(CanRecord::Error)
                                 << qint64(2000000) << "(2.000000) can0 20000040#0000000000000000";
    QTest::newRow("no data") << "7FF#" << 0x7FFu << QByteArray() << 0 << qint64(0)
                             << "(0.000000) can0 7FF#";
}

void tst_CanRecordParser::candumpLog()
{
    QFETCH(QString, line);
    QFETCH(quint32, id);
    QFETCH(QByteArray, data);
    QFETCH(int, flags);
    QFETCH(qint64, us);
    QFETCH(QString, written);
    const std::optional<CanRecord> r = CanRecord::fromCandump(line);
    QVERIFY(r);
    QCOMPARE(r->canId, id);
    QCOMPARE(r->data, data);
    QCOMPARE(int(r->flags), flags);
    QCOMPARE(r->timestampUs, us);
    QCOMPARE(r->candumpLogLine(QStringLiteral("can0")), written);
    QCOMPARE(CanRecord::fromCandump(written), r); // what we write, we read back
}

void tst_CanRecordParser::candumpRefused_data()
{
    QTest::addColumn<QString>("line");
    QTest::newRow("empty") << QString();
    QTest::newRow("odd hex digits") << "141#9C0";
    QTest::newRow("nine bytes") << "141#9C000000000000000A";
    QTest::newRow("remote frame") << "141#R";
    QTest::newRow("CAN FD") << "141##0112233";
    QTest::newRow("11-bit ID beyond 0x7FF") << "800#00";
    QTest::newRow("4-digit ID") << "0141#00";
    QTest::newRow("no interface after the time") << "(1.0) 141#00";
    QTest::newRow("RS485 hex") << "3E 9C 01 00 DB";
}

void tst_CanRecordParser::candumpRefused()
{
    QFETCH(QString, line);
    QVERIFY(!CanRecord::fromCandump(line));
}

void tst_CanRecordParser::direction_data()
{
    QTest::addColumn<int>("end");
    QTest::addColumn<quint32>("canId");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<int>("flags");
    QTest::addColumn<int>("direction");
    const QByteArray read = hex("9C00000000000000");
    const QByteArray off = hex("8000000000000000");
    const int host = int(LinkEnd::Host), drive = int(LinkEnd::Drive);
    QTest::newRow("host: old reply on 0x141")
        << host << 0x141u << read << 0 << int(FrameDirection::Reply);
    QTest::newRow("host: V2.36 reply on 0x181")
        << host << 0x181u << read << 0 << int(FrameDirection::Reply);
    QTest::newRow("host: our request, echoed")
        << host << 0x141u << read << int(CanRecord::Echo) << int(FrameDirection::Request);
    QTest::newRow("host: motor_off answer is an echo")
        << host << 0x141u << off << 0 << int(FrameDirection::Echo);
    QTest::newRow("drive: request on 0x141")
        << drive << 0x141u << read << 0 << int(FrameDirection::Request);
    QTest::newRow("drive: its own reply, echoed")
        << drive << 0x181u << read << int(CanRecord::Echo) << int(FrameDirection::Reply);
    QTest::newRow("drive: another drive's reply on 0x182")
        << drive << 0x182u << read << 0 << int(FrameDirection::Reply);
}

void tst_CanRecordParser::direction()
{
    QFETCH(int, end);
    QFETCH(quint32, canId);
    QFETCH(QByteArray, data);
    QFETCH(int, flags);
    QFETCH(int, direction);
    CanRecord r;
    r.canId = canId;
    r.data = data;
    r.flags = quint8(flags);
    CanRecordParser parser{LinkEnd(end)};
    EventLog log;
    parser.feed(r.encode(), log.sink());
    QCOMPARE(int(log.events.size()), 1);
    const proto::ParseEvent &ev = log.events[0];
    QVERIFY(ev.isFrame);
    QCOMPARE(int(ev.direction), direction);
    QCOMPARE(ev.frame.command, quint8(data[0]));
    QCOMPARE(ev.frame.id, quint8(canId >= 0x180 ? canId - 0x180 : canId - 0x140));
    QCOMPARE(ev.frame.data, data.mid(1));
    QCOMPARE(ev.bytes, r.encode());
}

void tst_CanRecordParser::everySplitPoint()
{
    QByteArray stream;
    for (quint32 id = 0x141; id < 0x145; ++id)
        stream += record(id, "9C326400F4010020").encode();
    for (int cut = 0; cut <= stream.size(); ++cut) {
        CanRecordParser parser;
        EventLog log;
        parser.feed(stream.left(cut), log.sink());
        QCOMPARE(parser.pendingBytes(), qsizetype(cut % CanRecord::kSize));
        parser.feed(stream.mid(cut), log.sink());
        QCOMPARE(int(log.events.size()), 4);
        for (int i = 0; i < 4; ++i) {
            QVERIFY(log.events[size_t(i)].isFrame);
            QCOMPARE(log.events[size_t(i)].frame.id, quint8(i + 1));
        }
        QCOMPARE(parser.pendingBytes(), qsizetype(0));
    }
}

void tst_CanRecordParser::faults()
{
    CanRecordParser parser;
    EventLog log;
    QByteArray bad = record(0x141, "9C00000000000000").encode();
    bad[0] = 9;                                                          // another version
    parser.feed(record(0x141, "9C00").encode(), log.sink());             // DLC 2
    parser.feed(record(0x141, "EE00000000000000").encode(), log.sink()); // unknown B0
    parser.feed(bad, log.sink());
    parser.feed(hex("0141"), log.sink());
    parser.finish(log.sink());
    QCOMPARE(int(log.events.size()), 4);
    QCOMPARE(int(log.events[0].error), int(ParseError::BadLength));
    QCOMPARE(log.events[0].frame.id, quint8(1)); // a fault that names its drive
    QCOMPARE(int(log.events[1].error), int(ParseError::UnknownCommand));
    QCOMPARE(log.events[1].frame.command, quint8(0xEE));
    QCOMPARE(int(log.events[2].error), int(ParseError::Garbage));
    QCOMPARE(log.events[2].bytes, bad);
    QCOMPARE(int(log.events[3].error), int(ParseError::Truncated));
    QCOMPARE(log.events[3].bytes, hex("0141"));
    for (const auto &e : log.events)
        QVERIFY(!e.isFrame);
}

void tst_CanRecordParser::notParseEvents()
{
    CanRecordParser parser;
    QList<CanRecord> errors, others;
    parser.setErrorFrameSink([&](const CanRecord &r) { errors.append(r); });
    parser.setOtherFrameSink([&](const CanRecord &r) { others.append(r); });
    EventLog log;
    const CanRecord busOff = record(0x40, "0000000000000000", CanRecord::Error);
    parser.feed(busOff.encode(), log.sink());
    parser.feed(record(0x280, "64009CFF00000000").encode(), log.sink());
    parser.feed(record(0x123, "01").encode(), log.sink());
    parser.feed(record(0x141, "9C00000000000000", CanRecord::Extended).encode(), log.sink());
    QVERIFY(log.events.empty());
    QCOMPARE(errors.size(), 1);
    QCOMPARE(errors[0], busOff);
    QCOMPARE(others.size(), 3);
    QCOMPARE(parser.errorFrames(), quint64(1));
    QCOMPARE(parser.otherFrames(), quint64(3));
}

void tst_CanRecordParser::factoryChoosesByLink()
{
    const auto can = proto::makeFrameParser(proto::Link::Can);
    const auto rs485 = proto::makeFrameParser(proto::Link::Rs485);
    QVERIFY(dynamic_cast<CanRecordParser *>(can.get()));
    QVERIFY(dynamic_cast<proto::StreamParser *>(rs485.get()));
    EventLog log;
    rs485->feed(hex("3E 80 01 00 BF"), log.sink());
    QCOMPARE(int(log.events.size()), 1);
    QVERIFY(log.events[0].isFrame);
}

QTEST_APPLESS_MAIN(tst_CanRecordParser)
#include "tst_canrecordparser.moc"
