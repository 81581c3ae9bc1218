#include <bus/QuietPeriod.h>

#include <QtTest/QTest>

using lk::bus::QuietPeriod;

namespace {
constexpr qint64 kMs = 1'000'000;
} // namespace

/// The half-duplex hold after a timeout, on a clock the test gives: how long nothing is
/// sent, what pushes the end back, and what ends it early.
class tst_QuietPeriod : public QObject {
    Q_OBJECT
private slots:
    void holdsUntilItsEnd();
    void bytesMeanwhilePushTheEndBack();
    void bytesAfterTheEndChangeNothing();
    void theWholeLateReplyEndsIt();
    void aLateReplyFollowedByMoreBytesDoesNot();
    void anotherDrivesFrameDoesNot();
    void theAnswerCountsForItsOwnChunkOnly();
};

void tst_QuietPeriod::holdsUntilItsEnd()
{
    QuietPeriod q;
    QVERIFY(!q.isQuiet(0));
    q.begin(10 * kMs, 5 * kMs, 3, 0x9A);
    QVERIFY(q.isQuiet(9 * kMs));
    QCOMPARE(q.leftNs(9 * kMs), 1 * kMs);
    QVERIFY(!q.isQuiet(10 * kMs));
}

void tst_QuietPeriod::bytesMeanwhilePushTheEndBack()
{
    // Someone is still talking: a full length after the last byte, not after the first.
    QuietPeriod q;
    q.begin(10 * kMs, 5 * kMs, 3, 0x9A);
    q.bytesArrived(8 * kMs);
    QVERIFY(q.isQuiet(12 * kMs));
    QCOMPARE(q.leftNs(12 * kMs), 1 * kMs);
    q.bytesArrived(2 * kMs); // an earlier arrival never shortens it
    QCOMPARE(q.leftNs(12 * kMs), 1 * kMs);
}

void tst_QuietPeriod::bytesAfterTheEndChangeNothing()
{
    QuietPeriod q;
    q.begin(10 * kMs, 5 * kMs, 3, 0x9A);
    q.bytesArrived(11 * kMs);
    QVERIFY(!q.isQuiet(11 * kMs));
}

void tst_QuietPeriod::theWholeLateReplyEndsIt()
{
    QuietPeriod q;
    q.begin(10 * kMs, 5 * kMs, 3, 0x9A);
    q.bytesArrived(4 * kMs);
    q.chunkStarted();
    q.lateFrameParsed(3, 0x9A);
    QVERIFY(q.endIfAnswered(true, 4 * kMs));
    QVERIFY(!q.isQuiet(4 * kMs));             // the wire is free again
    QVERIFY(!q.endIfAnswered(true, 4 * kMs)); // once
}

void tst_QuietPeriod::aLateReplyFollowedByMoreBytesDoesNot()
{
    // Bytes after the reply wait in the parser: someone is still talking.
    QuietPeriod q;
    q.begin(10 * kMs, 5 * kMs, 3, 0x9A);
    q.chunkStarted();
    q.lateFrameParsed(3, 0x9A);
    QVERIFY(!q.endIfAnswered(false, 4 * kMs));
    QVERIFY(q.isQuiet(4 * kMs));
}

void tst_QuietPeriod::anotherDrivesFrameDoesNot()
{
    QuietPeriod q;
    q.begin(10 * kMs, 5 * kMs, 3, 0x9A);
    q.chunkStarted();
    q.lateFrameParsed(4, 0x9A); // another ID
    q.lateFrameParsed(3, 0x9C); // another command
    QVERIFY(!q.endIfAnswered(true, 4 * kMs));
    QVERIFY(q.isQuiet(4 * kMs));
}

void tst_QuietPeriod::theAnswerCountsForItsOwnChunkOnly()
{
    // The reply came, then more bytes: the next chunk, without the reply, ends nothing.
    QuietPeriod q;
    q.begin(10 * kMs, 5 * kMs, 3, 0x9A);
    q.chunkStarted();
    q.lateFrameParsed(3, 0x9A);
    QVERIFY(!q.endIfAnswered(false, 4 * kMs));
    q.chunkStarted();
    QVERIFY(!q.endIfAnswered(true, 5 * kMs));
    QVERIFY(q.isQuiet(5 * kMs));
}

QTEST_GUILESS_MAIN(tst_QuietPeriod)
#include "tst_quietperiod.moc"
