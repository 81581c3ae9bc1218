// The shipped Wireshark dissector (packaging/wireshark/lkservo.lua) on a pcap that
// `lkctl export` wrote: tshark names every command of both generations in both directions,
// decodes fields and values with the recorded context, and raises no Lua error.
#include "E2eUtil.h"
#include "RecordingTestUtil.h"

#include <protocol/Command.h>
#include <protocol/Reply.h>

#include <algorithm>

#include <QtCore/QStandardPaths>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace lk::recording;
namespace protocol = lk::protocol;
using lk::e2e::describeRun;
using lk::e2e::runProgram;
using lk::testsupport::lines;

namespace {

const QString kDissector = QStringLiteral(LK_SOURCE_DIR "/packaging/wireshark/lkservo.lua");

QByteArray modelReply(int id, protocol::Generation generation)
{
    protocol::ModelInfo m;
    m.driverName = QStringLiteral("LK-DRV");
    m.motorName = generation == protocol::Generation::V2_35 ? QStringLiteral("MF4015")
                                                            : QStringLiteral("MS5010");
    m.hardwareRaw = generation == protocol::Generation::V2_35 ? 120 : 12;
    m.firmwareRaw = generation == protocol::Generation::V2_35 ? 235 : 22;
    m.generation = generation;
    m.motorId = QByteArray(12, '\x07');
    return protocol::Reply{protocol::Command::ReadModel, quint8(id), m}.encode();
}

/// The data bytes 1, 2, 3, ... of a LEN.
QByteArray pattern(int len)
{
    QByteArray d;
    for (int i = 0; i < len; ++i)
        d.append(char(i + 1));
    return d;
}

struct Expected {
    QString command;
    QString kind;
};

/// Every command: its request, then its reply (V2.3 commands to drive 1, an MS on V2.3;
/// V2.35-only ones to drive 2, an MF on V2.35), then drive 2's V2.35 model reply.
QByteArray everyCommand(QVector<Expected> *expected)
{
    RecordingHeader h = lk::testsupport::testHeader();
    h.context = {{1, protocol::Series::MS, protocol::Generation::V2_3},
                 {2, protocol::Series::MF, protocol::Generation::V2_35}};
    QByteArray file = RecordEncoder::encodeHeader(h);
    RecordEncoder enc;
    qint64 t = 0;
    const auto add = [&](RecordEvent::Kind k, const QByteArray &b) {
        enc.append(RecordEvent::data(k, t += 1'000'000, b));
    };
    expected->append({QString(), QStringLiteral("decode context")});
    for (const protocol::CommandInfo &c : protocol::CommandTable::all()) {
        if (c.canOnly) // 0xC0/0xC1: no RS485 frame carries them
            continue;
        const bool v23 = c.generations & protocol::kOnV23;
        const int id = v23 ? 1 : 2;
        const auto code = quint8(c.command);
        const QString name = QString::fromLatin1(c.name);
        const QByteArray request = protocol::encodeFrame(
            code, quint8(id), code == 0x8C ? QByteArray(1, '\x10') : pattern(c.requestLength));
        add(RecordEvent::Kind::Tx, request);
        const bool echo = c.replyEchoesRequest;
        expected->append({name, echo ? QStringLiteral("echo") : QStringLiteral("request")});
        QByteArray reply;
        if (code == 0x12)
            reply = modelReply(id, v23 ? protocol::Generation::V2_3 : protocol::Generation::V2_35);
        else if (code == 0x8C)
            reply = protocol::encodeFrame(code, quint8(id), QByteArray(1, '\x01'));
        else
            reply =
                echo ? request : protocol::encodeFrame(code, quint8(id), pattern(c.replyLength));
        add(RecordEvent::Kind::Rx, reply);
        expected->append(
            {name, echo || code == 0x8C ? QStringLiteral("echo") : QStringLiteral("reply")});
    }
    // The V2.35 model reply (58 bytes), from drive 2.
    add(RecordEvent::Kind::Tx, protocol::encodeFrame(0x12, 2, {}));
    add(RecordEvent::Kind::Rx, modelReply(2, protocol::Generation::V2_35));
    expected->append({QStringLiteral("read_model"), QStringLiteral("request")});
    expected->append({QStringLiteral("read_model"), QStringLiteral("reply")});
    file += enc.takeBlock();
    return file;
}

} // namespace

class tst_WiresharkDissector : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString m_tshark;
    QString m_pcap;
    QVector<Expected> m_expected;

    lk::e2e::CtlResult tshark(const QStringList &args)
    {
        return runProgram(m_tshark,
                          QStringList{QStringLiteral("-X"),
                                      QStringLiteral("lua_script:") + kDissector,
                                      QStringLiteral("-r"), m_pcap} +
                              args,
                          QProcessEnvironment::systemEnvironment(), 120000);
    }

