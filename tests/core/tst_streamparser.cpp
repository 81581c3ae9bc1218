#include "protocol/Checksum.h"
#include "protocol/StreamParser.h"

#include "ProtocolTestUtil.h"
#include "StreamTestUtil.h"

#include <QtCore/QElapsedTimer>
#include <QtTest/QTest>

#include <cstring>

using lk::protocol::Frame;
using lk::protocol::ParseError;
using lk::protocol::ParseEvent;
using lk::protocol::StreamParser;
using namespace lk::test;
namespace proto = lk::protocol;

/// StreamParser: frames, faults and resync, every split point, truncation, bit flips, and the
/// invariant that every input byte is reported exactly once, on hand-made and random streams.
class tst_StreamParser : public QObject {
    Q_OBJECT

private slots:
    void singleFrame_data();
    void singleFrame();
    void sequences_data();
    void sequences();
    void truncatedAtEnd_data();
    void truncatedAtEnd();
    void resyncAfterFault_data();
    void resyncAfterFault();
    void faultEventsCarryTheHeader_data();
    void faultEventsCarryTheHeader();
    void bitFlips_data();
    void bitFlips();
    void largeChunkOfFrames();
    void cleanRandomStreams_data();
    void cleanRandomStreams();
    void randomStreams_data();
    void randomStreams();
    void tenMegabytesOfNoise();
    void tenMegabytesOfFrames();
    void pendingAndReset();
    void parseErrorNames_data();
    void parseErrorNames();

private:
    static void addFaultSequences();
};

void tst_StreamParser::singleFrame_data()
{
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<QString>("direction");
    const auto add = [](const char *name, const char *wire, const char *dir) {
        QTest::newRow(name) << hex(wire) << QString::fromLatin1(dir);
    };
    add("motor_off echo", kMotorOff, "echo");
    add("read_state2 request", "3E 9C 01 00 DB", "request");
    add("read_state2 reply", kState2, "reply");
    add("torque request", kTorque, "request");
    add("pid echo", kPidEcho, "echo");
    add("0x3E in data", kHeadInData, "echo");
    add("data checksum 0x3E", kHeadAsChecksum, "request");
    add("multi_position_limited request", kMultiLimited, "request");
    add("read_model reply 42", kModel42, "reply");
    add("write_zero_rom reply LEN 2", kZeroLen2, "reply");
    add("write_zero_rom echo", "3E 19 01 00 58", "echo");
}

void tst_StreamParser::singleFrame()
{
    QFETCH(QByteArray, wire);
    QFETCH(QString, direction);
    const EventLog log = lk::test::parseAll(wire);
    QCOMPARE(int(log.events.size()), 1);
    const ParseEvent &ev = log.events.front();
    QVERIFY2(ev.isFrame, qPrintable(lk::test::describe(ev)));
    QCOMPARE(QString::fromLatin1(proto::directionName(ev.direction)), direction);
    QCOMPARE(ev.bytes, wire);
    // The frame's bytes are its own, not the parser's reserved buffer (about 4 KiB) that a
    // chunk of exactly one frame filled: a view keeping the event must not keep that too.
    QVERIFY2(ev.bytes.capacity() < 256, qPrintable(QString::number(ev.bytes.capacity())));
    QCOMPARE(int(ev.frame.command), int(quint8(wire[1])));
    QCOMPARE(int(ev.frame.id), int(quint8(wire[2])));
    QCOMPARE(ev.frame.data, wire.mid(5, quint8(wire[3])));
}

void tst_StreamParser::sequences_data()
{
    QTest::addColumn<QByteArray>("stream");
    QTest::addColumn<QStringList>("expected");
    const QString off = frameLine("echo", kMotorOff);
    const QString st2 = frameLine("reply", kState2);

    QTest::newRow("empty stream") << QByteArray() << QStringList();
    QTest::newRow("frames back to back")
        << concat({kMotorOff, kState2, kTorque, kPidEcho, kHeadInData, kHeadAsChecksum,
                   kMultiLimited, kModel42, kZeroLen2})
        << QStringList{off,
                       st2,
                       frameLine("request", kTorque),
                       frameLine("echo", kPidEcho),
                       frameLine("echo", kHeadInData),
                       frameLine("request", kHeadAsChecksum),
                       frameLine("request", kMultiLimited),
                       frameLine("reply", kModel42),
                       frameLine("reply", kZeroLen2)};
    addFaultSequences();
}

