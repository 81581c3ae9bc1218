// Series names as the command line and settings give them, and which series report power
// instead of iq (split from tst_reply).

#include <protocol/Series.h>

#include <QtTest/QTest>

#include <optional>

namespace proto = lk::protocol;
using lk::protocol::DecodeContext;
using lk::protocol::Series;

class tst_Series : public QObject {
    Q_OBJECT
private slots:
    void seriesNames_data();
    void seriesNames();
    void linksAndDialects();
};

void tst_Series::seriesNames_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("series"); ///< -1: refused
    QTest::addColumn<bool>("power");
    QTest::newRow("MS") << QStringLiteral("MS") << int(Series::MS) << true;
    QTest::newRow("MF") << QStringLiteral("MF") << int(Series::MF) << false;
    QTest::newRow("MG") << QStringLiteral("MG") << int(Series::MG) << false;
    QTest::newRow("MH") << QStringLiteral("MH") << int(Series::MH) << false;
    QTest::newRow("lower case") << QStringLiteral("ms") << int(Series::MS) << true;
    QTest::newRow("spaces") << QStringLiteral(" mg ") << int(Series::MG) << false;
    QTest::newRow("unknown") << QStringLiteral("MX") << -1 << false;
    QTest::newRow("empty") << QString() << -1 << false;
    QTest::newRow("model, not series") << QStringLiteral("MF4015") << -1 << false;
}

void tst_Series::seriesNames()
{
    QFETCH(QString, text);
    QFETCH(int, series);
    QFETCH(bool, power);
    const std::optional<Series> s = proto::seriesFromName(text);
    if (series < 0) {
        QVERIFY(!s.has_value());
        return;
    }
    QVERIFY(s.has_value());
    QCOMPARE(int(*s), series);
    QCOMPARE(proto::seriesName(*s), text.trimmed().toUpper());
    DecodeContext ctx;
    ctx.series = *s;
    QCOMPARE(ctx.reportsPower(), power);
}

void tst_Series::linksAndDialects()
{
    using proto::Generation;
    using proto::Link;
    QCOMPARE(proto::linkName(Link::Rs485), QStringLiteral("rs485"));
    QCOMPARE(proto::linkName(Link::Can), QStringLiteral("can"));
    QCOMPARE(proto::linkFromName(QStringLiteral(" CAN ")), std::optional<Link>(Link::Can));
    QCOMPARE(proto::linkFromName(QStringLiteral("rs485")), std::optional<Link>(Link::Rs485));
    QVERIFY(!proto::linkFromName(QStringLiteral("canfd")));
    DecodeContext ctx; // RS485 unless told otherwise: every existing caller keeps its meaning
    QCOMPARE(int(ctx.link), int(Link::Rs485));
    QVERIFY(!ctx.onCan());
    QCOMPARE(proto::dialectName(ctx), QStringLiteral("RS485 v2.3"));
    ctx.generation = Generation::V2_35;
    QCOMPARE(proto::dialectName(ctx), QStringLiteral("RS485 v2.35"));
    ctx.link = Link::Can;
    QVERIFY(ctx.onCan());
    QCOMPARE(proto::dialectName(ctx), QStringLiteral("CAN V2.36"));
    ctx.generation = Generation::V2_3;
    QCOMPARE(proto::dialectName(ctx), QStringLiteral("CAN (old)"));
}

QTEST_APPLESS_MAIN(tst_Series)
#include "tst_series.moc"
