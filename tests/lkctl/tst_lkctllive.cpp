#include "E2eUtil.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

// The live subcommands of the lkctl binary (scan, info, read, write, control, off/stop/run,
// monitor): argument errors, which are refused before any bus is opened, and their behaviour
// on the in-process simulated bus (--sim), which needs no pseudo-terminal. tests/e2e runs the
// same commands against lksim over a real serial port.

namespace {

using Result = lk::e2e::CtlResult;
using lk::e2e::lkctl;

QStringList words(const char *text)
{
    return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

const char kSim[] = "--sim 3:MF,17:MS,32:MG";

QStringList sim(const char *text)
{
    return words(text) + words(kSim);
}

} // namespace

class tst_LkctlLive : public QObject {
    Q_OBJECT
private slots:
    void argumentErrors_data();
    void argumentErrors();
    void help_data();
    void help();
    void overviewListsLiveCommands();
    void scanSimulatedBus();
    void readAndInfoShapes();
    void controlWithinAndOverLimits_data();
    void controlWithinAndOverLimits();
    void limitsFile();
    void limitsFileMistakesSendNothing_data();
    void limitsFileMistakesSendNothing();
    void positionMovesCarryTheSpeedLimit_data();
    void positionMovesCarryTheSpeedLimit();
    void romNeedsYes();
    void romPersistsInSimRomDirRamDoesNot();
    void readBackMismatchExits5();
    void offStopRun();
    void monitorCountAndJson();
    void silentIdFailsNamingIt();
};

void tst_LkctlLive::argumentErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QByteArray>("message");
    const auto row = [](const char *name, QStringList args, const char *message) {
        QTest::newRow(name) << args << QByteArray(message);
    };
    // Bus options.
    row("no bus", words("scan"), "no bus: give --port DEV");
    row("port and sim", words("scan --port /dev/null --sim 1:MF"), "not both");
    row("bad baud", sim("scan --baud 1234"), "--baud must be one of 9600");
    row("bad sim spec", words("scan --sim 40:MF"), "--sim:");
    row("rom dir without sim", words("scan --port /dev/null --sim-rom-dir /tmp"),
        "--sim-rom-dir goes with --sim");
    row("unknown option", sim("scan --frobnicate"), "unknown option '--frobnicate'");
    row("missing value", words("scan --port"), "--port needs a value");
    row("flag with value", sim("scan --json=1"), "--json takes no value");
    row("option twice", sim("scan --from 1 --from 2"), "--from given twice");
    // scan
    row("scan from 0", sim("scan --from 0"), "--from must be 1..32");
    row("scan range reversed", sim("scan --from 10 --to 5"), "--from 10 is above --to 5");
    row("scan extra", sim("scan 3"), "unexpected argument '3'");
    row("scan retries", sim("scan --retries x"), "--retries must be an integer in 0..5");
    // info, read
    row("info no id", sim("info"), "missing the drive ID");
    row("info bad id", sim("info 33"), "ID must be 1..32 (got '33')");
    row("info two ids", sim("info 3 4"), "expected one ID");
    row("read no what", sim("read 3"), "expected ID and WHAT");
    row("read bad what", sim("read 3 speed"), "cannot read 'speed'; WHAT is one of pid");
    row("read bad id", sim("read x pid"), "ID must be 1..32 (got 'x')");
    // write
    row("write few gains", sim("write 3 pid 1 2 3 --ram"), "pid takes six gains");
    row("write where", sim("write 3 pid 1 2 3 4 5 6"), "say where to write: --ram");
    row("write ram and rom", sim("write 3 pid 1 2 3 4 5 6 --ram --rom"), "not both");
    row("write gain range", sim("write 3 pid 1 2 3 4 5 256 --ram"), "iq_ki must be in 0..255");
    row("write gain text", sim("write 3 pid 1 2 x 4 5 6 --ram"), "speed_kp must be in 0..255");
    row("write accel rom", sim("write 3 accel 5 --rom"), "no ROM write");
    row("write accel range", sim("write 3 accel -1 --ram"), "accel_dps2 must be in");
    row("write accel two", sim("write 3 accel 1 2 --ram"), "accel takes one value");
    row("write what", sim("write 3 zero 1 --ram"), "cannot write 'zero'");
    // control
    row("control short", sim("control 3"), "expected ID MODE VALUE");
    row("control mode", sim("control 3 warp 1"), "unknown mode 'warp'");
    row("control range", sim("control 3 torque 40"), "iq_a must be in -32..32 A");
    row("control text", sim("control 3 speed fast"), "not a number");
    row("control two values", sim("control 3 speed 10 20"), "speed takes one value");
    row("control no direction", sim("control 3 single-position 90"), "needs --direction");
    row("control stray direction", sim("control 3 speed 10 --direction cw"),
        "--direction goes with single-position only");
    row("control bad direction", sim("control 3 single-position 90 --direction up"),
        "direction must be in cw|ccw");
    row("control single range", sim("control 3 single-position 400 --direction cw"),
        "angle_deg must be in 0..359.99 deg");
    row("control stray max speed", sim("control 3 torque 1 --max-speed 5"),
        "--max-speed goes with the position modes only");
    row("control max speed range", sim("control 3 increment 10 --max-speed -5"),
        "max_speed_dps must be in");
    row("control power range", sim("control 17 open-loop 1001"), "power must be in");
    row("control torque limit", sim("control 3 speed 10 --max-torque-a -1"),
        "--max-torque-a must be a number >= 0");
    row("control power limit", sim("control 3 speed 10 --max-power 2000"),
        "--max-power must be an integer in 0..1000");
    row("control limits file", sim("control 3 speed 10 --limits /nonexistent/limits.json"),
        "cannot read --limits /nonexistent/limits.json");
    // off, stop, run
    row("off nothing", sim("off"), "missing ID or 'all'");
    row("stop bad id", sim("stop 40"), "ID must be 1..32 (got '40'), or 'all'");
    row("run two", sim("run 1 2"), "expected one ID or 'all'");
    // monitor
    row("monitor no id", sim("monitor"), "missing the drive ID(s)");
    row("monitor twice", sim("monitor 3 3"), "ID 3 given twice");
    row("monitor what", sim("monitor 3 --what state2,speed"), "cannot poll 'speed'");
    row("monitor rate", sim("monitor 3 --rate -1"), "--rate must be a number >= 0");
    row("monitor count", sim("monitor 3 --count 0"), "--count must be an integer in 1..");
    row("monitor duration", sim("monitor 3 --duration soon"), "--duration must be a number");
    row("monitor layout", sim("monitor 3 --csv-layout tall"),
        "--csv-layout takes wide or long, not 'tall'");
    row("monitor layout json", sim("monitor 3 --json --csv-layout long"),
        "--csv-layout is for CSV, not --json");
    row("monitor csv json", sim("monitor 3 --json --csv"), "--csv and --json exclude each other");
}

