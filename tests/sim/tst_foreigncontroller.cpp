#include "sim/ForeignController.h"

#include "SimTestUtil.h"
#include "protocol/FieldJson.h"
#include "sim/SimBus.h"

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using lk::protocol::Command;
using lk::sim::ControllerSpec;
using lk::sim::ControllerTransaction;
using lk::sim::ForeignController;
using lk::sim::SimBus;
using lk::sim::WireChunk;
using Outcome = ControllerTransaction::Outcome;

namespace {

constexpr int kBaud = 115200;
constexpr double kStartS = 100.0; // the bus clock is not zero when the master starts

std::unique_ptr<SimBus> makeBus(const char *spec)
{
    QString error;
    const auto parsed = sim::SimBusSpec::parse(QString::fromLatin1(spec), &error);
    if (!parsed)
        qFatal("bad test bus: %s", qPrintable(error));
    return SimBus::fromSpec(*parsed);
}

ControllerSpec makeSpec(const char *text)
{
    QString error;
    const std::optional<ControllerSpec> s =
        ControllerSpec::parse(QString::fromLatin1(text), &error);
    if (!s)
        qFatal("bad test spec: %s", qPrintable(error));
    return *s;
}

double wire(int bytes)
{
    return bytes * 10.0 / kBaud;
}

/// A bus, its master and everything the master did, advanced on a clock the test moves.
struct Rig {
    std::unique_ptr<SimBus> bus;
    ForeignController controller;
    QList<WireChunk> chunks;
    QList<ControllerTransaction> done;

    Rig(const char *drives, const char *spec)
        : bus(makeBus(drives)), controller(makeSpec(spec), *bus, kBaud, kStartS)
    {
    }
    double lastS = kStartS;
    /// Advance in 0.1 ms steps (any step gives the same result) up to `s` after the start.
    void runTo(double s)
    {
        for (double t = lastS; t <= kStartS + s + 1e-9; t += 1e-4)
            step(t);
    }
    void step(double t)
    {
        lastS = t;
        chunks += controller.advanceTo(t);
        done += controller.takeFinished();
    }
    QByteArray stream() const
    {
        QByteArray out;
        for (const WireChunk &c : chunks)
            out += c.bytes;
        return out;
    }
};

} // namespace

/// lksim's foreign master on the bus clock: its round, its timing at the baud, what it logs,
/// the faults, and a second master on the same wire.
class tst_ForeignController : public QObject {
    Q_OBJECT
private slots:
    void roundOrderAndRate();
    void wireTiming();
    void rateMaxIsBackToBack();
    void unansweredWaitsTimeout();
    void faultOutcomes_data();
    void faultOutcomes();
    void speedSine();
    void moveEveryPeriodHoldsSpeed();
    void bothGenerations();
    void tapStreamPairsWithLog();
    void stepSizeDoesNotMatter();
    void jsonLine();
    void secondMasterOverRequest();
    void secondMasterOverReply();
    void secondMasterOnIdleWire();
    void secondMasterInTheGapSpoilsTheNextRequest();
};

void tst_ForeignController::roundOrderAndRate()
{
    Rig r("1:MF,2:MS", "rate=100,poll=9c:9a");
    r.runTo(0.0795);
    QCOMPARE(r.done.size(), 8);
    const QList<QPair<int, Command>> expected{{1, Command::ReadState2}, {1, Command::ReadState1},
                                              {2, Command::ReadState2}, {2, Command::ReadState1},
                                              {1, Command::ReadState2}, {1, Command::ReadState1},
                                              {2, Command::ReadState2}, {2, Command::ReadState1}};
    for (int i = 0; i < r.done.size(); ++i) {
        QCOMPARE(r.done[i].request.id, expected[i].first);
        QCOMPARE(r.done[i].request.command, expected[i].second);
        QCOMPARE(r.done[i].outcome, Outcome::Answered);
        QVERIFY(std::abs(r.done[i].requestS - i * 0.01) < 1e-9); // 100 requests a second
    }
}

