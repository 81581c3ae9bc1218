// The lkctl commands that run a while or work on files, on CAN, both generations, against
// lksim --can over Qt's virtualcan (a port per test), the wire heard by CanSniffer: monitor,
// step, freq, tune, backup/diff/restore/clone, stop/run/off all. Drives 1 and 3 are old CAN
// MGs (0x141/0x143 both ways), drive 2 a V2.36 MF (0x142 -> 0x182).

#include "CanSniffer.h"
#include "E2eUtil.h"
#include "LksimProcess.h"

#include <QtCore/QFile>
#include <QtCore/QHash>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QSet>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <memory>

using namespace lk::e2e;

namespace {
const QString kOld = QStringLiteral("1:MG@can");
const QString kNew = QStringLiteral("2:MF@can236");
const QString kAll = QStringLiteral("1:MG@can,2:MF@can236,3:MG@can");
} // namespace

class tst_E2eCanTools : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void monitorReadsBothGenerations();
    void monitorSpeaksOfTheCanLink();
    void stepOnOldCan_data();
    void stepOnOldCan();
    void freqOnOldCan();
    void tuneOnOldCanWritesNothingUnasked();
    void backupDiffRestoreOnOldCan();
    void cloneOnOldCan();
    void haltAllReachesEveryId_data();
    void haltAllReachesEveryId();
    void runAllResumesTheDrivesFound();
    void stepOnV236();
    void freqAndTuneOnV236();
    void v236BackupHoldsControlParamsRestoreIsRamOnly();
    void listenPairsCanFrames();
    void decodeReadsCandumpLog();
    void gearFromDrivesBoundsAMove();

private:
    CtlResult run(const QStringList &args) { return m_bus.run(args); }
    /// run(), once more when lkctl ended a tuning run on a reply lost on virtualcan's TCP
    /// (a stall of this 2-core machine: seen at the start of full suites, on 0xC1 writes and
    /// on a sweep's setpoints). lkctl then names the unanswered request, stops the drive and
    /// puts the gains it read back in RAM, exiting 1: what it must do, so the run is retried.
    CtlResult runTuning(const QStringList &args)
    {
        CtlResult r = run(args);
        const bool replyLost = r.err.contains(QLatin1String("no reply to")) ||
                               r.err.contains(QLatin1String("did not answer"));
        if (r.exitCode == 1 && replyLost &&
            r.err.contains(QLatin1String("the gains and acceleration read before are back in RAM")))
            r = run(args);
        return r;
    }
    /// Drive `id` of the backup file `path`, as JSON.
    static QJsonObject fileDrive(const QString &path, int id);

    CanE2eBus m_bus;
    CanSniffer &m_wire = m_bus.wire();
    QTemporaryDir m_dir;
};

QJsonObject tst_E2eCanTools::fileDrive(const QString &path, int id)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll())
        .object()
        .value("drives")
        .toObject()
        .value(QString::number(id))
        .toObject();
}

void tst_E2eCanTools::init()
{
    const QString error = m_bus.start(kAll, kOld);
    QVERIFY2(error.isEmpty(), qPrintable(error));
}

void tst_E2eCanTools::cleanup()
{
    m_bus.stop();
}

