#include "E2eUtil.h"
#include "LksimFrames.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QJsonArray>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>

using namespace lk::e2e;

/// lkctl's zero tools against lksim, as the Encoder view does them: `zero --ram` (0x95) and
/// `clear-turns` (0x93) read the multi-turn angle before and after and say what was verified,
/// `zero --rom` (0x19) is sent once and never again, `clear-errors` (0x9B) tells the flags
/// before and after; each asks for --yes where the GUI asks, says RAM or ROM, and a command
/// the drive's generation lacks is refused naming it.
class tst_E2eZero : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void zeroInRamClearsTheAngle();
    void zeroInRamOnFirmwareThatIgnoresIt();
    void withoutYesNothingIsSent_data();
    void withoutYesNothingIsSent();
    void lostZeroRomReplyIsNotRepeated();
    void zeroRomReportsTheNewZero();
    void clearTurnsKeepsTheAngleWithinTheTurn();
    void clearTurnsOnV23IsRefused();
    void clearErrorsTellsBeforeAndAfter_data();
    void clearErrorsTellsBeforeAndAfter();

private:
    bool startSim(const QString &motors, const QStringList &extra = {});
    QStringList port() const { return {QStringLiteral("--port"), m_link}; }
    CtlResult run(const QStringList &args) const { return lkctl(args + port()); }
    qsizetype framesStartingWith(const QByteArray &start) const;
    double multiTurnDeg(int id) const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

bool tst_E2eZero::startSim(const QString &motors, const QStringList &extra)
{
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    const bool ok = m_sim->start(loggedSimArgs(m_link, motors, extra));
    if (!ok)
        qWarning("%s", qPrintable(m_sim->errorString()));
    return ok;
}

void tst_E2eZero::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    m_link = m_dir->filePath(QStringLiteral("bus"));
}

void tst_E2eZero::cleanup()
{
    if (m_sim)
        verifyNoCollisions(*m_sim);
    m_sim.reset();
}

qsizetype tst_E2eZero::framesStartingWith(const QByteArray &start) const
{
    return lk::e2e::framesStartingWith(*m_sim, start);
}

double tst_E2eZero::multiTurnDeg(int id) const
{
    const CtlResult r = run({"read", QString::number(id), "multi-turn", "--json"});
    return jsonOf(r.out).value("fields").toObject().value("angle_deg").toDouble(NAN);
}

void tst_E2eZero::zeroInRamClearsTheAngle()
{
    QVERIFY(startSim(QStringLiteral("3:MF")));
    const double before = multiTurnDeg(3);
    QVERIFY2(std::fabs(before) > 1, "the simulated drive starts away from 0");
    CtlResult r = run({"zero", "3", "--ram", "--yes", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("command").toString(), QStringLiteral("clear_angle"));
    QCOMPARE(o.value("memory").toString(), QStringLiteral("ram"));
    QCOMPARE(o.value("before_deg").toDouble(), before);
    QCOMPARE(o.value("after_deg").toDouble(), 0.0);
    QCOMPARE(o.value("result").toString(), QStringLiteral("cleared"));
    QCOMPARE(multiTurnDeg(3), 0.0);
    QCOMPARE(framesStartingWith("3E 95 03"), qsizetype(1));
    // The text form says RAM and what was verified.
    r = run({"zero", "3", "--ram", "--yes"});
    QVERIFY(r.out.contains("RAM, until power-off"));
    QVERIFY(r.out.contains("not verifiable: the angle read 0 before already"));
}

void tst_E2eZero::zeroInRamOnFirmwareThatIgnoresIt()
{
    QVERIFY(startSim(QStringLiteral("3:MF+clear-angle-ignored")));
    const CtlResult r = run({"zero", "3", "--ram", "--yes"});
    QCOMPARE(r.exitCode, 5);
    QVERIFY(r.out.contains("NOT verified"));
    QVERIFY2(r.err.contains("acknowledged clear_angle (0x95) but its angle did not change"),
             r.err.constData());
}

void tst_E2eZero::withoutYesNothingIsSent_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("said");
    QTest::newRow("zero --ram") << QStringList{"zero", "1", "--ram"} << "clear_angle: RAM";
    QTest::newRow("zero --rom") << QStringList{"zero", "1", "--rom"}
                                << "write_zero_rom: the "
                                   "drive's flash";
    QTest::newRow("clear-turns") << QStringList{"clear-turns", "1"}
                                 << "clear_turn_count, RAM or ROM not documented";
}

void tst_E2eZero::withoutYesNothingIsSent()
{
    QFETCH(QStringList, args);
    QFETCH(QString, said);
    QVERIFY(startSim(QStringLiteral("1:MS4015@2.35")));
    const CtlResult r = run(args);
    QCOMPARE(r.exitCode, 4);
    QCOMPARE(r.out, QByteArray());
    QVERIFY2(r.err.contains(said.toUtf8()) && r.err.contains("nothing was sent"),
             r.err.constData());
    QCOMPARE(m_sim->receivedFrames().size(), 0);
}

