// PassivePairing: requests and replies another master exchanges, seen on one stream, paired by
// order. Each row is a script of frames and pauses fed through the real StreamParser; the
// counts say what was paired, what went unanswered, what stayed ambiguous (echo frames look
// the same both ways) and what a fault or a lost frame left unpaired.
//
// Script words: R<cmd>.<id> a request (reads: no data; 0x8C: the read code), A<cmd>.<id> the
// drive's reply to it (FakeDrives' answer; 0x8C: the brake state), E<cmd>.<id> an echo-layout
// frame (motor_off...), X<cmd>.<id> that reply with a bad data checksum, G garbage bytes,
// W<ms> a pause.

#include "FakeDrives.h"

#include <bus/PassivePairing.h>
#include <protocol/CanRecord.h>
#include <protocol/CanRecordParser.h>
#include <protocol/Checksum.h>
#include <protocol/StreamParser.h>
#include <protocol/Values.h>

#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using lk::bustest::FakeDrives;

namespace {

struct Expected {
    quint64 requests, replies, paired, unanswered, orphans, ambiguous, corrupt, broken;
};

QByteArray frameBytes(QChar kind, quint8 cmd, quint8 id)
{
    FakeDrives drives;
    drives.add(id, protocol::Series::MF);
    QByteArray data;
    if (cmd == 0x8C)
        data = QByteArray(1, kind == QLatin1Char('R') ? char(protocol::kBrakeReadCode) : '\x01');
    const QByteArray request = protocol::encodeFrame(cmd, id, data);
    if (kind == QLatin1Char('R') || kind == QLatin1Char('E'))
        return request;
    if (cmd == 0x8C)
        return protocol::encodeFrame(cmd, id, data);
    QByteArray reply = drives.reply(protocol::Frame{cmd, id, {}});
    if (kind == QLatin1Char('X'))
        reply[reply.size() - 1] = char(reply.at(reply.size() - 1) ^ 0x5A); // data checksum
    return reply;
}

/// One CAN frame of a listener's script (see canScript_data), as the CAN transport's record.
QByteArray canRecordBytes(QChar kind, quint8 cmd, quint8 id)
{
    // B1..B7 of a request (R, E) and of a drive's reply (O on 0x140+ID, N on 0x180+ID).
    QByteArray data(7, '\0');
    const bool request = kind == QLatin1Char('R') || kind == QLatin1Char('E');
    if (cmd == 0x8C)
        data[0] = char(request ? protocol::kBrakeReadCode : 0x01);
    else if (cmd == 0xA2 && request) // V2.36: torque limit 512, 100.00 dps (CAN.md section 9)
        data = QByteArray::fromHex("00000210270000");
    else if (!request && cmd != 0x80) // temp 30, iq 100, speed 10, encoder 10000
        data = QByteArray::fromHex("1e64000a001027");
    const quint32 base = kind == QLatin1Char('N') ? 0x180 : 0x140;
    return protocol::CanRecord::of({base + id, QByteArray(1, char(cmd)) + data}).encode();
}

void verifyCounts(const PassivePairing::Counts &c, const Expected &expected)
{
    QCOMPARE(c.requests, expected.requests);
    QCOMPARE(c.replies, expected.replies);
    QCOMPARE(c.paired, expected.paired);
    QCOMPARE(c.unanswered, expected.unanswered);
    QCOMPARE(c.orphanReplies, expected.orphans);
    QCOMPARE(c.ambiguous, expected.ambiguous);
    QCOMPARE(c.corruptReplies, expected.corrupt);
    QCOMPARE(c.brokenPairs, expected.broken);
}

} // namespace

Q_DECLARE_METATYPE(Expected)

class tst_PassivePairing : public QObject {
    Q_OBJECT
private slots:
    void script_data();
    void script();
    void latencyAndUnansweredFrame();
    void canScript_data();
    void canScript();
};

