#include <bus/ReplyMatcher.h>
#include <protocol/CanRecord.h>
#include <protocol/CanRecordParser.h>
#include <protocol/LinkCodec.h>
#include <protocol/Reply.h>

#include <QtTest/QTest>

using namespace lk;
using namespace lk::bus;
using protocol::Command;
using V = ReplyMatcher::Verdict;

Q_DECLARE_METATYPE(lk::bus::ReplyMatcher::Verdict)

namespace {
protocol::Request request(Command c, int id)
{
    protocol::Request r;
    r.command = c;
    r.id = static_cast<quint8>(id);
    return r;
}

/// Every event the parser makes of `bytes`.
QVector<protocol::ParseEvent> parse(const QByteArray &bytes)
{
    QVector<protocol::ParseEvent> out;
    protocol::StreamParser p;
    const auto sink = [&out](const protocol::ParseEvent &e) { out.append(e); };
    p.feed(bytes, sink);
    p.finish(sink);
    return out;
}

QByteArray state2Reply(int id)
{
    protocol::Reply r;
    r.command = Command::ReadState2;
    r.id = static_cast<quint8>(id);
    r.payload = protocol::State2{30, 100, false, 5, 6, lk::protocol::kIqReplyAmpsPerLsb};
    return r.encode();
}
} // namespace

/// What each received frame or fault means for the request on the wire.
class tst_ReplyMatcher : public QObject {
    Q_OBJECT
private slots:
    void classify_data();
    void classify();
    void lateReplyWindow();
    void lateReplyToAnOlderProbe();
    void tooSoonIsTheEarlierRequestsReply_data();
    void tooSoonIsTheEarlierRequestsReply();
    void canEchoIsTheTransportsFlag_data();
    void canEchoIsTheTransportsFlag();
};

void tst_ReplyMatcher::classify_data()
{
    QTest::addColumn<protocol::Request>("sent");
    QTest::addColumn<bool>("localEcho");
    QTest::addColumn<bool>("timedOut");
    QTest::addColumn<QByteArray>("received");
    QTest::addColumn<QVector<V>>("verdicts");
    const auto s2 = request(Command::ReadState2, 3);
    const auto off = request(Command::MotorOff, 3);
    QByteArray corrupt = state2Reply(3);
    corrupt[corrupt.size() - 1] = char(corrupt.at(corrupt.size() - 1) + 1);

    QTest::newRow("reply") << s2 << false << false << state2Reply(3) << QVector<V>{V::Reply};
    QTest::newRow("other ID") << s2 << false << false << state2Reply(4)
                              << QVector<V>{V::Unexpected};
    QTest::newRow("own request read back") << s2 << false << false << s2.encode() + state2Reply(3)
                                           << QVector<V>{V::LocalEcho, V::Reply};
    QTest::newRow("echo command, no adapter echo")
        << off << false << false << off.encode() << QVector<V>{V::Reply};
    QTest::newRow("echo command, adapter echoes")
        << off << true << false << off.encode() + off.encode()
        << QVector<V>{V::LocalEcho, V::Reply};
    QTest::newRow("corrupt reply")
        << s2 << false << false << corrupt << QVector<V>{V::CorruptReply};
    QTest::newRow("corrupt frame of another ID")
        << request(Command::ReadState2, 4) << false << false << corrupt << QVector<V>{V::Fault};
    QTest::newRow("garbage then reply")
        << s2 << false << false << QByteArray("\x01\x02", 2) + state2Reply(3)
        << QVector<V>{V::Fault, V::Reply};
    QTest::newRow("late reply") << s2 << false << true << state2Reply(3)
                                << QVector<V>{V::LateReply};
    QTest::newRow("second late reply is unexpected")
        << s2 << false << true << state2Reply(3) + state2Reply(3)
        << QVector<V>{V::LateReply, V::Unexpected};
}

void tst_ReplyMatcher::classify()
{
    QFETCH(protocol::Request, sent);
    QFETCH(bool, localEcho);
    QFETCH(bool, timedOut);
    QFETCH(QByteArray, received);
    QFETCH(QVector<V>, verdicts);
    ReplyMatcher m;
    m.setLocalEcho(localEcho);
    m.expect(sent, sent.encode(), 0);
    if (timedOut)
        m.timedOut();
    QVector<V> got;
    for (const protocol::ParseEvent &e : parse(received)) {
        const ReplyMatcher::Outcome o = m.classify(e, {}, 1000);
        QCOMPARE(o.reply.has_value(), o.verdict == V::Reply);
        got.append(o.verdict);
        if (o.verdict == V::Reply)
            m.clear(); // as the worker does once the request is complete
    }
    QCOMPARE(got, verdicts);
}