void tst_E2eZero::lostZeroRomReplyIsNotRepeated()
{
    // lkctl reads the model first. Seed 2 with drop=0.5 keeps the 1st reply (read_model) and
    // drops the 2nd (write_zero_rom): QRandomGenerator(2) draws 0.70, 0.17, ...
    QVERIFY(startSim(QStringLiteral("3:MF"), {"--faults", "drop=0.5,seed=2"}));
    const CtlResult r = run({"zero", "3", "--rom", "--yes"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("no reply to write_zero_rom (ID 3)"), r.err.constData());
    QVERIFY2(r.err.contains("write_zero_rom was NOT sent again"), r.err.constData());
    QCOMPARE(framesStartingWith("3E 19 03"), qsizetype(1));
}

void tst_E2eZero::zeroRomReportsTheNewZero()
{
    QVERIFY(startSim(QStringLiteral("1:MS4015@2.35,3:MF")));
    CtlResult r = run({"zero", "1", "--rom", "--yes", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("command").toString(), QStringLiteral("write_zero_rom"));
    QCOMPARE(o.value("memory").toString(), QStringLiteral("rom"));
    QVERIFY(o.value("encoder_zero").isDouble()); // V2.35 answers with the new zero
    r = run({"zero", "3", "--rom", "--yes", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(jsonOf(r.out).value("encoder_zero").isNull()); // V2.3: an echo, no value
    r = run({"zero", "3", "--rom", "--yes"});
    QVERIFY(r.out.contains("ROM, from the next power-on"));
    QCOMPARE(framesStartingWith("3E 19"), qsizetype(3));
}

void tst_E2eZero::clearTurnsKeepsTheAngleWithinTheTurn()
{
    QVERIFY(startSim(QStringLiteral("1:MS4015@2.35")));
    // Some whole turns first: motor on (0x88 on V2.35), then two increments.
    QCOMPARE(run({"run", "1"}).exitCode, 0);
    const double start = multiTurnDeg(1);
    for (int i = 0; i < 2; ++i) {
        const CtlResult r = run({"control", "1", "increment", "300"});
        QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
        // Each read is an lkctl run of its own: wait by the clock, not by QTRY's count.
        const double target = start + 300 * (i + 1);
        QElapsedTimer clock;
        clock.start();
        double angle = multiTurnDeg(1);
        while (!(std::fabs(angle - target) < 1) && clock.elapsed() < 30000) {
            QTest::qWait(100);
            angle = multiTurnDeg(1);
        }
        QVERIFY2(std::fabs(angle - target) < 1,
                 qPrintable(QStringLiteral("angle %1, target %2").arg(angle).arg(target)));
    }
    const CtlResult r = run({"clear-turns", "1", "--yes", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.value("command").toString(), QStringLiteral("clear_turn_count"));
    QCOMPARE(o.value("memory").toString(), QStringLiteral("undocumented"));
    const double before = o.value("before_deg").toDouble();
    const double after = o.value("after_deg").toDouble();
    QVERIFY2(before > 360, qPrintable(QString::number(before)));
    QVERIFY2(std::fabs(after) < 360, qPrintable(QString::number(after)));
    QCOMPARE(o.value("result").toString(), QStringLiteral("cleared"));
    QCOMPARE(framesStartingWith("3E 93 01"), qsizetype(1));
    QCOMPARE(run({"off", "1"}).exitCode, 0);
}

void tst_E2eZero::clearTurnsOnV23IsRefused()
{
    QVERIFY(startSim(QStringLiteral("3:MF")));
    const CtlResult r = run({"clear-turns", "3", "--yes"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("drive 3 speaks protocol V2.3") &&
                 r.err.contains("has no clear_turn_count (0x93); nothing was sent"),
             r.err.constData());
    QCOMPARE(framesStartingWith("3E 93"), qsizetype(0));
}

void tst_E2eZero::clearErrorsTellsBeforeAndAfter_data()
{
    QTest::addColumn<QString>("motors");
    QTest::addColumn<int>("id");
    QTest::newRow("V2.3 MF") << "3:MF" << 3;
    QTest::newRow("V2.35 MS") << "1:MS4015@2.35" << 1;
}

void tst_E2eZero::clearErrorsTellsBeforeAndAfter()
{
    QFETCH(QString, motors);
    QFETCH(int, id);
    QVERIFY(startSim(motors));
    CtlResult r = run({"clear-errors", QString::number(id), "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject o = jsonOf(r.out);
    QCOMPARE(o.keys(), (QStringList{"after", "before", "cleared", "command", "id"}));
    QCOMPARE(o.value("command").toString(), QStringLiteral("clear_errors"));
    QCOMPARE(o.value("after").toObject().value("error_state").toInt(), 0);
    QCOMPARE(o.value("after").toObject().value("errors").toArray().size(), 0);
    QCOMPARE(o.value("cleared").toBool(), true);
    const QByteArray head = QStringLiteral("3E 9B %1").arg(id, 2, 10, QLatin1Char('0')).toUtf8();
    QCOMPARE(framesStartingWith(head), qsizetype(1));
    r = run({"clear-errors", QString::number(id)});
    QVERIFY(r.out.contains("before  none") && r.out.contains("after   none"));
}

QTEST_GUILESS_MAIN(tst_E2eZero)
#include "tst_e2ezero.moc"
