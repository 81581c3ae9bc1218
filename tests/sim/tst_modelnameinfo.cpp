#include "motor/ModelNameInfo.h"

#include <QtTest/QTest>

using lk::motor::encoderCountsPerTurn;
using lk::motor::ModelNameInfo;
using lk::protocol::Series;

/// Motor-name parsing: series prefix, "-iN" gear ratio, "Nbit" encoder resolution.
class tst_ModelNameInfo : public QObject {
    Q_OBJECT
private slots:
    void parse_data();
    void parse();
    void countsPerTurn_data();
    void countsPerTurn();
};

void tst_ModelNameInfo::parse_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("series"); // "" = none
    QTest::addColumn<double>("gear");
    QTest::addColumn<bool>("gearFromName");
    QTest::addColumn<int>("bits");
    QTest::addColumn<bool>("bitsFromName");
    QTest::addColumn<int>("counts");

    QTest::newRow("MG geared, default 18 bit") << "MG5010E-i10"
                                               << "MG" << 10.0 << true << 18 << false << 65536;
    QTest::newRow("MG i36") << "MG4010E-i36"
                            << "MG" << 36.0 << true << 18 << false << 65536;
    QTest::newRow("lower case") << "mg8008e-i6"
                                << "MG" << 6.0 << true << 18 << false << 65536;
    QTest::newRow("MF 14 bit named") << "MF4015-14bit"
                                     << "MF" << 1.0 << false << 14 << true << 16384;
    QTest::newRow("MF 18 bit named") << "MF4015-18bit"
                                     << "MF" << 1.0 << false << 18 << true << 65536;
    QTest::newRow("MF default") << "MF4015"
                                << "MF" << 1.0 << false << 14 << false << 16384;
    QTest::newRow("MS default 12 bit") << "MS5005"
                                       << "MS" << 1.0 << false << 12 << false << 4096;
    QTest::newRow("MS 18 bit") << "MS5015-18bit"
                               << "MS" << 1.0 << false << 18 << true << 65536;
    QTest::newRow("MH default") << "MH7015"
                                << "MH" << 1.0 << false << 14 << false << 16384;
    QTest::newRow("15 bit with space") << "MF4015 15bit"
                                       << "MF" << 1.0 << false << 15 << true << 32768;
    QTest::newRow("gear and bits") << "MG6012-i8-18bit"
                                   << "MG" << 8.0 << true << 18 << true << 65536;
    QTest::newRow("vendor prefix") << "LK-MF4015"
                                   << "MF" << 1.0 << false << 14 << false << 16384;
    QTest::newRow("surrounding blanks") << "  MS5005  "
                                        << "MS" << 1.0 << false << 12 << false << 4096;
    QTest::newRow("ratio below 1 ignored") << "MG5010E-i0"
                                           << "MG" << 1.0 << false << 18 << false << 65536;
    QTest::newRow("absurd bits ignored") << "MF4015-64bit"
                                         << "MF" << 1.0 << false << 14 << false << 16384;
    QTest::newRow("empty") << ""
                           << "" << 1.0 << false << 14 << false << 16384;
    QTest::newRow("no series") << "XYZ-100"
                               << "" << 1.0 << false << 14 << false << 16384;
    QTest::newRow("word, not a series") << "MSG"
                                        << "" << 1.0 << false << 14 << false << 16384;
}

void tst_ModelNameInfo::parse()
{
    QFETCH(QString, name);
    QFETCH(QString, series);
    QFETCH(double, gear);
    QFETCH(bool, gearFromName);
    QFETCH(int, bits);
    QFETCH(bool, bitsFromName);
    QFETCH(int, counts);

    const ModelNameInfo info = ModelNameInfo::parse(name);
    QCOMPARE(info.name, name.trimmed());
    QCOMPARE(info.series.has_value(), !series.isEmpty());
    if (info.series)
        QCOMPARE(lk::protocol::seriesName(*info.series), series);
    QCOMPARE(info.gearRatio, gear);
    QCOMPARE(info.gearFromName, gearFromName);
    QCOMPARE(info.encoderBits, bits);
    QCOMPARE(info.encoderBitsFromName, bitsFromName);
    QCOMPARE(info.countsPerTurn(), counts);
}

void tst_ModelNameInfo::countsPerTurn_data()
{
    QTest::addColumn<int>("bits");
    QTest::addColumn<int>("counts");
    QTest::newRow("12") << 12 << 4096;
    QTest::newRow("14") << 14 << 16384;
    QTest::newRow("15") << 15 << 32768;
    QTest::newRow("16") << 16 << 65536;
    QTest::newRow("18 reports top 16 bits") << 18 << 65536;
    QTest::newRow("0") << 0 << 1;
}

void tst_ModelNameInfo::countsPerTurn()
{
    QFETCH(int, bits);
    QFETCH(int, counts);
    QCOMPARE(encoderCountsPerTurn(bits), counts);
}

QTEST_APPLESS_MAIN(tst_ModelNameInfo)
#include "tst_modelnameinfo.moc"
