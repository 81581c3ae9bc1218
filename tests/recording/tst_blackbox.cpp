// BlackBox: keeps the last N minutes (and no more than its byte bound), saves them as a
// recording that opens with the decode context in force at its first record; the ring reads
// back as traffic events for the Traffic view.
#include "RecordingTestUtil.h"

#include <recording/BlackBox.h>
#include <recording/RecordTraffic.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using namespace lk::recording;
namespace protocol = lk::protocol;
using lk::bus::TrafficEvent;
using lk::testsupport::readAll;
using lk::testsupport::testHeader;

namespace {

constexpr qint64 kS = 1'000'000'000;
const QByteArray kRequest = QByteArray::fromHex("3e9c0100db");
const QByteArray kReply = QByteArray::fromHex("3e9c0107e21ff40168010030ad");

RecordEvent contextRecord(qint64 ns, std::optional<protocol::Series> series)
{
    RecordEvent e;
    e.kind = RecordEvent::Kind::Context;
    e.timeNs = ns;
    e.context = {{1, series, protocol::Generation::V2_3}};
    return e;
}

/// A poll every 100 ms from 0 to `seconds`.
void poll(BlackBox &box, int seconds)
{
    for (qint64 t = 0; t < seconds * kS; t += kS / 10) {
        box.append(RecordEvent::data(RecordEvent::Kind::Tx, t, kRequest));
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, t + kS / 1000, kReply));
    }
}

} // namespace

class tst_BlackBox : public QObject {
    Q_OBJECT
private slots:
    void keepsTheLastWindow_data()
    {
        QTest::addColumn<int>("windowS");
        QTest::addColumn<int>("runS");
        QTest::addColumn<int>("firstS"); ///< the oldest second left
        QTest::newRow("shorter than the window") << 600 << 30 << 0;
        QTest::newRow("10 minutes of 15") << 600 << 900 << 299;
        QTest::newRow("1 minute of 3") << 60 << 180 << 119;
    }
    void keepsTheLastWindow()
    {
        QFETCH(int, windowS);
        QFETCH(int, runS);
        QFETCH(int, firstS);
        BlackBox::Limits limits;
        limits.windowNs = windowS * kS;
        BlackBox box(testHeader(), limits);
        poll(box, runS);
        const auto events = box.events();
        QVERIFY(!events.isEmpty());
        // Eviction is by whole one-second blocks: the oldest left is at most a second older.
        QVERIFY2(events.first().timeNs / kS >= firstS && events.first().timeNs / kS <= firstS + 1,
                 qPrintable(QString::number(events.first().timeNs)));
        QCOMPARE(events.last().timeNs, (runS * 10 - 1) * kS / 10 + kS / 1000);
        QVERIFY(box.spanNs() <= windowS * kS + kS);
    }

    void staysWithinItsByteBound()
    {
        BlackBox::Limits limits;
        limits.maxBytes = 64 * 1024;
        limits.blockBytes = 4096;
        BlackBox box(testHeader(), limits);
        for (int i = 0; i < 20000; ++i)
            box.append(RecordEvent::data(RecordEvent::Kind::Rx, i * 1000LL, QByteArray(50, 'x')));
        QVERIFY2(box.bytes() <= 64 * 1024, qPrintable(QString::number(box.bytes())));
        const auto events = box.events();
        QVERIFY(events.size() > 500);
        QCOMPARE(events.last().timeNs, 19999 * 1000LL);
    }

