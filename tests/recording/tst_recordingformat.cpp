// The recording format (docs/RECORDING.md): every record kind round-trips; a truncated file
// opens up to its last whole block and names the offset; a damaged byte is found by the
// block's CRC; other versions and other files are refused by name.
#include "RecordingTestUtil.h"

#include <recording/Crc32.h>
#include <recording/RecordTags.h>
#include <recording/RecordedFrameParser.h>
#include <recording/ReplayTransport.h>
#include <recording/Varint.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

#include <tuple>

using namespace lk::recording;
namespace protocol = lk::protocol;
using lk::testsupport::readAll;
using lk::testsupport::testHeader;
using lk::testsupport::writeFile;

namespace {

QVector<RecordEvent> sampleRecords()
{
    QVector<RecordEvent> r;
    RecordEvent open;
    open.kind = RecordEvent::Kind::Link;
    open.link = LinkEventKind::Opened;
    open.baud = 115200;
    open.text = QStringLiteral("/dev/ttyTEST @ 115200 \u00b5");
    r.append(open);
    r.append(RecordEvent::data(RecordEvent::Kind::Tx, 1000, QByteArray::fromHex("3e9c0100db")));
    r.append(RecordEvent::data(RecordEvent::Kind::Rx, 251'337,
                               QByteArray::fromHex("3e9c0107e21ff40168010030ad")));
    r.append(RecordEvent::data(RecordEvent::Kind::Rx, 251'337, QByteArray(200, '\x55')));
    RecordEvent ctx;
    ctx.kind = RecordEvent::Kind::Context;
    ctx.timeNs = 5'000'000'000;
    ctx.context = {{1, protocol::Series::MS, protocol::Generation::V2_35},
                   {7, std::nullopt, protocol::Generation::V2_3}};
    r.append(ctx);
    RecordEvent dropped;
    dropped.kind = RecordEvent::Kind::Dropped;
    dropped.timeNs = 6'000'000'000;
    dropped.droppedBytes = 123456;
    dropped.droppedChunks = 789;
    r.append(dropped);
    RecordEvent err;
    err.kind = RecordEvent::Kind::Link;
    err.timeNs = 7'000'000'001;
    err.link = LinkEventKind::Disconnected;
    err.text = QStringLiteral("unplugged");
    r.append(err);
    return r;
}

void compareEvents(const RecordEvent &a, const RecordEvent &b)
{
    QCOMPARE(int(a.kind), int(b.kind));
    QCOMPARE(a.timeNs, b.timeNs);
    QCOMPARE(a.bytes, b.bytes);
    if (a.kind == RecordEvent::Kind::Link) {
        QCOMPARE(int(a.link), int(b.link));
        QCOMPARE(a.baud, b.baud);
        QCOMPARE(a.text, b.text);
    }
    QVERIFY(a.context == b.context);
    QCOMPARE(a.droppedBytes, b.droppedBytes);
    QCOMPARE(a.droppedChunks, b.droppedChunks);
}

/// Header plus the sample records in blocks of three records each.
QByteArray sampleFile(QVector<qsizetype> *blockEnds = nullptr)
{
    QByteArray file = RecordEncoder::encodeHeader(testHeader());
    RecordEncoder enc;
    const auto records = sampleRecords();
    for (int i = 0; i < records.size(); ++i) {
        enc.append(records.at(i));
        if (i % 3 == 2 || i + 1 == records.size()) {
            file += enc.takeBlock();
            if (blockEnds)
                blockEnds->append(file.size());
        }
    }
    return file;
}

/// The records `events` read back as, through an encoder's block.
QVector<RecordEvent> roundTrip(const QVector<RecordEvent> &events)
{
    RecordEncoder enc;
    for (const RecordEvent &e : events)
        enc.append(e);
    RecordingReader reader;
    QVector<RecordEvent> out;
    if (!reader.openBytes(RecordEncoder::encodeHeader(testHeader()) + enc.takeBlock()))
        return out;
    RecordEvent e;
    while (reader.next(&e))
        out.append(e);
    return out;
}

/// Every frame and fault of `events` with its time and direction, as a reader decodes them.
QStringList framesOf(const QVector<RecordEvent> &events)
{
    RecordedFrameParser parser(testHeader().context);
    QStringList out;
    const auto sink = [&out](const RecordedFrame &f) {
        out.append(QStringLiteral("%1 %2 %3 %4")
                       .arg(f.timeNs)
                       .arg(f.transmitted ? QLatin1String("tx") : QLatin1String("rx"))
                       .arg(f.event.isFrame ? QLatin1String("frame") : QLatin1String("fault"))
                       .arg(QString::fromLatin1(f.event.bytes.toHex())));
    };
    for (const RecordEvent &e : events)
        parser.feed(e, sink);
    parser.finish(sink);
    return out;
}

const QByteArray kRequest = QByteArray::fromHex("3e9c0100db");
const QByteArray kReply = QByteArray::fromHex("3e9c0107e21ff40168010030ad");

RecordEvent rx(qint64 timeNs, const QByteArray &bytes)
{
    return RecordEvent::data(RecordEvent::Kind::Rx, timeNs, bytes);
}

/// A version 1 block written by hand, one data record per chunk as the encoder wrote them
/// before it merged split frames: (tx?, delta, bytes) each.
QByteArray handWrittenBlock(qint64 baseNs, const QVector<std::tuple<bool, qint64, QByteArray>> &rs)
{
    QByteArray payload;
    for (const auto &[tx, delta, bytes] : rs) {
        payload.append(char((tx ? tags::kTxBit : 0) | quint8(bytes.size())));
        varint::put(payload, quint64(delta));
        payload.append(bytes);
    }
    QByteArray block(kBlockSync, sizeof kBlockSync);
    varint::putFixed<quint32>(block, quint32(payload.size()));
    varint::putFixed<qint64>(block, baseNs);
    const quint32 crc =
        crc32(payload.constData(), payload.size(), crc32(block.constData() + 4, 12));
    varint::putFixed<quint32>(block, crc);
    return block + payload;
}

} // namespace

class tst_RecordingFormat : public QObject {
    Q_OBJECT
private slots:
    void crc32MatchesTheCheckValue()
    {
        // The published check value of CRC-32/ISO-HDLC.
        QCOMPARE(crc32("123456789", 9), 0xCBF43926u);
    }

    void crc32EightAtATimeMatchesTheBitwiseDefinition()
    {
        // The table-sliced crc32 against the polynomial itself, bit by bit: every length from
        // 0 to 70 at every alignment, and each split into two continued calls.
        const auto bitwise = [](const QByteArray &data) {
            quint32 crc = ~0u;
            for (const char c : data) {
                crc ^= quint8(c);
                for (int k = 0; k < 8; ++k)
                    crc = (crc & 1) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
            }
            return ~crc;
        };
        QByteArray buffer;
        quint32 seed = 12345;
        for (int i = 0; i < 80; ++i) {
            seed = seed * 1103515245u + 12345u;
            buffer.append(char(seed >> 16));
        }
        for (int offset = 0; offset < 8; ++offset) {
            for (int length = 0; length <= 70; ++length) {
                const QByteArray data = buffer.mid(offset, length);
                const quint32 expected = bitwise(data);
                QCOMPARE(crc32(data.constData(), data.size()), expected);
                const int half = length / 3;
                QCOMPARE(
                    crc32(data.constData() + half, length - half, crc32(data.constData(), half)),
                    expected);
            }
        }
    }

    void everyRecordKindRoundTrips()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.lkrec"));
        QVERIFY(writeFile(path, sampleFile()));
        RecordingError error;
        RecordingHeader header;
        const auto got = readAll(path, &error, &header);
        QCOMPARE(int(error.kind), int(RecordingError::Kind::None));
        QCOMPARE(header.toolVersion, testHeader().toolVersion);
        QCOMPARE(header.linkDescription, testHeader().linkDescription);
        QCOMPARE(header.baud, 115200);
        QCOMPARE(header.wallClockStartMs, testHeader().wallClockStartMs);
        QVERIFY(header.context == testHeader().context);
        const auto want = sampleRecords();
        QCOMPARE(got.size(), want.size());
        for (int i = 0; i < want.size(); ++i)
            compareEvents(got.at(i), want.at(i));
    }

    void truncatedFileOpensToTheLastWholeBlock_data()
    {
        QTest::addColumn<int>("cut");
        QTest::addColumn<int>("records");
        QTest::addColumn<int>("errorOffset");
        QVector<qsizetype> ends;
        const QByteArray file = sampleFile(&ends);
        const int header = int(RecordEncoder::encodeHeader(testHeader()).size());
        QTest::newRow("after the header") << header << 0 << -1;
        QTest::newRow("one byte into block 1") << header + 1 << 0 << header;
        QTest::newRow("block 1 whole") << int(ends[0]) << 3 << -1;
        QTest::newRow("inside block 2 header") << int(ends[0]) + 10 << 3 << int(ends[0]);
        QTest::newRow("last byte of block 3 missing") << int(file.size()) - 1 << 6 << int(ends[1]);
    }
    void truncatedFileOpensToTheLastWholeBlock()
    {
        QFETCH(int, cut);
        QFETCH(int, records);
        QFETCH(int, errorOffset);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("cut.lkrec"));
        QVERIFY(writeFile(path, sampleFile().left(cut)));
        RecordingError error;
        const auto got = readAll(path, &error);
        QCOMPARE(got.size(), records);
        if (errorOffset < 0) {
            QCOMPARE(int(error.kind), int(RecordingError::Kind::None));
        } else {
            QCOMPARE(int(error.kind), int(RecordingError::Kind::Truncated));
            QCOMPARE(error.offset, qint64(errorOffset));
            QVERIFY2(error.message.contains(QString::number(errorOffset)),
                     qPrintable(error.message));
        }
    }

