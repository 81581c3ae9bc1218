#include "E2eUtil.h"

#include <QtCore/QDir>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <algorithm>

using namespace lk::e2e;

namespace {

/// Frames lksim received that start with `prefix` ("3E 44 01").
qsizetype countFrames(const QList<QByteArray> &frames, const QByteArray &prefix)
{
    return std::count_if(frames.cbegin(), frames.cend(),
                         [&prefix](const QByteArray &f) { return f.startsWith(prefix); });
}

} // namespace

/// lkctl against lksim with a firmware-2.35 drive (protocol V2.35) beside a V2.3 one, over a
/// pseudo-terminal: the parameter table (read params, write param), the brake, and firmware
/// 2.35's bad 0xA4 checksums.
class tst_E2eV235 : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void scanAndInfoTellTheGenerations();
    void readParamsUsesInfosNames();
    void v23DriveHasNoParameterTable();
    void v235DriveIsNotSentV23Writes();
    void writeParamRamReadsBack();
    void maxAngleIsWrittenAndReadAsAPair();
    void outOfRangeParamSendsNothing();
    void romWriteNeedsYesAndIsSentOnce();
    void brakeStatusEngageRelease();
    void releaseRefusedWhileMotorOff();
    void badChecksumIsCountedNeverSuccess();

private:
    bool startSim(const QStringList &extra = {});
    QStringList port() const;
    CtlResult ctl(const QStringList &args) const { return lkctl(args + port()); }

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

bool tst_E2eV235::startSim(const QStringList &extra)
{
    if (!m_sim)
        m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    const QStringList args{QStringLiteral("--motors"),         QStringLiteral("1:MS4015@2.35,3:MF"),
                           QStringLiteral("--link"),           m_link,
                           QStringLiteral("--wire-time"),      QStringLiteral("--baud"),
                           QStringLiteral("115200"),           QStringLiteral("--verbose"),
                           QStringLiteral("--measure-pty-lag")};
    const bool ok = m_sim->start(args + extra);
    if (!ok)
        qWarning("%s", qPrintable(m_sim->errorString()));
    return ok;
}

QStringList tst_E2eV235::port() const
{
    return {QStringLiteral("--port"), m_link, QStringLiteral("--baud"), QStringLiteral("115200")};
}

void tst_E2eV235::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_link = m_dir->filePath(QStringLiteral("lkbus"));
}

void tst_E2eV235::cleanup()
{
    if (m_sim)
        verifyNoCollisions(*m_sim);
    m_sim.reset();
    m_dir.reset();
}

void tst_E2eV235::scanAndInfoTellTheGenerations()
{
    QVERIFY(startSim());
    const CtlResult scan = ctl({"scan", "--json", "--retries", "1"});
    QVERIFY2(scan.exitCode == 0, qPrintable(describeRun(scan)));
    const QJsonArray drives = QJsonDocument::fromJson(scan.out).array();
    QCOMPARE(drives.size(), 2);
    QCOMPARE(drives.at(0).toObject().value("generation").toString(), QStringLiteral("v2.35"));
    QCOMPARE(drives.at(1).toObject().value("generation").toString(), QStringLiteral("v2.3"));

    const CtlResult info = ctl({"info", "1", "--json"});
    QVERIFY2(info.exitCode == 0, qPrintable(describeRun(info)));
    const QJsonObject o = jsonOf(info.out);
    QCOMPARE(o.value("pid").toObject().size(), 9);
    QVERIFY(o.value("params").toObject().contains("max_angle_deg"));
}

