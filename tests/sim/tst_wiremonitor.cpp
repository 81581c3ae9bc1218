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
    void requestReadWithTheAskingOneIsUnjudged();
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
    wire.replyScheduled(1.000, 1.0005, 3, 0x80, 0.0001, 0.9995);
    const auto c = wire.overlapAt(1.0002);
    QVERIFY(c);
    QVERIFY(!c->unjudged);
    // The log says what it was judged on: the requests 0.7 ms apart, the first read late by
    // at most 0.1 ms.
    QVERIFY2(c->describe().contains(QStringLiteral("0.700 ms before this one, at most 0.100 ms")),
             qPrintable(c->describe()));
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

void tst_WireMonitor::requestReadWithTheAskingOneIsUnjudged()
{
    // Both requests came out of one read at 1.000: the first may have waited in the kernel
    // for as long as the host waited for its reply.
    WireMonitor wire;
    wire.replyScheduled(1.0006, 1.0017, 32, 0x80, 0, 1.000);
    const auto c = wire.overlapAt(1.000);
    QVERIFY(c);
    QVERIFY(c->sameRead);
    QVERIFY(c->unjudged);
    wire.requestEnded(c, 1.0);
    QCOMPARE(wire.counters().collisions(), 0);
    QCOMPARE(wire.counters().overlapsUnjudged, 1);
    QVERIFY(c->describe().contains(QStringLiteral("same read as ID 32's request")));
    // Read a moment apart, the same overlap is judged.
    WireMonitor apart;
    apart.replyScheduled(1.0006, 1.0017, 32, 0x80, 0, 1.000);
    const auto d = apart.overlapAt(1.0001);
    QVERIFY(d && !d->unjudged && !d->sameRead);
}

QTEST_GUILESS_MAIN(tst_WireMonitor)
#include "tst_wiremonitor.moc"