void tst_StreamParser::addFaultSequences()
{
    const QString off = frameLine("echo", kMotorOff);
    const QString st2 = frameLine("reply", kState2);
    QTest::newRow("garbage prefix") << concat({"00 11 22 FF", kMotorOff})
                                    << QStringList{QStringLiteral("garbage: 00 11 22 FF"), off};
    QTest::newRow("garbage between frames")
        << concat({kMotorOff, "3D 3F C1 80", kState2})
        << QStringList{off, QStringLiteral("garbage: 3D 3F C1 80"), st2};
    QTest::newRow("garbage suffix")
        << concat({kState2, "01 02 03"}) << QStringList{st2, QStringLiteral("garbage: 01 02 03")};
    QTest::newRow("only garbage") << hex("01 02 03 C3") << QStringList{"garbage: 01 02 03 C3"};
    QTest::newRow("bad header checksum")
        << concat({"3E 80 01 00 BE", kMotorOff})
        << QStringList{QStringLiteral("bad_header_checksum: 3E 80 01 00 BE"), off};
    QTest::newRow("bad header stops at the next 0x3E")
        << concat({"3E 80", kMotorOff})
        << QStringList{QStringLiteral("bad_header_checksum: 3E 80"), off};
    QTest::newRow("stray 0x3E") << concat({"3E", kMotorOff})
                                << QStringList{QStringLiteral("bad_header_checksum: 3E"), off};
    QTest::newRow("bad data checksum (CLI.md example)")
        << concat({"3E A4 01 07 EA 21 00 00 0A 00 2C 19 73", kMotorOff})
        << QStringList{QStringLiteral("bad_data_checksum: 3E A4 01 07 EA 21 00 00 0A 00 2C 19 73"),
                       off};
    QTest::newRow("LEN 61") << concat({"3E 9C 01 3D 18 01 02", kState2})
                            << QStringList{QStringLiteral("bad_length: 3E 9C 01 3D 18"),
                                           QStringLiteral("garbage: 01 02"), st2};
    QTest::newRow("LEN 255") << concat({"3E 9C 01 FF DA", kMotorOff})
                             << QStringList{QStringLiteral("bad_length: 3E 9C 01 FF DA"), off};
    QTest::newRow("unknown command, valid checksums")
        << concat({"3E 89 01 00 C8", kMotorOff})
        << QStringList{QStringLiteral("unknown_command: 3E 89 01 00 C8"), off};
    const QByteArray unknown60 = hex("3E 41 01 3C BC") + QByteArray(60, 0x3E) + hex("88");
    QTest::newRow("unknown command LEN 60 of 0x3E")
        << unknown60 + hex(kMotorOff)
        << QStringList{QStringLiteral("unknown_command: ") + spaced(unknown60), off};
    QTest::newRow("bad length for a known command")
        << concat({"3E 9C 01 03 DE 01 02 03 06", kMotorOff})
        << QStringList{QStringLiteral("bad_length: 3E 9C 01 03 DE 01 02 03 06"), off};
    QTest::newRow("read_state2 reply LEN 8")
        << concat({"3E 9C 01 08 E3 00 00 00 00 00 00 00 00 00", kMotorOff})
        << QStringList{QStringLiteral("bad_length: 3E 9C 01 08 E3 00 00 00 00 00 00 00 00 00"),
                       off};
    QTest::newRow("truncated at end")
        << concat({kMotorOff, "3E 9C 01 07 E2 1E 00"})
        << QStringList{off, QStringLiteral("truncated: 3E 9C 01 07 E2 1E 00")};
    QTest::newRow("two heads at end")
        << concat({kMotorOff, "3E 3E"})
        << QStringList{off, QStringLiteral("truncated: 3E"), QStringLiteral("truncated: 3E")};
    QTest::newRow("every fault in a row")
        << concat({"AA", "3E 80 01 00 BE", "3E A4 01 07 EA 21 00 00 0A 00 2C 19 73",
                   "3E 89 01 00 C8", "3E 9C 01 FF DA", kState2, "3E 9C 01"})
        << QStringList{QStringLiteral("garbage: AA"),
                       QStringLiteral("bad_header_checksum: 3E 80 01 00 BE"),
                       QStringLiteral("bad_data_checksum: 3E A4 01 07 EA 21 00 00 0A 00 2C 19 73"),
                       QStringLiteral("unknown_command: 3E 89 01 00 C8"),
                       QStringLiteral("bad_length: 3E 9C 01 FF DA"),
                       st2,
                       QStringLiteral("truncated: 3E 9C 01")};
}

