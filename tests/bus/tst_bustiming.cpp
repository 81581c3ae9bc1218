#include <bus/AdaptiveTimeout.h>
#include <bus/BusTiming.h>
#include <bus/LatencyWindow.h>
#include <bus/LinkTiming.h>
#include <bus/TelemetrySample.h>

#include <QtCore/QRandomGenerator>
#include <QtTest/QTest>

#include <algorithm>
#include <cmath>

using namespace lk;
using namespace lk::bus;
using protocol::Command;

Q_DECLARE_METATYPE(protocol::Command)
Q_DECLARE_METATYPE(protocol::Reply)

/// The bus-limit formula, latency statistics, adaptive timeouts and telemetry extraction.
class tst_BusTiming : public QObject {
    Q_OBJECT
private slots:
    void wireTime_data();
    void wireTime();
    void workedExample();
    void frameBytes_data();
    void frameBytes();
    void mixLimit();
    void replyTimeout();
    void standardBauds();
    void latencyQuantiles();
    void latencyWindowIsBounded();
    void latencyWindowKeepsItsLastSamplesSorted();
    void adaptiveMargin_data();
    void adaptiveMargin();
    void marginCoversTheSlowestPercent();
    void lateReplyLiftsMarginAtOnce();
    void slowDriveStaysWaitedFor();
    void longReplyIsWireTimeNotLatency();
    void marginWarmsUpPerCommandClass();
    void quietPeriodCoversTheLongestReply();
    void turnaroundIsMeasured();
    void telemetryFromReply_data();
    void telemetryFromReply();
};

void tst_BusTiming::wireTime_data()
{
    QTest::addColumn<int>("requestBytes");
    QTest::addColumn<int>("replyBytes");
    QTest::addColumn<int>("baud");
    QTest::addColumn<double>("seconds");
    QTest::newRow("read_state2 @115200") << 5 << 13 << 115200 << 0.0015625;
    QTest::newRow("read_state2 @9600") << 5 << 13 << 9600 << 0.01875;
    QTest::newRow("read_model @1M") << 5 << 48 << 1000000 << 0.00053;
    QTest::newRow("motor_off @2M") << 5 << 5 << 2000000 << 0.00005;
    QTest::newRow("zero baud") << 5 << 13 << 0 << 0.0;
}

void tst_BusTiming::wireTime()
{
    QFETCH(int, requestBytes);
    QFETCH(int, replyBytes);
    QFETCH(int, baud);
    QFETCH(double, seconds);
    QVERIFY(qAbs(BusTiming::wireTimeS(requestBytes, replyBytes, baud) - seconds) < 1e-12);
}

void tst_BusTiming::workedExample()
{
    // docs/ARCHITECTURE.md: Read State 2, 5 + 13 bytes at 115200 = 1.5625 ms on the wire; with
    // 0.5 ms turnaround at most ~485 transactions/s.
    QCOMPARE(BusTiming::requestBytes(Command::ReadState2), 5);
    QCOMPARE(BusTiming::replyBytes(Command::ReadState2), 13);
    const double t = BusTiming::transactionTimeS(Command::ReadState2, 115200);
    QVERIFY(qAbs(t - 0.0020625) < 1e-12);
    const double perSecond = BusTiming::transactionsPerSecond({Command::ReadState2}, 115200);
    QCOMPARE(qRound(perSecond), 485);
}

