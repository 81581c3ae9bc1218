#include "motor/SeriesLimits.h"

#include <QtTest/QTest>

using lk::motor::seriesLimits;
using lk::motor::supports;
using lk::protocol::Command;
using lk::protocol::CommandTable;
using lk::protocol::Series;

Q_DECLARE_METATYPE(Series)
Q_DECLARE_METATYPE(Command)

/// Series capabilities against the series table in docs/ERRATA.md.
class tst_SeriesLimits : public QObject {
    Q_OBJECT
private slots:
    void limits_data();
    void limits();
    void supportsCommand_data();
    void supportsCommand();
    void commonCommandsEverywhere_data();
    void commonCommandsEverywhere();
};

void tst_SeriesLimits::limits_data()
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<double>("minV");
    QTest::addColumn<double>("maxV");
    QTest::addColumn<double>("maxA");
    QTest::addColumn<double>("rpm");
    QTest::addColumn<QList<int>>("bits");
    QTest::addColumn<int>("defaultBits");
    QTest::addColumn<bool>("power");
    QTest::addColumn<bool>("gearbox");

    QTest::newRow("MS") << Series::MS << 7.4 << 24.0 << 4.0 << 1000.0 << QList<int>{12, 18} << 12
                        << true << false;
    QTest::newRow("MF") << Series::MF << 12.0 << 36.0 << 9.0 << 3000.0 << QList<int>{14, 18} << 14
                        << false << false;
    QTest::newRow("MG") << Series::MG << 24.0 << 48.0 << 14.0 << 2000.0 << QList<int>{18} << 18
                        << false << true;
    QTest::newRow("MH") << Series::MH << 12.0 << 24.0 << 4.0 << 3000.0 << QList<int>{14} << 14
                        << false << false;
}

void tst_SeriesLimits::limits()
{
    QFETCH(Series, series);
    QFETCH(double, minV);
    QFETCH(double, maxV);
    QFETCH(double, maxA);
    QFETCH(double, rpm);
    QFETCH(QList<int>, bits);
    QFETCH(int, defaultBits);
    QFETCH(bool, power);
    QFETCH(bool, gearbox);

    const auto &l = seriesLimits(series);
    QCOMPARE(l.series, series);
    QCOMPARE(l.minSupplyV, minV);
    QCOMPARE(l.maxSupplyV, maxV);
    QCOMPARE(l.maxCurrentA, maxA);
    QCOMPARE(l.maxSpeedRpm, rpm);
    QCOMPARE(l.maxSpeedDps(), rpm * 6.0);
    QCOMPARE(l.encoderBits, bits);
    QCOMPARE(l.defaultEncoderBits, defaultBits);
    QVERIFY(l.encoderBits.contains(l.defaultEncoderBits));
    QCOMPARE(l.repliesCarryPower, power);
    QCOMPARE(l.hasGearbox, gearbox);
    QVERIFY(l.nominalSupplyV >= l.minSupplyV && l.nominalSupplyV <= l.maxSupplyV);
}

void tst_SeriesLimits::supportsCommand_data()
{
    QTest::addColumn<Series>("series");
    QTest::addColumn<Command>("command");
    QTest::addColumn<bool>("expected");

    // MS: open loop instead of torque, no phase currents (ERRATA "Series capabilities").
    QTest::newRow("MS open_loop") << Series::MS << Command::OpenLoop << true;
    QTest::newRow("MS torque") << Series::MS << Command::Torque << false;
    QTest::newRow("MS read_state3") << Series::MS << Command::ReadState3 << false;
    QTest::newRow("MS speed") << Series::MS << Command::Speed << true;
    QTest::newRow("MS multi_position") << Series::MS << Command::MultiPosition << true;
    for (Series s : {Series::MF, Series::MG, Series::MH}) {
        const QByteArray name = lk::protocol::seriesName(s).toLatin1();
        QTest::newRow(name + " open_loop") << s << Command::OpenLoop << false;
        QTest::newRow(name + " torque") << s << Command::Torque << true;
        QTest::newRow(name + " read_state3") << s << Command::ReadState3 << true;
        QTest::newRow(name + " speed") << s << Command::Speed << true;
        QTest::newRow(name + " increment") << s << Command::IncrementPositionLimited << true;
    }
}

void tst_SeriesLimits::supportsCommand()
{
    QFETCH(Series, series);
    QFETCH(Command, command);
    QFETCH(bool, expected);
    QCOMPARE(supports(series, command), expected);
}

void tst_SeriesLimits::commonCommandsEverywhere_data()
{
    QTest::addColumn<Series>("series");
    QTest::newRow("MS") << Series::MS;
    QTest::newRow("MF") << Series::MF;
    QTest::newRow("MG") << Series::MG;
    QTest::newRow("MH") << Series::MH;
}

void tst_SeriesLimits::commonCommandsEverywhere()
{
    // Only 0xA0, 0xA1 and 0x9D depend on the series; every other command works on all.
    QFETCH(Series, series);
    int unsupported = 0;
    for (const auto &info : CommandTable::all()) {
        if (!supports(series, info.command)) {
            ++unsupported;
            QVERIFY2(info.command == Command::OpenLoop || info.command == Command::Torque ||
                         info.command == Command::ReadState3,
                     info.name);
        }
    }
    QCOMPARE(unsupported, series == Series::MS ? 2 : 1);
}

QTEST_APPLESS_MAIN(tst_SeriesLimits)
#include "tst_serieslimits.moc"