void tst_LkctlLive::argumentErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QByteArray, message);
    const Result r = lkctl(args);
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, QByteArray()); // nothing printed, nothing sent
    QVERIFY2(r.err.startsWith("lkctl " + args.first().toUtf8() + ": "), r.err.constData());
    QVERIFY2(r.err.contains(message), r.err.constData());
    QVERIFY2(r.err.contains("--help"), r.err.constData()); // where to look
}

void tst_LkctlLive::help_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QStringList>("mentions");
    QTest::newRow("scan") << "scan" << QStringList{"--sweep-bauds", "--from", "--json", "series"};
    QTest::newRow("info") << "info" << QStringList{"read_model", "read_accel"};
    QTest::newRow("read") << "read" << QStringList{"multi-turn", "single-turn", "state3"};
    QTest::newRow("write") << "write" << QStringList{"--rom", "--yes", "flash", "  5  "};
    QTest::newRow("control") << "control"
                             << QStringList{"open-loop",       "torque",          "speed",
                                            "multi-position",  "single-position", "increment",
                                            "--max-speed",     "--limits",        "--max-torque-a",
                                            "--max-speed-dps", "--max-power",     "  4  "};
    QTest::newRow("off") << "off" << QStringList{"emergency", "all"};
    QTest::newRow("stop") << "stop" << QStringList{"motor_stop", "all"};
    QTest::newRow("run") << "run" << QStringList{"motor_run", "  4  "};
    QTest::newRow("monitor") << "monitor"
                             << QStringList{"--rate", "--duration", "--count", "--what", "SIGINT"};
}

void tst_LkctlLive::help()
{
    QFETCH(QString, command);
    QFETCH(QStringList, mentions);
    const Result r = lkctl({command, QStringLiteral("--help")});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.startsWith("Usage: lkctl " + command.toUtf8()));
    for (const QString &m : mentions + QStringList{"--port", "--sim", "Examples:", "Exit status"})
        QVERIFY2(r.out.contains(m.toUtf8()), qPrintable(m));
}