void tst_BusTiming::frameBytes_data()
{
    QTest::addColumn<Command>("command");
    QTest::addColumn<int>("request");
    QTest::addColumn<int>("reply");
    QTest::addColumn<int>("maxReply");
    QTest::newRow("read_state2") << Command::ReadState2 << 5 << 13 << 13;
    QTest::newRow("read_model 42 or 58") << Command::ReadModel << 5 << 48 << 64;
    QTest::newRow("motor_off echo") << Command::MotorOff << 5 << 5 << 5;
    QTest::newRow("write_pid_ram echo") << Command::WritePidRam << 12 << 12 << 12;
    QTest::newRow("speed") << Command::Speed << 10 << 13 << 13;
    QTest::newRow("multi_position_limited") << Command::MultiPositionLimited << 18 << 13 << 13;
    QTest::newRow("increment_position (LEN 4)") << Command::IncrementPosition << 10 << 13 << 13;
    QTest::newRow("write_zero_rom 0 or 2") << Command::WriteZeroRom << 5 << 5 << 8;
    QTest::newRow("read_multi_turn") << Command::ReadMultiTurn << 5 << 14 << 14;
}

void tst_BusTiming::frameBytes()
{
    QFETCH(Command, command);
    QFETCH(int, request);
    QFETCH(int, reply);
    QFETCH(int, maxReply);
    QCOMPARE(BusTiming::requestBytes(command), request);
    QCOMPARE(BusTiming::replyBytes(command), reply);
    QCOMPARE(BusTiming::maxReplyBytes(command), maxReply);
}

void tst_BusTiming::mixLimit()
{
    // The dashboard mix: 9C, 9A, 92, 9D, each 5-byte requests; replies 13, 13, 14, 13.
    const QVector<Command> mix{Command::ReadState2, Command::ReadState1, Command::ReadMultiTurn,
                               Command::ReadState3};
    const double cycle = (18 + 18 + 19 + 18) * 10.0 / 115200 + 4 * 0.0005;
    QVERIFY(qAbs(BusTiming::transactionsPerSecond(mix, 115200) - 4 / cycle) < 1e-9);
    QCOMPARE(BusTiming::transactionsPerSecond({}, 115200), 0.0);
    // Faster baud, more transactions, but never past the turnaround bound of 2000/s.
    QVERIFY(BusTiming::transactionsPerSecond(mix, 1000000) >
            BusTiming::transactionsPerSecond(mix, 115200));
    QVERIFY(BusTiming::transactionsPerSecond(mix, 2000000) < 2000);
}

void tst_BusTiming::replyTimeout()
{
    const double expected = (5 + 64) * 10.0 / 115200 + 0.0005 + 0.002;
    QVERIFY(qAbs(BusTiming::replyTimeoutS(Command::ReadModel, 115200, 0.002) - expected) < 1e-12);
}

void tst_BusTiming::standardBauds()
{
    QCOMPARE(int(BusTiming::standardBauds().size()), 10);
    for (int b : {9600, 19200, 38400, 57600, 115200, 230400, 460800, 1000000, 2000000})
        QVERIFY(BusTiming::isStandardBaud(b));
    QVERIFY(BusTiming::isStandardBaud(4000000)); // V2.35
    QVERIFY(!BusTiming::isStandardBaud(3000000));
    QVERIFY(!BusTiming::isStandardBaud(0));
}

void tst_BusTiming::latencyQuantiles()
{
    LatencyWindow w(1000);
    QCOMPARE(w.median(), 0.0);
    for (int i = 100; i >= 1; --i)
        w.add(i);
    QCOMPARE(w.min(), 1.0);
    QCOMPARE(w.median(), 50.0);
    QCOMPARE(w.p95(), 95.0);
    QCOMPARE(w.max(), 100.0);
    const LatencySummary s = w.summaryMs();
    QCOMPARE(s.samples, 100);
    QCOMPARE(s.maxMs, 100000.0);
}

void tst_BusTiming::latencyWindowIsBounded()
{
    LatencyWindow w(10);
    for (int i = 1; i <= 25; ++i)
        w.add(i);
    QCOMPARE(w.size(), 10);
    QCOMPARE(w.min(), 16.0); // only the last ten remain
    QCOMPARE(w.max(), 25.0);
    w.clear();
    QVERIFY(w.isEmpty());
}

