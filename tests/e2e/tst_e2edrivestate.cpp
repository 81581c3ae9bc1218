#include "E2eUtil.h"

#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>
#include <memory>

using namespace lk::e2e;

/// lkctl against lksim: values at each drive's own scale and the drive's own state on both
/// generations. The torque read back for 2 A on V2.3 and V2.35 MF and MG; a V2.35 drive that
/// stays off after motor_off until motor_run (docs/V2.35.md sections 3 and 11) and a brake that
/// holds the shaft; a protection fault scheduled with --fault that stops the drive; lksim's
/// fw 2.35 MS4015 as the real one reports itself.
class tst_E2eDriveState : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void torqueReadsBackAtTheDrivesScale_data();
    void torqueReadsBackAtTheDrivesScale();
    void offDriveIsRefusedUntilMotorOn();
    void engagedBrakeHoldsTheShaftAndWarns();
    void scheduledFaultStopsTheDrive();
    void ms235IsTheCapturedDrive();
    void drivesOwnMaxSpeedBoundsControl();

private:
    bool startSim(const QString &motors, const QStringList &extra = {});
    CtlResult ctl(const QStringList &args) const;
    QJsonObject state(int id, const QString &what) const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

bool tst_E2eDriveState::startSim(const QString &motors, const QStringList &extra)
{
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    const QStringList args{QStringLiteral("--motors"),    motors,
                           QStringLiteral("--link"),      m_link,
                           QStringLiteral("--wire-time"), QStringLiteral("--baud"),
                           QStringLiteral("115200"),      QStringLiteral("--measure-pty-lag")};
    const bool ok = m_sim->start(args + extra);
    if (!ok)
        qWarning("%s", qPrintable(m_sim->errorString()));
    return ok;
}

CtlResult tst_E2eDriveState::ctl(const QStringList &args) const
{
    return lkctl(args + QStringList{QStringLiteral("--port"), m_link, QStringLiteral("--baud"),
                                    QStringLiteral("115200")});
}

QJsonObject tst_E2eDriveState::state(int id, const QString &what) const
{
    const CtlResult r = ctl({QStringLiteral("read"), QString::number(id), what, "--json"});
    return jsonOf(r.out).value(QStringLiteral("fields")).toObject();
}

void tst_E2eDriveState::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_link = m_dir->filePath(QStringLiteral("lkbus"));
}

void tst_E2eDriveState::cleanup()
{
    if (m_sim) {
        ctl({"off", "all"}); // nothing this test set turning outlives it
        verifyNoCollisions(*m_sim);
    }
    m_sim.reset();
    m_dir.reset();
}

void tst_E2eDriveState::torqueReadsBackAtTheDrivesScale_data()
{
    QTest::addColumn<QString>("motor");
    QTest::addColumn<int>("iqRaw"); // 2 A on the wire
    // V2.3: 32 A / 2000 LSB; V2.35: MF 33/4096 A, MG 66/4096 A per LSB.
    QTest::newRow("V2.3 MF") << QStringLiteral("MF4015") << 125;
    QTest::newRow("V2.35 MF") << QStringLiteral("MF4015@2.35") << 248;
    QTest::newRow("V2.3 MG") << QStringLiteral("MG") << 125;
    QTest::newRow("V2.35 MG") << QStringLiteral("MG@2.35") << 124;
}