    void damagedByteIsFoundAtItsBlock_data()
    {
        QTest::addColumn<int>("flip");
        QTest::addColumn<int>("records");
        QTest::addColumn<int>("errorOffset");
        QVector<qsizetype> ends;
        sampleFile(&ends);
        QTest::newRow("block 2 sync") << int(ends[0]) << 3 << int(ends[0]);
        // A length grown past the end of the file reads as a truncation at the same offset.
        QTest::newRow("block 2 length") << int(ends[0]) + 4 << 3 << int(ends[0]);
        QTest::newRow("block 2 payload") << int(ends[0]) + 25 << 3 << int(ends[0]);
        QTest::newRow("block 3 last byte") << int(ends[2]) - 1 << 6 << int(ends[1]);
    }
    void damagedByteIsFoundAtItsBlock()
    {
        QFETCH(int, flip);
        QFETCH(int, records);
        QFETCH(int, errorOffset);
        QByteArray file = sampleFile();
        file[flip] = char(file[flip] ^ 0x10);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.lkrec"));
        QVERIFY(writeFile(path, file));
        RecordingError error;
        const auto got = readAll(path, &error);
        QCOMPARE(got.size(), records);
        QCOMPARE(int(error.kind), int(RecordingError::Kind::Damaged));
        QCOMPARE(error.offset, qint64(errorOffset));
        QVERIFY2(error.message.contains(QString::number(errorOffset)), qPrintable(error.message));
    }