void tst_BusTiming::latencyWindowKeepsItsLastSamplesSorted()
{
    // Full, the window moves only what lies between the evicted sample's place and the new
    // one's: every order of the two (before, after, equal values, repeats) must leave the
    // quantiles of a plain sort of the last samples.
    constexpr int kCapacity = 16;
    LatencyWindow w(kCapacity);
    QRandomGenerator random(7);
    QVector<double> added;
    for (int i = 0; i < 3000; ++i) {
        const double v = double(random.bounded(i % 3 == 0 ? 4 : 40)); // with many repeats
        w.add(v);
        added.append(v);
        QVector<double> last = added.mid(std::max<qsizetype>(0, added.size() - kCapacity));
        std::sort(last.begin(), last.end());
        for (double q : {0.0, 0.1, 0.25, 0.5, 0.75, 0.95, 1.0}) {
            const auto rank = std::max<qsizetype>(
                0, std::min<qsizetype>(last.size() - 1,
                                       qsizetype(std::ceil(q * double(last.size()))) - 1));
            QCOMPARE(w.quantile(q), last.at(rank));
        }
    }
}

void tst_BusTiming::adaptiveMargin_data()
{
    QTest::addColumn<int>("replies");
    QTest::addColumn<double>("extraMs");
    QTest::addColumn<double>("marginMs");
    QTest::newRow("no replies yet: initial margin") << 0 << 0.0 << 20.0;
    QTest::newRow("warming up: at least the initial margin") << 3 << 1.0 << 20.0;
    QTest::newRow("fast link: minimum margin") << 20 << 0.1 << 2.0;
    QTest::newRow("FTDI-like 10 ms: 2 x p99") << 20 << 10.0 << 20.0;
    QTest::newRow("pathological link: bounded") << 20 << 1000.0 << 200.0;
}

void tst_BusTiming::adaptiveMargin()
{
    QFETCH(int, replies);
    QFETCH(double, extraMs);
    QFETCH(double, marginMs);
    AdaptiveTimeout t; // defaults: min 2, initial 20, max 200 ms
    const double wire = BusTiming::transactionTimeS(Command::ReadState2, 115200);
    for (int i = 0; i < replies; ++i)
        t.addReply(Command::ReadState2, LinkTiming::rs485(115200), wire + extraMs * 1e-3);
    QVERIFY2(qAbs(t.marginS() * 1e3 - marginMs) < 1e-6, qPrintable(QString::number(t.marginS())));
    QVERIFY(qAbs(t.timeoutS(Command::ReadState2, LinkTiming::rs485(115200)) -
                 (wire + t.marginS())) < 1e-12);
}

void tst_BusTiming::marginCoversTheSlowestPercent()
{
    // A loaded host: one reply in fifty comes 10 ms late. The margin must cover it (p99),
    // or one poll in fifty times out and is retried while its reply is on its way.
    AdaptiveTimeout t; // defaults: min 2, initial 20, max 200 ms
    const double wire = BusTiming::transactionTimeS(Command::ReadState2, 115200);
    for (int i = 0; i < AdaptiveTimeout::kWindow; ++i)
        t.addReply(Command::ReadState2, LinkTiming::rs485(115200),
                   wire + (i % 50 == 25 ? 10e-3 : 0.1e-3));
    QVERIFY2(t.marginS() >= 2 * 10e-3 - 1e-12, qPrintable(QString::number(t.marginS())));
    QVERIFY(t.timeoutS(Command::ReadState2, LinkTiming::rs485(115200)) > wire + 10e-3);
}