void tst_StreamParser::sequences()
{
    QFETCH(QByteArray, stream);
    QFETCH(QStringList, expected);

    // In one piece: exactly the expected events.
    const EventLog whole = lk::test::parseAll(stream);
    QCOMPARE(lines(whole.events, false), expected);
    QString problem = streamProblem(whole, stream);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    // Two chunks, at every split point: the same events (garbage may come in pieces).
    for (qsizetype i = 0; i <= stream.size(); ++i) {
        const EventLog log = parseChunked(stream, {i});
        QVERIFY2(
            lines(log.events, true) == expected,
            qPrintable(
                QStringLiteral("split at %1: %2").arg(i).arg(lines(log.events, true).join(u'|'))));
        problem = streamProblem(log, stream);
        QVERIFY2(problem.isEmpty(), qPrintable(QStringLiteral("split at %1: ").arg(i) + problem));
    }
    // Byte by byte.
    QList<qsizetype> every;
    for (qsizetype i = 1; i < stream.size(); ++i)
        every << i;
    const EventLog bytewise = parseChunked(stream, every);
    QCOMPARE(lines(bytewise.events, true), expected);
    problem = streamProblem(bytewise, stream);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

void tst_StreamParser::truncatedAtEnd_data()
{
    QTest::addColumn<QByteArray>("frame");
    QTest::addColumn<int>("keep");
    for (const char *f : kAllFrames) {
        const QByteArray frame = hex(f);
        for (int keep = 1; keep < frame.size(); ++keep)
            QTest::addRow("%s | %d of %d bytes", qPrintable(spaced(frame.left(6))), keep,
                          int(frame.size()))
                << frame << keep;
    }
}

void tst_StreamParser::truncatedAtEnd()
{
    QFETCH(QByteArray, frame);
    QFETCH(int, keep);
    const QByteArray lead = hex(kState2);
    const QByteArray cut = frame.left(keep);

    EventLog log;
    StreamParser parser;
    parser.feed(lead + cut, log.sink());
    // Nothing is reported for the partial frame until the stream ends.
    QCOMPARE(int(log.events.size()), 1);
    QVERIFY(log.events.front().isFrame);
    QCOMPARE(int(parser.pendingBytes()), keep);
    parser.finish(log.sink());
    QCOMPARE(int(parser.pendingBytes()), 0);
    // The header of a truncated frame may promise bytes that never came, so truncation covers
    // only the bytes up to the next 0x3E; each 0x3E inside the cut starts a new attempt.
    QStringList expected{QStringLiteral("frame reply: ") + spaced(lead)};
    qsizetype from = 0;
    while (from < cut.size()) {
        qsizetype next = cut.indexOf(char(0x3E), from + 1);
        if (next < 0)
            next = cut.size();
        expected << QStringLiteral("truncated: ") + spaced(cut.mid(from, next - from));
        from = next;
    }
    QCOMPARE(lines(log.events, false), expected);
    // finish() twice reports nothing more.
    parser.finish(log.sink());
    QCOMPARE(int(log.events.size()), int(expected.size()));
}

void tst_StreamParser::resyncAfterFault_data()
{
    QTest::addColumn<QByteArray>("fault");
    QTest::addColumn<QByteArray>("frame");
    const char *faults[] = {"00 11 22",
                            "3E",
                            "3E 3E",
                            "3E 80 01 00 BE",
                            "3E 80 3E",
                            "3E A4 01 07 EA 21 00 00 0A 00 2C 19 73",
                            "3E 9C 01 3D 18",
                            "3E 9C 01 FF DA",
                            "3E 89 01 00 C8",
                            "3E 9C 01 03 DE 01 02 03 06",
                            "3E 9C 01 08 E3 00 00 00 00 00 00 00 00 00",
                            "3E A1 01 02 E2 3E 00 3F"}; // bad data checksum, 0x3E in data
    const char *frames[] = {kMotorOff, kState2, kHeadInData, kModel42};
    for (const char *fault : faults) {
        for (const char *frame : frames)
            QTest::addRow("%s then %s", fault, qPrintable(spaced(hex(frame).left(5))))
                << hex(fault) << hex(frame);
    }
}

void tst_StreamParser::resyncAfterFault()
{
    QFETCH(QByteArray, fault);
    QFETCH(QByteArray, frame);
    const QByteArray stream = fault + frame;
    for (qsizetype split = 0; split <= stream.size(); ++split) {
        const EventLog log = parseChunked(stream, {split});
        QVERIFY2(!log.events.empty(), "no events");
        QCOMPARE(log.frameCount(), 1);
        QVERIFY2(log.events.back().isFrame, qPrintable(lk::test::describe(log.events.back())));
        QCOMPARE(log.events.back().bytes, frame);
        const QString problem = streamProblem(log, stream);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
}

void tst_StreamParser::faultEventsCarryTheHeader_data()
{
    // StreamParser.h: the frame is set for UnknownCommand and BadLength, whose header
    // checksum was valid; the bus layer (ReplyMatcher) also relies on it for BadDataChecksum,
    // to tell which reply a damaged frame spoils.
    QTest::addColumn<QByteArray>("wire");
    QTest::addColumn<int>("error");
    QTest::addColumn<int>("command");
    QTest::addColumn<int>("id");
    QTest::newRow("bad data checksum") << hex("3E A4 01 07 EA 21 00 00 0A 00 2C 19 73")
                                       << int(ParseError::BadDataChecksum) << 0xA4 << 1;
    QTest::newRow("unknown command")
        << hex("3E 89 05 00 CC") << int(ParseError::UnknownCommand) << 0x89 << 5;
    QTest::newRow("bad length, LEN 3")
        << hex("3E 9C 01 03 DE 01 02 03 06") << int(ParseError::BadLength) << 0x9C << 1;
    QTest::newRow("bad length, LEN 61 (valid header checksum)")
        << hex("3E 9C 01 3D 18") << int(ParseError::BadLength) << 0x9C << 1;
    QTest::newRow("bad length, LEN 255 id 32 (valid header checksum)")
        << hex("3E 9C 20 FF F9") << int(ParseError::BadLength) << 0x9C << 32;
}

void tst_StreamParser::faultEventsCarryTheHeader()
{
    QFETCH(QByteArray, wire);
    QFETCH(int, error);
    QFETCH(int, command);
    QFETCH(int, id);
    const EventLog log = lk::test::parseAll(wire);
    QCOMPARE(int(log.events.size()), 1);
    const ParseEvent &ev = log.events.front();
    QVERIFY(!ev.isFrame);
    QCOMPARE(QString::fromLatin1(proto::parseErrorName(ev.error)),
             QString::fromLatin1(proto::parseErrorName(static_cast<ParseError>(error))));
    QCOMPARE(ev.bytes, wire);
    QCOMPARE(int(ev.frame.command), command);
    QCOMPARE(int(ev.frame.id), id);
}

void tst_StreamParser::bitFlips_data()
{
    QTest::addColumn<QByteArray>("frame");
    for (const char *f : kAllFrames)
        QTest::newRow(qPrintable(spaced(hex(f).left(8)))) << hex(f);
}

void tst_StreamParser::bitFlips()
{
    QFETCH(QByteArray, frame);
    const QByteArray sentinel = hex("3E 81 01 00 C0"); // motor_stop: in no row
    int flips = 0;
    for (qsizetype byte = 0; byte < frame.size(); ++byte) {
        for (int bit = 0; bit < 8; ++bit) {
            QByteArray flipped = frame;
            flipped[byte] = char(flipped[byte] ^ (1 << bit));
            const QByteArray stream = flipped + sentinel;
            const QString where = QStringLiteral("byte %1 bit %2: ").arg(byte).arg(bit);
            const EventLog log = lk::test::parseAll(stream);
            for (const ParseEvent &ev : log.events) {
                QVERIFY2(!(ev.isFrame && ev.bytes == frame),
                         qPrintable(where + QStringLiteral("original frame reported")));
                QVERIFY2(!(ev.isFrame && ev.bytes == flipped),
                         qPrintable(where + QStringLiteral("flipped frame accepted")));
            }
            const QString problem = streamProblem(log, stream);
            QVERIFY2(problem.isEmpty(), qPrintable(where + problem));
            // The frame after the damaged one is still found.
            QVERIFY2(log.events.back().isFrame && log.events.back().bytes == sentinel,
                     qPrintable(where + lines(log.events, false).join(u'|')));
            ++flips;
        }
    }
    QCOMPARE(flips, int(frame.size()) * 8);
}

void tst_StreamParser::largeChunkOfFrames()
{
    // Far more than the parser's 4096-byte slice in one feed: frames straddle slices.
    const QByteArray one = hex(kState2) + hex(kHeadInData) + hex(kModel42);
    QByteArray stream;
    for (int i = 0; i < 500; ++i)
        stream += one;
    EventLog log;
    StreamParser parser;
    parser.feed(stream, log.sink());
    QVERIFY(parser.pendingBytes() == 0);
    parser.finish(log.sink());
    QCOMPARE(log.frameCount(), 1500);
    QCOMPARE(int(log.events.size()), 1500);
    const QString problem = streamProblem(log, stream);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

void tst_StreamParser::cleanRandomStreams_data()
{
    QTest::addColumn<quint32>("seed");
    for (quint32 seed : {1u, 2u, 3u, 42u, 1234u, 99991u})
        QTest::addRow("seed %u", seed) << seed;
}

void tst_StreamParser::cleanRandomStreams()
{
    // Valid frames separated by garbage that holds no 0x3E: every frame must come out, and
    // the garbage exactly, whatever the chunking.
    QFETCH(quint32, seed);
    QRandomGenerator rng(seed);
    QByteArray stream;
    QStringList expected;
    for (int i = 0; i < 400; ++i) {
        if (rng.bounded(3) == 0) {
            const QByteArray g = randomGarbageWithoutHead(rng, rng.bounded(1, 40));
            stream += g;
            expected << QStringLiteral("garbage: ") + spaced(g);
        }
        const QByteArray f = hex(kAllFrames[rng.bounded(int(std::size(kAllFrames)))]);
        stream += f;
        const auto dir = Frame{quint8(f[1]), quint8(f[2]), f.mid(5, quint8(f[3]))}.direction();
        QVERIFY(dir.has_value());
        expected << QStringLiteral("frame %1: %2")
                        .arg(QLatin1String(proto::directionName(*dir)), spaced(f));
    }
    // Adjacent garbage pieces of the expectation never occur (a frame is always between).
    for (int maxChunk : {1, 7, 64, 5000, 100000}) {
        const EventLog log = parseChunked(stream, randomCuts(rng, stream.size(), maxChunk));
        QCOMPARE(lines(log.events, true), expected);
        const QString problem = streamProblem(log, stream);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
}

void tst_StreamParser::randomStreams_data()
{
    QTest::addColumn<quint32>("seed");
    for (quint32 seed : {7u, 8u, 9u, 2024u, 31337u, 4000000000u})
        QTest::addRow("seed %u", seed) << seed;
}

void tst_StreamParser::randomStreams()
{
    // Frames, damaged frames, cut frames, random bytes and lone heads, in any mix.
    QFETCH(quint32, seed);
    QRandomGenerator rng(seed);
    QByteArray stream;
    for (int i = 0; i < 2000; ++i) {
        QByteArray piece = hex(kAllFrames[rng.bounded(int(std::size(kAllFrames)))]);
        switch (rng.bounded(6)) {
        case 0: // one bit flipped
            piece[rng.bounded(int(piece.size()))] ^= char(1 << rng.bounded(8));
            break;
        case 1: // cut short
            piece.truncate(rng.bounded(1, int(piece.size())));
            break;
        case 2: // random bytes, heads included
            piece = QByteArray(rng.bounded(1, 80), '\0');
            for (char &c : piece)
                c = char(rng.bounded(256));
            break;
        case 3:
            piece = hex("3E");
            break;
        default: // intact
            break;
        }
        stream += piece;
    }
    for (int maxChunk : {1, 13, 300, 9000}) {
        EventLog log;
        StreamParser parser;
        const QList<qsizetype> cuts = randomCuts(rng, stream.size(), maxChunk);
        qsizetype from = 0;
        for (qsizetype cut : cuts + QList<qsizetype>{stream.size()}) {
            parser.feed(stream.mid(from, cut - from), log.sink());
            from = cut;
            // At most one partial frame and one garbage run under 4 KiB wait for more input.
            QVERIFY(parser.pendingBytes() < proto::kMaxFrameSize + 4096);
        }
        parser.finish(log.sink());
        QCOMPARE(int(parser.pendingBytes()), 0);
        const QString problem = streamProblem(log, stream);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
}

void tst_StreamParser::tenMegabytesOfNoise()
{
    constexpr qsizetype kSize = 10 * 1024 * 1024;
    QRandomGenerator rng(0x4C4B5354); // "LKST"
    QByteArray input(kSize, Qt::Uninitialized);
    rng.fillRange(reinterpret_cast<quint32 *>(input.data()), kSize / 4);

    // Check each event against the input as it arrives, without keeping the events.
    qsizetype offset = 0;
    qsizetype bad = 0, frames = 0, events = 0, headInGarbage = 0;
    const StreamParser::Sink sink = [&](const ParseEvent &ev) {
        ++events;
        frames += ev.isFrame ? 1 : 0;
        if (offset + ev.bytes.size() > kSize ||
            std::memcmp(ev.bytes.constData(), input.constData() + offset, ev.bytes.size()) != 0)
            ++bad;
        if (!ev.isFrame && ev.error == ParseError::Garbage && ev.bytes.contains(char(0x3E)))
            ++headInGarbage;
        offset += ev.bytes.size();
    };
    StreamParser parser;
    QElapsedTimer timer;
    timer.start();
    qsizetype maxPending = 0;
    for (qsizetype at = 0; at < kSize;) {
        const qsizetype n = std::min<qsizetype>(rng.bounded(1, 12000), kSize - at);
        parser.feed(input.constData() + at, n, sink);
        at += n;
        maxPending = std::max(maxPending, parser.pendingBytes());
        QVERIFY2(parser.pendingBytes() <= 66 + 4096, qPrintable(QString::number(maxPending)));
    }
    parser.finish(sink);
    const qint64 ms = timer.elapsed();
    QCOMPARE(bad, qsizetype(0));
    QCOMPARE(headInGarbage, qsizetype(0));
    QCOMPARE(offset, kSize);
    QCOMPARE(parser.pendingBytes(), qsizetype(0));
    // A figure, not an assertion.
    qInfo("10 MiB of noise: %lld events, %lld frames, max pending %lld bytes, %lld ms "
          "(%.1f MB/s)",
          qlonglong(events), qlonglong(frames), qlonglong(maxPending), qlonglong(ms),
          ms > 0 ? kSize / 1e3 / double(ms) : 0.0);
}

void tst_StreamParser::tenMegabytesOfFrames()
{
    // Valid frames with 0x3E-free garbage between some of them: every frame comes out,
    // whatever the chunking, and the parser's own work per frame stays cheap.
    constexpr qsizetype kSize = 10 * 1024 * 1024;
    QRandomGenerator rng(0x46524D53); // "FRMS"
    QList<QByteArray> frames;
    for (const char *f : kAllFrames)
        frames << hex(f);
    QByteArray input;
    input.reserve(kSize + 200);
    qsizetype inserted = 0;
    while (input.size() < kSize) {
        if (rng.bounded(4) == 0)
            input += randomGarbageWithoutHead(rng, rng.bounded(1, 20));
        input += frames[rng.bounded(int(frames.size()))];
        ++inserted;
    }
    qsizetype offset = 0, bad = 0, found = 0;
    const StreamParser::Sink sink = [&](const ParseEvent &ev) {
        found += ev.isFrame ? 1 : 0;
        if (std::memcmp(ev.bytes.constData(), input.constData() + offset, ev.bytes.size()) != 0)
            ++bad;
        offset += ev.bytes.size();
    };
    StreamParser parser;
    QElapsedTimer timer;
    timer.start();
    for (qsizetype at = 0; at < input.size();) {
        const qsizetype n = std::min<qsizetype>(rng.bounded(1, 9000), input.size() - at);
        parser.feed(input.constData() + at, n, sink);
        at += n;
        QVERIFY(parser.pendingBytes() <= 66 + 4096);
    }
    parser.finish(sink);
    const qint64 ms = timer.elapsed();
    QCOMPARE(bad, qsizetype(0));
    QCOMPARE(offset, input.size());
    QCOMPARE(found, inserted);
    qInfo("%.1f MiB of frames: %lld frames, %lld ms (%.1f MB/s)", input.size() / 1048576.0,
          qlonglong(found), qlonglong(ms), ms > 0 ? input.size() / 1e3 / double(ms) : 0.0);
}

void tst_StreamParser::pendingAndReset()
{
    EventLog log;
    StreamParser parser;
    parser.feed(hex("3E 9C 01 07 E2 1E"), log.sink());
    QCOMPARE(int(parser.pendingBytes()), 6);
    QVERIFY(log.events.empty());
    parser.reset();
    QCOMPARE(int(parser.pendingBytes()), 0);
    parser.finish(log.sink());
    QVERIFY(log.events.empty()); // reset drops without reporting
    parser.feed(nullptr, 0, log.sink());
    parser.feed(QByteArray(), log.sink());
    QVERIFY(log.events.empty());
    parser.feed(hex(kMotorOff), log.sink());
    QCOMPARE(lines(log.events, false),
             QStringList{QStringLiteral("frame echo: ") + spaced(hex(kMotorOff))});
}

void tst_StreamParser::parseErrorNames_data()
{
    QTest::addColumn<int>("error");
    QTest::addColumn<QString>("name");
    QTest::newRow("header") << int(ParseError::BadHeaderChecksum) << "bad_header_checksum";
    QTest::newRow("data") << int(ParseError::BadDataChecksum) << "bad_data_checksum";
    QTest::newRow("length") << int(ParseError::BadLength) << "bad_length";
    QTest::newRow("unknown") << int(ParseError::UnknownCommand) << "unknown_command";
    QTest::newRow("garbage") << int(ParseError::Garbage) << "garbage";
    QTest::newRow("truncated") << int(ParseError::Truncated) << "truncated";
}

void tst_StreamParser::parseErrorNames()
{
    QFETCH(int, error);
    QFETCH(QString, name);
    QCOMPARE(QString::fromLatin1(proto::parseErrorName(static_cast<ParseError>(error))), name);
}

QTEST_APPLESS_MAIN(tst_StreamParser)
#include "tst_streamparser.moc"
