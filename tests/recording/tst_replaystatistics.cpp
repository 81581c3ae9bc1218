// ReplayStatistics: a recording's traffic counted as a listen-only session counts it (pairs,
// unanswered requests, per drive and command, CAN error frames and frames of no drive), on
// the recording's clock, afresh after a restart (a seek).
#include <protocol/CanRecord.h>
#include <protocol/FrameParser.h>
#include <recording/ReplayStatistics.h>

#include <QtTest/QtTest>

using namespace lk;
using lk::recording::ReplayStatistics;

namespace {

constexpr qint64 kMs = 1'000'000;

/// Feeds `bytes` arriving at `timeNs` through the link's parser into `stats`.
void play(ReplayStatistics &stats, protocol::FrameParser &parser, const QByteArray &bytes,
          qint64 timeNs, protocol::Link link = protocol::Link::Rs485)
{
    stats.addBytes(bytes.size());
    parser.feed(bytes, [&](const protocol::ParseEvent &e) {
        stats.take(e,
                   protocol::DecodeContext{protocol::Series::MF, protocol::Generation::V2_3, link},
                   timeNs);
    });
}

QByteArray can(quint32 id, const char *hex, quint8 flags = 0)
{
    protocol::CanRecord r = protocol::CanRecord::of({id, QByteArray::fromHex(hex)});
    r.flags = flags;
    return r.encode();
}

} // namespace

class tst_ReplayStatistics : public QObject {
    Q_OBJECT
private slots:
    void rs485TrafficIsPairedAndCounted()
    {
        ReplayStatistics stats;
        stats.restart(protocol::Link::Rs485, 115200, 0);
        auto parser = protocol::makeFrameParser(protocol::Link::Rs485, protocol::LinkEnd::Host);
        stats.attach(*parser);
        play(stats, *parser, QByteArray::fromHex("3e9c0100db"), 0);
        play(stats, *parser, QByteArray::fromHex("3e9c0107e21ff40168010030ad"), 1 * kMs);
        play(stats, *parser, QByteArray::fromHex("3e9c0200dc"), 10 * kMs); // never answered
        play(stats, *parser, QByteArray::fromHex("3e9c0100db"), 20 * kMs);
        play(stats, *parser, QByteArray::fromHex("3e9c0107e21ff40168010030ad"), 21 * kMs);
        QVERIFY(!stats.snapshotDue(400 * kMs));
        QVERIFY(stats.snapshotDue(500 * kMs));
        const bus::ListenStatistics st = stats.snapshot(500 * kMs);
        QCOMPARE(st.requests, quint64(3));
        QCOMPARE(st.replies, quint64(2));
        QCOMPARE(st.paired, quint64(2));
        QCOMPARE(st.unanswered, quint64(1));
        QCOMPARE(st.perDrive.value(1).requests, quint64(2));
        QCOMPARE(int(st.perDrive.value(1).latency.samples), 2);
        QCOMPARE(st.perDrive.value(2).unanswered, quint64(1));
        QCOMPARE(st.perCommand.value(0x9C).requests, quint64(3));
        QCOMPARE(st.time, 0.5);
        QCOMPARE(st.requestsPerSecond, 6.0); // 3 requests in half a second of the recording
        QVERIFY(!stats.snapshotDue(600 * kMs));
    }

    void aRestartCountsAfresh()
    {
        ReplayStatistics stats;
        stats.restart(protocol::Link::Rs485, 115200, 0);
        auto parser = protocol::makeFrameParser(protocol::Link::Rs485, protocol::LinkEnd::Host);
        play(stats, *parser, QByteArray::fromHex("3e9c0100db"), 0);
        QCOMPARE(stats.snapshot(1 * kMs).requests, quint64(1));
        stats.restart(protocol::Link::Rs485, 115200, 3000 * kMs); // a seek to 3 s
        const bus::ListenStatistics st = stats.snapshot(3000 * kMs);
        QCOMPARE(st.requests, quint64(0));
        QVERIFY(st.perDrive.isEmpty());
        QVERIFY(!stats.snapshotDue(3400 * kMs)); // half a second of the recording from there
        QVERIFY(stats.snapshotDue(3500 * kMs));
    }

    void canErrorFramesAndFramesOfNoDriveAreCounted()
    {
        ReplayStatistics stats;
        stats.restart(protocol::Link::Can, 1000000, 0);
        auto parser = protocol::makeFrameParser(protocol::Link::Can, protocol::LinkEnd::Host);
        stats.attach(*parser);
        const protocol::Link c = protocol::Link::Can;
        play(stats, *parser, can(0x141, "9C00000000000000"), 0, c);
        play(stats, *parser, can(0x141, "9C1E64000A001027"), 1 * kMs, c);
        play(stats, *parser, can(0x141, "9C00000000000000", protocol::CanRecord::Echo), 2 * kMs,
             c); // an echo of a frame the recording holds as Tx already: not counted again
        play(stats, *parser, can(0x08, "0000000000000000", protocol::CanRecord::Error), 3 * kMs, c);
        play(stats, *parser, can(0x300, "0102030405060708"), 4 * kMs, c);
        const bus::ListenStatistics st = stats.snapshot(10 * kMs);
        QCOMPARE(st.requests, quint64(1));
        QCOMPARE(st.paired, quint64(1));
        QCOMPARE(st.canErrorFrames, quint64(1));
        QCOMPARE(st.otherFrames, quint64(1));
        QCOMPARE(st.bytes, quint64(5 * protocol::CanRecord::kSize));
    }
};

QTEST_APPLESS_MAIN(tst_ReplayStatistics)
#include "tst_replaystatistics.moc"
