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

QTEST_APPLESS_MAIN(tst_Series)
#include "tst_series.moc"