void tst_E2eV235::readParamsUsesInfosNames()
{
    QVERIFY(startSim());
    const CtlResult info = ctl({"info", "1", "--json"});
    QVERIFY2(info.exitCode == 0, qPrintable(describeRun(info)));
    const CtlResult r = ctl({"read", "1", "params", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("command").toString(), QStringLiteral("read_param"));
    QCOMPARE(o.value("code").toString(), QStringLiteral("0x40"));
    const QJsonObject fields = o.value("fields").toObject();
    // Every parameter, under exactly the names info prints (gains and params together).
    QJsonObject expected = jsonOf(info.out).value("pid").toObject();
    const QJsonObject params = jsonOf(info.out).value("params").toObject();
    for (auto it = params.begin(); it != params.end(); ++it)
        expected.insert(it.key(), it.value());
    QCOMPARE(fields.keys(), expected.keys());
    QCOMPARE(fields, expected);
    // One read_param per ParamID 0x96..0x9E, nothing else but read_model.
    const QList<QByteArray> frames = m_sim->receivedFrames();
    for (const char *param : {"96", "97", "98", "99", "9A", "9B", "9C", "9D", "9E"})
        QVERIFY2(countFrames(frames, QByteArray("3E 40 01 02 81 ") + param) >= 1, param);
}

void tst_E2eV235::v23DriveHasNoParameterTable()
{
    QVERIFY(startSim());
    CtlResult r = ctl({"read", "3", "params", "--json"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.contains("no parameter table") && r.err.contains("lkctl read 3 pid") &&
                 r.err.contains("nothing was sent"),
             r.err.constData());
    r = ctl({"write", "3", "param", "max_speed_dps", "100", "--ram"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("no parameter table"), r.err.constData());
    r = ctl({"brake", "3", "status"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("no brake command"), r.err.constData());
    const QList<QByteArray> frames = m_sim->receivedFrames();
    for (const QByteArray &f : frames) // only read_model reached drive 3
        QVERIFY2(f.startsWith("3E 12 03"), f.constData());
    QCOMPARE(frames.size(), 3);
}

void tst_E2eV235::v235DriveIsNotSentV23Writes()
{
    // write pid / accel read the model first: a V2.35 drive has no 0x31, 0x32 or 0x34.
    QVERIFY(startSim());
    CtlResult r = ctl({"write", "1", "pid", "1", "2", "3", "4", "5", "6", "--ram"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("has no write_pid_ram; nothing was sent") &&
                 r.err.contains("param angle_pid KP KI KD"),
             r.err.constData());
    r = ctl({"write", "1", "accel", "500", "--ram"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("speed_ramp_dps2"), r.err.constData());
    for (const QByteArray &f : m_sim->receivedFrames())
        QVERIFY2(f.startsWith("3E 12 01"), f.constData()); // read_model only
}

void tst_E2eV235::writeParamRamReadsBack()
{
    QVERIFY(startSim());
    CtlResult r = ctl({"write", "1", "param", "speed_pid", "51", "21", "3", "--ram", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(r.out.startsWith("{\"command\":\"write_param_ram\",\"id\":1,\"param\":\"speed_pid\","
                             "\"written\":{\"speed_kp\":51,\"speed_ki\":21,\"speed_kd\":3},"));
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("match").toBool(), true);
    QCOMPARE(o.value("holds").toObject(), o.value("written").toObject());
    r = ctl({"write", "1", "param", "max_speed_dps", "360", "--ram", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    // The frame of docs/V2.35.md section 13, then the read-back.
    const QList<QByteArray> frames = m_sim->receivedFrames();
    QCOMPARE(countFrames(frames, "3E 42 01 07 88 9A A0 8C 00 00 00 00 C6"), qsizetype(1));
    r = ctl({"read", "1", "params", "--json"});
    const QJsonObject fields = jsonOf(r.out).value("fields").toObject();
    QCOMPARE(fields.value("speed_kp").toInt(), 51);
    QCOMPARE(fields.value("speed_kd").toInt(), 3);
    QCOMPARE(fields.value("max_speed_dps").toDouble(), 360.0);
}

void tst_E2eV235::maxAngleIsWrittenAndReadAsAPair()
{
    QVERIFY(startSim());
    // 3e9 deg = 3e11 in 0.01 deg: both halves carry bits.
    const CtlResult r =
        ctl({"write", "1", "param", "max_angle_deg", "3000000000", "--ram", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("holds").toObject().value("max_angle_raw").toInteger(), 300000000000LL);
    QCOMPARE(o.value("match").toBool(), true);
    const QList<QByteArray> frames = m_sim->receivedFrames();
    const auto low = std::find_if(frames.cbegin(), frames.cend(), [](const QByteArray &f) {
        return f.startsWith("3E 42 01 07 88 9B");
    });
    const auto high = std::find_if(frames.cbegin(), frames.cend(), [](const QByteArray &f) {
        return f.startsWith("3E 42 01 07 88 9C");
    });
    QVERIFY(low != frames.cend() && high != frames.cend());
    QVERIFY(low < high); // 0x9B then 0x9C
    QCOMPARE(countFrames(frames, "3E 40 01 02 81 9B"), qsizetype(1));
    QCOMPARE(countFrames(frames, "3E 40 01 02 81 9C"), qsizetype(1));
    const CtlResult params = ctl({"read", "1", "params", "--json"});
    QCOMPARE(jsonOf(params.out).value("fields").toObject().value("max_angle_deg").toDouble(), 3e9);
}

void tst_E2eV235::outOfRangeParamSendsNothing()
{
    QVERIFY(startSim());
    CtlResult r = ctl({"write", "1", "param", "max_torque", "5000", "--ram"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("max_torque must be in 0..2048"), r.err.constData());
    r = ctl({"write", "1", "param", "angle_pid", "1", "2", "70000", "--rom", "--yes"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("angle_kd") && r.err.contains("0..65535"), r.err.constData());
    r = ctl({"write", "1", "param", "max_angle_deg", "-1", "--ram"});
    QCOMPARE(r.exitCode, 2);
    r = ctl({"write", "1", "param", "max_angle_low", "1", "--ram"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("max_angle_deg"), r.err.constData()); // names the right one
    QVERIFY(m_sim->receivedFrames().isEmpty());
}

void tst_E2eV235::romWriteNeedsYesAndIsSentOnce()
{
    const QString romDir = m_dir->filePath(QStringLiteral("rom"));
    QVERIFY(QDir().mkpath(romDir));
    QVERIFY(startSim({QStringLiteral("--rom-dir"), romDir}));
    CtlResult r = ctl({"write", "1", "param", "speed_ramp_dps2", "12345", "--rom"});
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("flash") && r.err.contains("speed_ramp_dps2"), r.err.constData());
    QVERIFY(m_sim->receivedFrames().isEmpty()); // not even read_model
    r = ctl({"write", "1", "param", "speed_ramp_dps2", "12345", "--rom", "--yes", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out).value("command").toString(), QStringLiteral("write_param_rom"));
    QCOMPARE(jsonOf(r.out).value("match").toBool(), true);
    QCOMPARE(countFrames(m_sim->receivedFrames(), "3E 44 01"), qsizetype(1));
    // Kept across a restart of the drive.
    m_sim->stop();
    QVERIFY(startSim({QStringLiteral("--rom-dir"), romDir}));
    r = ctl({"read", "1", "params", "--json"});
    QCOMPARE(jsonOf(r.out).value("fields").toObject().value("speed_ramp_dps2").toInt(), 12345);
}

void tst_E2eV235::brakeStatusEngageRelease()
{
    QVERIFY(startSim());
    CtlResult r = ctl({"brake", "1", "status", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    // A real drive powers up with its motor on and its brake released (docs/V2.35.md).
    QCOMPARE(r.out, QByteArray("{\"command\":\"brake\",\"id\":1,\"action\":\"status\","
                               "\"motor_on\":null,\"brake_released\":true,\"brake_raw\":1}\n"));
    r = ctl({"brake", "1", "engage", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out).value("brake_released").toBool(true), false);
    r = ctl({"brake", "1", "release"});
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("--yes"), r.err.constData());
    // The motor is on, so release is allowed with --yes.
    r = ctl({"brake", "1", "release", "--yes", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out).value("motor_on").toBool(), true);
    QCOMPARE(jsonOf(r.out).value("brake_released").toBool(), true);
    r = ctl({"brake", "1", "engage", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out).value("brake_released").toBool(), false);
    const QList<QByteArray> frames = m_sim->receivedFrames();
    QCOMPARE(countFrames(frames, "3E 8C 01 01 CC 10 10"), qsizetype(1));
    QCOMPARE(countFrames(frames, "3E 8C 01 01 CC 01 01"), qsizetype(1));
    QCOMPARE(countFrames(frames, "3E 8C 01 01 CC 00 00"), qsizetype(2));
}

void tst_E2eV235::releaseRefusedWhileMotorOff()
{
    QVERIFY(startSim());
    CtlResult r = ctl({"off", "1"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    r = ctl({"brake", "1", "release", "--yes"});
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("the motor is off") && r.err.contains("--motor-off-ok"),
             r.err.constData());
    QCOMPARE(countFrames(m_sim->receivedFrames(), "3E 8C"), qsizetype(0));
    r = ctl({"brake", "1", "release", "--yes", "--motor-off-ok", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(jsonOf(r.out).value("motor_on").toBool(true), false);
    QCOMPARE(jsonOf(r.out).value("brake_released").toBool(), true);
    QCOMPARE(countFrames(m_sim->receivedFrames(), "3E 8C 01 01 CC 01 01"), qsizetype(1));
}

void tst_E2eV235::badChecksumIsCountedNeverSuccess()
{
    // Every 0xA4 reply of the V2.35 drive is spoilt: the move is retried once (an absolute
    // target is safe to repeat), then reported as failed, never as done.
    QVERIFY(startSim({QStringLiteral("--bad-checksum-pct"), QStringLiteral("100"),
                      QStringLiteral("--faults"), QStringLiteral("seed=7")}));
    CtlResult r = ctl({"control", "1", "multi-position", "10", "--json"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.contains("bad data checksum") && r.err.contains("may have acted"),
             r.err.constData());
    QCOMPARE(countFrames(m_sim->receivedFrames(), "3E A4 01"), qsizetype(2));
    // The V2.3 drive's 0xA4 replies are good, and monitoring goes on.
    r = ctl({"control", "3", "multi-position", "10", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    r = ctl({"monitor", "1", "3", "--count", "3", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(r.out.count('\n'), 3); // --count counts lines: one per drive and round
    QVERIFY(r.out.contains("\"id\":1,") && r.out.contains("\"id\":3,"));
    m_sim->stop();
    const std::optional<LksimCounters> c = m_sim->counters();
    QVERIFY(c);
    QCOMPARE(c->badChecksumReplies, qint64(2));
}

QTEST_GUILESS_MAIN(tst_E2eV235)
#include "tst_e2ev235.moc"