void tst_ForeignController::wireTiming()
{
    Rig r("1:MF", "rate=10");
    r.bus->setReplyDelay(0.0003);
    r.step(kStartS);
    QVERIFY(r.chunks.isEmpty()); // the request is still on the wire
    QCOMPARE(r.controller.nextEventS(), kStartS + wire(5));
    r.step(kStartS + wire(5));
    QCOMPARE(r.chunks.size(), 1);
    QCOMPARE(test::spaced(r.chunks[0].bytes), QStringLiteral("3E 9C 01 00 DB"));
    const double replyEnd = kStartS + wire(5) + 0.0003 + wire(13);
    QCOMPARE(r.controller.nextEventS(), replyEnd);
    r.step(replyEnd - 1e-7);
    QCOMPARE(r.chunks.size(), 1);
    r.step(replyEnd);
    QCOMPARE(r.chunks.size(), 2);
    QCOMPARE(r.chunks[1].atS, replyEnd);
    QCOMPARE(r.chunks[1].bytes.size(), 13);
    QCOMPARE(r.done.size(), 1);
    QCOMPARE(r.done[0].requestS, 0.0);
    QVERIFY(std::abs(r.done[0].replyEndS - (replyEnd - kStartS)) < 1e-12);
    QCOMPARE(r.controller.nextEventS(), kStartS + 0.1); // 10 requests a second
}

void tst_ForeignController::rateMaxIsBackToBack()
{
    Rig r("1:MF", "rate=max");
    r.runTo(0.05);
    QVERIFY(r.done.size() > 20);
    for (int i = 1; i < r.done.size(); ++i)
        QVERIFY(std::abs(r.done[i].requestS -
                         (r.done[i - 1].replyEndS + ForeignController::kTurnaroundS)) < 1e-9);
}

void tst_ForeignController::unansweredWaitsTimeout()
{
    Rig r("1:MF", "rate=max,ids=1:5,timeout=2ms");
    r.runTo(0.01);
    QVERIFY(r.done.size() >= 3);
    QCOMPARE(r.done[1].request.id, 5);
    QCOMPARE(r.done[1].outcome, Outcome::Unanswered);
    QCOMPARE(r.done[1].replyEndS, -1.0);
    QVERIFY(!r.done[1].reply);
    QVERIFY(std::abs(r.done[2].requestS -
                     (r.done[1].requestEndS + 0.002 + ForeignController::kTurnaroundS)) < 1e-9);
}

void tst_ForeignController::faultOutcomes_data()
{
    QTest::addColumn<QString>("faults");
    QTest::addColumn<int>("outcome");
    QTest::addColumn<bool>("replyBytes");
    QTest::newRow("drop") << "drop_next=1" << int(Outcome::Dropped) << false;
    QTest::newRow("corrupt") << "corrupt_next=1" << int(Outcome::Garbled) << true;
    QTest::newRow("length") << "length_next=1" << int(Outcome::Garbled) << true;
    QTest::newRow("garbage") << "garbage_next=1" << int(Outcome::Answered) << true;
    QTest::newRow("delay") << "delay_next=1,delay_ms=20" << int(Outcome::Answered) << true;
    QTest::newRow("silent") << "silent=1" << int(Outcome::Unanswered) << false;
}

void tst_ForeignController::faultOutcomes()
{
    QFETCH(QString, faults);
    QFETCH(int, outcome);
    QFETCH(bool, replyBytes);
    Rig r("1:MF", "rate=100,poll=9a");
    QVERIFY(r.bus->faults().configure(faults));
    r.runTo(0.045);
    QVERIFY(r.done.size() >= 3);
    QCOMPARE(int(r.done[0].outcome), outcome);
    QCOMPARE(!r.done[0].replyBytes.isEmpty(), replyBytes);
    QCOMPARE(r.done[0].reply.has_value(), outcome == int(Outcome::Answered));
    if (faults.startsWith(QLatin1String("garbage")))
        QVERIFY(r.done[0].noiseBytes > 0);
    if (faults.startsWith(QLatin1String("delay")))
        QVERIFY(r.done[0].replyEndS > 0.02); // the master waited for the late reply
    if (!faults.startsWith(QLatin1String("silent")))
        QCOMPARE(r.done[1].outcome, Outcome::Answered); // one fault only
}

void tst_ForeignController::speedSine()
{
    Rig r("1:MF,2:MG", "rate=200,poll=9c,speed=sine:300dps:0.5Hz");
    r.runTo(0.5);
    // The drives follow: drive 1 runs forward at the sine's crest.
    QVERIFY(r.bus->drive(1)->speedDps() > 200);
    r.runTo(1.0);
    int speeds = 0;
    for (const ControllerTransaction &t : r.done) {
        if (t.request.command != Command::Speed)
            continue;
        ++speeds;
        const auto &cmd = std::get<protocol::SpeedCommand>(t.request.payload);
        const double expected = 300 * std::sin(2 * M_PI * 0.5 * t.requestS);
        QVERIFY2(std::abs(cmd.speedDps() - expected) <= 0.005 + 1e-9,
                 qPrintable(QStringLiteral("%1 at %2").arg(cmd.speedDps()).arg(t.requestS)));
        QCOMPARE(t.outcome, Outcome::Answered);
    }
    QCOMPARE(speeds, 100); // half of the 200 requests a second
}

