// `lkctl control multi-torque` against lksim --can over Qt's virtualcan (a port per test): the
// old CAN generation's multi-motor frame (0x280) as the wire carries it, each drive's reply,
// the watch's stop to every drive, and refusals that put no frame on the bus at all. Also the
// max speed a CAN position move reports: the uint16 of 1 dps that went out.

#include "CanSniffer.h"
#include "E2eUtil.h"
#include "LksimProcess.h"

#include <QtCore/QJsonArray>
#include <QtCore/QJsonObject>
#include <QtTest/QTest>

using namespace lk::e2e;

namespace {
const QString kDrives = QStringLiteral("1:MG@can,2:MG@can,3:MF@can236");
const QString kMarker = QStringLiteral("1:MG@can");
/// Drives 1 and 2 only: drive 3, declared, would get 0 A from the frame's empty slot.
const QString kPair = QStringLiteral("1:MG@can,2:MG@can");
constexpr quint32 kMulti = 0x280;
} // namespace

class tst_E2eCanMultiTorque : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void theDocumentedFrameIsOnTheWire();
    void watchStopsEveryDrive();
    void refusalPutsNoFrameOnTheBus_data();
    void refusalPutsNoFrameOnTheBus();
    void refusedOnRs485();
    void maxSpeedRawIsTheWiresOnCan();

private:
    CtlResult run(const QStringList &args) { return m_bus.run(args); }
    /// Frames of the multi-motor ID seen so far, in candump notation.
    QStringList multiFrames()
    {
        QStringList out;
        for (const SniffedFrame &f : m_wire.frames()) {
            if (f.id == kMulti)
                out << f.text();
        }
        return out;
    }
    /// A marker read of drive 1 passed the sniffer: frames an earlier lkctl sent are all seen.
    void settle()
    {
        const int before = m_wire.count(0x141, 0x94);
        const CtlResult r = run({"read", "1", "single-turn", "--drives", kMarker});
        QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
        QVERIFY(m_wire.waitFor(0x141, 0x94, before + 2));
    }

    CanE2eBus m_bus;
    CanSniffer &m_wire = m_bus.wire();
};

void tst_E2eCanMultiTorque::init()
{
    const QString error = m_bus.start(kDrives, kMarker);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    m_wire.clear();
}

void tst_E2eCanMultiTorque::cleanup()
{
    m_bus.stop();
}