void tst_PassivePairing::script_data()
{
    QTest::addColumn<QString>("script");
    QTest::addColumn<Expected>("expected");
    // requests, replies, paired, unanswered, orphans, ambiguous, corrupt, broken
    QTest::newRow("request, reply") << "R9C.1 A9C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("poll round of two drives")
        << "R9C.1 A9C.1 R9A.2 A9A.2 R92.1 A92.1" << Expected{3, 3, 3, 0, 0, 0, 0, 0};
    QTest::newRow("echo command and its echo") << "E80.1 E80.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("lone echo, then a request: not guessed")
        << "E80.1 R9C.1 A9C.1" << Expected{2, 1, 1, 0, 0, 1, 0, 0};
    QTest::newRow("echo to another drive is a new request")
        << "E80.1 E80.2 E80.2" << Expected{2, 1, 1, 0, 0, 1, 0, 0};
    QTest::newRow("request unanswered, next request")
        << "R9C.1 R9C.2 A9C.2" << Expected{2, 1, 1, 1, 0, 0, 0, 0};
    QTest::newRow("reply whose request was lost") << "A9C.1" << Expected{0, 1, 0, 0, 1, 0, 0, 0};
    QTest::newRow("another drive's reply while a request is open")
        << "R9C.1 A9C.2" << Expected{1, 1, 0, 0, 1, 0, 0, 1};
    QTest::newRow("a reply read late still answers: no request came between")
        << "R9C.1 W100 A9C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("a long silence: unanswered, the late reply unpaired")
        << "R9C.1 W300 A9C.1" << Expected{1, 1, 0, 1, 1, 0, 0, 0};
    QTest::newRow("a slow reply within the window still pairs")
        << "R9C.1 W5 A9C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("echo retried after silence, then answered")
        << "E80.1 W100 E80.1 E80.1" << Expected{2, 1, 1, 0, 0, 1, 0, 0};
    QTest::newRow("brake read and the brake state (0x8C)")
        << "R8C.1 A8C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("garbage between request and reply")
        << "R9C.1 G A9C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("garbage, then the next request: maybe the reply was lost")
        << "R9C.1 G R9C.2 A9C.2" << Expected{2, 1, 1, 0, 0, 0, 0, 1};
    QTest::newRow("reply with a bad data checksum")
        << "R9C.1 X9C.1 R9C.2" << Expected{2, 0, 0, 0, 0, 0, 1, 0};
}

void tst_PassivePairing::script()
{
    QFETCH(QString, script);
    QFETCH(Expected, expected);
    PassivePairing pairing;
    pairing.setBaud(1000000);
    pairing.setSlackS(0.010);
    protocol::StreamParser parser;
    qint64 nowNs = 0;
    const auto feed = [&](const QByteArray &bytes) {
        parser.feed(bytes, [&](const protocol::ParseEvent &ev) { pairing.take(ev, nowNs); });
    };
    for (const QString &word : script.split(QLatin1Char(' '))) {
        nowNs += 200'000; // 0.2 ms between frames: a busy bus
        const QChar kind = word.at(0);
        if (kind == QLatin1Char('W')) {
            nowNs += qint64(word.mid(1).toInt()) * 1'000'000;
        } else if (kind == QLatin1Char('G')) {
            feed(QByteArray("\x01\x02\x03", 3));
        } else {
            bool ok = false;
            const auto cmd = quint8(word.mid(1, 2).toUInt(&ok, 16));
            QVERIFY(ok);
            const auto id = quint8(word.mid(4).toUInt());
            feed(frameBytes(kind, cmd, id));
        }
    }
    parser.finish([&](const protocol::ParseEvent &ev) { pairing.take(ev, nowNs); });
    verifyCounts(pairing.counts(), expected);
}