void tst_E2eCanTools::monitorReadsBothGenerations()
{
    const CtlResult r = run({"monitor", "1", "2", "--count", "8", "--rate", "20", "--json",
                             "--drives", kOld + "," + kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 8); // --count counts rows: one per drive and round
    const QByteArray oldState = m_wire.last(0x141, 0x9A).data;
    const QByteArray newState = m_wire.last(0x182, 0x9A).data;
    // A reply that came later than its timeout (lksim descheduled on a loaded host) leaves its
    // values out of that row, never 0 (CSV.md): each value is checked where it is, and each
    // drive must have brought every one of them in some round.
    QHash<int, QSet<QString>> keys;
    for (const QByteArray &line : lines) {
        const QJsonObject o = jsonOf(line);
        const bool old = o.value("id").toInt() == 1;
        // Old CAN: 0.1 V in B3-B4, no bus current; V2.36: 0.01 V in B2-B3, bus current, state.
        if (o.contains("voltage_v"))
            QCOMPARE(o.value("voltage_v").toDouble(), old ? leBytes(oldState, 3, 2, false) * 0.1
                                                          : leBytes(newState, 2, 2, true) * 0.01);
        QVERIFY2(!old || (!o.contains("bus_current_a") && !o.contains("motor_on")),
                 line.constData());
        for (const QString &k : o.keys())
            keys[o.value("id").toInt()].insert(k);
    }
    for (int id : {1, 2}) {
        const QSet<QString> &k = keys.value(id);
        QVERIFY2(k.contains("voltage_v") && k.contains("multi_turn_deg"),
                 qPrintable(describeRun(r)));
        QCOMPARE(k.contains("bus_current_a"), id == 2);
        QCOMPARE(k.contains("motor_on"), id == 2);
    }
}

void tst_E2eCanTools::monitorSpeaksOfTheCanLink()
{
    // The rate summary is figured from the CAN link's timing, not an RS485 baud.
    const CtlResult r =
        run({"monitor", "1", "--count", "20", "--rate", "0", "--json", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY2(!r.err.contains("baud"), r.err.constData());
    QVERIFY2(r.err.contains("bit/s") || r.err.contains("CAN"), r.err.constData());
}

void tst_E2eCanTools::stepOnOldCan_data()
{
    QTest::addColumn<QString>("loop");
    QTest::addColumn<int>("code");
    QTest::newRow("speed") << "speed" << 0xA2;
    QTest::newRow("position") << "position" << 0xA4;
}

void tst_E2eCanTools::stepOnOldCan()
{
    QFETCH(QString, loop);
    QFETCH(int, code);
    // Position starts where the drive is: read its angle first.
    const CtlResult at = run({"read", "1", "multi-turn", "--json", "--drives", kOld});
    QVERIFY2(at.exitCode == 0, qPrintable(describeRun(at)));
    const double angle =
        jsonOf(at.out.trimmed()).value("fields").toObject().value("angle_deg").toDouble();
    const double from = loop == QLatin1String("speed") ? 0 : std::round(angle);
    const CtlResult r =
        run({"step", "1", loop, QString::number(from), QString::number(from + 20), "--duration",
             "0.3", "--pre-roll", "0.2", "--max-speed-dps", "360", "--json", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out.trimmed());
    QVERIFY2(o.value("samples").toInt() > 10, r.out.constData());
    QCOMPARE(o.value("edges").toArray().size(), 1);
    // Every setpoint reached the wire, in CAN layout, each with its reply on the same ID:
    // pre-roll and edge, and for speed the return to FROM.
    QVERIFY(m_wire.waitFor(0x141, quint8(code), code == 0xA2 ? 6 : 4));
    const QList<SniffedFrame> sent = m_wire.on(0x141, quint8(code));
    const qint64 target = qint64(std::llround((from + 20) * 100));
    bool edgeSeen = false;
    for (qsizetype i = 0; i < sent.size(); i += 2) { // request, its reply on the same ID, ...
        const SniffedFrame &f = sent.at(i);
        edgeSeen = edgeSeen || leBytes(f.data, 4, 4, true) == target;
        if (code == 0xA4) // max speed: uint16 whole dps in B2-B3
            QCOMPARE(leBytes(f.data, 2, 2, false), 360);
    }
    QVERIFY(edgeSeen);
    QVERIFY(run({"off", "1"}).exitCode == 0);
}

void tst_E2eCanTools::freqOnOldCan()
{
    const CtlResult r =
        run({"freq", "1", "speed", "--from", "1", "--to", "4", "--points", "2", "--amplitude", "30",
             "--per-point", "0.3", "--json", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonArray points = jsonOf(r.out.trimmed()).value("points").toArray();
    QCOMPARE(points.size(), 2);
    QVERIFY(m_wire.count(0x141, 0xA2) > 10);
    QVERIFY(run({"off", "1"}).exitCode == 0);
}

void tst_E2eCanTools::tuneOnOldCanWritesNothingUnasked()
{
    const CtlResult r = run({"tune", "1", "speed", "--json", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(!jsonOf(r.out.trimmed()).value("candidates").toArray().isEmpty());
    // Candidates go to RAM only (0x31), never ROM (0x32).
    QCOMPARE(m_wire.count(0x141, 0x32), 0);
    QVERIFY(run({"off", "1"}).exitCode == 0);
}

void tst_E2eCanTools::backupDiffRestoreOnOldCan()
{
    // CAN has no read_model: the drive's identity is the user's --drives, the file says it was
    // declared, and a backup of an old CAN drive holds its gains, acceleration and encoder
    // offset (0x30, 0x33, 0x90), as V2.3.
    const QString file = m_dir.filePath(QStringLiteral("b.json"));
    const CtlResult b = run({"backup", "1", "--out", file, "--json", "--drives", kOld});
    QVERIFY2(b.exitCode == 0, qPrintable(describeRun(b)));
    for (int code : {0x30, 0x33, 0x90})
        QVERIFY2(m_wire.waitFor(0x141, quint8(code), 2), qPrintable(QString::number(code, 16)));
    const QJsonObject saved = fileDrive(file, 1);
    QCOMPARE(saved.value("identity").toString(), QStringLiteral("declared"));
    QCOMPARE(saved.value("link").toString(), QStringLiteral("can"));
    QCOMPARE(saved.value("generation").toString(), QStringLiteral("can"));
    QVERIFY2(!saved.contains("motor_name") && !saved.contains("firmware_version_raw"),
             qPrintable(QJsonDocument(saved).toJson()));
    const QByteArray gains = m_wire.last(0x141, 0x30).data;
    QCOMPARE(saved.value("params").toObject().value("speed_kp").toObject().value("value").toInt(),
             int(quint8(gains.at(4))));
    const CtlResult d = run({"diff", file, "--json", "--drives", kOld});
    QVERIFY2(d.exitCode == 0, qPrintable(describeRun(d)));
    const CtlResult w =
        run({"write", "1", "pid", "1", "2", "3", "4", "5", "6", "--ram", "--drives", kOld});
    QVERIFY2(w.exitCode == 0, qPrintable(describeRun(w)));
    QCOMPARE(run({"diff", file, "--drives", kOld}).exitCode, 5);
    const CtlResult r = run(
        {"restore", file, "--ram", "--undo", m_dir.filePath("u.json"), "--json", "--drives", kOld});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out.trimmed()).value("drives").toArray().at(0).toObject().value("outcome"),
             QJsonValue("verified"));
    // The restore wrote the backup's gains with 0x31 (RAM), once, and nothing to ROM.
    QVERIFY(m_wire.waitFor(0x141, 0x31, 4)); // the write above and the restore, each echoed
    QCOMPARE(m_wire.last(0x141, 0x31).data.mid(2).toHex(), gains.mid(2).toHex());
    QCOMPARE(m_wire.count(0x141, 0x32), 0);
    QCOMPARE(m_wire.count(0x141, 0x12), 0);
    const CtlResult after = run({"diff", file, "--json", "--drives", kOld});
    QVERIFY2(after.exitCode == 0, qPrintable(describeRun(after)));
}

void tst_E2eCanTools::cloneOnOldCan()
{
    const QString drives = kOld + ",3:MG@can";
    const CtlResult w =
        run({"write", "3", "pid", "1", "2", "3", "4", "5", "6", "--ram", "--drives", drives});
    QVERIFY2(w.exitCode == 0, qPrintable(describeRun(w)));
    const QString undo = m_dir.filePath(QStringLiteral("undo.json"));
    const CtlResult r =
        run({"clone", "1", "3", "--ram", "--undo", undo, "--json", "--drives", drives});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out.trimmed()).value("drives").toArray().at(0).toObject().value("outcome"),
             QJsonValue("verified"));
    // Drive 1's gains went to drive 3 in RAM (0x31 on 0x143), nothing to ROM; the undo file
    // holds what drive 3 had, declared.
    QVERIFY(m_wire.waitFor(0x141, 0x30, 2));
    QVERIFY(m_wire.waitFor(0x143, 0x31, 4));
    QCOMPARE(m_wire.last(0x143, 0x31).data.mid(2).toHex(),
             m_wire.last(0x141, 0x30).data.mid(2).toHex());
    QCOMPARE(m_wire.count(0x143, 0x32), 0);
    const QJsonObject before = fileDrive(undo, 3);
    QCOMPARE(before.value("identity").toString(), QStringLiteral("declared"));
    QCOMPARE(before.value("params").toObject().value("angle_kp").toObject().value("value").toInt(),
             1);
    // A target declared as another series than the source is refused, nothing sent.
    const int sent = m_wire.count(0x143, 0x31);
    const CtlResult other =
        run({"clone", "1", "3", "--ram", "--undo", undo, "--json", "--drives", kOld + ",3:MF@can"});
    QCOMPARE(other.exitCode, 4);
    QCOMPARE(
        jsonOf(other.out.trimmed()).value("drives").toArray().at(0).toObject().value("refused_key"),
        QJsonValue("series"));
    QCOMPARE(m_wire.count(0x143, 0x31), sent);
    QCOMPARE(m_wire.count(0x143, 0xC1), 0);
}

void tst_E2eCanTools::haltAllReachesEveryId_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<int>("code");
    QTest::newRow("off all") << "off" << 0x80;
    QTest::newRow("stop all") << "stop" << 0x81;
}

void tst_E2eCanTools::haltAllReachesEveryId()
{
    QFETCH(QString, command);
    QFETCH(int, code);
    const CtlResult r = run({command, "all", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out.trimmed()).value("acknowledged").toArray(), (QJsonArray{1, 2, 3}));
    // Every ID 1..32 hears it on its request ID; the V2.36 drive answers on 0x182.
    for (quint32 id = 1; id <= 32; ++id)
        QVERIFY2(m_wire.waitFor(0x140 + id, quint8(code), 1, 5000),
                 qPrintable(QString::number(id)));
    QVERIFY(m_wire.waitFor(0x182, quint8(code)));
}

void tst_E2eCanTools::runAllResumesTheDrivesFound()
{
    QVERIFY(run({"stop", "all"}).exitCode == 0);
    const CtlResult r = run({"run", "all", "--json", "--drives", kAll});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out.trimmed()).value("acknowledged").toArray(), (QJsonArray{1, 2, 3}));
    QVERIFY(m_wire.waitFor(0x182, 0x88));
}

void tst_E2eCanTools::stepOnV236()
{
    const CtlResult r = run({"step", "2", "speed", "0", "60", "--duration", "0.3", "--pre-roll",
                             "0.2", "--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    for (const SniffedFrame &f : m_wire.on(0x142, 0xA2))
        QVERIFY2(leBytes(f.data, 2, 2, true) > 0, qPrintable(f.text())); // torque limit
}

void tst_E2eCanTools::freqAndTuneOnV236()
{
    CtlResult r =
        runTuning({"freq", "2", "speed", "--from", "1", "--to", "4", "--points", "2", "--amplitude",
                   "30", "--per-point", "0.3", "--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    r = runTuning({"tune", "2", "speed", "--write", "ram", "--json", "--drives", kNew});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(m_wire.count(0x142, 0xC1) > 0);
}

void tst_E2eCanTools::v236BackupHoldsControlParamsRestoreIsRamOnly()
{
    // A V2.36 backup reads every control parameter with 0xC0 (0x0A..0x26) and says its
    // identity was declared; a restore writes RAM only (0xC1) and says so; --rom is refused
    // with nothing sent; a declared series other than the file's is refused naming the key.
    const QString file = m_dir.filePath(QStringLiteral("b236.json"));
    const CtlResult b = run({"backup", "2", "--out", file, "--json", "--drives", kNew});
    QVERIFY2(b.exitCode == 0, qPrintable(describeRun(b)));
    QVERIFY(m_wire.waitFor(0x182, 0xC0, 8));
    QStringList asked;
    for (const SniffedFrame &f : m_wire.on(0x142, 0xC0))
        asked << QString::number(quint8(f.data.at(1)), 16);
    QCOMPARE(asked, (QStringList{"a", "b", "c", "1e", "20", "22", "24", "26"}));
    QCOMPARE(m_wire.count(0x142, 0x12), 0);
    const QJsonObject saved = fileDrive(file, 2);
    QCOMPARE(saved.value("identity").toString(), QStringLiteral("declared"));
    QCOMPARE(saved.value("generation").toString(), QStringLiteral("can236"));
    const QJsonObject params = saved.value("params").toObject();
    for (const char *key : {"angle_kd", "max_torque", "max_speed_raw", "current_ramp_raw",
                            "speed_ramp_dps2", "encoder_offset"})
        QVERIFY2(params.contains(key), key);
    const qint64 speedLimit = params.value("max_speed_raw").toObject().value("value").toInteger();

    CtlResult w = run({"write", "2", "param", "max_speed_dps", "123", "--ram", "--drives", kNew});
    QVERIFY2(w.exitCode == 0, qPrintable(describeRun(w)));
    QVERIFY(m_wire.waitFor(0x182, 0xC1)); // its reply seen: the request was seen before it
    const int written = m_wire.count(0x142, 0xC1);
    QCOMPARE(written, 1);

    const CtlResult rom = run({"restore", file, "--rom", "--yes", "--drives", kNew});
    QVERIFY2(rom.exitCode == 4, qPrintable(describeRun(rom)));
    QVERIFY2(rom.err.contains("RAM only"), rom.err.constData());
    const CtlResult series = run({"restore", file, "--ram", "--undo", m_dir.filePath("u0.json"),
                                  "--json", "--drives", "2:MG@can236"});
    QVERIFY2(series.exitCode == 4, qPrintable(describeRun(series)));
    QCOMPARE(jsonOf(series.out.trimmed())
                 .value("drives")
                 .toArray()
                 .at(0)
                 .toObject()
                 .value("refused_key"),
             QJsonValue("series"));
    // A read after the refusals has passed the sniffer: so has anything they sent before it.
    QVERIFY(run({"read", "2", "single-turn", "--drives", kNew}).exitCode == 0);
    QVERIFY(m_wire.waitFor(0x182, 0x94));
    QCOMPARE(m_wire.count(0x142, 0xC1), written);

    const CtlResult ram = run(
        {"restore", file, "--ram", "--undo", m_dir.filePath("u.json"), "--json", "--drives", kNew});
    QVERIFY2(ram.exitCode == 0, qPrintable(describeRun(ram)));
    const QJsonObject drive = jsonOf(ram.out.trimmed()).value("drives").toArray().at(0).toObject();
    QCOMPARE(drive.value("outcome"), QJsonValue("verified"));
    QVERIFY2(drive.value("notes").toArray().at(0).toString().contains("RAM only"),
             ram.out.constData());
    // Only the value that changed went out: the speed limit, back to the backup's.
    QVERIFY(m_wire.waitFor(0x182, 0xC1, written + 1));
    QCOMPARE(m_wire.count(0x142, 0xC1), written + 1);
    const QByteArray restored = m_wire.last(0x142, 0xC1).data;
    QCOMPARE(quint8(restored.at(1)), quint8(0x20));
    QCOMPARE(leBytes(restored, 4, 4, true), speedLimit);
}

void tst_E2eCanTools::listenPairsCanFrames()
{
    QProcess listen;
    listen.start(QStringLiteral(LKCTL_PATH), {"listen", "--can", m_bus.can(), "--drives",
                                              "1:MG,2:MF", "--json", "--duration", "20"});
    QVERIFY(listen.waitForStarted(60000));
    // Rows in monitor's schema: drive 2's state 2 reply, paired with the read another master
    // (this test's lkctl) sent, gives its encoder. Read until listen has printed such a row
    // (it may join the bus after the first read), then end it as a user would: SIGTERM.
    QByteArray out;
    const auto listenSawIt = [&] {
        out += listen.readAllStandardOutput();
        return out.contains("\"id\":2") && out.contains("\"encoder\"");
    };
    QVERIFY(QTest::qWaitFor(
        [&] {
            if (!run({"read", "2", "state2", "--drives", kNew}).out.contains("encoder"))
                return false;
            return QTest::qWaitFor(listenSawIt, 500);
        },
        30000));
    listen.terminate();
    QVERIFY(QTest::qWaitFor([&] { return listen.state() == QProcess::NotRunning; }, 60000));
    QCOMPARE(listen.exitStatus(), QProcess::NormalExit);
    QCOMPARE(listen.exitCode(), 0);
    QVERIFY2(listenSawIt(), out.constData());
}

void tst_E2eCanTools::decodeReadsCandumpLog()
{
    const QString file = m_dir.filePath(QStringLiteral("log.txt"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("(1700000000.000000) can0 141#9C00000000000000\n"
            "(1700000000.000300) can0 141#9C1900000000A00F\n");
    f.close();
    const CtlResult r = lkctl({"decode", file}); // JSON lines, its only form
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY2(r.out.contains("read_state2") && r.out.contains("4000"), r.out.constData());
}

void tst_E2eCanTools::gearFromDrivesBoundsAMove()
{
    // One output turn of a 36:1 gear is 12960 rotor degrees: 3000 is within it, 13000 is not.
    const QString geared = QStringLiteral("1:MG@can/36");
    CtlResult r = run({"control", "1", "increment", "3000", "--drives", geared});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    r = run({"control", "1", "increment", "13000", "--drives", geared});
    QCOMPARE(r.exitCode, 4);
}

QTEST_GUILESS_MAIN(tst_E2eCanTools)
#include "tst_e2ecantools.moc"