void tst_ReplyMatcher::lateReplyWindow()
{
    ReplyMatcher m;
    const auto s2 = request(Command::ReadState2, 3);
    m.expect(s2, s2.encode(), 0);
    m.timedOut();
    const auto ev = parse(state2Reply(3)).at(0);
    const auto o = m.classify(ev, {}, 2 * ReplyMatcher::kLateWindowNs);
    QCOMPARE(o.verdict, V::Unexpected); // far too late to mean anything
    m.expect(s2, s2.encode(), 0);
    m.timedOut();
    const auto late = m.classify(ev, {}, 50'000'000);
    QCOMPARE(late.verdict, V::LateReply);
    QCOMPARE(late.lateLatencyS, 0.05);
    m.reset();
    QCOMPARE(m.classify(ev, {}, 60'000'000).verdict, V::Unexpected);
}

void tst_ReplyMatcher::lateReplyToAnOlderProbe()
{
    // A scan's first pass times out ID after ID; behind a slow adapter the reply to ID 3
    // arrives while ID 6 is on the wire. It is still recognised as late (and measured).
    ReplyMatcher m;
    qint64 t = 0;
    for (int id = 3; id <= 6; ++id) {
        const auto r = request(Command::ReadState2, id);
        m.expect(r, r.encode(), t);
        if (id < 6)
            m.timedOut();
        t += 5'000'000;
    }
    const auto late = m.classify(parse(state2Reply(3)).at(0), {}, 16'000'000);
    QCOMPARE(late.verdict, V::LateReply);
    QCOMPARE(late.lateLatencyS, 0.016);
    QCOMPARE(m.classify(parse(state2Reply(4)).at(0), {}, 17'000'000).verdict, V::LateReply);
    QCOMPARE(m.classify(parse(state2Reply(3)).at(0), {}, 18'000'000).verdict, V::Unexpected);
    QCOMPARE(m.classify(parse(state2Reply(6)).at(0), {}, 19'000'000).verdict, V::Reply);
}

void tst_ReplyMatcher::tooSoonIsTheEarlierRequestsReply_data()
{
    QTest::addColumn<bool>("timedOutBefore");
    QTest::addColumn<qint64>("arrivalNs");
    QTest::addColumn<V>("verdict");
    // The request goes out at 10 ms; its reply cannot arrive before 11.5 ms.
    QTest::newRow("too soon, earlier one timed out") << true << qint64(10'200'000) << V::LateReply;
    QTest::newRow("in time, earlier one timed out") << true << qint64(12'000'000) << V::Reply;
    QTest::newRow("too soon, nothing timed out") << false << qint64(10'200'000) << V::Reply;
}

void tst_ReplyMatcher::tooSoonIsTheEarlierRequestsReply()
{
    QFETCH(bool, timedOutBefore);
    QFETCH(qint64, arrivalNs);
    QFETCH(V, verdict);
    ReplyMatcher m;
    const auto s2 = request(Command::ReadState2, 3);
    if (timedOutBefore) {
        m.expect(s2, s2.encode(), 0, 1'500'000);
        m.timedOut();
    }
    m.expect(s2, s2.encode(), 10'000'000, 11'500'000);
    QCOMPARE(m.classify(parse(state2Reply(3)).at(0), {}, arrivalNs).verdict, verdict);
}

void tst_ReplyMatcher::canEchoIsTheTransportsFlag_data()
{
    QTest::addColumn<bool>("echoFlag");
    QTest::addColumn<bool>("localEchoConfig");
    QTest::addColumn<V>("verdict");
    // The old CAN generation answers motor_off on the request's own ID with the same 8 bytes:
    // only the adapter's echo flag tells our frame from the drive's, whatever the config says.
    QTest::newRow("flagged: our own frame") << true << false << V::LocalEcho;
    QTest::newRow("unflagged: the drive's echo") << false << false << V::Reply;
    QTest::newRow("unflagged, localEcho set: still the drive's") << false << true << V::Reply;
}

void tst_ReplyMatcher::canEchoIsTheTransportsFlag()
{
    QFETCH(bool, echoFlag);
    QFETCH(bool, localEchoConfig);
    QFETCH(V, verdict);
    const protocol::DecodeContext ctx{protocol::Series::MG, protocol::Generation::V2_3,
                                      protocol::Link::Can};
    const auto off = request(Command::MotorOff, 1);
    const QByteArray sent = protocol::encodeRequest(off, ctx).bytes;
    QVERIFY(!sent.isEmpty());
    protocol::CanRecord received = *protocol::CanRecord::decode(sent);
    if (echoFlag)
        received.flags |= protocol::CanRecord::Echo;
    QVector<protocol::ParseEvent> events;
    protocol::CanRecordParser parser;
    parser.feed(received.encode(), [&events](const protocol::ParseEvent &e) { events.append(e); });
    QCOMPARE(events.size(), 1);
    ReplyMatcher m;
    m.setLocalEcho(localEchoConfig);
    m.expect(off, sent, 0);
    QCOMPARE(m.classify(events.at(0), ctx, 1'000'000).verdict, verdict);
}

QTEST_APPLESS_MAIN(tst_ReplyMatcher)
#include "tst_replymatcher.moc"