void tst_E2eCanMultiTorque::theDocumentedFrameIsOnTheWire()
{
    // 1.6 A at the old generation's 32 A / 2000 is 100: CAN.md's example, ID 1 +100, ID 2 -100.
    const CtlResult r = run({"control", "multi-torque", "1=1.6,2=-1.6", "--drives", kPair,
                             "--max-torque-a", "2", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(m_wire.waitFor(0x141, 0xA1) && m_wire.waitFor(0x142, 0xA1));
    QCOMPARE(multiFrames(), QStringList{QStringLiteral("280#64009CFF00000000")});
    // Each drive answered on its own ID with the motion reply, in ascending ID order.
    const QList<SniffedFrame> frames = m_wire.frames();
    int at1 = -1, at2 = -1;
    for (int i = 0; i < frames.size(); ++i) {
        if (frames.at(i).command() == 0xA1 && frames.at(i).id == 0x141)
            at1 = i;
        if (frames.at(i).command() == 0xA1 && frames.at(i).id == 0x142)
            at2 = i;
    }
    QVERIFY(at1 >= 0 && at2 > at1);
    const QJsonObject o = jsonOf(r.out.trimmed());
    QCOMPARE(o.value("command").toString(), QStringLiteral("multi_torque"));
    QCOMPARE(o.value("frame").toString(), QStringLiteral("280#64009CFF00000000"));
    const QJsonArray drives = o.value("drives").toArray();
    QCOMPARE(drives.size(), 2);
    for (int i = 0; i < 2; ++i) {
        const QJsonObject d = drives.at(i).toObject();
        QCOMPARE(d.value("id").toInt(), i + 1);
        QCOMPARE(d.value("sent").toObject().value("iq_raw").toInt(), i == 0 ? 100 : -100);
        QVERIFY2(d.value("reply").toObject().contains("speed_dps"), r.out.constData());
    }
    // Without --watch the drives stay under torque: said on stderr (stdout is one JSON line).
    QVERIFY2(r.err.contains("stay under torque"), r.err.constData());
}

void tst_E2eCanMultiTorque::watchStopsEveryDrive()
{
    const CtlResult r = run(
        {"control", "multi-torque", "1=0.1,2=-0.1", "--drives", kPair, "--watch", "0.5", "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 2);
    const QJsonObject watch = jsonOf(lines.at(1)).value("watch").toObject();
    QCOMPARE(watch.value("ended").toString(), QStringLiteral("time"));
    const QJsonArray drives = watch.value("drives").toArray();
    QCOMPARE(drives.size(), 2);
    for (const QJsonValue &d : drives)
        QVERIFY2(d.toObject().value("stop_acknowledged").toBool(), lines.at(1).constData());
    // Motor Stop (0x81) to both drives, on the wire.
    QVERIFY(m_wire.waitFor(0x141, 0x81) && m_wire.waitFor(0x142, 0x81));
}

void tst_E2eCanMultiTorque::refusalPutsNoFrameOnTheBus_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("words");
    QTest::newRow("over drive 2's torque limit")
        << QStringList{"1=0.5,2=-1.6", "--drives", kDrives, "--max-torque-a", "1"} << 4
        << "drive 2";
    QTest::newRow("drive 2 not identified")
        << QStringList{"1=0.5,2=-0.5", "--drives", kMarker} << 4
        << "drive 2: its series and CAN generation are not known";
    QTest::newRow("drive 3 is V2.36")
        << QStringList{"1=0.5,3=0.5", "--drives", kDrives} << 4 << "drive 3 speaks CAN V2.36";
    QTest::newRow("drive 3 declared, not named") << QStringList{"1=0.5,2=-0.5", "--drives", kDrives}
                                                 << 4 << "drive 3 is on the bus and would get 0 A";
    QTest::newRow("ID 5") << QStringList{"1=0.5,5=0.5", "--drives", kDrives} << 2
                          << "IDs 1..4 only";
    QTest::newRow("named twice") << QStringList{"1=0.5,1=0.2", "--drives", kDrives} << 2
                                 << "named twice";
    QTest::newRow("beyond the wire") << QStringList{"1=40", "--drives", kDrives} << 2 << "drive 1";
}

void tst_E2eCanMultiTorque::refusalPutsNoFrameOnTheBus()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QString, words);
    const CtlResult r = run(QStringList{"control", "multi-torque"} + args);
    QVERIFY2(r.exitCode == exitCode, qPrintable(describeRun(r)));
    QVERIFY2(r.err.contains(words.toUtf8()), r.err.constData());
    QVERIFY2(r.out.isEmpty(), r.out.constData());
    settle();
    // The marker's read (its 0x9A state probe and its 0x94, each with its reply) is all the bus
    // carried: not one frame of the refused run.
    const QList<SniffedFrame> frames = m_wire.frames();
    QStringList seen;
    bool onlyMarker = true;
    for (const SniffedFrame &f : frames) {
        seen << f.text();
        onlyMarker = onlyMarker && f.id == 0x141 && (f.command() == 0x9A || f.command() == 0x94);
    }
    QVERIFY2(onlyMarker && m_wire.count(0x141, 0x94) == 2, qPrintable(seen.join(QLatin1Char(' '))));
    QCOMPARE(multiFrames(), QStringList{});
}

void tst_E2eCanMultiTorque::refusedOnRs485()
{
    const CtlResult r = lkctlHeard(QStringLiteral(LKCTL_PATH),
                                   {"control", "multi-torque", "1=0.5", "--sim", "1:MG"});
    QVERIFY2(r.exitCode == 4, qPrintable(describeRun(r)));
    QVERIFY2(r.err.contains("exists on CAN only"), r.err.constData());
}

void tst_E2eCanMultiTorque::maxSpeedRawIsTheWiresOnCan()
{
    // CAN carries a max speed as uint16 of 1 dps, rounded down: 90.7 dps goes out as 90, and
    // the JSON says so (not RS485's 9070).
    const CtlResult r = run({"control", "1", "multi-position", "10", "--max-speed", "90.7",
                             "--drives", kMarker, "--json"});
    QVERIFY2(r.exitCode == 0, qPrintable(describeRun(r)));
    QVERIFY(m_wire.waitFor(0x141, 0xA4));
    const QByteArray request = m_wire.on(0x141, 0xA4).first().data;
    QCOMPARE(leBytes(request, 2, 2, false), 90);
    const QJsonObject sent = jsonOf(r.out.trimmed()).value("sent").toObject();
    QCOMPARE(sent.value("max_speed_raw").toInt(), 90);
}

QTEST_GUILESS_MAIN(tst_E2eCanMultiTorque)
#include "tst_e2ecanmultitorque.moc"