void tst_E2eDriveState::torqueReadsBackAtTheDrivesScale()
{
    QFETCH(QString, motor);
    QFETCH(int, iqRaw);
    QVERIFY(startSim(QStringLiteral("1:") + motor));
    // A V2.35 drive's brake holds the rotor, so that the current settles where it was sent
    // (a free rotor runs up until its back-EMF eats the supply).
    if (motor.endsWith(QLatin1String("@2.35")))
        QCOMPARE(ctl({"brake", "1", "engage"}).exitCode, 0);
    const CtlResult r = ctl({"control", "1", "torque", "2", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject sent = jsonOf(r.out).value("sent").toObject();
    QCOMPARE(sent.value("iq_raw").toInt(), iqRaw);
    QVERIFY2(std::abs(sent.value("iq_a").toDouble() - 2.0) < 0.01, r.out.constData());
    // What the drive does with it: 2 A, where the V2.3 scale on a V2.35 MF gave 1.007 A.
    const QJsonObject back = state(1, QStringLiteral("state2"));
    QVERIFY2(
        std::abs(back.value("iq_a").toDouble() - 2.0) < 0.05,
        qPrintable(
            QStringLiteral("%1 read back %2 A").arg(motor).arg(back.value("iq_a").toDouble())));
}

void tst_E2eDriveState::offDriveIsRefusedUntilMotorOn()
{
    QVERIFY(startSim(QStringLiteral("1:MF4015@2.35")));
    // A V2.35 drive powers up on: a speed command moves it.
    QCOMPARE(state(1, QStringLiteral("state1")).value("motor_on").toBool(), true);
    CtlResult r = ctl({"off", "1"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(state(1, QStringLiteral("state1")).value("motor_on").toBool(true), false);
    // Off: refused before anything moves, with what to do; the drive did not turn.
    r = ctl({"control", "1", "speed", "360"});
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("drive 1 is off: Motor On first") && r.err.contains("lkctl run 1"),
             r.err.constData());
    QVERIFY(r.out.isEmpty());
    // motor_run (0x88) turns it on; then the same command moves it.
    r = ctl({"run", "1"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QCOMPARE(state(1, QStringLiteral("state1")).value("motor_on").toBool(), true);
    r = ctl({"control", "1", "speed", "360"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(QTest::qWaitFor(
        [&] { return state(1, QStringLiteral("state2")).value("speed_dps").toDouble() > 300; },
        20000));
}

void tst_E2eDriveState::engagedBrakeHoldsTheShaftAndWarns()
{
    QVERIFY(startSim(QStringLiteral("1:MS4015@2.35")));
    QCOMPARE(ctl({"brake", "1", "engage"}).exitCode, 0);
    const int encoder = state(1, QStringLiteral("state2")).value("encoder").toInt();
    const CtlResult r = ctl({"control", "1", "speed", "360"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY2(r.err.contains("warning: the brake of drive 1 reads engaged") &&
                 r.err.contains("lkctl brake 1 release"),
             r.err.constData());
    QTest::qWait(300);
    // The brake holds: the shaft stays where it was.
    const QJsonObject held = state(1, QStringLiteral("state2"));
    QCOMPARE(held.value("speed_dps").toDouble(), 0.0);
    QCOMPARE(held.value("encoder").toInt(), encoder);
    QCOMPARE(ctl({"brake", "1", "release", "--yes"}).exitCode, 0);
    QVERIFY(QTest::qWaitFor(
        [&] { return state(1, QStringLiteral("state2")).value("speed_dps").toDouble() > 300; },
        20000));
}

void tst_E2eDriveState::scheduledFaultStopsTheDrive()
{
    // Drive 1 (V2.35) stalls 5 s after lksim started, drive 3 (V2.3) is hot from the start.
    QVERIFY(startSim(QStringLiteral("1:MF4015@2.35,3:MF"),
                     {QStringLiteral("--fault"), QStringLiteral("1:stall@5s,3:over_temperature")}));
    QVERIFY(m_sim->log().contains("1:MF@2.35+fault=stall@5s,3:MF+fault=over_temperature"));
    // Drive 1 runs until the stall trips it.
    QCOMPARE(ctl({"control", "1", "speed", "360"}).exitCode, 0);

    const QJsonObject s3 = state(3, QStringLiteral("state1"));
    QCOMPARE(s3.value("over_temperature").toBool(), true);
    QVERIFY2(s3.value("temperature_c").toInt() > 85,
             qPrintable(QString::number(s3.value("temperature_c").toInt())));
    // A V2.3 drive in protection answers a control command but does not move.
    QCOMPARE(ctl({"control", "3", "speed", "360"}).exitCode, 0);
    QTest::qWait(300);
    QCOMPARE(state(3, QStringLiteral("state2")).value("speed_dps").toDouble(), 0.0);

    // The stall: the motor reads off and the drive coasts down.
    QVERIFY(QTest::qWaitFor(
        [&] { return state(1, QStringLiteral("state1")).value("stall").toBool(); }, 30000));
    QCOMPARE(state(1, QStringLiteral("state1")).value("motor_on").toBool(true), false);
    QVERIFY(QTest::qWaitFor(
        [&] { return state(1, QStringLiteral("state2")).value("speed_dps").toDouble() == 0; },
        20000));
    // Off after the trip: a control command is refused until Motor On.
    const CtlResult r = ctl({"control", "1", "speed", "360"});
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("drive 1 is off"), r.err.constData());
}

void tst_E2eDriveState::ms235IsTheCapturedDrive()
{
    // docs/V2.35.md sections 7 and 12: a DS40R7 driving an MS4015, its encoder zero away from
    // 0, Max Power within MS's range, on and unbraked after power-up.
    QVERIFY(startSim(QStringLiteral("1:MS4015@2.35")));
    const CtlResult info = ctl({"read", "1", "model", "--json"});
    QVERIFY2(info.exitCode == 0, qPrintable(describeRun(info)));
    QCOMPARE(jsonOf(info.out).value("fields").toObject().value("driver_name").toString(),
             QStringLiteral("DS40R7"));
    QVERIFY(state(1, QStringLiteral("encoder")).value("encoder_offset").toInt() != 0);
    const QJsonObject params = state(1, QStringLiteral("params"));
    QVERIFY2(std::abs(params.value("max_torque").toInt()) <= 1000,
             qPrintable(QString::number(params.value("max_torque").toInt())));
    QCOMPARE(state(1, QStringLiteral("state1")).value("motor_on").toBool(), true);
    const CtlResult brake = ctl({"brake", "1", "status", "--json"});
    QCOMPARE(jsonOf(brake.out).value("brake_released").toBool(), true);
}

void tst_E2eDriveState::drivesOwnMaxSpeedBoundsControl()
{
    // The drive holds a Max Speed of 720 dps; the MF soft limit is the series' 18000.
    QVERIFY(startSim(QStringLiteral("1:MF4015@2.35")));
    CtlResult r = ctl({"write", "1", "param", "max_speed_dps", "720", "--ram"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    r = ctl({"control", "1", "speed", "800"});
    QCOMPARE(r.exitCode, 4);
    QVERIFY2(r.err.contains("the drive's own Max Speed of 720 dps"), r.err.constData());
    QVERIFY(r.out.isEmpty());
    // A position move goes out capped at it, and says whose bound it is.
    r = ctl({"control", "1", "increment", "90", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("sent").toObject().value("max_speed_raw").toInt(), 72000);
    QCOMPARE(o.value("speed_bound").toObject().value("source").toString(),
             QStringLiteral("drive_max_speed"));
    QCOMPARE(o.value("speed_bound").toObject().value("dps").toDouble(), 720.0);
}

QTEST_GUILESS_MAIN(tst_E2eDriveState)
#include "tst_e2edrivestate.moc"