    void otherFilesAndVersionsAreRefused_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("named");
        QByteArray v2 = sampleFile();
        v2[8] = 2;
        QByteArray badHeader = sampleFile();
        badHeader[14] = char(badHeader[14] ^ 1);
        QTest::newRow("empty") << QByteArray() << int(RecordingError::Kind::NotARecording)
                               << QStringLiteral("not an LK Servo Studio recording");
        QTest::newRow("hex text") << QByteArray("3E 80 01 00 BF\n")
                                  << int(RecordingError::Kind::NotARecording)
                                  << QStringLiteral("no recording magic");
        QTest::newRow("version 2") << v2 << int(RecordingError::Kind::UnsupportedVersion)
                                   << QStringLiteral("format version 2");
        QTest::newRow("header bit flipped")
            << badHeader << int(RecordingError::Kind::DamagedHeader) << QStringLiteral("header");
        QTest::newRow("magic only") << QByteArray(kMagic, 8) << int(RecordingError::Kind::Truncated)
                                    << QStringLiteral("inside its header");
    }
    void otherFilesAndVersionsAreRefused()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(int, kind);
        QFETCH(QString, named);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("x.lkrec"));
        QVERIFY(writeFile(path, bytes));
        RecordingReader reader;
        QVERIFY(!reader.open(path));
        QCOMPARE(int(reader.error().kind), kind);
        QVERIFY2(reader.error().message.contains(named), qPrintable(reader.error().message));
    }

    void metaRecordsOfALaterRevisionAreSkipped()
    {
        // Payload: an unknown meta record (type 0x7F, 3 bytes), a 2-byte rx chunk 5 ns later,
        // another unknown one as the block's last record.
        const QByteArray payload = QByteArray::fromHex("ff0003aabbcc") +
                                   QByteArray::fromHex("0205") + "hi" +
                                   QByteArray::fromHex("ff0701ee");
        QByteArray block(kBlockSync, 4);
        const auto put32 = [&block](quint32 v) {
            for (int i = 0; i < 4; ++i)
                block.append(char(v >> (8 * i)));
        };
        put32(quint32(payload.size()));
        block.append(QByteArray(8, '\0')); // base time 0
        quint32 crc = crc32(block.constData() + 4, 12);
        crc = crc32(payload.constData(), payload.size(), crc);
        put32(crc);
        block += payload;
        RecordingReader reader;
        QVERIFY(reader.openBytes(RecordEncoder::encodeHeader(testHeader()) + block));
        RecordEvent e;
        QVERIFY(reader.next(&e));
        QCOMPARE(int(e.kind), int(RecordEvent::Kind::Rx));
        QCOMPARE(e.bytes, QByteArray("hi"));
        QCOMPARE(e.timeNs, qint64(5));
        QVERIFY(!reader.next(&e));
        QCOMPARE(int(reader.error().kind), int(RecordingError::Kind::None));
        QVERIFY(reader.openBytes(RecordEncoder::encodeHeader(testHeader()) + block));
        reader.index();
        QCOMPARE(reader.lastTimeNs(), qint64(12));
    }

    void indexSeeksToEveryBlock()
    {
        QVector<qsizetype> ends;
        const QByteArray file = sampleFile(&ends);
        RecordingReader reader;
        QVERIFY(reader.openBytes(file));
        const auto blocks = reader.index();
        QCOMPARE(blocks.size(), 3);
        QCOMPARE(blocks.at(1).offset, qint64(ends[0]));
        QCOMPARE(blocks.at(1).baseTimeNs, qint64(251'337));
        QCOMPARE(reader.lastTimeNs(), qint64(7'000'000'001));
        QVERIFY(reader.seek(blocks.at(2)));
        RecordEvent e;
        QVERIFY(reader.next(&e));
        QCOMPARE(int(e.kind), int(RecordEvent::Kind::Link));
        QCOMPARE(int(e.link), int(LinkEventKind::Disconnected));
        QVERIFY(!reader.next(&e));
        // After index() reading starts at the first record again.
        RecordingReader again;
        QVERIFY(again.openBytes(file));
        again.index();
        QVERIFY(again.next(&e));
        QCOMPARE(int(e.kind), int(RecordEvent::Kind::Link));
    }

    void splitFramesAreMerged_data()
    {
        QTest::addColumn<QVector<RecordEvent>>("chunks");
        QTest::addColumn<QList<QByteArray>>("records"); // the data records read back
        QTest::addColumn<QList<qint64>>("times");
        const QByteArray half = kReply.left(6);
        const QByteArray rest = kReply.mid(6);
        QTest::newRow("a reply in two chunks")
            << QVector<RecordEvent>{rx(1000, half), rx(61'000, rest)} << QList<QByteArray>{kReply}
            << QList<qint64>{61'000};
        QTest::newRow("in three") << QVector<RecordEvent>{rx(1000, kReply.left(2)),
                                                          rx(2000, kReply.mid(2, 3)),
                                                          rx(9000, kReply.mid(5))}
                                  << QList<QByteArray>{kReply} << QList<qint64>{9000};
        QTest::newRow("a frame's end and the next one's start: its own time kept")
            << QVector<RecordEvent>{rx(1000, kRequest + half), rx(2000, rest)}
            << QList<QByteArray>{kRequest + half, rest} << QList<qint64>{1000, 2000};
        QTest::newRow("a gap longer than an adapter's latency timer")
            << QVector<RecordEvent>{rx(0, half), rx(RecordEncoder::kMergeGapNs + 1, rest)}
            << QList<QByteArray>{half, rest} << QList<qint64>{0, RecordEncoder::kMergeGapNs + 1};
        QTest::newRow("the other direction")
            << QVector<RecordEvent>{RecordEvent::data(RecordEvent::Kind::Tx, 0, kRequest.left(2)),
                                    rx(1000, kRequest.mid(2))}
            << QList<QByteArray>{kRequest.left(2), kRequest.mid(2)} << QList<qint64>{0, 1000};
        RecordEvent closed;
        closed.kind = RecordEvent::Kind::Link;
        closed.link = LinkEventKind::Closed;
        closed.timeNs = 1500;
        QTest::newRow("a link event between")
            << QVector<RecordEvent>{rx(1000, half), closed, rx(2000, rest)}
            << QList<QByteArray>{half, rest} << QList<qint64>{1000, 2000};
    }

    void splitFramesAreMerged()
    {
        QFETCH(QVector<RecordEvent>, chunks);
        QFETCH(QList<QByteArray>, records);
        QFETCH(QList<qint64>, times);
        QList<QByteArray> gotRecords;
        QList<qint64> gotTimes;
        for (const RecordEvent &e : roundTrip(chunks)) {
            if (e.kind == RecordEvent::Kind::Rx || e.kind == RecordEvent::Kind::Tx) {
                gotRecords.append(e.bytes);
                gotTimes.append(e.timeNs);
            }
        }
        QCOMPARE(gotRecords, records);
        QCOMPARE(gotTimes, times);
        // Whatever was merged, a reader decodes the same frames at the same times.
        QCOMPARE(framesOf(roundTrip(chunks)), framesOf(chunks));
    }

    void everyFrameKeepsItsTimeWhereverTheChunksAreCut()
    {
        // A poll stream with garbage, cut at every offset of the reply in turn.
        QVector<RecordEvent> chunks;
        qint64 t = 0;
        for (int cut = 0; cut <= kReply.size(); ++cut) {
            t += 1'000'000;
            chunks.append(RecordEvent::data(RecordEvent::Kind::Tx, t, kRequest));
            const QByteArray reply =
                (cut % 4 == 1 ? QByteArray("\x55\xAA") : QByteArray()) + kReply;
            t += 200'000;
            chunks.append(rx(t, reply.left(cut)));
            t += 30'000 * (cut % 3);
            chunks.append(rx(t, reply.mid(cut)));
        }
        chunks.removeIf([](const RecordEvent &e) { return e.bytes.isEmpty(); });
        const QVector<RecordEvent> read = roundTrip(chunks);
        QVERIFY(read.size() < chunks.size()); // some were merged
        QCOMPARE(framesOf(read), framesOf(chunks));
    }

    void chunkPerRecordFilesOfVersion1StillRead()
    {
        // Written before split frames were merged: a reply in two records, 60 us apart.
        const QByteArray file = RecordEncoder::encodeHeader(testHeader()) +
                                handWrittenBlock(5000, {{true, 0, kRequest},
                                                        {false, 180'000, kReply.left(6)},
                                                        {false, 60'000, kReply.mid(6)}});
        RecordingReader reader;
        QVERIFY(reader.openBytes(file));
        QCOMPARE(reader.header().version, quint16(1));
        QVector<RecordEvent> got;
        RecordEvent e;
        while (reader.next(&e))
            got.append(e);
        QCOMPARE(int(reader.error().kind), int(RecordingError::Kind::None));
        QCOMPARE(got.size(), 3);
        QCOMPARE(got.at(1).bytes, kReply.left(6));
        QCOMPARE(got.at(1).timeNs, qint64(185'000));
        QCOMPARE(got.at(2).bytes, kReply.mid(6));
        QCOMPARE(got.at(2).timeNs, qint64(245'000));
        QCOMPARE(framesOf(got).size(), 2);
    }

    void pollTrafficCostsAtMost1_6TimesItsWireBytes_data()
    {
        QTest::addColumn<bool>("split");
        QTest::newRow("one chunk per frame") << false;
        QTest::newRow("replies in two chunks (a USB adapter)") << true;
    }

    void pollTrafficCostsAtMost1_6TimesItsWireBytes()
    {
        // A typical poll: 5-byte requests and 13-byte replies, ~0.2 ms apart, in 64 KiB blocks.
        QFETCH(bool, split);
        RecordEncoder enc;
        qsizetype wire = 0;
        qsizetype file = 0;
        qint64 t = 0;
        const QByteArray request = QByteArray::fromHex("3e9c0100db");
        const QByteArray reply = QByteArray::fromHex("3e9c0107e21ff40168010030ad");
        for (int i = 0; i < 100000; ++i) {
            t += 1'300'000;
            enc.append(RecordEvent::data(RecordEvent::Kind::Tx, t, request));
            t += 180'000 + (i % 7) * 1000;
            if (split) {
                enc.append(RecordEvent::data(RecordEvent::Kind::Rx, t, reply.left(6)));
                t += 60'000;
                enc.append(RecordEvent::data(RecordEvent::Kind::Rx, t, reply.mid(6)));
            } else {
                enc.append(RecordEvent::data(RecordEvent::Kind::Rx, t, reply));
            }
            wire += request.size() + reply.size();
            if (enc.pendingBytes() >= 64 * 1024)
                file += enc.takeBlock().size();
        }
        file += enc.takeBlock().size();
        const double ratio = double(file) / double(wire);
        qInfo("file/wire ratio %.3f", ratio);
        QVERIFY2(ratio <= 1.6, qPrintable(QString::number(ratio)));
    }
};

QTEST_APPLESS_MAIN(tst_RecordingFormat)
#include "tst_recordingformat.moc"
