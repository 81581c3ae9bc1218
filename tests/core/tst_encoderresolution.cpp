#include "motor/EncoderResolution.h"

#include <QtTest/QTest>

using lk::motor::EncoderResolution;
using lk::motor::ModelNameInfo;
using lk::protocol::Series;
using Source = EncoderResolution::Source;

/// The resolution believed for a drive: name hint or series default, raised by data, the
/// user's choice over both.
class tst_EncoderResolution : public QObject {
    Q_OBJECT
private slots:
    void startsFromNameOrSeries();
    void v235MsStartsAt16Bits();
    void raisesToSmallestThatHoldsTheValue_data();
    void raisesToSmallestThatHoldsTheValue();
    void neverLowers();
    void userChoiceWins();
    void refusesUnknownChoice();
    void largeRangeIsNotRaised();
};

void tst_EncoderResolution::startsFromNameOrSeries()
{
    const auto named =
        EncoderResolution::fromModel(ModelNameInfo::parse("MF4015-18bit"), Series::MF);
    QCOMPARE(named.bits(), 18);
    QCOMPARE(named.source(), Source::Name);
    const auto series = EncoderResolution::fromModel(ModelNameInfo::parse("MS4015"), Series::MS);
    QCOMPARE(series.bits(), 12);
    QCOMPARE(series.countsPerTurn(), 4096);
    QCOMPARE(series.source(), Source::SeriesDefault);
    const auto guess = EncoderResolution::fromModel(ModelNameInfo::parse("X"), std::nullopt);
    QCOMPARE(guess.bits(), 14);
    QCOMPARE(guess.source(), Source::Guess);
    QVERIFY(!guess.largestSeen());
}

void tst_EncoderResolution::v235MsStartsAt16Bits()
{
    // docs/V2.35.md section 12: the encoder field of an MS4015 on fw 2.35 spans 16 bits.
    const auto v235 = EncoderResolution::fromModel(ModelNameInfo::parse("MS4015"), Series::MS,
                                                   lk::protocol::Generation::V2_35);
    QCOMPARE(v235.bits(), 16);
    QCOMPARE(v235.source(), Source::Generation);
    // 6437 is then 35.36 deg, as the drive's single-turn angle says, not 141.44 (14 bit).
    QCOMPARE(qRound(36000.0 * 6437 / v235.countsPerTurn()), 3536);
    auto seen = v235;
    QVERIFY(!seen.observe(43388)); // within: nothing to raise
    QCOMPARE(seen.source(), Source::Generation);
    // The name's hint still comes first; V2.3 and other series keep their defaults.
    QCOMPARE(EncoderResolution::fromModel(ModelNameInfo::parse("MS4015-18bit"), Series::MS,
                                          lk::protocol::Generation::V2_35)
                 .source(),
             Source::Name);
    QCOMPARE(EncoderResolution::fromModel(ModelNameInfo::parse("MS4015"), Series::MS,
                                          lk::protocol::Generation::V2_3)
                 .bits(),
             12);
    QCOMPARE(EncoderResolution::fromModel(ModelNameInfo::parse("MF4015"), Series::MF,
                                          lk::protocol::Generation::V2_35)
                 .source(),
             Source::SeriesDefault);
}

void tst_EncoderResolution::raisesToSmallestThatHoldsTheValue_data()
{
    QTest::addColumn<int>("value");
    QTest::addColumn<int>("bits");
    QTest::addColumn<bool>("changed");
    QTest::addColumn<int>("source"); // Source
    QTest::newRow("inside 12 bit") << 4095 << 12 << false << int(Source::SeriesDefault);
    QTest::newRow("just beyond 12 bit") << 4096 << 14 << true << int(Source::Data);
    QTest::newRow("14 bit top") << 16383 << 14 << true << int(Source::Data);
    QTest::newRow("15 bit") << 16384 << 15 << true << int(Source::Data);
    QTest::newRow("real MS4015 on 2.35") << 43388 << 16 << true << int(Source::Data);
    QTest::newRow("16 bit top") << 65535 << 16 << true << int(Source::Data);
}

void tst_EncoderResolution::raisesToSmallestThatHoldsTheValue()
{
    QFETCH(int, value);
    QFETCH(int, bits);
    QFETCH(bool, changed);
    QFETCH(int, source);
    auto r = EncoderResolution::fromModel(ModelNameInfo::parse("MS4015"), Series::MS);
    QCOMPARE(r.observe(value), changed);
    QCOMPARE(r.bits(), bits);
    QCOMPARE(int(r.source()), source);
    QCOMPARE(r.largestSeen(), std::optional<int>(value));
}

void tst_EncoderResolution::neverLowers()
{
    auto r = EncoderResolution::fromModel(ModelNameInfo::parse("MS4015"), Series::MS);
    QVERIFY(r.observe(43388));
    QVERIFY(!r.observe(6437));
    QCOMPARE(r.bits(), 16);
    QCOMPARE(r.largestSeen(), std::optional<int>(43388));
    QVERIFY(!r.observe(-1)); // not a reported value
    QCOMPARE(r.largestSeen(), std::optional<int>(43388));
}

void tst_EncoderResolution::userChoiceWins()
{
    auto r = EncoderResolution::fromModel(ModelNameInfo::parse("MS4015"), Series::MS);
    QVERIFY(r.setUserBits(12));
    QCOMPARE(r.source(), Source::User);
    QVERIFY(!r.observe(43388)); // the choice stays in force ...
    QCOMPARE(r.bits(), 12);
    QVERIFY(r.contradictedByData()); // ... and the data that contradicts it is known
    QVERIFY(r.setUserBits(16));
    QVERIFY(!r.contradictedByData());
    QCOMPARE(r.userBits(), std::optional<int>(16));
}

void tst_EncoderResolution::refusesUnknownChoice()
{
    auto r = EncoderResolution::fromModel(ModelNameInfo::parse("MF4015"), Series::MF);
    QVERIFY(!r.setUserBits(13));
    QCOMPARE(r.bits(), 14);
    QCOMPARE(r.source(), Source::SeriesDefault);
}

void tst_EncoderResolution::largeRangeIsNotRaised()
{
    // An 18-bit MG reports its top 16 bits: every value fits, nothing is claimed from data.
    auto r = EncoderResolution::fromModel(ModelNameInfo::parse("MG5010E-i10"), Series::MG);
    QVERIFY(!r.observe(65535));
    QCOMPARE(r.bits(), 18);
    QCOMPARE(r.source(), Source::SeriesDefault);
}

QTEST_APPLESS_MAIN(tst_EncoderResolution)
#include "tst_encoderresolution.moc"