// The bus limit's turnaround is what the replies show: the least latency minus wire time
// (a drive answering after 0.2 ms, one late reply among them), the formula's 0.5 ms only
// before a handful of replies; flash writes (the drive is busy writing) do not count.
void tst_BusTiming::turnaroundIsMeasured()
{
    AdaptiveTimeout t;
    const double wire0 = BusTiming::transactionTimeS(Command::ReadState2, 115200, 0);
    QVERIFY(!t.measuredTurnaroundS());
    for (int i = 0; i < 20; ++i)
        t.addReply(Command::ReadState2, LinkTiming::rs485(115200),
                   wire0 + (i == 7 ? 5e-3 : 0.2e-3));
    t.addReply(Command::WritePidRom, LinkTiming::rs485(115200),
               1e-4); // no flash write teaches the link
    QVERIFY(t.measuredTurnaroundS());
    QVERIFY2(qAbs(*t.measuredTurnaroundS() - 0.2e-3) < 1e-9,
             qPrintable(QString::number(*t.measuredTurnaroundS())));
    t.reset();
    QVERIFY(!t.measuredTurnaroundS());
}

void tst_BusTiming::lateReplyLiftsMarginAtOnce()
{
    AdaptiveTimeout t;
    const double wire = BusTiming::transactionTimeS(Command::ReadState1, 115200);
    for (int i = 0; i < 100; ++i)
        t.addReply(Command::ReadState1, LinkTiming::rs485(115200), wire + 0.1e-3, 3);
    QCOMPARE(t.marginS(), 2e-3);
    // Drive 3 answered 30 ms after its request had timed out: the very next attempts to it,
    // of any class, wait longer than that. Drive 4 and the link do not wait for drive 3.
    t.addLateReply(Command::ReadState1, LinkTiming::rs485(115200), wire + 30e-3, 3);
    for (AdaptiveTimeout::CommandClass c :
         {AdaptiveTimeout::CommandClass::Read, AdaptiveTimeout::CommandClass::Write})
        QVERIFY2(t.marginS(c, 3) >= 1.5 * 30e-3 - 1e-9,
                 qPrintable(QString::number(t.marginS(c, 3))));
    QVERIFY(t.quietS(Command::ReadState1, LinkTiming::rs485(115200), 3) > 30e-3);
    QCOMPARE(t.marginS(AdaptiveTimeout::CommandClass::Read, 4), 2e-3);
    QCOMPARE(t.marginS(), 2e-3);
    QVERIFY(t.quietS(Command::ReadState1, LinkTiming::rs485(115200), 4) < 10e-3);
    // Replies of drive 3 in time halve the lift each; it is gone within a few.
    int replies = 0;
    while (t.lateExtraS(3) > 0 && replies < 10) {
        t.addReply(Command::ReadState1, LinkTiming::rs485(115200), wire + 0.1e-3, 3);
        ++replies;
    }
    QVERIFY2(replies >= 3 && replies <= 6, qPrintable(QString::number(replies)));
    QCOMPARE(t.marginS(AdaptiveTimeout::CommandClass::Read, 3), 2e-3);
}

void tst_BusTiming::slowDriveStaysWaitedFor()
{
    // A drive that answers 30 ms late every time keeps its lift: each reply in time decays it
    // no further than that reply's own extra latency.
    AdaptiveTimeout t;
    const double wire = BusTiming::transactionTimeS(Command::ReadState1, 115200);
    t.addLateReply(Command::ReadState1, LinkTiming::rs485(115200), wire + 30e-3, 5);
    for (int i = 0; i < 50; ++i)
        t.addReply(Command::ReadState1, LinkTiming::rs485(115200), wire + 30e-3, 5);
    QVERIFY(t.timeoutS(Command::ReadState1, LinkTiming::rs485(115200), 5) > wire + 30e-3);
}

void tst_BusTiming::longReplyIsWireTimeNotLatency()
{
    // A V2.35 drive's model reply is 64 bytes on the wire, not the usual 48: at 9600 baud that
    // is 16.7 ms of wire time, which must not teach the link a 17 ms latency.
    AdaptiveTimeout t;
    const double wire58 =
        BusTiming::wireTimeS(BusTiming::requestBytes(Command::ReadModel), 64, 9600) +
        BusTiming::kTurnaroundS;
    for (int i = 0; i < 100; ++i)
        t.addReply(Command::ReadModel, LinkTiming::rs485(9600), wire58 + 0.1e-3, 1, 64);
    QCOMPARE(t.marginS(), 2e-3);
}