void tst_LkctlLive::overviewListsLiveCommands()
{
    const Result r = lkctl({QStringLiteral("--help")});
    QCOMPARE(r.exitCode, 0);
    for (const char *c : {"scan", "info", "read", "write", "control", "off", "stop", "run",
                          "monitor", "encode", "decode"})
        QVERIFY2(r.out.contains(QByteArray("\n  ") + c + ' '), c);
    for (const char *status : {"  0  success", "  1  ", "  2  ", "  3  ", "  4  ", "  5  "})
        QVERIFY2(r.out.contains(status), status);
}

void tst_LkctlLive::scanSimulatedBus()
{
    const Result r = lkctl(sim("scan --json"));
    QCOMPARE(r.exitCode, 0);
    const QJsonArray a = QJsonDocument::fromJson(r.out).array();
    QCOMPARE(a.size(), 3);
    QCOMPARE(a.at(0).toObject().value("id").toInt(), 3);
    QCOMPARE(a.at(1).toObject().value("series").toString(), QStringLiteral("MS"));
    QCOMPARE(a.at(2).toObject().value("motor_name").toString(), QStringLiteral("MG5010E-i10"));
    QVERIFY2(r.out.startsWith("[{\"id\":3,\"driver_name\":\"LK-MF4015-DRV\",\"motor_name\":"
                              "\"MF4015\",\"hardware_version\":1.0,\"firmware_version\":2.3,"
                              "\"series\":\"MF\",\"generation\":\"v2.3\",\"temperature_c\":25,"
                              "\"voltage_v\":24.0,\"bus_current_a\":null,\"motor_on\":null,"
                              "\"error_state\":0,\"errors\":[]},"),
             r.out.constData()); // CLI.md's keys in CLI.md's order, and no baud without a sweep
    const Result swept = lkctl(sim("scan --sweep-bauds --from 3 --to 3 --json"));
    QCOMPARE(swept.exitCode, 0);
    const QJsonArray s = QJsonDocument::fromJson(swept.out).array();
    QVERIFY(!s.isEmpty());
    for (const QJsonValue &v : s) {
        QCOMPARE(v.toObject().value("id").toInt(), 3);
        QVERIFY2(v.toObject().value("baud").toInt() >= 9600, swept.out.constData());
    }
    const Result range = lkctl(sim("scan --from 4 --to 16 --json"));
    QCOMPARE(range.exitCode, 0);
    QCOMPARE(range.out, QByteArray("[]\n"));
    const Result text = lkctl(sim("scan --from 4 --to 16"));
    QVERIFY(text.out.startsWith("No drive answered on IDs 4..16"));
}

void tst_LkctlLive::readAndInfoShapes()
{
    Result r = lkctl(sim("read 17 state2 --json"));
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.startsWith("{\"command\":\"read_state2\",\"code\":\"0x9C\",\"id\":17,\"fields\":"
                              "{\"temperature_c\":"),
             r.out.constData());
    QVERIFY(r.out.contains("\"power\":")); // MS: power, not iq
    r = lkctl(sim("read 17 state3"));
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("MS: that series has no read_state3"), r.err.constData());
    r = lkctl(sim("info 32 --json"));
    QCOMPARE(r.exitCode, 0);
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(o.keys(),
             (QStringList{"accel", "generation", "id", "model", "pid", "series", "state1"}));
}

