#include "WireMonitor.h"

#include <QtTest/QTest>

using lk::app::WireMonitor;

/// lksim's half-duplex judge: which host requests collide with a drive's reply, and which
/// overlap it only because lksim may have read the asking request late.
class tst_WireMonitor : public QObject {
    Q_OBJECT
private slots:
    void requestDuringReplyCollides();
    void requestBeforeReplyCollides();
    void requestAfterReplyIsClear();
    void overlapWithinLatenessIsUnjudged();
    void overlapBeyondLatenessStillCollides();
    void longestRequestGap();
};

void tst_WireMonitor::requestDuringReplyCollides()
{
    WireMonitor wire;
    wire.replyScheduled(1.000, 1.0005, 3, 0x80);
    const auto c = wire.overlapAt(1.0002);
    QVERIFY(c);
    QVERIFY(!c->beforeReply);
    QVERIFY(!c->unjudged);
    QCOMPARE(c->id, 3);
    wire.requestEnded(c, 1.0);
    QCOMPARE(wire.counters().collisionsDuring, 1);
    QCOMPARE(wire.counters().collisions(), 1);
    QCOMPARE(wire.counters().overlapsUnjudged, 0);
    QVERIFY(c->describe().contains(QStringLiteral("into ID 3's reply")));
}

void tst_WireMonitor::requestBeforeReplyCollides()
{
    WireMonitor wire;
    wire.replyScheduled(1.000, 1.0005, 3, 0x80);
    const auto c = wire.overlapAt(0.9995);
    QVERIFY(c);
    QVERIFY(c->beforeReply);
    wire.requestEnded(c, 1.0);
    QCOMPARE(wire.counters().collisionsBefore, 1);
}

void tst_WireMonitor::requestAfterReplyIsClear()
{
    WireMonitor wire;
    wire.replyScheduled(1.000, 1.0005, 3, 0x80, 0.01);
    QVERIFY(!wire.overlapAt(1.0005));
    wire.requestEnded(std::nullopt, 1.0);
    QCOMPARE(wire.counters().requests, 1);
    QCOMPARE(wire.counters().collisions(), 0);
}

void tst_WireMonitor::overlapWithinLatenessIsUnjudged()
{
    // lksim read the request up to 2 ms late: had it come that early, the reply would have
    // ended at 0.9985, before this request; a drive may well have been silent by then.
    WireMonitor wire;
    wire.replyScheduled(1.000, 1.0005, 3, 0x80, 0.002);
    const auto c = wire.overlapAt(1.0002);
    QVERIFY(c);
    QVERIFY(c->unjudged);
    wire.requestEnded(c, 1.0);
    QCOMPARE(wire.counters().collisions(), 0);
    QCOMPARE(wire.counters().overlapsUnjudged, 1);
    QVERIFY(c->describe().contains(QStringLiteral("up to 2.000 ms late")));
}

void tst_WireMonitor::overlapBeyondLatenessStillCollides()
{
    // Read at most 0.1 ms late: the reply ends no sooner than 1.0004, after this request came.
    WireMonitor wire;
    wire.replyScheduled(1.000, 1.0005, 3, 0x80, 0.0001);
    const auto c = wire.overlapAt(1.0002);
    QVERIFY(c);
    QVERIFY(!c->unjudged);
    wire.requestEnded(c, 1.0);
    QCOMPARE(wire.counters().collisions(), 1);
    QCOMPARE(wire.counters().overlapsUnjudged, 0);
}

void tst_WireMonitor::longestRequestGap()
{
    WireMonitor wire;
    wire.requestEnded(std::nullopt, 5.0); // the first request: no gap before it counts
    wire.requestEnded(std::nullopt, 5.002);
    wire.requestEnded(std::nullopt, 5.25);
    wire.requestEnded(std::nullopt, 5.3);
    wire.requestEnded(std::nullopt, 5.45);
    QCOMPARE(wire.counters().requests, 5);
    QVERIFY(qAbs(wire.counters().longestRequestGapS - 0.248) < 1e-9);
    QCOMPARE(wire.counters().requestGapsOver100ms, 2);
}

QTEST_GUILESS_MAIN(tst_WireMonitor)
#include "tst_wiremonitor.moc"
