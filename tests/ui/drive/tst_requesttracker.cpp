#include <drive/RequestTracker.h>

#include <bus/BusSession.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <memory>

using namespace lk;
using bus::BusSession;
using bus::RequestResult;
using ui::RequestTracker;

namespace {
protocol::Request readState(int id)
{
    protocol::Request r;
    r.command = protocol::Command::ReadState1;
    r.id = static_cast<quint8>(id);
    return r;
}
} // namespace

/// RequestTracker over closed sessions (each send ends Disconnected, queued): what is pending,
/// and whose callback runs.
class tst_RequestTracker : public QObject {
    Q_OBJECT
private slots:
    void callbackOnceAndPendingCount();
    void forgetAllDropsResults();
    void ticketsOfAnotherSessionDoNotMix();
    void noSessionSendsNothing();
};

void tst_RequestTracker::callbackOnceAndPendingCount()
{
    BusSession session;
    RequestTracker tracker;
    tracker.setSession(&session);
    QSignalSpy pending(&tracker, &RequestTracker::pendingChanged);
    QVector<RequestResult> results;
    const quint64 t = tracker.send(readState(3), [&](const RequestResult &r) {
        QVERIFY(!tracker.isPending(r.ticket)); // out of the count before the callback
        results.append(r);
    });
    QVERIFY(t != 0);
    QVERIFY(tracker.isPending(t));
    QCOMPARE(tracker.pendingCount(), 1);
    QTRY_COMPARE(results.size(), 1);
    QCOMPARE(results.at(0).ticket, t);
    QCOMPARE(results.at(0).status, bus::RequestStatus::Disconnected);
    QCOMPARE(tracker.pendingCount(), 0);
    QCOMPARE(pending.size(), 2);
    QCOMPARE(pending.at(1).at(0).toInt(), 0);
    QTest::qWait(50);
    QCOMPARE(results.size(), 1);
}

void tst_RequestTracker::forgetAllDropsResults()
{
    BusSession session;
    RequestTracker tracker;
    tracker.setSession(&session);
    QSignalSpy done(&session, &BusSession::requestCompleted);
    int calls = 0;
    tracker.send(readState(3), [&calls](const RequestResult &) { ++calls; });
    tracker.forgetAll();
    QCOMPARE(tracker.pendingCount(), 0);
    const quint64 later = tracker.send(readState(4), [&calls](const RequestResult &) { ++calls; });
    QTRY_COMPARE(done.size(), 2);
    QCOMPARE(calls, 1); // only the one sent after forgetAll()
    QVERIFY(!tracker.isPending(later));
}

void tst_RequestTracker::ticketsOfAnotherSessionDoNotMix()
{
    // Both sessions number their tickets from 1: the old one's result must not end the new
    // one's request.
    BusSession a, b;
    RequestTracker tracker;
    tracker.setSession(&a);
    QVector<int> seen;
    const quint64 ta =
        tracker.send(readState(1), [&seen](const RequestResult &r) { seen << r.request.id; });
    tracker.setSession(&b);
    const quint64 tb =
        tracker.send(readState(2), [&seen](const RequestResult &r) { seen << r.request.id; });
    QCOMPARE(ta, tb);
    QTRY_COMPARE(seen.size(), 1);
    QTest::qWait(50);
    QCOMPARE(seen, QVector<int>{2});
    QCOMPARE(tracker.pendingCount(), 0);
}

void tst_RequestTracker::noSessionSendsNothing()
{
    RequestTracker tracker;
    int calls = 0;
    QCOMPARE(tracker.send(readState(1), [&calls](const RequestResult &) { ++calls; }), 0u);
    auto session = std::make_unique<BusSession>();
    tracker.setSession(session.get());
    tracker.send(readState(1), [&calls](const RequestResult &) { ++calls; });
    session.reset(); // the session goes, and its results with it
    QCOMPARE(tracker.session(), nullptr);
    QTest::qWait(50);
    QCOMPARE(calls, 0);
    QCOMPARE(tracker.send(readState(1)), 0u);
}

QTEST_GUILESS_MAIN(tst_RequestTracker)
#include "tst_requesttracker.moc"