void tst_LkctlLive::controlWithinAndOverLimits_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QByteArray>("message");
    QTest::newRow("speed ok") << sim("control 3 speed 100") << 0 << QByteArray();
    QTest::newRow("speed over series")
        << sim("control 3 speed 20000") << 4 << QByteArray("MF series top speed of 18000 dps");
    QTest::newRow("torque over default")
        << sim("control 3 torque 2.5") << 4 << QByteArray("your torque limit of 2.25 A");
    QTest::newRow("torque raised")
        << sim("control 3 torque 2.5 --max-torque-a 3") << 0 << QByteArray();
    // A limit above the series' own is no limit: the flag is refused as such.
    QTest::newRow("torque limit over the series")
        << sim("control 3 torque 10 --max-torque-a 20") << 2
        << QByteArray("--max-torque-a 20 A is above 9 A, the current limit of the MF series");
    QTest::newRow("torque over the limit at the series rating")
        << sim("control 3 torque 10 --max-torque-a 9") << 4 << QByteArray("series rating");
    QTest::newRow("open loop on MF") << sim("control 3 open-loop 100") << 4
                                     << QByteArray("MF drives do not implement open_loop");
    QTest::newRow("open loop on MS") << sim("control 17 open-loop 100") << 0 << QByteArray();
    // MG5010E-i10: one output turn is 3600 rotor deg; the simulated drive is at 80.26 deg.
    QTest::newRow("position") << sim("control 32 multi-position -720 --max-speed 360") << 0
                              << QByteArray();
    QTest::newRow("geared position over one output turn")
        << sim("control 32 multi-position 5000") << 4
        << QByteArray("is more than one output turn (3600°)");
    QTest::newRow("position over one turn")
        << sim("control 3 multi-position 11000") << 4
        << QByteArray("from the current angle 52.52° is more than one output turn (360°)");
    QTest::newRow("increment over one turn")
        << sim("control 3 increment -400") << 4
        << QByteArray("an increment of 400° is more than one output turn (360°)");
    QTest::newRow("max speed over the speed limit")
        << sim("control 3 multi-position 100 --max-speed 800 --max-speed-dps 720") << 4
        << QByteArray("max speed 800 dps is over your speed limit of 720 dps");
    QTest::newRow("silent drive") << sim("control 5 speed 10") << 1
                                  << QByteArray("read_model (ID 5)");
}

void tst_LkctlLive::controlWithinAndOverLimits()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QByteArray, message);
    const Result r = lkctl(args);
    QVERIFY2(r.exitCode == exitCode, r.err.constData());
    QVERIFY2(r.err.contains(message), r.err.constData());
    if (exitCode == 0)
        QVERIFY(r.out.startsWith("Sent "));
    else
        QVERIFY(r.out.isEmpty());
    if (exitCode == 4)
        QVERIFY(r.err.contains("refused for safety, nothing was sent"));
}

void tst_LkctlLive::limitsFile()
{
    QTemporaryDir dir;
    const QString good = dir.filePath(QStringLiteral("good.json"));
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    const QString wrongType = dir.filePath(QStringLiteral("type.json"));
    for (const auto &[path, text] :
         {std::pair{good, QByteArray(R"({"max_speed_dps":50,"max_increment_deg":30})")},
          {bad, QByteArray("{not json")},
          {wrongType, QByteArray(R"({"max_torque_a":"lots"})")}}) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text);
    }
    Result r = lkctl(words("control 3 speed 60 --limits") + QStringList{good} + words(kSim));
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("your speed limit of 50 dps"), r.err.constData());
    r = lkctl(words("control 3 increment 45 --limits") + QStringList{good} + words(kSim));
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("your step limit of 30°"), r.err.constData());
    r = lkctl(words("control 3 speed 60 --max-speed-dps 70 --limits") + QStringList{good} +
              words(kSim));
    QCOMPARE(r.exitCode, 0); // the flag overrides the file
    r = lkctl(words("control 3 speed 60 --limits") + QStringList{bad} + words(kSim));
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("not a JSON object"), r.err.constData());
    r = lkctl(words("control 3 speed 60 --limits") + QStringList{wrongType} + words(kSim));
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("max_torque_a must be a number in 0..32 A (got \"lots\")"),
             r.err.constData());
}

void tst_LkctlLive::limitsFileMistakesSendNothing_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QByteArray>("message");
    QTest::newRow("misspelt key") << QByteArray(R"({"max_speed": 720})")
                                  << QByteArray("unknown key \"max_speed\"");
    QTest::newRow("duplicate key") << QByteArray(R"({"max_speed_dps": 720, "max_speed_dps": 9000})")
                                   << QByteArray("key \"max_speed_dps\" is given twice");
    QTest::newRow("negative") << QByteArray(R"({"max_speed_dps": -720})")
                              << QByteArray("max_speed_dps must be a number in 0.01..18000 dps");
    QTest::newRow("zero speed") << QByteArray(R"({"max_speed_dps": 0})")
                                << QByteArray("max_speed_dps must be a number in 0.01..18000 dps");
    QTest::newRow("fractional power") << QByteArray(R"({"max_power": 10.5})")
                                      << QByteArray("max_power must be a whole number in 0..1000");
}

