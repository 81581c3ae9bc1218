#include "sim/ControllerSpec.h"

#include <QtTest/QTest>

using lk::protocol::Command;
using lk::sim::ControllerSpec;

/// lksim --controller's SPEC: what parses, what it means, and that a bad one names its key.
class tst_ControllerSpec : public QObject {
    Q_OBJECT
private slots:
    void defaults();
    void valid_data();
    void valid();
    void fields();
    void refused_data();
    void refused();
    void pollable_data();
    void pollable();
};

void tst_ControllerSpec::defaults()
{
    QString error;
    const std::optional<ControllerSpec> s =
        ControllerSpec::parse(QStringLiteral("rate=100"), &error);
    QVERIFY2(s, qPrintable(error));
    QCOMPARE(s->rateHz, 100.0);
    QVERIFY(s->ids.isEmpty()); // every drive on the bus
    QCOMPARE(s->poll, QList<Command>{Command::ReadState2});
    QVERIFY(!s->speed);
    QVERIFY(!s->move);
    QCOMPARE(s->timeoutS, 0.005);
}

void tst_ControllerSpec::valid_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("canonical");
    QTest::newRow("rate only") << "rate=200"
                               << "rate=200,poll=9c,timeout=5ms";
    QTest::newRow("max") << "rate=max"
                         << "rate=max,poll=9c,timeout=5ms";
    QTest::newRow("the brief's example")
        << "rate=200,ids=1-4,poll=9c:9a:92,speed=sine:300dps:0.5Hz,move=every:5s"
        << "rate=200,ids=1-4,poll=9c:9a:92,speed=sine:300dps:0.5Hz,"
           "move=every:5s:90deg:360dps,timeout=5ms";
    QTest::newRow("names and 0x codes") << "poll=read_state1:0x9D:read_multi_turn"
                                        << "rate=100,poll=9a:9d:92,timeout=5ms";
    QTest::newRow("ids list and ranges") << "ids=17:1-3:5"
                                         << "rate=100,ids=17:1-3:5,poll=9c,timeout=5ms";
    QTest::newRow("move parts any order")
        << "move=every:2.5s:200dps:45deg,poll=none"
        << "rate=100,poll=none,move=every:2.5s:45deg:200dps,timeout=5ms";
    QTest::newRow("speed only") << "poll=none,speed=sine:100dps:2Hz"
                                << "rate=100,poll=none,speed=sine:100dps:2Hz,timeout=5ms";
    QTest::newRow("timeout") << "timeout=0.8ms"
                             << "rate=100,poll=9c,timeout=0.8ms";
}

void tst_ControllerSpec::valid()
{
    QFETCH(QString, spec);
    QFETCH(QString, canonical);
    QString error;
    const std::optional<ControllerSpec> s = ControllerSpec::parse(spec, &error);
    QVERIFY2(s, qPrintable(error));
    QCOMPARE(s->toString(), canonical);
    // The canonical text reads back to itself.
    const std::optional<ControllerSpec> again = ControllerSpec::parse(canonical, &error);
    QVERIFY2(again, qPrintable(error));
    QCOMPARE(again->toString(), canonical);
}

void tst_ControllerSpec::fields()
{
    const std::optional<ControllerSpec> s = ControllerSpec::parse(
        QStringLiteral("ids=1-3:7,poll=9a:read_state2,speed=sine:300dps:0.5Hz,"
                       "move=every:5s:30deg:100dps,timeout=2ms,rate=max"));
    QVERIFY(s);
    QCOMPARE(s->ids, (QList<int>{1, 2, 3, 7}));
    QCOMPARE(s->poll, (QList<Command>{Command::ReadState1, Command::ReadState2}));
    QVERIFY(s->speed);
    QCOMPARE(s->speed->amplitudeDps, 300.0);
    QCOMPARE(s->speed->frequencyHz, 0.5);
    QVERIFY(s->move);
    QCOMPARE(s->move->periodS, 5.0);
    QCOMPARE(s->move->stepDeg, 30.0);
    QCOMPARE(s->move->maxSpeedDps, 100.0);
    QCOMPARE(s->timeoutS, 0.002);
    QCOMPARE(s->rateHz, 0.0);
}