void tst_BusTiming::marginWarmsUpPerCommandClass()
{
    AdaptiveTimeout t;
    const double wire = BusTiming::transactionTimeS(Command::ReadState2, 115200);
    for (int i = 0; i < 100; ++i)
        t.addReply(Command::ReadState2, LinkTiming::rs485(115200), wire + 0.1e-3);
    QCOMPARE(AdaptiveTimeout::classOf(Command::ReadState2), AdaptiveTimeout::CommandClass::Read);
    QCOMPARE(AdaptiveTimeout::classOf(Command::Speed), AdaptiveTimeout::CommandClass::Write);
    QCOMPARE(AdaptiveTimeout::classOf(Command::MotorOff), AdaptiveTimeout::CommandClass::Write);
    QCOMPARE(AdaptiveTimeout::classOf(Command::WritePidRom), AdaptiveTimeout::CommandClass::Flash);
    QCOMPARE(t.marginS(AdaptiveTimeout::CommandClass::Read), 2e-3);
    // Commands that act have not been timed yet: the initial margin until they have.
    QCOMPARE(t.marginS(AdaptiveTimeout::CommandClass::Write), 20e-3);
    QCOMPARE(t.timeoutS(Command::Speed, LinkTiming::rs485(115200)),
             BusTiming::replyTimeoutS(Command::Speed, 115200, 20e-3));
    // A drive that takes 8 ms to write its flash: ROM writes get their own, longer margin.
    for (int i = 0; i < AdaptiveTimeout::kWarmupSamples; ++i)
        t.addReply(Command::WritePidRom, LinkTiming::rs485(115200),
                   BusTiming::transactionTimeS(Command::WritePidRom, 115200) + 8e-3);
    QVERIFY(t.marginS(AdaptiveTimeout::CommandClass::Flash) >= 16e-3 - 1e-12);
    QCOMPARE(t.marginS(AdaptiveTimeout::CommandClass::Read), 2e-3); // not the link's latency
}

void tst_BusTiming::quietPeriodCoversTheLongestReply()
{
    // After a timeout a reply may still begin: the drive's longest turnaround, then its
    // longest reply on the wire, then the adapter's latency before the host sees it.
    AdaptiveTimeout t; // min margin 2 ms, initial 20 ms
    const double longest =
        BusTiming::wireTimeS(0, BusTiming::maxReplyBytes(Command::ReadModel), 115200);
    QCOMPARE(BusTiming::maxReplyBytes(Command::ReadModel), 64);
    // Nothing measured yet: the link's latency is taken as the initial margin.
    QVERIFY(qAbs(t.quietS(Command::ReadModel, LinkTiming::rs485(115200)) -
                 (BusTiming::kTurnaroundS + longest + 20e-3)) < 1e-12);
    const double fast = BusTiming::transactionTimeS(Command::ReadModel, 115200) + 0.1e-3;
    for (int i = 0; i < AdaptiveTimeout::kPercentileSamples; ++i)
        t.addReply(Command::ReadModel, LinkTiming::rs485(115200), fast);
    // A fast link, measured: the least allowance (the minimum margin).
    QVERIFY(qAbs(t.quietS(Command::ReadModel, LinkTiming::rs485(115200)) -
                 (BusTiming::kTurnaroundS + longest + 2e-3)) < 1e-12);
    t.reset();
    // A link whose replies come up to 16 ms late (FTDI's latency timer): the quiet period
    // waits for that too.
    const double wire = BusTiming::transactionTimeS(Command::ReadState2, 115200);
    for (int i = 0; i < 100; ++i)
        t.addReply(Command::ReadState2, LinkTiming::rs485(115200), wire + (i % 10) * 16e-3 / 9);
    QVERIFY(t.quietS(Command::ReadState2, LinkTiming::rs485(115200)) >= 16e-3);
    QVERIFY(t.quietS(Command::ReadState2, LinkTiming::rs485(1000000)) <
            t.quietS(Command::ReadState2, LinkTiming::rs485(115200)));
    // A probe's quiet period ends when a reply could have come through this link, counted
    // from the send: the formula with the longest reply plus the same latency.
    const double linkS =
        t.quietS(Command::ReadState2, LinkTiming::rs485(115200)) - BusTiming::kTurnaroundS -
        BusTiming::wireTimeS(0, BusTiming::maxReplyBytes(Command::ReadState2), 115200);
    QVERIFY(qAbs(t.replyDeadlineS(Command::ReadState2, LinkTiming::rs485(115200)) -
                 BusTiming::replyTimeoutS(Command::ReadState2, 115200, linkS)) < 1e-12);
}

