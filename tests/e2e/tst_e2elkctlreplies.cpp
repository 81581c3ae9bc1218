#include "E2eUtil.h"
#include "LksimFrames.h"

#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

using namespace lk::e2e;

/// What lkctl sends and says, against lksim on a pseudo-terminal: `read model` asks once, a
/// relative --port reaches the device it names, and a step test whose drive answers with a
/// bad checksum says so (and that the drive may be moving) instead of "did not answer".
class tst_E2eLkctlReplies : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void readModelAsksOnce();
    void relativePortIsAPath();
    void corruptReplyIsNotSilence();

private:
    bool startSim(const QString &motors, const QStringList &extra = {});
    qsizetype framesStartingWith(const QByteArray &start) const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

bool tst_E2eLkctlReplies::startSim(const QString &motors, const QStringList &extra)
{
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
    const bool ok = m_sim->start(loggedSimArgs(m_link, motors, extra));
    if (!ok)
        qWarning("%s", qPrintable(m_sim->errorString()));
    return ok;
}

qsizetype tst_E2eLkctlReplies::framesStartingWith(const QByteArray &start) const
{
    return lk::e2e::framesStartingWith(*m_sim, start);
}

void tst_E2eLkctlReplies::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    m_link = m_dir->filePath(QStringLiteral("bus"));
}

void tst_E2eLkctlReplies::cleanup()
{
    if (m_sim)
        verifyNoCollisions(*m_sim);
    m_sim.reset();
}

void tst_E2eLkctlReplies::readModelAsksOnce()
{
    QVERIFY(startSim(QStringLiteral("3:MF,1:MS4015@2.35")));
    for (const char *id : {"3", "1"}) {
        const CtlResult r = lkctl({"read", id, "model", "--json", "--port", m_link});
        QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
        const QJsonObject o = jsonOf(r.out);
        QCOMPARE(o.value("command").toString(), QStringLiteral("read_model"));
        QVERIFY(!o.value("fields").toObject().value("motor_name").toString().isEmpty());
    }
    QCOMPARE(framesStartingWith("3E 12 03"), qsizetype(1));
    QCOMPARE(framesStartingWith("3E 12 01"), qsizetype(1));
}

void tst_E2eLkctlReplies::relativePortIsAPath()
{
    QVERIFY(startSim(QStringLiteral("3:MF")));
    QProcess p;
    p.setWorkingDirectory(m_dir->path());
    p.start(QStringLiteral(LKCTL_PATH), {"read", "3", "state1", "--port", "./bus"});
    QVERIFY(p.waitForFinished(60000));
    QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
    QVERIFY(p.readAllStandardOutput().startsWith("Drive 3, read_state1:"));
}

void tst_E2eLkctlReplies::corruptReplyIsNotSilence()
{
    // Every 0xA4 reply of the V2.35 drive carries a bad data checksum (fw 2.35's bug, always).
    QVERIFY(startSim(QStringLiteral("1:MS4015@2.35"), {"--bad-checksum-pct", "100"}));
    const CtlResult r = lkctl({"step", "1", "position", "140", "180", "--duration", "0.1",
                               "--pre-roll", "0.1", "--port", m_link});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(!r.err.contains("did not answer"), r.err.constData());
    QVERIFY2(r.err.contains("corrupt reply to multi_position_limited (ID 1) (bad data "
                            "checksum)") &&
                 r.err.contains("drive 1 answered"),
             r.err.constData());
    QVERIFY2(r.err.contains("may have acted on it: it may be moving"), r.err.constData());
    QVERIFY2(r.err.contains("keeps its last command"), r.err.constData());
    QVERIFY(framesStartingWith("3E A4 01") >= 1);
}

QTEST_GUILESS_MAIN(tst_E2eLkctlReplies)
#include "tst_e2elkctlreplies.moc"