void tst_LkctlLive::limitsFileMistakesSendNothing()
{
    QFETCH(QByteArray, text);
    QFETCH(QByteArray, message);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("limits.json"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
    f.close();
    const Result r =
        lkctl(words("control 3 speed 5000 --limits") + QStringList{path} + words(kSim));
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(message), r.err.constData());
    QVERIFY2(r.err.contains("nothing was sent"), r.err.constData());
    QVERIFY(r.out.isEmpty());
}

void tst_LkctlLive::positionMovesCarryTheSpeedLimit_data()
{
    QTest::addColumn<QString>("args");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("source");
    QTest::addColumn<double>("dps");
    QTest::newRow("multi") << "multi-position 100 --max-speed-dps 100"
                           << "multi_position_limited"
                           << "soft_limit" << 100.0;
    QTest::newRow("single") << "single-position 90 --direction cw --max-speed-dps 100"
                            << "single_position_limited"
                            << "soft_limit" << 100.0;
    QTest::newRow("increment") << "increment -90 --max-speed-dps 100"
                               << "increment_position_limited"
                               << "soft_limit" << 100.0;
    QTest::newRow("lower max speed") << "increment 90 --max-speed 50 --max-speed-dps 100"
                                     << "increment_position_limited"
                                     << "max_speed" << 50.0;
    QTest::newRow("series default") << "increment 90"
                                    << "increment_position_limited"
                                    << "soft_limit" << 18000.0;
    QTest::newRow("speed") << "speed 60 --max-speed-dps 100"
                           << "speed"
                           << "command" << 100.0;
}

void tst_LkctlLive::positionMovesCarryTheSpeedLimit()
{
    QFETCH(QString, args);
    QFETCH(QString, command);
    QFETCH(QString, source);
    QFETCH(double, dps);
    const Result r =
        lkctl(words("control 3") + args.split(QLatin1Char(' ')) + words("--json") + words(kSim));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(o.value("command").toString(), command);
    const QJsonObject bound = o.value("speed_bound").toObject();
    QCOMPARE(bound.value("source").toString(), source);
    QCOMPARE(bound.value("dps").toDouble(), dps);
    if (source != QLatin1String("command"))
        QCOMPARE(o.value("sent").toObject().value("max_speed_dps").toDouble(), dps);
    const Result text = lkctl(words("control 3") + args.split(QLatin1Char(' ')) + words(kSim));
    QVERIFY2(text.out.contains("Speed bound: "), text.out.constData());
}

void tst_LkctlLive::romNeedsYes()
{
    const Result r = lkctl(sim("write 3 pid 1 2 3 4 5 6 --rom"));
    QCOMPARE(r.exitCode, 4);
    QCOMPARE(r.out, QByteArray());
    QVERIFY2(r.err.contains("flash") && r.err.contains("--yes") &&
                 r.err.contains("nothing was sent"),
             r.err.constData());
}

void tst_LkctlLive::romPersistsInSimRomDirRamDoesNot()
{
    QTemporaryDir dir;
    const QStringList rom{QStringLiteral("--sim-rom-dir"), dir.path()};
    Result r = lkctl(sim("write 3 pid 31 32 33 34 35 36 --rom --yes --json") + rom);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY(r.out.contains("\"match\":true"));
    r = lkctl(sim("write 17 pid 41 42 43 44 45 46 --ram") + rom);
    QCOMPARE(r.exitCode, 0);
    // Each lkctl --sim run powers the simulated drives up afresh: ROM stays, RAM is gone.
    r = lkctl(sim("read 3 pid --json") + rom);
    QVERIFY2(r.out.contains("\"angle_kp\":31"), r.out.constData());
    r = lkctl(sim("read 17 pid --json") + rom);
    QVERIFY2(!r.out.contains("\"angle_kp\":41"), r.out.constData());
}

