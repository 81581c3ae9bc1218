#include "sim/CanForeignController.h"

#include "SimTestUtil.h"
#include "protocol/CanRecord.h"
#include "sim/SimBus.h"
#include "sim/SimBusSpec.h"
#include "sim/SimCanFront.h"

#include <QtTest/QTest>

#include <cmath>

// lksim's foreign master on CAN: its requests in each drive's CAN layout on 0x140+ID, the
// drives' replies on their own IDs, in bus order; what it logs; CAN's faults (a dropped reply,
// a late one, an error frame instead of a corrupted one); and what CAN cannot carry.

using namespace lk;
using lk::sim::CanForeignController;
using lk::sim::CanWireFrame;
using lk::sim::ControllerSpec;
using lk::sim::ControllerTransaction;
using lk::sim::SimBus;
using Outcome = ControllerTransaction::Outcome;

namespace {

constexpr int kBitRate = 1000000;
constexpr double kStartS = 50.0; // the bus clock is not zero when the master starts

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

/// A CAN bus of simulated drives and its master, advanced on a clock the test moves.
struct Rig {
    std::unique_ptr<SimBus> bus;
    sim::SimCanFront front;
    CanForeignController controller;
    QList<protocol::CanRecord> frames;
    QList<ControllerTransaction> done;
    double lastS = kStartS;

    Rig(const char *drives, const char *spec)
        : bus(makeBus(drives)), front(*bus),
          controller(makeSpec(spec), *bus, front, kBitRate, kStartS)
    {
    }
    /// Advance in 0.1 ms steps up to `s` after the start.
    void runTo(double s)
    {
        for (double t = lastS; t <= kStartS + s + 1e-9; t += 1e-4) {
            lastS = t;
            for (const CanWireFrame &f : controller.advanceTo(t))
                frames.append(*protocol::CanRecord::decode(f.record));
            done += controller.takeFinished();
        }
    }
    int count(quint32 canId, quint8 command) const
    {
        int n = 0;
        for (const protocol::CanRecord &r : frames)
            n += !r.isError() && r.canId == canId && quint8(r.data.at(0)) == command;
        return n;
    }
};

} // namespace

class tst_CanForeignController : public QObject {
    Q_OBJECT
private slots:
    void requestsAndRepliesInBusOrder();
    void logMatchesTheBus();
    void v236SpeedCarriesATorqueLimit();
    void readModelIsNotSentOnCan();
    void faultOutcomes_data();
    void faultOutcomes();
    void lateReplyIsWaitedFor();
};

void tst_CanForeignController::requestsAndRepliesInBusOrder()
{
    // 1: an old CAN MF (replies on 0x141), 2: a V2.36 MG (0x182), 3: absent.
    Rig rig("1:MF@can,2:MG@can236", "rate=2000,ids=1-3,poll=9c:9a,timeout=1ms");
    rig.runTo(0.2);
    QVERIFY(rig.done.size() > 100);
    QVERIFY(rig.count(0x141, 0x9C) >= 2 * 20); // request and reply share 0x141
    QVERIFY(rig.count(0x142, 0x9A) >= 20);
    QVERIFY(rig.count(0x182, 0x9A) >= 20);
    // Every request is followed by its reply before the next request (one at a time), but
    // for drive 3, which never answers.
    qsizetype i = 0;
    for (const ControllerTransaction &t : rig.done) {
        QVERIFY(i < rig.frames.size());
        const protocol::CanRecord &req = rig.frames[i++];
        QCOMPARE(req.canId, 0x140u + t.request.id);
        QCOMPARE(quint8(req.data.at(0)), quint8(t.request.command));
        if (t.request.id == 3) {
            QCOMPARE(t.outcome, Outcome::Unanswered);
            continue;
        }
        QCOMPARE(t.outcome, Outcome::Answered);
        QVERIFY(i < rig.frames.size());
        const protocol::CanRecord &rep = rig.frames[i++];
        QCOMPARE(rep.canId, (t.request.id == 1 ? 0x140u : 0x180u) + t.request.id);
        QCOMPARE(rep.encode(), t.replyBytes);
        QVERIFY(t.replyEndS > t.requestEndS);
    }
}