    void savesWithTheContextInForceAtItsStart()
    {
        BlackBox::Limits limits;
        limits.windowNs = 60 * kS;
        BlackBox box(testHeader(), limits); // header: drive 1 is an MS
        box.append(contextRecord(5 * kS, protocol::Series::MG));
        poll(box, 120); // the context record is long out of the ring
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bb.lkrec"));
        const auto saved = box.saveLast(path);
        QVERIFY(!saved.error);
        QCOMPARE(saved.path, path);
        RecordingError error;
        RecordingHeader header;
        const auto got = readAll(path, &error, &header);
        QCOMPARE(int(error.kind), int(RecordingError::Kind::None));
        QCOMPARE(header.context.size(), 1);
        QVERIFY(header.context.first().series == protocol::Series::MG);
        QCOMPARE(got.size(), box.events().size());
        QVERIFY(got.first().timeNs >= 59 * kS);
        // The ring goes on after a save.
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, 200 * kS, kReply));
        QCOMPARE(box.events().last().timeNs, 200 * kS);
    }

    void aSaveThatCannotBeWrittenSaysWhy()
    {
        BlackBox box(testHeader());
        poll(box, 1);
        const auto full = box.saveLast(QStringLiteral("/dev/full"));
        QVERIFY(full.error);
        QCOMPARE(int(full.error->kind), int(RecordingError::Kind::DiskFull));
        QVERIFY(full.path.isEmpty());
        const auto missing = box.saveLast(QStringLiteral("/nonexistent/bb.lkrec"));
        QVERIFY(missing.error);
        QCOMPARE(int(missing.error->kind), int(RecordingError::Kind::OpenFailed));
    }

    void theRingReadsAsTrafficEvents()
    {
        BlackBox box(testHeader()); // drive 1: MS
        box.append(RecordEvent::data(RecordEvent::Kind::Tx, 1000, kRequest));
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, 2000, kReply.left(6)));
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, 3000, kReply.mid(6) + "\x01\x02"));
        box.append(contextRecord(4000, protocol::Series::MF));
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, 5000, kReply));
        RecordEvent lost;
        lost.kind = RecordEvent::Kind::Link;
        lost.timeNs = 6000;
        lost.link = LinkEventKind::Disconnected;
        lost.text = QStringLiteral("/dev/ttyUSB0");
        box.append(lost);
        ContextSnapshot before;
        const auto records = box.events(&before);
        const auto traffic = trafficEventsOf(records, before);
        QCOMPARE(traffic.size(), 5);
        QCOMPARE(int(traffic[0].kind), int(TrafficEvent::Kind::Sent));
        QCOMPARE(traffic[0].id, 1);
        QCOMPARE(int(traffic[1].kind), int(TrafficEvent::Kind::Frame));
        QCOMPARE(traffic[1].bytes, kReply);
        QCOMPARE(traffic[1].time, 3e-6);
        QVERIFY(traffic[1].context.series == protocol::Series::MS); // before the change
        // The two stray bytes are garbage, told when the next frame begins.
        QCOMPARE(int(traffic[2].kind), int(TrafficEvent::Kind::Fault));
        QCOMPARE(traffic[2].bytes, QByteArray("\x01\x02"));
        QCOMPARE(int(traffic[3].kind), int(TrafficEvent::Kind::Frame));
        QVERIFY(traffic[3].context.series == protocol::Series::MF); // after the change
        QCOMPARE(int(traffic[4].kind), int(TrafficEvent::Kind::Note));
        QVERIFY(traffic[4].text.contains(QStringLiteral("/dev/ttyUSB0")));
    }

    void oneRecordAtATimeGivesTheSameRows()
    {
        // The Traffic view converts the ring as records come (trafficEventOf, noteEventOf on
        // a parser it keeps): the rows a whole recording gives at once (trafficEventsOf).
        BlackBox box(testHeader());
        box.append(RecordEvent::data(RecordEvent::Kind::Tx, 1000, kRequest));
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, 2000, "\x55" + kReply.left(6)));
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, 3000, kReply.mid(6)));
        RecordEvent reopened;
        reopened.kind = RecordEvent::Kind::Link;
        reopened.timeNs = 4000;
        reopened.link = LinkEventKind::BaudChanged;
        reopened.baud = 1000000;
        box.append(reopened);
        box.append(RecordEvent::data(RecordEvent::Kind::Rx, 5000, kReply));
        ContextSnapshot before;
        const auto records = box.events(&before);
        const auto whole = trafficEventsOf(records, before);
        lk::bus::TrafficBatch byRecord;
        RecordedFrameParser parser(before);
        const auto sink = [&byRecord](const RecordedFrame &f) {
            byRecord.append(trafficEventOf(f));
        };
        for (const RecordEvent &r : records) {
            parser.feed(r, sink);
            if (const auto note = noteEventOf(r))
                byRecord.append(*note);
        }
        QVERIFY(!noteEventOf(records.first()));
        QCOMPARE(byRecord.size(), whole.size());
        QCOMPARE(whole.size(), 5); // sent, garbage, frame, note, frame
        for (int i = 0; i < whole.size(); ++i) {
            QCOMPARE(int(byRecord[i].kind), int(whole[i].kind));
            QCOMPARE(byRecord[i].time, whole[i].time);
            QCOMPARE(byRecord[i].bytes, whole[i].bytes);
            QCOMPARE(byRecord[i].text, whole[i].text);
        }
    }
};

QTEST_APPLESS_MAIN(tst_BlackBox)
#include "tst_blackbox.moc"