void tst_PassivePairing::latencyAndUnansweredFrame()
{
    PassivePairing pairing;
    pairing.setBaud(115200);
    protocol::StreamParser parser;
    QVector<PassivePairing::Outcome> outs;
    const auto feed = [&](const QByteArray &bytes, qint64 nowNs) {
        parser.feed(bytes,
                    [&](const protocol::ParseEvent &ev) { outs.append(pairing.take(ev, nowNs)); });
    };
    feed(frameBytes(QLatin1Char('R'), 0x9C, 3), 1'000'000);
    feed(frameBytes(QLatin1Char('A'), 0x9C, 3), 2'500'000);
    QCOMPARE(outs.size(), 2);
    QCOMPARE(outs.at(1).role, PassivePairing::Outcome::Role::Reply);
    QVERIFY(outs.at(1).request.has_value());
    QCOMPARE(outs.at(1).request->id, quint8(3));
    QCOMPARE(outs.at(1).latencyNs, qint64(1'500'000));

    feed(frameBytes(QLatin1Char('R'), 0x9A, 4), 3'000'000);
    QVERIFY(pairing.hasOpenRequest());
    QCOMPARE(pairing.expire(3'500'000), std::nullopt); // its reply may still come
    const std::optional<protocol::Frame> late = pairing.expire(3'000'000 + 1'000'000'000);
    QVERIFY(late.has_value()); // a second later it cannot: unanswered, and which one
    QCOMPARE(late->id, quint8(4));
    QCOMPARE(late->command, quint8(0x9A));
    QVERIFY(!pairing.hasOpenRequest());
}

// On CAN a listener hears requests on 0x140+ID and replies on 0x140+ID (old generation) or
// 0x180+ID (V2.36), every frame 8 bytes. Script words: R<cmd>.<id> a request, O<cmd>.<id> the
// drive's reply on 0x140+ID, N<cmd>.<id> on 0x180+ID, E<cmd>.<id> an echo command's frame,
// F an error frame, W<ms> a pause.
void tst_PassivePairing::canScript_data()
{
    QTest::addColumn<QString>("script");
    QTest::addColumn<Expected>("expected");
    // requests, replies, paired, unanswered, orphans, ambiguous, corrupt, broken
    QTest::newRow("old: request and reply on the one ID")
        << "R9C.1 O9C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("V2.36: the reply on 0x180+ID")
        << "R9C.1 N9C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("a poll round of two drives, both generations")
        << "R9C.1 O9C.1 R9A.2 N9A.2 R92.1 O92.1" << Expected{3, 3, 3, 0, 0, 0, 0, 0};
    QTest::newRow("speed and its motion reply")
        << "RA2.1 OA2.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("echo command on the shared ID: by order")
        << "E80.1 E80.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("echo retried after its window, then answered")
        << "E80.1 W100 E80.1 E80.1" << Expected{2, 1, 1, 0, 0, 1, 0, 0};
    QTest::newRow("lone echo, then a request: not guessed")
        << "E80.1 R9C.1 O9C.1" << Expected{2, 1, 1, 0, 0, 1, 0, 0};
    QTest::newRow("a read retried: the first unanswered (a request's layout is no reply)")
        << "R9C.1 R9C.1 O9C.1" << Expected{2, 1, 1, 1, 0, 0, 0, 0};
    QTest::newRow("a reply's layout on the shared ID, its request lost")
        << "O9C.1" << Expected{0, 1, 0, 0, 1, 0, 0, 0};
    QTest::newRow("another drive's reply while a request is open")
        << "R9C.1 O9C.2" << Expected{1, 1, 0, 0, 1, 0, 0, 1};
    QTest::newRow("request unanswered, next request")
        << "R9C.1 R9C.2 N9C.2" << Expected{2, 1, 1, 1, 0, 0, 0, 0};
    QTest::newRow("brake read and the brake state (0x8C)")
        << "R8C.1 O8C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("an error frame between request and reply")
        << "R9C.1 F O9C.1" << Expected{1, 1, 1, 0, 0, 0, 0, 0};
    QTest::newRow("a long silence: unanswered, the late reply unpaired")
        << "R9C.1 W300 O9C.1" << Expected{1, 1, 0, 1, 1, 0, 0, 0};
}

void tst_PassivePairing::canScript()
{
    QFETCH(QString, script);
    QFETCH(Expected, expected);
    PassivePairing pairing;
    pairing.setLink(protocol::Link::Can);
    pairing.setBaud(1000000);
    pairing.setSlackS(0.010);
    protocol::CanRecordParser parser(protocol::LinkEnd::Host);
    protocol::DecodeContext context;
    context.link = protocol::Link::Can;
    qint64 nowNs = 0;
    const auto take = [&](const protocol::ParseEvent &ev) {
        const PassivePairing::CanDirections d = PassivePairing::canDirections(ev, context);
        pairing.takeCan(ev, d.direction, d.openAs, nowNs);
    };
    for (const QString &word : script.split(QLatin1Char(' '))) {
        nowNs += 200'000;
        const QChar kind = word.at(0);
        if (kind == QLatin1Char('W')) {
            nowNs += qint64(word.mid(1).toInt()) * 1'000'000;
        } else if (kind == QLatin1Char('F')) {
            protocol::CanRecord error;
            error.canId = 0x20000080; // CAN_ERR_FLAG | CAN_ERR_BUSERROR
            error.flags = protocol::CanRecord::Error;
            error.data = QByteArray(8, '\0');
            parser.feed(error.encode(), take);
        } else {
            bool ok = false;
            const auto cmd = quint8(word.mid(1, 2).toUInt(&ok, 16));
            QVERIFY(ok);
            parser.feed(canRecordBytes(kind, cmd, quint8(word.mid(4).toUInt())), take);
        }
    }
    verifyCounts(pairing.counts(), expected);
}

QTEST_GUILESS_MAIN(tst_PassivePairing)
#include "tst_passivepairing.moc"