void tst_ForeignController::moveEveryPeriodHoldsSpeed()
{
    Rig r("1:MF", "rate=100,poll=9c,speed=sine:50dps:1Hz,move=every:1s:90deg:300dps");
    r.runTo(2.6);
    QList<double> moves;
    QList<double> moveSteps;
    for (const ControllerTransaction &t : r.done) {
        if (t.request.command == Command::IncrementPositionLimited) {
            moves.append(t.requestS);
            const auto &m = std::get<protocol::IncrementPositionCommand>(t.request.payload);
            moveSteps.append(m.angleRaw * 0.01);
            QCOMPARE(m.maxSpeedRaw, std::optional<quint32>(30000));
        }
    }
    QCOMPARE(moves.size(), 2);
    QCOMPARE(moveSteps, (QList<double>{90, -90}));
    QVERIFY(moves[0] >= 1.0 && moves[0] < 1.02);
    QVERIFY(moves[1] >= 2.0 && moves[1] < 2.02);
    // No speed setpoint while the move runs: 90 deg at 300 dps plus the settle time.
    for (const ControllerTransaction &t : r.done) {
        if (t.request.command == Command::Speed)
            QVERIFY(t.requestS < moves[0] || t.requestS >= moves[0] + 0.3 + 0.1);
    }
}

void tst_ForeignController::bothGenerations()
{
    Rig r("1:MS4015@2.35,2:MF", "rate=max,poll=9a:12");
    r.runTo(0.05);
    bool seenNew = false;
    bool seenOld = false;
    for (const ControllerTransaction &t : r.done) {
        QCOMPARE(t.outcome, Outcome::Answered);
        const QJsonObject reply = protocol::FieldJson::replyFields(*t.reply);
        if (t.request.command != Command::ReadState1)
            continue;
        if (t.request.id == 1) {
            seenNew = true;
            QCOMPARE(t.context.generation, protocol::Generation::V2_35);
            QVERIFY(reply.contains(QStringLiteral("motor_on")));
        } else {
            seenOld = true;
            QVERIFY(!reply.contains(QStringLiteral("motor_on")));
        }
    }
    QVERIFY(seenNew && seenOld);
}

void tst_ForeignController::tapStreamPairsWithLog()
{
    Rig r("1:MF,2:MS,3:MG@2.35", "rate=max,ids=1-4,poll=9c:9a:92,speed=sine:300dps:2Hz");
    QVERIFY(
        r.bus->faults().configure(QStringLiteral("drop=0.05,garbage=0.05,corrupt=0.02,seed=7")));
    r.runTo(0.5);
    QVERIFY(r.done.size() > 100);
    // The stream is each request followed by its reply bytes (if any), in log order.
    QByteArray expected;
    for (const ControllerTransaction &t : r.done)
        expected += t.request.encode() + t.replyBytes;
    QVERIFY(r.stream().startsWith(expected));
    QSet<int> outcomes;
    for (const ControllerTransaction &t : r.done)
        outcomes.insert(int(t.outcome));
    QVERIFY(outcomes.contains(int(Outcome::Dropped)));
    QVERIFY(outcomes.contains(int(Outcome::Garbled)));
    QVERIFY(outcomes.contains(int(Outcome::Unanswered))); // ID 4 is not on the bus
    QVERIFY(outcomes.contains(int(Outcome::Answered)));
}

void tst_ForeignController::stepSizeDoesNotMatter()
{
    Rig fine("1:MF,2:MS", "rate=500,poll=9c:92");
    Rig coarse("1:MF,2:MS", "rate=500,poll=9c:92");
    fine.runTo(0.2);
    for (double t = kStartS; t <= kStartS + 0.2; t += 0.037)
        coarse.step(t);
    coarse.step(kStartS + 0.2 + 1e-9);
    QCOMPARE(coarse.stream(), fine.stream());
    QCOMPARE(coarse.done.size(), fine.done.size());
}