private slots:
    void initTestCase()
    {
        m_tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        if (m_tshark.isEmpty())
            QSKIP("tshark is not installed (packaging/install-deps.sh installs it)");
        const QString rec = m_dir.filePath(QStringLiteral("all.lkrec"));
        m_pcap = m_dir.filePath(QStringLiteral("all.pcap"));
        QVERIFY(lk::testsupport::writeFile(rec, everyCommand(&m_expected)));
        const auto r =
            lk::e2e::lkctl({QStringLiteral("export"), rec, QStringLiteral("--pcap"), m_pcap});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
    }

    void everyCommandIsNamedInBothDirections()
    {
        const auto r = tshark({QStringLiteral("-T"), QStringLiteral("fields"), QStringLiteral("-e"),
                               QStringLiteral("lkservo.command"), QStringLiteral("-e"),
                               QStringLiteral("lkservo.kind")});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
        const auto l = lines(r.out);
        QCOMPARE(l.size(), m_expected.size());
        const auto rs485 = std::count_if(protocol::CommandTable::all().cbegin(),
                                         protocol::CommandTable::all().cend(),
                                         [](const protocol::CommandInfo &c) { return !c.canOnly; });
        QCOMPARE(m_expected.size(), 1 + 2 * int(rs485) + 2);
        for (int i = 1; i < l.size(); ++i) {
            const QList<QByteArray> cols = l[i].split('\t');
            QCOMPARE(QString::fromUtf8(cols.value(0)), m_expected[i].command);
            // kind is printed as its number: 0 request, 1 reply, 2 echo.
            const QString kind = m_expected[i].kind;
            const int want = kind == QLatin1String("request") ? 0
                             : kind == QLatin1String("reply") ? 1
                                                              : 2;
            QCOMPARE(cols.value(1).toInt(), want);
        }
    }

    void noLuaErrorAndNoMalformedPacket()
    {
        const auto r = tshark({QStringLiteral("-V")});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
        QVERIFY2(!r.out.contains("Lua Error"), r.out.constData());
        QVERIFY(!r.out.contains("Malformed"));
        QVERIFY(!r.out.contains("Dissector bug"));
        QVERIFY(!r.err.contains("Lua"));
        // Every frame was built with valid checksums.
        QVERIFY(!r.out.contains("Checksums valid: False"));
    }

    void fieldsAndValuesFollowTheRecordedContext_data()
    {
        QTest::addColumn<QString>("filter");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("value");
        // Drive 1 is an MS: its 0x9C reply carries power (bytes 02 03 = 0x0302 = 770).
        QTest::newRow("MS power") << "lkservo.code == 0x9c && lkservo.id == 1 && lkservo.kind == 1"
                                  << "lkservo.power"
                                  << "770";
        QTest::newRow("MS has no iq")
            << "lkservo.code == 0x9c && lkservo.id == 1 && lkservo.kind == 1"
            << "lkservo.iq_raw"
            << "";
        // Speed request: 01 02 03 04 = 0x04030201 centi-dps.
        QTest::newRow("speed command") << "lkservo.code == 0xa2 && lkservo.kind == 0"
                                       << "lkservo.speed_command_raw"
                                       << "67305985";
        QTest::newRow("V2.3 model firmware")
            << "lkservo.code == 0x12 && lkservo.id == 1 && lkservo.kind == 1"
            << "lkservo.firmware_version"
            << "2.2";
        QTest::newRow("V2.35 model firmware")
            << "lkservo.code == 0x12 && lkservo.id == 2 && lkservo.kind == 1"
            << "lkservo.firmware_version"
            << "2.35";
        QTest::newRow("motor name")
            << "lkservo.code == 0x12 && lkservo.id == 2 && lkservo.kind == 1"
            << "lkservo.motor_name"
            << "MF4015";
        // The V2.35 read_param reply of drive 2: parameter 0x01 is none the table names, but the
        // ID is decoded.
        QTest::newRow("param id") << "lkservo.code == 0x40 && lkservo.kind == 1"
                                  << "lkservo.param_id"
                                  << "0x01";
        QTest::newRow("brake read") << "lkservo.code == 0x8c && lkservo.wire == 1"
                                    << "lkservo.brake"
                                    << "0x10";
        QTest::newRow("error bits") << "lkservo.code == 0x9a && lkservo.kind == 1"
                                    << "lkservo.error_state"
                                    << "0x07";
    }
    void fieldsAndValuesFollowTheRecordedContext()
    {
        QFETCH(QString, filter);
        QFETCH(QString, field);
        QFETCH(QString, value);
        const auto r = tshark({QStringLiteral("-Y"), filter, QStringLiteral("-T"),
                               QStringLiteral("fields"), QStringLiteral("-e"), field});
        QVERIFY2(r.exitCode == 0, describeRun(r).toUtf8());
        const auto l = r.out.split('\n');
        QCOMPARE(QString::fromUtf8(l.value(0)).trimmed(), value);
    }
};

QTEST_GUILESS_MAIN(tst_WiresharkDissector)
#include "tst_wiresharkdissector.moc"
