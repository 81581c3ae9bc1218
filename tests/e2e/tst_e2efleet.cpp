#include "LksimFrames.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

using namespace lk::e2e;

// lkctl backup, diff, restore and clone against lksim on a pty: the round trip, the refusals
// (bad files, other generation, a target that cannot be read) with nothing written, ROM once.

namespace {

const QString kMotors = QStringLiteral("1:MF,2:MF,3:MS4015@2.35,4:MS4015@2.35");

/// Frames of every write command the restore may send (to any drive).
qsizetype writeFrames(LksimProcess &sim)
{
    qsizetype n = 0;
    for (const char *code : {"3E 31", "3E 32", "3E 34", "3E 42", "3E 44", "3E 91", "3E 19"})
        n += framesStartingWith(sim, code);
    return n;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeAll(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

} // namespace

class tst_E2eFleet : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void backupRestoreRoundTrip();
    void idMapPutsOldValuesOnNewDrive();
    void badFileIsRefusedNamingTheKey_data();
    void badFileIsRefusedNamingTheKey();
    void otherGenerationIsRefusedNothingSent();
    void failedReadOfTargetBlocksItsWrite();
    void romNeedsYesAndIsSentOnce();

private:
    CtlResult ctl(const QStringList &args)
    {
        return lkctl(args + QStringList{QStringLiteral("--port"), m_link});
    }
    bool startSim(const QStringList &extra = {})
    {
        return m_sim->start(loggedSimArgs(
            m_link, kMotors,
            QStringList{QStringLiteral("--param-seed"), QStringLiteral("11")} + extra));
    }
    QString path(const char *name) const { return m_dir->filePath(QLatin1String(name)); }
    /// A backup of the whole bus in path("bus.json").
    void backup()
    {
        const CtlResult r =
            ctl({QStringLiteral("backup"), QStringLiteral("all"), QStringLiteral("--out"),
                 path("bus.json"), QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
        QCOMPARE(jsonOf(r.out).value(QStringLiteral("drives")).toArray().size(), 4);
    }

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<LksimProcess> m_sim;
    QString m_link;
};

void tst_E2eFleet::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    m_link = m_dir->filePath(QStringLiteral("lkbus"));
    m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
}

void tst_E2eFleet::cleanup()
{
    if (m_sim->isRunning())
        verifyNoCollisions(*m_sim);
    m_sim.reset();
}

void tst_E2eFleet::backupRestoreRoundTrip()
{
    QVERIFY2(startSim(), qPrintable(m_sim->errorString()));
    backup();
    // The seeded drives differ from their siblings.
    CtlResult r = ctl({QStringLiteral("diff"), QStringLiteral("1"), QStringLiteral("2")});
    QVERIFY2(r.exitCode == 5, qPrintable(describeRun(r)));
    // Commission: 1 onto 2, 3 onto 4; now they are identical.
    for (const QStringList &pair : {QStringList{"1", "2"}, QStringList{"3", "4"}}) {
        r = ctl(QStringList{QStringLiteral("clone")} + pair +
                QStringList{QStringLiteral("--ram"), QStringLiteral("--undo"), path("undo.json"),
                            QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
        const QJsonObject drive = jsonOf(r.out)["drives"].toArray().at(0).toObject();
        QCOMPARE(drive["outcome"].toString(), QStringLiteral("verified"));
        QVERIFY(!drive["changes"].toArray().isEmpty());
        r = ctl(QStringList{QStringLiteral("diff")} + pair);
        QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    }
    // The undo file of the last clone holds drive 4 as it was: a backup.
    QVERIFY(readAll(path("undo.json")).contains("lkstudio-bus-backup"));
    // Restoring the backup leaves every drive as it was backed up.
    r = ctl({QStringLiteral("restore"), path("bus.json"), QStringLiteral("--ram"),
             QStringLiteral("--undo"), path("undo2.json"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    r = ctl({QStringLiteral("diff"), path("bus.json"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    for (const QJsonValue &d : jsonOf(r.out)["drives"].toArray()) {
        for (const QJsonValue &row : d["rows"].toArray())
            QCOMPARE(row["state"].toString(), QStringLiteral("same"));
    }
}

void tst_E2eFleet::idMapPutsOldValuesOnNewDrive()
{
    QVERIFY2(startSim(), qPrintable(m_sim->errorString()));
    backup();
    // Drive 1 "replaced" by drive 2: the backup's 1 goes onto 2.
    CtlResult r = ctl({QStringLiteral("restore"), path("bus.json"), QStringLiteral("1"),
                       QStringLiteral("--map"), QStringLiteral("1:2"), QStringLiteral("--ram"),
                       QStringLiteral("--undo"), path("undo.json"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject drive = jsonOf(r.out)["drives"].toArray().at(0).toObject();
    QCOMPARE(drive["source"].toInt(), 1);
    QCOMPARE(drive["target"].toInt(), 2);
    r = ctl({QStringLiteral("diff"), QStringLiteral("1"), QStringLiteral("2")});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
}

void tst_E2eFleet::badFileIsRefusedNamingTheKey_data()
{
    QTest::addColumn<QString>("edit");
    QTest::addColumn<QString>("named");
    QTest::newRow("truncated") << QStringLiteral("truncate") << QStringLiteral("not valid JSON");
    QTest::newRow("damaged") << QStringLiteral("damage") << QStringLiteral("not valid JSON");
    QTest::newRow("edited out of range")
        << QStringLiteral("range") << QStringLiteral("drives.1.params.angle_kp.value");
    QTest::newRow("other generation's values")
        << QStringLiteral("generation") << QStringLiteral("drives.1.params.accel_dps2");
}

void tst_E2eFleet::badFileIsRefusedNamingTheKey()
{
    QFETCH(QString, edit);
    QFETCH(QString, named);
    QVERIFY2(startSim(), qPrintable(m_sim->errorString()));
    backup();
    QByteArray bytes = readAll(path("bus.json"));
    if (edit == QLatin1String("truncate")) {
        bytes.truncate(bytes.size() / 2);
    } else if (edit == QLatin1String("damage")) {
        bytes[bytes.indexOf(':')] = ';';
    } else if (edit == QLatin1String("range")) {
        const qsizetype at = bytes.indexOf("\"angle_kp\"");
        const qsizetype value = bytes.indexOf("\"value\": ", at) + 9;
        bytes.replace(value, bytes.indexOf('\n', value) - value, "300");
    } else {
        bytes.replace(bytes.indexOf("\"v2.3\""), 6, "\"v2.35\"");
    }
    QVERIFY(writeAll(path("bad.json"), bytes));
    const qsizetype before = writeFrames(*m_sim);
    for (const char *command : {"restore", "diff"}) {
        QStringList args{QLatin1String(command), path("bad.json")};
        if (qstrcmp(command, "restore") == 0)
            args << QStringLiteral("--ram") << QStringLiteral("--undo") << path("undo.json");
        const CtlResult r = ctl(args);
        QVERIFY2(r.exitCode == 2, qPrintable(describeRun(r)));
        QVERIFY2(r.err.contains(named.toUtf8()), qPrintable(describeRun(r)));
        QVERIFY2(r.err.contains("nothing was sent"), qPrintable(describeRun(r)));
    }
    QVERIFY(!QFile::exists(path("undo.json")));
    QCOMPARE(writeFrames(*m_sim), before);
}

void tst_E2eFleet::otherGenerationIsRefusedNothingSent()
{
    QVERIFY2(startSim(), qPrintable(m_sim->errorString()));
    backup();
    // The V2.3 drive 1's values onto the V2.35 drive 3.
    const CtlResult r = ctl(
        {QStringLiteral("restore"), path("bus.json"), QStringLiteral("1"), QStringLiteral("--map"),
         QStringLiteral("1:3"), QStringLiteral("--rom"), QStringLiteral("--yes"),
         QStringLiteral("--undo"), path("undo.json"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 4, qPrintable(describeRun(r)));
    const QJsonObject drive = jsonOf(r.out)["drives"].toArray().at(0).toObject();
    QCOMPARE(drive["refused_key"].toString(), QStringLiteral("generation"));
    QVERIFY(!jsonOf(r.out)["sent"].toBool());
    QCOMPARE(writeFrames(*m_sim), 0);
}

void tst_E2eFleet::failedReadOfTargetBlocksItsWrite()
{
    QVERIFY2(startSim({QStringLiteral("--faults"), QStringLiteral("silent=2")}),
             qPrintable(m_sim->errorString()));
    const CtlResult r = ctl({QStringLiteral("clone"), QStringLiteral("1"), QStringLiteral("2"),
                             QStringLiteral("4"), QStringLiteral("--ram"), QStringLiteral("--undo"),
                             path("undo.json"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 4, qPrintable(describeRun(r)));
    const QJsonArray drives = jsonOf(r.out)["drives"].toArray();
    QCOMPARE(drives.at(0)["refused_key"].toString(), QStringLiteral("read"));
    QCOMPARE(drives.at(1)["refused_key"].toString(), QStringLiteral("generation"));
    QCOMPARE(writeFrames(*m_sim), 0);
}

void tst_E2eFleet::romNeedsYesAndIsSentOnce()
{
    QVERIFY2(startSim(), qPrintable(m_sim->errorString()));
    CtlResult r = ctl({QStringLiteral("clone"), QStringLiteral("1"), QStringLiteral("2"),
                       QStringLiteral("--rom"), QStringLiteral("--undo"), path("undo.json")});
    QVERIFY2(r.exitCode == 4, qPrintable(describeRun(r)));
    QCOMPARE(writeFrames(*m_sim), 0);
    r = ctl({QStringLiteral("clone"), QStringLiteral("1"), QStringLiteral("2"),
             QStringLiteral("--rom"), QStringLiteral("--yes"), QStringLiteral("--undo"),
             path("undo.json"), QStringLiteral("--json")});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QJsonObject drive = jsonOf(r.out)["drives"].toArray().at(0).toObject();
    QCOMPARE(drive["outcome"].toString(), QStringLiteral("written")); // V2.3 cannot read ROM
    QVERIFY(drive["not_verified"].toArray().size() >= 1);
    QCOMPARE(framesStartingWith(*m_sim, "3E 32 02"), 1); // write_pid_rom to 2: once
    QCOMPARE(framesStartingWith(*m_sim, "3E 31 02"), 1); // after RAM
}

QTEST_GUILESS_MAIN(tst_E2eFleet)
#include "tst_e2efleet.moc"
