// StreamParser's frames keep their chunk's bytes, shared, only when the chunk is exactly one
// frame in an allocation of its own size (a replay's records): never a read buffer's reserve.
#include "protocol/StreamParser.h"

#include "ProtocolTestUtil.h"
#include "StreamTestUtil.h"

#include <QtTest/QTest>

namespace proto = lk::protocol;
using lk::protocol::ParseEvent;

using lk::test::kState2;

class tst_StreamParserChunks : public QObject {
    Q_OBJECT
private slots:
    void oneFrameChunkIsSharedOnlyWhenItHoldsNoMore();
};

void tst_StreamParserChunks::oneFrameChunkIsSharedOnlyWhenItHoldsNoMore()
{
    const QByteArray wire = lk::test::hex(kState2);
    QVector<ParseEvent> events;
    const auto keep = [&events](const ParseEvent &e) { events.append(e); };
    proto::StreamParser parser;
    // A chunk of exactly the frame (a replay's record): the frame's bytes are that chunk.
    const QByteArray exact(wire.constData(), wire.size());
    parser.feed(exact, keep);
    QCOMPARE(events.size(), 1);
    QVERIFY(events[0].isFrame);
    QVERIFY(events[0].bytes.constData() == exact.constData()); // the same bytes, not a copy
    // A chunk whose allocation is a read buffer: copied, so the event keeps no 4 KiB.
    QByteArray reserved;
    reserved.reserve(4096);
    reserved.append(wire);
    parser.feed(reserved, keep);
    QCOMPARE(events.size(), 2);
    QVERIFY(events[1].bytes.constData() != reserved.constData());
    QVERIFY2(events[1].bytes.capacity() < 256,
             qPrintable(QString::number(events[1].bytes.capacity())));
    // Behind a partial frame, or two frames in one chunk: copied, and equal all the same.
    const QByteArray two = wire + wire;
    parser.feed(two, keep);
    QCOMPARE(events.size(), 4);
    QCOMPARE(events[2].bytes, wire);
    QCOMPARE(events[3].bytes, wire);
    QVERIFY(events[2].bytes.constData() != two.constData());
    parser.feed(wire.left(3), keep);
    const QByteArray rest = wire.mid(3) + wire;
    parser.feed(QByteArray(rest.constData(), rest.size()), keep);
    QCOMPARE(events.size(), 6);
    QCOMPARE(events[4].bytes, wire);
    QCOMPARE(events[5].bytes, wire);
    // Bytes the caller owns (fromRawData): copied, so the event outlives them.
    const QByteArray raw = QByteArray::fromRawData(wire.constData(), wire.size());
    parser.feed(raw, keep);
    QCOMPARE(events.size(), 7);
    QCOMPARE(events[6].bytes, wire);
    QVERIFY(events[6].bytes.constData() != wire.constData());
}

QTEST_APPLESS_MAIN(tst_StreamParserChunks)
#include "tst_streamparserchunks.moc"
