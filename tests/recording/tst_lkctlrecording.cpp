// lkctl on recordings: `decode` reads one (file or standard input, told by its magic) with the
// recorded decode context, and stops at damage naming the offset; `export` writes pcap and
// telemetry CSV.
#include "E2eUtil.h"
#include "RecordingTestUtil.h"

#include <protocol/CanRecord.h>
#include <protocol/Reply.h>
#include <recording/PcapExport.h>

#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtCore/QtEndian>
#include <QtTest/QtTest>

using namespace lk::recording;
namespace protocol = lk::protocol;
using lk::e2e::describeRun;
using lk::e2e::jsonOf;
using lk::e2e::lkctl;
using lk::testsupport::lines;
using lk::testsupport::writeFile;

namespace {

QByteArray state2Reply(int id, qint16 torqueRaw)
{
    protocol::State2 s;
    s.temperatureC = 31;
    s.torqueRaw = torqueRaw;
    s.speedDps = 120;
    s.encoder = 1000;
    return protocol::Reply{protocol::Command::ReadState2, quint8(id), s}.encode();
}

QByteArray request(int id)
{
    return protocol::encodeFrame(0x9C, quint8(id), {});
}

/// Drive 1 is an MS (power), drive 2 an MF; the reply of drive 2 comes in two chunks; then
/// two bytes of garbage and the link is lost.
QByteArray sampleRecording(qsizetype *secondBlock = nullptr)
{
    RecordingHeader h = lk::testsupport::testHeader();
    h.context = {{1, protocol::Series::MS, protocol::Generation::V2_3},
                 {2, protocol::Series::MF, protocol::Generation::V2_3}};
    QByteArray file = RecordEncoder::encodeHeader(h);
    RecordEncoder enc;
    enc.append(RecordEvent::data(RecordEvent::Kind::Tx, 1'000'000, request(1)));
    enc.append(RecordEvent::data(RecordEvent::Kind::Rx, 1'200'000, state2Reply(1, 500)));
    file += enc.takeBlock();
    if (secondBlock)
        *secondBlock = file.size();
    const QByteArray reply2 = state2Reply(2, 100);
    enc.append(RecordEvent::data(RecordEvent::Kind::Tx, 2'000'000, request(2)));
    enc.append(RecordEvent::data(RecordEvent::Kind::Rx, 2'100'000, reply2.left(4)));
    enc.append(RecordEvent::data(RecordEvent::Kind::Rx, 2'200'000, reply2.mid(4) + "\x01\x02"));
    RecordEvent lost;
    lost.kind = RecordEvent::Kind::Link;
    lost.timeNs = 3'000'000;
    lost.link = LinkEventKind::Disconnected;
    lost.text = QStringLiteral("/dev/ttyTEST");
    enc.append(lost);
    file += enc.takeBlock();
    return file;
}

QByteArray canRecord(quint32 canId, const char *hex, quint8 flags = 0)
{
    protocol::CanRecord r = protocol::CanRecord::of({canId, QByteArray::fromHex(hex)});
    r.flags = flags;
    return r.encode();
}

/// A recording made on CAN: drive 1 (old CAN MG) answers on 0x141, drive 2 (V2.36) on 0x182;
/// then an error frame (bus error).
QByteArray canRecording()
{
    RecordingHeader h = lk::testsupport::testHeader();
    h.linkKind = LinkKind::Can;
    h.linkDescription = QStringLiteral("virtualcan:can0 @ 1000000");
    h.baud = 1000000;
    h.context = {{1, protocol::Series::MG, protocol::Generation::V2_3},
                 {2, protocol::Series::MF, protocol::Generation::V2_3}};
    QByteArray file = RecordEncoder::encodeHeader(h);
    RecordEncoder enc;
    enc.append(
        RecordEvent::data(RecordEvent::Kind::Tx, 1'000'000, canRecord(0x141, "9C00000000000000")));
    enc.append(
        RecordEvent::data(RecordEvent::Kind::Rx, 1'200'000, canRecord(0x141, "9C1E64000A001027")));
    enc.append(
        RecordEvent::data(RecordEvent::Kind::Tx, 2'000'000, canRecord(0x142, "9A00000000000000")));
    // The adapter loops the tool's own frame back (flagged), then drive 2 answers.
    enc.append(RecordEvent::data(RecordEvent::Kind::Rx, 2'100'000,
                                 canRecord(0x142, "9A00000000000000", protocol::CanRecord::Echo) +
                                     canRecord(0x182, "9A1E60090A001000")));
    enc.append(RecordEvent::data(RecordEvent::Kind::Rx, 3'000'000,
                                 canRecord(0x80, "0000000000000000", protocol::CanRecord::Error)));
    file += enc.takeBlock();
    return file;
}

/// What `lkctl export` writes for the sample recording with `option` (--pcap, --csv).
QByteArray exported(const QString &option)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("s.lkrec"));
    const QString out = dir.filePath(QStringLiteral("s.out"));
    if (!writeFile(path, sampleRecording()))
        return {};
    const auto r = lkctl({QStringLiteral("export"), path, option, out});
    if (r.exitCode != 0)
        qWarning("%s", qPrintable(describeRun(r)));
    QFile f(out);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class tst_LkctlRecording : public QObject {
    Q_OBJECT
private slots:
    void decodeReadsARecordingWithItsContext()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.lkrec"));
        QVERIFY(writeFile(path, sampleRecording()));
        const auto r = lkctl({QStringLiteral("decode"), path});
        QCOMPARE(r.exitCode, 3); // the garbage
        const auto l = lines(r.out);
        QCOMPARE(l.size(), 6);
        const QJsonObject req = jsonOf(l[0]);
        QCOMPARE(req.value("direction").toString(), QStringLiteral("request"));
        QCOMPARE(req.value("wire").toString(), QStringLiteral("tx"));
        QCOMPARE(req.value("time_s").toDouble(), 0.001);
        const QJsonObject ms = jsonOf(l[1]);
        QCOMPARE(ms.value("wire").toString(), QStringLiteral("rx"));
        QCOMPARE(ms.value("fields").toObject().value("power").toInt(), 500); // MS: power
        const QJsonObject mf = jsonOf(l[3]);
        QCOMPARE(mf.value("id").toInt(), 2);
        QVERIFY2(mf.value("fields").toObject().contains("iq_a"), l[3].constData());
        QCOMPARE(jsonOf(l[4]).value("error").toString(), QStringLiteral("garbage"));
        QVERIFY(jsonOf(l[5]).value("note").toString().contains(QStringLiteral("/dev/ttyTEST")));
    }

    void decodeReadsARecordingOnStandardInput()
    {
        const auto r = lk::e2e::runProgram(
            QStringLiteral(LKCTL_PATH), {QStringLiteral("decode"), QStringLiteral("-")},
            QProcessEnvironment::systemEnvironment(), 60000, sampleRecording());
        QCOMPARE(lines(r.out).size(), 6);
        QCOMPARE(jsonOf(lines(r.out)[1]).value("fields").toObject().value("power").toInt(), 500);
        // Hex text still decodes as before.
        const auto hex = lk::e2e::runProgram(
            QStringLiteral(LKCTL_PATH), {QStringLiteral("decode"), QStringLiteral("-")},
            QProcessEnvironment::systemEnvironment(), 60000, "3E 80 01 00 BF\n");
        QCOMPARE(hex.exitCode, 0);
        QCOMPARE(jsonOf(lines(hex.out).value(0)).value("command").toString(),
                 QStringLiteral("motor_off"));
    }

    void decodeStopsAtDamageNamingTheOffset()
    {
        qsizetype second = 0;
        QByteArray file = sampleRecording(&second);
        file[second + 30] = char(file[second + 30] ^ 0x40);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.lkrec"));
        QVERIFY(writeFile(path, file));
        const auto r = lkctl({QStringLiteral("decode"), path});
        QCOMPARE(r.exitCode, 3);
        QCOMPARE(lines(r.out).size(), 2); // the first block
        QVERIFY2(r.err.contains(QByteArray::number(second)), describeRun(r).toUtf8());
    }

    void exportWritesPcap()
    {
        const QByteArray bytes = exported(QStringLiteral("--pcap"));
        QVERIFY(bytes.startsWith(PcapExport::fileHeader()));
        // The context, then five packets: request, reply, request, reply, garbage.
        qsizetype pos = 24;
        QVector<QByteArray> packets;
        while (pos + 16 <= bytes.size()) {
            const quint32 len = quint8(bytes[pos + 8]) | quint8(bytes[pos + 9]) << 8;
            packets.append(bytes.mid(pos + 16, len));
            pos += 16 + len;
        }
        QCOMPARE(pos, bytes.size());
        QCOMPARE(packets.size(), 6);
        QCOMPARE(packets[0], QByteArray("\x00\x04\x01\x01\x00\x02\x02\x00", 8));
        QCOMPARE(packets[1], QByteArray("\x01\x00", 2) + request(1));
        QCOMPARE(packets[2], QByteArray("\x00\x01", 2) + state2Reply(1, 500));
        QCOMPARE(packets[5], QByteArray("\x00\x03\x01\x02", 4));
        // The first packet's time: the wall-clock start.
        const quint32 sec = quint32(quint8(bytes[24])) | quint32(quint8(bytes[25])) << 8 |
                            quint32(quint8(bytes[26])) << 16 | quint32(quint8(bytes[27])) << 24;
        QCOMPARE(qint64(sec), lk::testsupport::testHeader().wallClockStartMs / 1000);
    }

    void exportWritesTelemetryCsv()
    {
        const auto l = lines(exported(QStringLiteral("--csv")));
        QCOMPARE(l.size(), 3);
        const QList<QByteArray> header = l[0].split(',');
        QCOMPARE(header.value(0), QByteArray("time_s"));
        QCOMPARE(header.value(1), QByteArray("id"));
        const QList<QByteArray> row1 = l[1].split(',');
        const QList<QByteArray> row2 = l[2].split(',');
        QCOMPARE(row1.value(0), QByteArray("0.001200"));
        QCOMPARE(row1.value(1), QByteArray("1"));
        const int power = int(header.indexOf("power"));
        const int iq = int(header.indexOf("iq_a"));
        QVERIFY(power > 0 && iq > 0);
        QCOMPARE(row1.value(power), QByteArray("500"));
        QCOMPARE(row1.value(iq), QByteArray()); // MS: no iq, never 0
        QCOMPARE(row2.value(1), QByteArray("2"));
        QCOMPARE(row2.value(power), QByteArray());
        QVERIFY(!row2.value(iq).isEmpty());
    }

    void timesAreMicrosecondsInEveryOutput()
    {
        // One notation for a recording's moments: six decimals, as monitor and the CSVs write
        // them, never a binary fraction's tail (300000 ns * 1e-9 = 0.00030000000000000003).
        static const QRegularExpression time(QStringLiteral("\"time_s\":(-?\\d+\\.\\d{6})[,}]"));
        QTemporaryDir dir;
        const QString log = dir.filePath(QStringLiteral("t.log"));
        QVERIFY(writeFile(log, "(1700000000.000000) can0 141#9C00000000000000\n"
                               "(1700000000.000300) can0 141#9C1E64000A001027\n"
                               "(1700000001.234567) can0 141#9C1E64000A001027\n"));
        const auto d = lkctl({QStringLiteral("decode"), log});
        QVERIFY2(d.exitCode == 0, describeRun(d).toUtf8());
        QStringList times;
        for (const QByteArray &line : lines(d.out))
            times << time.match(QString::fromUtf8(line)).captured(1);
        QCOMPARE(times, (QStringList{QStringLiteral("0.000000"), QStringLiteral("0.000300"),
                                     QStringLiteral("1.234567")}));
        // A recording: every frame, fault and note; the reply of drive 1 at 1.2 ms is written
        // as replay and the CSV export write it.
        const QString path = dir.filePath(QStringLiteral("s.lkrec"));
        QVERIFY(writeFile(path, sampleRecording()));
        const auto r = lkctl({QStringLiteral("decode"), path});
        for (const QByteArray &line : lines(r.out))
            QVERIFY2(time.match(QString::fromUtf8(line)).hasMatch(), line.constData());
        QVERIFY2(lines(r.out).value(0).endsWith("\"time_s\":0.001000,\"wire\":\"tx\"}"),
                 r.out.constData());
        QVERIFY2(lines(r.out).value(1).contains("\"time_s\":0.001200,"), r.out.constData());
        QVERIFY2(lines(r.out).value(5).endsWith("\"time_s\":0.003000}"), r.out.constData());
        const auto replay = lkctl({QStringLiteral("replay"), path, QStringLiteral("--json")});
        QVERIFY2(lines(replay.out).value(0).startsWith("{\"time_s\":0.001200,"),
                 replay.out.constData());
        QVERIFY(lines(exported(QStringLiteral("--csv"))).value(1).startsWith("0.001200,"));
    }

    void replayDecodesThroughThePassivePath()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.lkrec"));
        QVERIFY(writeFile(path, sampleRecording()));
        const auto r = lkctl({QStringLiteral("replay"), path, QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
        const auto l = lines(r.out);
        QCOMPARE(l.size(), 2);
        const QJsonObject ms = jsonOf(l[0]);
        QCOMPARE(ms.value("id").toInt(), 1);
        QCOMPARE(ms.value("time_s").toDouble(), 0.0012); // the recording's clock
        QCOMPARE(ms.value("power").toInt(), 500);        // the recorded context: MS
        QVERIFY(!ms.contains("iq_a"));
        const QJsonObject mf = jsonOf(l[1]);
        QCOMPARE(mf.value("id").toInt(), 2);
        QVERIFY(mf.contains("iq_a"));
        QVERIFY2(r.err.contains("paired 2"), r.err.constData());
        // CSV: the long layout's header, then the same rows.
        const auto csv = lkctl({QStringLiteral("replay"), path});
        QCOMPARE(lines(csv.out).size(), 3);
        QVERIFY(csv.out.startsWith("time_s,id,"));
    }

    void replayStopsAtDamageNamingTheOffset()
    {
        qsizetype second = 0;
        QByteArray file = sampleRecording(&second);
        file.truncate(second + 10);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("cut.lkrec"));
        QVERIFY(writeFile(path, file));
        const auto r = lkctl({QStringLiteral("replay"), path, QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 3);
        QCOMPARE(lines(r.out).size(), 1);
        QVERIFY2(r.err.contains(QByteArray::number(second)), describeRun(r).toUtf8());
    }

    void canRecordingReplaysAndDecodesAsCan()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("can.lkrec"));
        QVERIFY(writeFile(path, canRecording()));
        const auto r = lkctl({QStringLiteral("replay"), path, QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
        const auto l = lines(r.out);
        QCOMPARE(l.size(), 2);
        QCOMPARE(jsonOf(l[0]).value("id").toInt(), 1);
        QCOMPARE(jsonOf(l[0]).value("speed_dps").toDouble(), 10.0);
        QCOMPARE(jsonOf(l[0]).value("encoder").toInt(), 10000);
        QCOMPARE(jsonOf(l[1]).value("id").toInt(), 2);
        // The reply on 0x182 names drive 2 V2.36: 0.01 V, bus current, motor state.
        QCOMPARE(jsonOf(l[1]).value("voltage_v").toDouble(), 24.0);
        QCOMPARE(jsonOf(l[1]).value("bus_current_a").toDouble(), 0.1);
        QVERIFY2(r.err.contains("paired 2") && r.err.contains("CAN error frames 1"),
                 r.err.constData());

        const auto d = lkctl({QStringLiteral("decode"), path});
        QVERIFY2(d.exitCode == 0, describeRun(d).toUtf8());
        const auto dl = lines(d.out);
        QCOMPARE(dl.size(), 5); // the echo is a row of its own, as the adapter gave it
        QCOMPARE(jsonOf(dl[0]).value("direction").toString(), QStringLiteral("request"));
        QCOMPARE(jsonOf(dl[0]).value("wire").toString(), QStringLiteral("tx"));
        QCOMPARE(jsonOf(dl[0]).value("can_id").toString(), QStringLiteral("0x141"));
        QCOMPARE(jsonOf(dl[1]).value("direction").toString(), QStringLiteral("reply"));
        QCOMPARE(jsonOf(dl[1]).value("fields").toObject().value("speed_dps").toDouble(), 10.0);
        QCOMPARE(jsonOf(dl[4]).value("can_id").toString(), QStringLiteral("0x182"));
        QCOMPARE(jsonOf(dl[4]).value("fields").toObject().value("voltage_v").toDouble(), 24.0);
    }

    void decodeShowsAMultiTorqueFrame_data()
    {
        QTest::addColumn<bool>("ours");
        QTest::newRow("the tool's own (tx)") << true;
        QTest::newRow("another master's (rx)") << false;
    }

    void decodeShowsAMultiTorqueFrame()
    {
        // A 0x280 (docs/CAN.md section 4.2), sent or heard: a request of no drive, every slot.
        QFETCH(bool, ours);
        RecordingHeader h = lk::testsupport::testHeader();
        h.linkKind = LinkKind::Can;
        h.linkDescription = QStringLiteral("virtualcan:can0 @ 1000000");
        h.baud = 1000000;
        h.context = {{1, protocol::Series::MG, protocol::Generation::V2_3}};
        QByteArray file = RecordEncoder::encodeHeader(h);
        RecordEncoder enc;
        enc.append(RecordEvent::data(ours ? RecordEvent::Kind::Tx : RecordEvent::Kind::Rx,
                                     1'000'000, canRecord(0x280, "64009CFF00000000")));
        enc.append(RecordEvent::data(RecordEvent::Kind::Rx, 1'200'000,
                                     canRecord(0x141, "A11E64000A001027")));
        file += enc.takeBlock();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("multi.lkrec"));
        QVERIFY(writeFile(path, file));
        const auto d = lkctl({QStringLiteral("decode"), path});
        QVERIFY2(d.exitCode == 0, describeRun(d).toUtf8());
        const auto dl = lines(d.out);
        QCOMPARE(dl.size(), 2);
        const QJsonObject frame = jsonOf(dl[0]);
        QCOMPARE(frame.value("command").toString(), QStringLiteral("multi_torque"));
        QCOMPARE(frame.value("direction").toString(), QStringLiteral("request"));
        QCOMPARE(frame.value("wire").toString(),
                 ours ? QStringLiteral("tx") : QStringLiteral("rx"));
        QCOMPARE(frame.value("can_id").toString(), QStringLiteral("0x280"));
        const QJsonObject fields = frame.value("fields").toObject();
        QCOMPARE(fields.value("iq_a_1").toDouble(), 1.6);
        QCOMPARE(fields.value("iq_a_2").toDouble(), -1.6);
        QCOMPARE(fields.value("iq_a_3").toDouble(), 0.0);
        QCOMPARE(fields.value("iq_a_4").toDouble(), 0.0);
        // lkctl replay hears it as a listener does: a torque command to drive 1, its 0xA1
        // paired (drive 2 was never seen: no request to it); another master's is drive 1's
        // commanded torque, the tool's own none (as in its session and in lkstudio's replay).
        const auto r = lkctl({QStringLiteral("replay"), path, QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
        QCOMPARE(r.out.contains("\"commanded_iq_a\":1.6"), !ours);
        QVERIFY2(r.err.contains("requests 1, replies 1, paired 1"), r.err.constData());
        QCOMPARE(jsonOf(dl[1]).value("direction").toString(), QStringLiteral("reply"));
    }

    void candumpLogOutAndBackIn()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("can.lkrec"));
        const QString log = dir.filePath(QStringLiteral("can.log"));
        QVERIFY(writeFile(path, canRecording()));
        const auto r = lkctl({QStringLiteral("export"), path, QStringLiteral("--candump"), log});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
        QFile f(log);
        QVERIFY(f.open(QIODevice::ReadOnly));
        // The wall clock of the header plus the session time; the looped-back echo once.
        QCOMPARE(f.readAll(), QByteArray("(1800000000.001000) can0 141#9C00000000000000\n"
                                         "(1800000000.001200) can0 141#9C1E64000A001027\n"
                                         "(1800000000.002000) can0 142#9A00000000000000\n"
                                         "(1800000000.002100) can0 182#9A1E60090A001000\n"
                                         "(1800000000.003000) can0 20000080#0000000000000000\n"));
        // Read back: decoded as a recording of received frames, told apart as a listener does.
        const auto d = lkctl({QStringLiteral("decode"), log});
        QVERIFY2(d.exitCode == 0, describeRun(d).toUtf8());
        const auto dl = lines(d.out);
        QCOMPARE(dl.size(), 4);
        QCOMPARE(jsonOf(dl[0]).value("direction").toString(), QStringLiteral("request"));
        QCOMPARE(jsonOf(dl[1]).value("direction").toString(), QStringLiteral("reply"));
        QCOMPARE(jsonOf(dl[1]).value("time_s").toDouble(), 0.0002);
        QCOMPARE(jsonOf(dl[2]).value("command").toString(), QStringLiteral("read_state1"));
        QCOMPARE(jsonOf(dl[3]).value("fields").toObject().value("voltage_v").toDouble(), 24.0);
        // candump's default form on standard input.
        const auto plain = lk::e2e::runProgram(QStringLiteral(LKCTL_PATH),
                                               {QStringLiteral("decode"), QStringLiteral("-")},
                                               QProcessEnvironment::systemEnvironment(), 60000,
                                               "  can0  141   [8]  9C 00 00 00 00 00 00 00\n"
                                               "  can0  141   [8]  9C 1E 64 00 0A 00 10 27\n");
        QVERIFY2(plain.exitCode == 0, describeRun(plain).toUtf8());
        QCOMPARE(lines(plain.out).size(), 2);
        QCOMPARE(jsonOf(lines(plain.out)[1]).value("fields").toObject().value("encoder").toInt(),
                 10000);
        // An RS485 recording has no candump form.
        const QString rs485 = dir.filePath(QStringLiteral("s.lkrec"));
        QVERIFY(writeFile(rs485, sampleRecording()));
        const auto refused = lkctl({QStringLiteral("export"), rs485, QStringLiteral("--candump"),
                                    dir.filePath(QStringLiteral("s.log"))});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY(refused.err.contains("not CAN"));
    }

    void canRecordingExportsAsSocketCanPcap()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("can.lkrec"));
        const QString pcap = dir.filePath(QStringLiteral("can.pcap"));
        QVERIFY(writeFile(path, canRecording()));
        const auto r = lkctl({QStringLiteral("export"), path, QStringLiteral("--pcap"), pcap});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
        QFile f(pcap);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + 20), 227u); // CAN_SOCKETCAN
        // Five frames (the looped-back echo once), 16 + 16 bytes each; the first is
        // 141#9C00000000000000 as struct can_frame: ID big-endian, DLC, 3 zeros, data.
        QCOMPARE(bytes.size(), 24 + 5 * 32);
        QCOMPARE(bytes.mid(24 + 16, 16), QByteArray::fromHex("00000141080000009C00000000000000"));
        QCOMPARE(bytes.mid(24 + 4 * 32 + 16, 4), QByteArray::fromHex("20000080")); // CAN_ERR_FLAG
        // Wireshark's own CAN dissector reads it.
        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        QVERIFY2(!tshark.isEmpty(), "tshark is missing (.ci installs it)");
        const auto all = lk::e2e::runProgram(tshark, {QStringLiteral("-r"), pcap},
                                             QProcessEnvironment::systemEnvironment(), 120000);
        QCOMPARE(lines(all.out).size(), 5);
        const auto v236 = lk::e2e::runProgram(
            tshark,
            {QStringLiteral("-r"), pcap, QStringLiteral("-Y"), QStringLiteral("can.id == 0x182")},
            QProcessEnvironment::systemEnvironment(), 120000);
        QCOMPARE(lines(v236.out).size(), 1);
    }

    void exportRefusesWhatIsNoRecording()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("x.txt"));
        QVERIFY(writeFile(path, "3E 80 01 00 BF\n"));
        const auto r = lkctl({QStringLiteral("export"), path, QStringLiteral("--pcap"),
                              dir.filePath(QStringLiteral("x.pcap"))});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("not an LK Servo Studio recording"));
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("x.pcap"))));
    }
};

QTEST_GUILESS_MAIN(tst_LkctlRecording)
#include "tst_lkctlrecording.moc"