void tst_BusTiming::telemetryFromReply_data()
{
    QTest::addColumn<protocol::Reply>("reply");
    QTest::addColumn<int>("fields");
    const auto make = [](Command c, protocol::ReplyPayload p) {
        protocol::Reply r;
        r.command = c;
        r.id = 4;
        r.payload = std::move(p);
        return r;
    };
    using F = TelemetryField;
    QTest::newRow("state2 iq") << make(Command::ReadState2,
                                       protocol::State2{30, 2048, false, -5, 7,
                                                        lk::protocol::kIqReplyAmpsPerLsb})
                               << int(F::Temperature | F::IqA | F::Speed | F::Encoder);
    QTest::newRow("state2 power (MS)")
        << make(Command::Speed,
                protocol::State2{30, -500, true, 5, 7, lk::protocol::kIqReplyAmpsPerLsb})
        << int(F::Temperature | F::Power | F::Speed | F::Encoder);
    QTest::newRow("state1") << make(Command::ReadState1, protocol::State1{25, 240, 0x08})
                            << int(F::Temperature | F::Voltage | F::ErrorState);
    QTest::newRow("state3") << make(
                                   Command::ReadState3,
                                   protocol::State3{25, 64, 0, -64, lk::protocol::kPhaseAmpsPerLsb})
                            << int(F::Temperature | F::PhaseCurrents);
    QTest::newRow("multi turn") << make(Command::ReadMultiTurn, protocol::MultiTurnAngle{36000})
                                << int(F::MultiTurn);
    QTest::newRow("model: none") << make(Command::ReadModel, protocol::ModelInfo{}) << 0;
    QTest::newRow("ack: none") << make(Command::MotorOff, protocol::Acknowledged{}) << 0;
}

void tst_BusTiming::telemetryFromReply()
{
    QFETCH(protocol::Reply, reply);
    QFETCH(int, fields);
    const std::optional<TelemetrySample> s = TelemetrySample::fromReply(reply, 1.5);
    QCOMPARE(s.has_value(), fields != 0);
    if (!s)
        return;
    QCOMPARE(int(s->fields), fields);
    QCOMPARE(s->id, 4);
    QCOMPARE(s->time, 1.5);
    QCOMPARE(s->source, reply.command);
    if (s->has(TelemetryField::IqA))
        QCOMPARE(s->iqA, 33.0);
    if (s->has(TelemetryField::Power))
        QCOMPARE(s->power, -500);
    if (s->has(TelemetryField::Voltage))
        QCOMPARE(s->voltageV, 24.0);
    if (s->has(TelemetryField::PhaseCurrents))
        QCOMPARE(s->icA, -1.0);
    if (s->has(TelemetryField::MultiTurn))
        QCOMPARE(s->multiTurnDeg, 360.0);
}

QTEST_APPLESS_MAIN(tst_BusTiming)
#include "tst_bustiming.moc"