void tst_CanForeignController::logMatchesTheBus()
{
    Rig rig("1:MF@can", "rate=500,poll=9c,speed=sine:200dps:1Hz");
    rig.runTo(0.1);
    QVERIFY(rig.done.size() >= 40);
    int speeds = 0;
    for (const ControllerTransaction &t : rig.done) {
        QCOMPARE(t.outcome, Outcome::Answered);
        QVERIFY(t.reply.has_value());
        QCOMPARE(t.reply->command, t.request.command);
        if (t.request.command != protocol::Command::Speed)
            continue;
        ++speeds;
        // The speed setpoint at the request's time, at the wire's 0.01 dps.
        const double want = 200.0 * std::sin(2 * M_PI * 1.0 * t.requestS);
        const auto &cmd = std::get<protocol::SpeedCommand>(t.request.payload);
        QVERIFY(std::abs(cmd.speedRaw * 0.01 - want) <= 0.01);
        QVERIFY(t.toJsonLine().contains("\"outcome\":\"answered\""));
    }
    QVERIFY(speeds >= 20);
}

void tst_CanForeignController::v236SpeedCarriesATorqueLimit()
{
    Rig rig("2:MG@can236", "rate=500,poll=none,speed=sine:100dps:1Hz");
    rig.runTo(0.02);
    QVERIFY(!rig.frames.isEmpty());
    const protocol::CanRecord &req = rig.frames.first();
    QCOMPARE(req.canId, 0x142u);
    QCOMPARE(quint8(req.data.at(0)), quint8(0xA2));
    QCOMPARE(quint8(req.data.at(2)) | quint8(req.data.at(3)) << 8,
             int(protocol::can::kSpeedIqLimitMax));
    QCOMPARE(rig.done.first().outcome, Outcome::Answered);
}

void tst_CanForeignController::readModelIsNotSentOnCan()
{
    Rig rig("1:MF@can", "rate=1000,poll=12:9c");
    rig.runTo(0.05);
    QCOMPARE(rig.count(0x141, 0x12), 0);
    QVERIFY(rig.count(0x141, 0x9C) >= 20);
    for (const ControllerTransaction &t : rig.done)
        QCOMPARE(t.request.command, protocol::Command::ReadState2);
}

void tst_CanForeignController::faultOutcomes_data()
{
    QTest::addColumn<QString>("faults");
    QTest::addColumn<int>("outcome");
    QTest::addColumn<bool>("errorFrame");
    QTest::newRow("drop") << "drop=1" << int(Outcome::Dropped) << false;
    QTest::newRow("corrupt") << "corrupt=1" << int(Outcome::Garbled) << true;
    QTest::newRow("garbage") << "garbage=1" << int(Outcome::Garbled) << true;
    QTest::newRow("length") << "length=1" << int(Outcome::Garbled) << true;
    QTest::newRow("silent") << "silent=1" << int(Outcome::Unanswered) << false;
}

void tst_CanForeignController::faultOutcomes()
{
    QFETCH(QString, faults);
    QFETCH(int, outcome);
    QFETCH(bool, errorFrame);
    Rig rig("1:MF@can", "rate=1000,poll=9c,timeout=2ms");
    QString error;
    QVERIFY2(rig.bus->faults().configure(faults, &error), qPrintable(error));
    rig.runTo(0.03);
    QVERIFY(rig.done.size() >= 5);
    int errors = 0, replies = 0;
    for (const protocol::CanRecord &r : rig.frames) {
        errors += r.isError();
        replies += !r.isError() && r.data != QByteArray::fromHex("9C00000000000000");
    }
    QCOMPARE(replies, 0); // no reply reached the bus
    for (const ControllerTransaction &t : rig.done) {
        QCOMPARE(int(t.outcome), outcome);
        QVERIFY(!t.reply);
    }
    QCOMPARE(errors > 0, errorFrame);
    QCOMPARE(rig.controller.errorFrames(), qint64(errors));
    if (errorFrame)
        QVERIFY(errors >= rig.done.size());
}

void tst_CanForeignController::lateReplyIsWaitedFor()
{
    // Every reply 20 ms late, the timeout 5 ms: the master still waits for it.
    Rig rig("1:MF@can", "rate=1000,poll=9c");
    QString error;
    QVERIFY2(rig.bus->faults().configure(QStringLiteral("delay=1,delay_ms=20"), &error),
             qPrintable(error));
    rig.runTo(0.2);
    QVERIFY(rig.done.size() >= 5);
    for (qsizetype i = 0; i < rig.done.size(); ++i) {
        const ControllerTransaction &t = rig.done[i];
        QCOMPARE(t.outcome, Outcome::Answered);
        QVERIFY(t.replyEndS - t.requestEndS >= 0.020);
        if (i > 0)
            QVERIFY(t.requestS > rig.done[i - 1].replyEndS);
    }
}

QTEST_APPLESS_MAIN(tst_CanForeignController)
#include "tst_canforeigncontroller.moc"
