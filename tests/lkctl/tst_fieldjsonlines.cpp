// FieldJson over a byte stream: one JSON line per parser event (frames, faults), the line
// format, and hex text.

#include "FieldJsonTestUtil.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QRegularExpression>
#include <QtTest/QtTest>

using namespace lk::protocol;
using namespace lk::fieldjsontest;

class tst_FieldJsonLines : public QObject {
    Q_OBJECT
private slots:
    void eventLines_data();
    void eventLines();
    void jsonLineFormatting_data();
    void jsonLineFormatting();
    void hexText();
};

void tst_FieldJsonLines::eventLines_data()
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

void tst_FieldJsonLines::eventLines()
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

void tst_FieldJsonLines::jsonLineFormatting_data()
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

void tst_FieldJsonLines::jsonLineFormatting()
{
    QFETCH(QJsonObject, object);
    QFETCH(QByteArray, expected);
    const QByteArray got = FieldJson::toJsonLine(object);
    QCOMPARE(got, expected);
    QVERIFY(sameJson(QJsonDocument::fromJson(got).object(), object));
}

void tst_FieldJsonLines::hexText()
{
    QCOMPARE(FieldJson::hexText(QByteArray()), QString());
    QCOMPARE(FieldJson::hexText(fromHex("3ea4ff00")), QStringLiteral("3E A4 FF 00"));
    QCOMPARE(FieldJson::errorObject(ParseError::Truncated, fromHex("3e9c")),
             (QJsonObject{{"error", "truncated"}, {"bytes", "3E 9C"}}));
}

QTEST_APPLESS_MAIN(tst_FieldJsonLines)
#include "tst_fieldjsonlines.moc"