void tst_ControllerSpec::refused_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("named"); // the message must contain this
    QTest::newRow("unknown key") << "rate=100,speeed=sine:1dps:1Hz"
                                 << "unknown key 'speeed'";
    QTest::newRow("no value") << "rate"
                              << "rate=";
    QTest::newRow("empty value") << "rate="
                                 << "rate=";
    QTest::newRow("twice") << "rate=10,rate=20"
                           << "given twice";
    QTest::newRow("rate 0") << "rate=0"
                            << "rate=0";
    QTest::newRow("rate text") << "rate=fast"
                               << "rate=fast";
    QTest::newRow("rate too high") << "rate=200000"
                                   << "rate=200000";
    QTest::newRow("id 0") << "ids=0-3"
                          << "ids=0-3";
    QTest::newRow("id 33") << "ids=33"
                           << "ids=33";
    QTest::newRow("range backwards") << "ids=4-1"
                                     << "ids=4-1";
    QTest::newRow("id twice") << "ids=1-3:2"
                              << "ID 2 is given twice";
    QTest::newRow("comma list is keys") << "ids=1,2"
                                        << "unknown key '2'";
    QTest::newRow("poll a write") << "poll=write_pid_ram"
                                  << "poll=write_pid_ram";
    QTest::newRow("poll a motion") << "poll=a2"
                                   << "'a2' is not a read";
    QTest::newRow("poll motor_off") << "poll=80"
                                    << "'80' is not a read";
    QTest::newRow("poll clear_errors") << "poll=clear_errors"
                                       << "poll=clear_errors";
    QTest::newRow("poll read_param (takes data)") << "poll=40"
                                                  << "'40' is not a read";
    QTest::newRow("poll unknown") << "poll=9c:zz"
                                  << "'zz' is not a read";
    QTest::newRow("poll empty part") << "poll=9c::9a"
                                     << "'' is not a read";
    QTest::newRow("nothing to send") << "poll=none"
                                     << "would send nothing";
    QTest::newRow("speed shape") << "speed=square:300dps:1Hz"
                                 << "speed=square";
    QTest::newRow("speed unit") << "speed=sine:300:1Hz"
                                << "speed=sine:300:1Hz";
    QTest::newRow("speed zero") << "speed=sine:0dps:1Hz"
                                << "amplitude";
    QTest::newRow("speed huge") << "speed=sine:1e9dps:1Hz"
                                << "amplitude";
    QTest::newRow("speed freq") << "speed=sine:10dps:0Hz"
                                << "frequency";
    QTest::newRow("move syntax") << "move=5s"
                                 << "move=5s";
    QTest::newRow("move period unit") << "move=every:5"
                                      << "move=every:5";
    QTest::newRow("move ms is not s") << "move=every:500ms"
                                      << "move=every:500ms";
    QTest::newRow("move period short") << "move=every:0.001s"
                                       << "period";
    QTest::newRow("move two steps") << "move=every:5s:10deg:20deg"
                                    << "'20deg'";
    QTest::newRow("move negative step") << "move=every:5s:-10deg"
                                        << "step";
    QTest::newRow("move zero speed") << "move=every:5s:0dps"
                                     << "move=every:5s:0dps";
    QTest::newRow("timeout unit") << "timeout=5"
                                  << "timeout=5";
    QTest::newRow("timeout zero") << "timeout=0ms"
                                  << "timeout=0ms";
}

void tst_ControllerSpec::refused()
{
    QFETCH(QString, spec);
    QFETCH(QString, named);
    QString error;
    QVERIFY(!ControllerSpec::parse(spec, &error));
    QVERIFY2(error.startsWith(QLatin1String("--controller: ")), qPrintable(error));
    QVERIFY2(error.contains(named), qPrintable(error));
}

void tst_ControllerSpec::pollable_data()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<bool>("pollable");
    const QList<int> reads{0x12, 0x30, 0x33, 0x90, 0x92, 0x94, 0x9A, 0x9C, 0x9D};
    for (const lk::protocol::CommandInfo &c : lk::protocol::CommandTable::all()) {
        const int code = static_cast<quint8>(c.command);
        QTest::newRow(c.name) << code << reads.contains(code);
    }
}

void tst_ControllerSpec::pollable()
{
    QFETCH(int, code);
    QFETCH(bool, pollable);
    QCOMPARE(ControllerSpec::isPollable(static_cast<Command>(code)), pollable);
}

QTEST_GUILESS_MAIN(tst_ControllerSpec)
#include "tst_controllerspec.moc"