void tst_LkctlLive::readBackMismatchExits5()
{
    // Firmware that acknowledges 0x34 and ignores it (docs/ERRATA.md): the echo looks fine, only
    // the read-back shows the truth, and a script must see it in the exit status.
    const QStringList quirky = words("--sim 3:MF+accel-ignored");
    Result r = lkctl(words("write 3 accel 1000 --ram") + quirky);
    QCOMPARE(r.exitCode, 5);
    QVERIFY2(r.out.contains("acceleration  0 dps/s"), r.out.constData());
    QVERIFY2(r.err.contains("read-back mismatch on drive 3: wrote acceleration "
                            "(acceleration 1000 dps/s) but the drive holds acceleration "
                            "0 dps/s.") &&
                 r.err.contains("Some firmware acknowledges write_accel_ram and ignores it "
                                "(see docs/ERRATA.md)."),
             r.err.constData());
    r = lkctl(words("write 3 accel 1000 --ram --json") + quirky);
    QCOMPARE(r.exitCode, 5);
    QVERIFY2(r.out.contains("\"match\":false"), r.out.constData());
    r = lkctl(words("write 3 pid 1 2 3 4 5 6 --ram") + quirky); // only acceleration is ignored
    QVERIFY2(r.exitCode == 0, r.err.constData());
}

void tst_LkctlLive::offStopRun()
{
    Result r = lkctl(sim("off all --json"));
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(
        r.out.startsWith("{\"command\":\"motor_off\",\"acknowledged\":[3,17,32],\"silent\":[1,"),
        r.out.constData());
    r = lkctl(sim("stop 3"));
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out, QByteArray("motor_stop acknowledged by: 3\n"));
    r = lkctl(sim("stop all --json")); // every ID, as 'off all': no scan decides who stops
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.startsWith("{\"command\":\"motor_stop\",\"acknowledged\":[3,17,32],"
                              "\"silent\":[1,2,4,"),
             r.out.constData());
    r = lkctl(sim("run all --json"));
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out, QByteArray("{\"command\":\"motor_run\",\"acknowledged\":[3,17,32],"
                               "\"silent\":[]}\n"));
    r = lkctl(sim("off 9"));
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("motor_off (ID 9)"), r.err.constData());
}

void tst_LkctlLive::monitorCountAndJson()
{
    // Wide (the default): one row per poll round, a column per drive and signal.
    Result r = lkctl(sim("monitor 3 17 --count 6 --rate 0 --what state2"));
    QCOMPARE(r.exitCode, 0);
    QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 7);
    QCOMPARE(lines.first(), QByteArray("time_s,id3_temperature_c,id3_iq_a,id3_speed_dps,"
                                       "id3_encoder,id17_temperature_c,id17_power,"
                                       "id17_speed_dps,id17_encoder"));
    for (int i = 1; i < lines.size(); ++i)
        QCOMPARE(lines.at(i).count(','), 8);
    QVERIFY2(r.err.contains("6 rows in") && r.err.contains("bus: requests"), r.err.constData());

    // Long: one row per drive and round; both drives' rows of a round share its time.
    r = lkctl(sim("monitor 3 17 --count 6 --rate 0 --what state2 --csv-layout long"));
    QCOMPARE(r.exitCode, 0);
    lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 7);
    QCOMPARE(lines.first(), QByteArray("time_s,id,temperature_c,iq_a,power,speed_dps,encoder"));
    for (int i = 1; i < lines.size(); i += 2) {
        const QList<QByteArray> drive3 = lines.at(i).split(',');
        const QList<QByteArray> drive17 = lines.at(i + 1).split(',');
        QCOMPARE(drive3.at(1), QByteArray("3"));
        QCOMPARE(drive17.at(1), QByteArray("17"));
        QCOMPARE(drive17.at(0), drive3.at(0));
    }

    r = lkctl(sim("monitor 32 --count 2 --json --what multi-turn,state1"));
    QCOMPARE(r.exitCode, 0);
    for (const QByteArray &line : r.out.trimmed().split('\n')) {
        const QJsonObject o = QJsonDocument::fromJson(line).object();
        QCOMPARE(o.keys(), (QStringList{"error_state", "id", "multi_turn_deg", "temperature_c",
                                        "time_s", "voltage_v"}));
    }
    // --duration ends the run by itself: how many rows fit in it depends on the machine, so
    // only the header and a clean end are checked.
    r = lkctl(sim("monitor 3 --duration 0.3 --rate 20"));
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.startsWith("time_s,id3_temperature_c,"), r.out.constData());
    QVERIFY2(r.err.contains("rows in"), r.err.constData());
}

void tst_LkctlLive::silentIdFailsNamingIt()
{
    const Result r = lkctl(sim("info 9"));
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(r.out, QByteArray());
    QVERIFY2(r.err.startsWith("lkctl info: no reply to read_model (ID 9)"), r.err.constData());
}

QTEST_GUILESS_MAIN(tst_LkctlLive)
#include "tst_lkctllive.moc"
