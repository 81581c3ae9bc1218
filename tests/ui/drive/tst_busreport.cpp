// The bus report reads each drive by its generation: a V2.35 drive's state with the voltage
// at 0.01 V and its fault flags by their V2.35 names (over-current + stall is not "33 °C,
// 24.0 V"), its gains with Kd and its parameters, in the JSON (lkctl's field names) and the
// HTML page; a V2.3 drive as before, with its two flags named.

#include <record/BusReport.h>

#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtTest/QtTest>

using namespace lk;
using record::BusReport;
using record::BusReportDrive;

namespace {

protocol::State1 v235State(quint16 voltageRaw, quint8 errors)
{
    protocol::State1 s;
    s.generation = protocol::Generation::V2_35;
    s.temperatureC = 33;
    s.voltageRaw = voltageRaw;
    s.busCurrentRaw = 150;
    s.motorStateRaw = 0x00;
    s.errorState = errors;
    return s;
}

BusReportDrive v235Drive()
{
    BusReportDrive d;
    d.id = 1;
    d.series = protocol::Series::MS;
    d.generation = protocol::Generation::V2_35;
    d.params = {protocol::ParameterValue::pid(protocol::ParamId::AnglePid, 100, 90, 1),
                protocol::ParameterValue::pid(protocol::ParamId::SpeedPid, 50, 40, 2),
                protocol::ParameterValue::pid(protocol::ParamId::CurrentPid, 30, 20, 3),
                protocol::ParameterValue::int16(protocol::ParamId::MaxTorqueCurrent, 800),
                protocol::ParameterValue::int32(protocol::ParamId::MaxSpeed, 72000),
                protocol::ParameterValue::maxAngleHalf(36000, false),
                protocol::ParameterValue::maxAngleHalf(36000, true),
                protocol::ParameterValue::int16(protocol::ParamId::CurrentRamp, 5),
                protocol::ParameterValue::int32(protocol::ParamId::SpeedRamp, 20000)};
    d.state1 = v235State(2437, 0x50); // 24.37 V, over-current (bit 4) and stall (bit 6)
    return d;
}

} // namespace

class tst_BusReport : public QObject {
    Q_OBJECT
private slots:
    void v235StateNamesItsFlags();
    void v235GainsAndParameters();
    void v23AsBefore();
    void jsonByGeneration();
    void htmlByGeneration();
};

void tst_BusReport::v235StateNamesItsFlags()
{
    const BusReportDrive d = v235Drive();
    QCOMPARE(d.stateText(), QStringLiteral("33 \u00b0C, 24.37 V; over-current, stall"));
    BusReportDrive all = d;
    all.state1 = v235State(2400, 0xFF);
    QCOMPARE(all.stateText(),
             QStringLiteral("33 \u00b0C, 24.00 V; low voltage, over-voltage, driver "
                            "over-temperature, motor over-temperature, over-current, short "
                            "circuit, stall, input signal lost (timeout)"));
}

void tst_BusReport::v235GainsAndParameters()
{
    const BusReportDrive d = v235Drive();
    QVERIFY(d.answered());
    QCOMPARE(d.gainsText(), QStringLiteral("100/90/1 \u00b7 50/40/2 \u00b7 30/20/3"));
    QCOMPARE(d.limitsText(),
             QStringLiteral("max power 800 \u00b7 max speed 720 dps \u00b7 max angle 360\u00b0 "
                            "\u00b7 current ramp 5 \u00b7 speed ramp 20000 dps/s"));
}

void tst_BusReport::v23AsBefore()
{
    BusReportDrive d;
    d.id = 3;
    d.series = protocol::Series::MF;
    d.generation = protocol::Generation::V2_3;
    d.pid = protocol::PidGains{100, 100, 50, 40, 50, 50};
    d.accelDps2 = 20000;
    d.state1 = protocol::State1(25, 243, 0x09);
    QCOMPARE(d.stateText(), QStringLiteral("25 \u00b0C, 24.3 V; low voltage, over-temperature"));
    QCOMPARE(d.gainsText(), QStringLiteral("100/100 \u00b7 50/40 \u00b7 50/50"));
    QCOMPARE(d.limitsText(), QStringLiteral("20000 dps/s"));
    QCOMPARE(BusReportDrive{}.stateText(), QStringLiteral("\u2013"));
}

void tst_BusReport::jsonByGeneration()
{
    BusReport r;
    r.drives = {v235Drive()};
    const QJsonObject d = QJsonDocument::fromJson(r.toJsonBytes())
                              .object()
                              .value("drives")
                              .toArray()
                              .at(0)
                              .toObject();
    QCOMPARE(d.value("generation").toString(), QStringLiteral("v2.35"));
    const QJsonObject state = d.value("state1").toObject();
    QCOMPARE(state.value("voltage_v").toDouble(), 24.37);
    QCOMPARE(state.value("over_current").toBool(), true);
    QCOMPARE(state.value("stall").toBool(), true);
    QCOMPARE(state.value("low_voltage").toBool(), false);
    QCOMPARE(state.value("bus_current_a").toDouble(), 1.5);
    QCOMPARE(state.value("errors").toArray(), (QJsonArray{"over_current", "stall"}));
    const QJsonObject pid = d.value("pid").toObject();
    QCOMPARE(pid.value("angle_kd").toInt(), 1);
    QCOMPARE(pid.value("iq_ki").toInt(), 20);
    const QJsonObject params = d.value("params").toObject();
    QCOMPARE(params.value("max_speed_dps").toDouble(), 720.0);
    QCOMPARE(params.value("max_angle_deg").toDouble(), 360.0);
    QCOMPARE(params.value("speed_ramp_dps2").toInt(), 20000);
    QVERIFY(!d.contains("accel_dps2"));
}

void tst_BusReport::htmlByGeneration()
{
    BusReport r;
    r.drives = {v235Drive()};
    const QString html = r.toHtml();
    QVERIFY2(html.contains(QStringLiteral("24.37 V; over-current, stall")), qPrintable(html));
    QVERIFY(html.contains(QStringLiteral("<td>V2.35</td>")));
    QVERIFY(html.contains(QStringLiteral("100/90/1")));
    QVERIFY(html.contains(QStringLiteral("max speed 720 dps")));
    QVERIFY(!html.contains(QStringLiteral("24.4 V")));
}

QTEST_APPLESS_MAIN(tst_BusReport)
#include "tst_busreport.moc"