void tst_ForeignController::jsonLine()
{
    Rig r("1:MF", "rate=100,poll=none,speed=sine:100dps:0.25Hz");
    r.runTo(1.005);
    QCOMPARE(r.done.size(), 101);
    const ControllerTransaction &t = r.done[100];
    const QByteArray line = t.toJsonLine();
    // At 1 s the sine is at its crest; the reply ends after the 10-byte request (0.868 ms),
    // the 0.2 ms turnaround and the 13-byte reply (1.128 ms).
    QVERIFY2(line.startsWith("{\"time_s\":1.0,\"id\":1,\"command\":\"speed\",\"code\":\"0xA2\","
                             "\"request\":{\"speed_dps\":100.0,\"speed_raw\":10000},"
                             "\"outcome\":\"answered\",\"reply_s\":1.002197,"),
             line.constData());
    const QJsonObject o = QJsonDocument::fromJson(line).object();
    QCOMPARE(o.value(QStringLiteral("reply")).toObject(),
             protocol::FieldJson::replyFields(*t.reply));
    ControllerTransaction dropped = t;
    dropped.outcome = Outcome::Dropped;
    dropped.reply.reset();
    dropped.replyEndS = -1;
    QVERIFY(
        !QJsonDocument::fromJson(dropped.toJsonLine()).object().contains(QStringLiteral("reply")));
    QVERIFY(dropped.toJsonLine().contains("\"outcome\":\"dropped\""));
}

void tst_ForeignController::secondMasterOverRequest()
{
    Rig r("1:MF", "rate=10");
    r.step(kStartS + wire(5) / 2); // the controller's request is on the wire
    const QByteArray tool = protocol::build::plain(Command::MotorOff, 1).request->encode();
    const ForeignController::SecondMaster m =
        r.controller.secondMaster(tool, kStartS + wire(5) / 2);
    QVERIFY(m.collided);
    QVERIFY(!m.duringReply);
    QVERIFY2(m.what.contains(QLatin1String("read_state2 request")), qPrintable(m.what));
    r.runTo(0.05);
    QCOMPARE(r.done.size(), 1);
    QCOMPARE(r.done[0].outcome, Outcome::Collided);
    QCOMPARE(r.bus->counters().requests, 0); // neither request reached the drive
}

void tst_ForeignController::secondMasterOverReply()
{
    Rig r("1:MF", "rate=10");
    const double inReply = kStartS + wire(5) + r.bus->replyDelay() + wire(13) / 2;
    r.step(inReply);
    const QByteArray tool = protocol::build::plain(Command::ReadState2, 1).request->encode();
    const ForeignController::SecondMaster m = r.controller.secondMaster(tool, inReply);
    QVERIFY(m.collided);
    QVERIFY(m.duringReply);
    r.runTo(0.05);
    QCOMPARE(r.done.size(), 1);
    QCOMPARE(r.done[0].outcome, Outcome::Collided);
    QVERIFY(!r.done[0].reply);
    QCOMPARE(r.bus->counters().requests, 1); // the drive got the controller's request only
}

void tst_ForeignController::secondMasterOnIdleWire()
{
    Rig r("1:MF,2:MF", "rate=10,ids=1");
    const double idle = kStartS + 0.05;
    r.step(idle);
    const int before = r.chunks.size();
    const QByteArray tool = protocol::build::plain(Command::ReadState1, 2).request->encode();
    const ForeignController::SecondMaster m = r.controller.secondMaster(tool, idle);
    QVERIFY2(!m.collided, qPrintable(m.what));
    r.step(idle + 0.002);
    QCOMPARE(r.chunks.size(), before + 1); // drive 2's reply to the tool, on the wire
    QCOMPARE(r.chunks.last().bytes.at(1), char(0x9A));
    QCOMPARE(r.chunks.last().bytes.at(2), char(2));
    QCOMPARE(r.bus->requestCount(2, Command::ReadState1), 1);
}

void tst_ForeignController::secondMasterInTheGapSpoilsTheNextRequest()
{
    Rig r("1:MF", "rate=max");
    const double replyEnd = kStartS + wire(5) + r.bus->replyDelay() + wire(13);
    const double inGap = replyEnd + ForeignController::kTurnaroundS / 2;
    r.step(inGap); // the first transaction is done, the next request not yet sent
    QCOMPARE(r.done.size(), 1);
    const QByteArray tool = protocol::build::plain(Command::ReadState1, 2).request->encode();
    QVERIFY(!r.controller.secondMaster(tool, inGap).collided);
    for (double t = inGap; r.done.size() < 2 && t < kStartS + 1; t += 1e-4)
        r.step(t);
    // The controller's next request began while the tool's frame was on the wire: lost, the
    // drive never got it; the tool's request reached drive 2.
    QCOMPARE(r.done[1].outcome, Outcome::Collided);
    QCOMPARE(r.bus->requestCount(1, Command::ReadState2), 1);
    QCOMPARE(r.bus->requestCount(2, Command::ReadState1), 1);
    r.runTo(0.02);
    QCOMPARE(r.done[2].outcome, Outcome::Answered);
}

QTEST_GUILESS_MAIN(tst_ForeignController)
#include "tst_foreigncontroller.moc"
