// TrafficBacklog: batches kept whole and shared, the oldest dropped and counted by kind once
// none of their rows could be among the newest `limit`, the counts given with a batch used
// as they are.
#include <bus/TrafficBacklog.h>

#include <QtTest/QTest>

using lk::bus::TrafficBacklog;
using lk::bus::TrafficBatch;
using lk::bus::TrafficCounts;
using lk::bus::TrafficEvent;

namespace {

TrafficEvent row(TrafficEvent::Kind kind, double time,
                 lk::protocol::ParseError error = lk::protocol::ParseError::Garbage)
{
    TrafficEvent e;
    e.kind = kind;
    e.time = time;
    e.error = error;
    return e;
}

/// `n` rows from `t0`: a request sent, its reply, and every third a bad data checksum.
TrafficBatch batch(int n, double t0)
{
    TrafficBatch b;
    for (int i = 0; i < n; ++i) {
        if (i % 3 == 2)
            b.append(
                row(TrafficEvent::Kind::Fault, t0 + i, lk::protocol::ParseError::BadDataChecksum));
        else
            b.append(row(i % 3 ? TrafficEvent::Kind::Frame : TrafficEvent::Kind::Sent, t0 + i));
    }
    return b;
}

} // namespace

class tst_TrafficBacklog : public QObject {
    Q_OBJECT
private slots:
    void countsEventsByKind()
    {
        TrafficCounts c;
        c.add(batch(9, 0));
        c.add(row(TrafficEvent::Kind::Timeout, 9));
        c.add(row(TrafficEvent::Kind::Note, 10));
        QCOMPARE(c.events, quint64(11));
        QCOMPARE(c.sent, quint64(3));
        QCOMPARE(c.frames, quint64(3));
        QCOMPARE(c.timeouts, quint64(1));
        QCOMPARE(c.faults[size_t(lk::protocol::ParseError::BadDataChecksum)], quint64(3));
        QCOMPARE(c.faultTotal(), quint64(3));
        TrafficCounts twice = c;
        twice += c;
        QCOMPARE(twice.events, quint64(22));
        QCOMPARE(twice.faultTotal(), quint64(6));
    }

    void keepsWholeBatchesAsLongAsOneRowCouldStay()
    {
        TrafficBacklog backlog(10);
        for (int i = 0; i < 6; ++i)
            backlog.append(batch(7, i * 7)); // 42 rows
        // 10 rows need the last two batches (14 rows); the four before are dropped.
        QCOMPARE(backlog.rows(), qsizetype(14));
        QCOMPARE(backlog.batches().size(), 2);
        QCOMPARE(backlog.dropped().events, quint64(28));
        QCOMPARE(backlog.dropped().sent + backlog.dropped().frames + backlog.dropped().faultTotal(),
                 quint64(28));
        const TrafficBatch rows = backlog.takeRows();
        QCOMPARE(rows.size(), 14);
        QCOMPARE(rows.first().time, 28.0); // oldest first, in order
        QCOMPARE(rows.last().time, 41.0);
        QCOMPARE(backlog.rows(), qsizetype(0));
        QCOMPARE(backlog.takeDropped().events, quint64(28));
        QVERIFY(backlog.isEmpty());
    }

    void theNewestBatchStaysHoweverLarge()
    {
        TrafficBacklog backlog(10);
        backlog.append(batch(5, 0));
        backlog.append(batch(50, 5));
        QCOMPARE(backlog.rows(), qsizetype(50));
        QCOMPARE(backlog.dropped().events, quint64(5));
        QCOMPARE(backlog.takeRows().size(), 50); // the table keeps its newest 10
    }

    void droppedBatchesGoToTheDisposal()
    {
        TrafficBacklog backlog(10);
        QList<double> disposedFirstTimes;
        qsizetype disposedRows = 0;
        backlog.setDisposal([&](TrafficBatch &&rows) {
            disposedFirstTimes << rows.first().time;
            disposedRows += rows.size();
            rows = {};
        });
        for (int i = 0; i < 6; ++i)
            backlog.append(batch(7, i * 7));
        // The same four batches as kept without a disposal are dropped, in order, and counted.
        QCOMPARE(disposedFirstTimes, (QList<double>{0, 7, 14, 21}));
        QCOMPARE(disposedRows, qsizetype(28));
        QCOMPARE(backlog.dropped().events, quint64(28));
        QCOMPARE(backlog.rows(), qsizetype(14));
        backlog.setDisposal({}); // freed here again
        backlog.append(batch(7, 42));
        QCOMPARE(disposedRows, qsizetype(28));
        QCOMPARE(backlog.dropped().events, quint64(35));
    }

    void noLimitKeepsEverything()
    {
        TrafficBacklog backlog;
        for (int i = 0; i < 100; ++i)
            backlog.append(batch(3, i * 3));
        QCOMPARE(backlog.rows(), qsizetype(300));
        QVERIFY(backlog.dropped().events == 0);
        QCOMPARE(backlog.takeRows().size(), 300);
    }

    void givenCountsAreTheDroppedBatchesCounts()
    {
        // A caller that counted its rows while building them: the backlog adds those counts,
        // and they equal what counting the rows gives.
        TrafficBacklog counted(10);
        TrafficBacklog recounted(10);
        for (int i = 0; i < 6; ++i) {
            const TrafficBatch b = batch(7, i * 7);
            TrafficCounts c;
            c.add(b);
            counted.append(b, c);
            recounted.append(b);
        }
        QCOMPARE(counted.dropped().events, recounted.dropped().events);
        QCOMPARE(counted.dropped().sent, recounted.dropped().sent);
        QCOMPARE(counted.dropped().frames, recounted.dropped().frames);
        QCOMPARE(counted.dropped().faults, recounted.dropped().faults);
        // Counts that disagree with the rows are taken as given: it does not read the rows.
        TrafficBacklog trusting(1);
        TrafficCounts wrong;
        wrong.events = 99;
        trusting.append(batch(3, 0), wrong);
        trusting.append(batch(3, 3));
        QCOMPARE(trusting.dropped().events, quint64(99));
    }

    void droppedElsewhereAddsUp()
    {
        TrafficBacklog backlog(10);
        TrafficCounts before;
        before.add(batch(4, 0));
        backlog.addDropped(before);
        QVERIFY(!backlog.isEmpty()); // counts alone are something to hand on
        backlog.append(batch(7, 4));
        backlog.append(batch(7, 11));
        backlog.append(batch(7, 18));
        QCOMPARE(backlog.dropped().events, quint64(4 + 7));
        backlog.clear();
        QVERIFY(backlog.isEmpty());
        QCOMPARE(backlog.dropped().events, quint64(0));
    }
};

QTEST_APPLESS_MAIN(tst_TrafficBacklog)
#include "tst_trafficbacklog.moc"
