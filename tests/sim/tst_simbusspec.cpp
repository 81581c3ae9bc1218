#include "sim/SimBusSpec.h"

#include <QtTest/QTest>

using lk::protocol::Series;
using lk::sim::SimBusSpec;

/// The --sim/--motors syntax "3:MF,17:MS,32:MG".
class tst_SimBusSpec : public QObject {
    Q_OBJECT
private slots:
    void valid_data();
    void valid();
    void invalid_data();
    void invalid();
    void motorNameEntry();
    void quirksReachTheModel();
};

void tst_SimBusSpec::valid_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QList<int>>("ids");
    QTest::addColumn<QStringList>("series");
    QTest::addColumn<QString>("canonical");
    QTest::newRow("brief example") << "3:MF,17:MS,32:MG" << QList<int>{3, 17, 32}
                                   << QStringList{"MF", "MS", "MG"} << "3:MF,17:MS,32:MG";
    QTest::newRow("one drive") << "1:MH" << QList<int>{1} << QStringList{"MH"} << "1:MH";
    QTest::newRow("blanks and case")
        << "  1 : mf , 2:Mg " << QList<int>{1, 2} << QStringList{"MF", "MG"} << "1:MF,2:MG";
    QTest::newRow("order kept") << "9:MS,2:MS" << QList<int>{9, 2} << QStringList{"MS", "MS"}
                                << "9:MS,2:MS";
    QTest::newRow("motor names") << "5:MG5010E-i36,6:MF4015-18bit" << QList<int>{5, 6}
                                 << QStringList{"MG", "MF"} << "5:MG5010E-i36,6:MF4015-18bit";
    QTest::newRow("quirks, canonical order")
        << "3:mf + Clear-Angle-Ignored+accel-ignored,4:MG5010E-i36+accel-ignored"
        << QList<int>{3, 4} << QStringList{"MF", "MG"}
        << "3:MF+accel-ignored+clear-angle-ignored,4:MG5010E-i36+accel-ignored";
}

void tst_SimBusSpec::valid()
{
    QFETCH(QString, text);
    QFETCH(QList<int>, ids);
    QFETCH(QStringList, series);
    QFETCH(QString, canonical);
    QString error;
    const auto spec = SimBusSpec::parse(text, &error);
    QVERIFY2(spec, qPrintable(error));
    QCOMPARE(spec->drives.size(), ids.size());
    for (int i = 0; i < ids.size(); ++i) {
        QCOMPARE(spec->drives[i].id, ids[i]);
        QCOMPARE(lk::protocol::seriesName(spec->drives[i].model.series), series[i]);
    }
    QCOMPARE(spec->toString(), canonical);
    QCOMPARE(SimBusSpec::parse(spec->toString())->toString(), canonical);
}

void tst_SimBusSpec::invalid_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("empty") << ""
                           << "no drives";
    QTest::newRow("blank") << "   "
                           << "no drives";
    QTest::newRow("id 0") << "0:MF"
                          << "1..32";
    QTest::newRow("id 33") << "33:MF"
                           << "1..32";
    QTest::newRow("id negative") << "-1:MF"
                                 << "1..32";
    QTest::newRow("id not a number") << "x:MF"
                                     << "1..32";
    QTest::newRow("duplicate") << "3:MF,3:MS"
                               << "ID 3 is given twice";
    QTest::newRow("unknown series") << "3:MX"
                                    << "unknown series 'MX'";
    QTest::newRow("no series") << "3:"
                               << "unknown series ''";
    QTest::newRow("no colon") << "3MF"
                              << "not ID:SERIES";
    QTest::newRow("trailing comma") << "3:MF,"
                                    << "empty entry";
    QTest::newRow("leading comma") << ",3:MF"
                                   << "empty entry";
    QTest::newRow("unknown quirk") << "3:MF+slow"
                                   << "unknown firmware quirk 'slow' (known: accel-ignored";
    QTest::newRow("empty quirk") << "3:MF+"
                                 << "unknown firmware quirk ''";
    QTest::newRow("quirk without model") << "3:+accel-ignored"
                                         << "unknown series";
    QTest::newRow("name without series") << "4:XY4015"
                                         << "unknown series 'XY4015'";
}

void tst_SimBusSpec::invalid()
{
    QFETCH(QString, text);
    QFETCH(QString, mentions);
    QString error;
    QVERIFY(!SimBusSpec::parse(text, &error));
    QVERIFY2(error.contains(mentions), qPrintable(error));
    QVERIFY(!SimBusSpec::parse(text)); // no error pointer: still refused, no crash
}

void tst_SimBusSpec::motorNameEntry()
{
    const auto spec = SimBusSpec::parse(QStringLiteral("5:MG5010E-i36"));
    QVERIFY(spec);
    const auto &model = spec->drives.first().model;
    QCOMPARE(model.series, Series::MG);
    QCOMPARE(model.motorName, QStringLiteral("MG5010E-i36"));
    QCOMPARE(model.driverName, QStringLiteral("LK-MG5010E-DRV"));
    QCOMPARE(model.nameInfo().gearRatio, 36.0);
    QCOMPARE(model.nameInfo().encoderBits, 18);
}

void tst_SimBusSpec::quirksReachTheModel()
{
    const auto spec = SimBusSpec::parse(QStringLiteral("3:MF+accel-ignored,4:MF"));
    QVERIFY(spec);
    QVERIFY(spec->drives[0].model.quirks.accelIgnored);
    QVERIFY(!spec->drives[0].model.quirks.clearAngleIgnored);
    QVERIFY(!spec->drives[1].model.quirks.accelIgnored);
}

QTEST_APPLESS_MAIN(tst_SimBusSpec)
#include "tst_simbusspec.moc"
