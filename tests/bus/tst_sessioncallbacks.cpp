#include "BusTestUtil.h"

#include <bus/BusSession.h>

#include <QtCore/QThread>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <atomic>
#include <memory>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

namespace {
/// FakeTransports with drives 3 and 9, answering after `delayMs`.
TransportFactory fakeBus(int delayMs = 0)
{
    return [delayMs](int baud) {
        auto t = std::make_unique<FakeTransport>(baud, std::make_shared<FakeLog>());
        t->drives().add(3, Series::MF);
        t->drives().add(9, Series::MF);
        t->setReplyDelayMs(delayMs);
        return t;
    };
}

/// What one callback saw: each call's result and thread (`count` last, for other threads).
struct Calls {
    QVector<RequestResult> results;
    QVector<QThread *> threads;
    std::atomic<int> count{0};
    BusSession::Completion record()
    {
        return [this](const RequestResult &r) {
            results.append(r);
            threads.append(QThread::currentThread());
            ++count;
        };
    }
};

QVector<RequestResult> completed(const QSignalSpy &spy)
{
    QVector<RequestResult> out;
    for (const auto &args : spy)
        out.append(args.at(0).value<RequestResult>());
    return out;
}
} // namespace

/// BusSession::send() with a context and a callback, and emergencyStop() with one.
class tst_SessionCallbacks : public QObject {
    Q_OBJECT
private slots:
    void callbackOnceWithItsResult();
    void callbackAfterRequestCompleted();
    void callbackOnContextThread();
    void droppedWhenContextDies();
    void droppedWhenOtherThreadContextDies();
    void closedSessionCallsBack();
    void closeEndsCallbacksCancelled();
    void emergencyStopCallback();
};

void tst_SessionCallbacks::callbackOnceWithItsResult()
{
    BusSession session;
    QSignalSpy done(&session, &BusSession::requestCompleted);
    session.open(fakeBus(), 115200, relaxedConfig());
    QTRY_VERIFY(session.connection().isOpen());
    QObject context;
    Calls a, b;
    const quint64 ta = session.send(plainRequest(Command::ReadState1, 3), &context, a.record());
    const quint64 tb = session.send(plainRequest(Command::ReadState2, 9), &context, b.record());
    QVERIFY(a.results.isEmpty()); // never inside send()
    QTRY_VERIFY_WITH_TIMEOUT(a.results.size() == 1 && b.results.size() == 1, 10000);
    QCOMPARE(a.results.at(0).ticket, ta);
    QCOMPARE(a.results.at(0).request.command, Command::ReadState1);
    QCOMPARE(a.results.at(0).status, RequestStatus::Ok);
    QCOMPARE(b.results.at(0).ticket, tb);
    QCOMPARE(b.results.at(0).request.id, quint8(9));
    QCOMPARE(std::get<protocol::State2>(b.results.at(0).reply->payload).encoder, quint16(4000));
    // The same result as the signal that carries its ticket.
    for (const RequestResult &r : completed(done)) {
        const RequestResult &mine = r.ticket == ta ? a.results.at(0) : b.results.at(0);
        QCOMPARE(mine.status, r.status);
        QCOMPARE(mine.attempts, r.attempts);
        QCOMPARE(mine.latencyMs, r.latencyMs);
    }
    QCOMPARE(done.size(), 2);
    QTest::qWait(200);
    QCOMPARE(a.results.size(), 1);
    QCOMPARE(b.results.size(), 1);
    session.close();
    QCOMPARE(a.results.size(), 1);
}

void tst_SessionCallbacks::callbackAfterRequestCompleted()
{
    // Observers (CommandedMotion, ...) have their state before the sender reacts.
    BusSession session;
    session.open(fakeBus(), 115200, relaxedConfig());
    QStringList order;
    connect(&session, &BusSession::requestCompleted, this,
            [&order] { order << QStringLiteral("signal"); });
    QObject context;
    session.send(plainRequest(Command::ReadState1, 3), &context,
                 [&order](const RequestResult &) { order << QStringLiteral("callback"); });
    QTRY_COMPARE_WITH_TIMEOUT(order.size(), 2, 10000);
    QCOMPARE(order, (QStringList{QStringLiteral("signal"), QStringLiteral("callback")}));
}

void tst_SessionCallbacks::callbackOnContextThread()
{
    BusSession session;
    session.open(fakeBus(), 115200, relaxedConfig());
    QThread other;
    other.start();
    auto *remote = new QObject;
    remote->moveToThread(&other);
    QObject local;
    Calls here, there;
    const quint64 t = session.send(plainRequest(Command::ReadState1, 3), remote, there.record());
    session.send(plainRequest(Command::ReadState1, 9), &local, here.record());
    QTRY_VERIFY_WITH_TIMEOUT(here.results.size() == 1, 10000);
    QCOMPARE(here.threads.at(0), QThread::currentThread());
    QTRY_COMPARE_WITH_TIMEOUT(there.count.load(), 1, 10000);
    remote->deleteLater();
    other.quit();
    QVERIFY(other.wait(5000));
    QCOMPARE(there.results.size(), 1);
    QCOMPARE(there.results.at(0).ticket, t);
    QCOMPARE(there.threads.at(0), &other);
}

void tst_SessionCallbacks::droppedWhenContextDies()
{
    BusSession session;
    QSignalSpy done(&session, &BusSession::requestCompleted);
    session.open(fakeBus(200), 115200, relaxedConfig());
    QTRY_VERIFY(session.connection().isOpen());
    int calls = 0;
    auto context = std::make_unique<QObject>();
    const quint64 t = session.send(plainRequest(Command::ReadState1, 3), context.get(),
                                   [&calls](const RequestResult &) { ++calls; });
    context.reset();
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), 1, 10000);
    QCOMPARE(completed(done).at(0).ticket, t); // the request itself still ends
    QCOMPARE(completed(done).at(0).status, RequestStatus::Ok);
    QTest::qWait(100);
    QCOMPARE(calls, 0);

    // Also when the context dies inside another listener of the same end.
    auto doomed = std::make_unique<QObject>();
    const auto c =
        connect(&session, &BusSession::requestCompleted, this, [&doomed] { doomed.reset(); });
    session.send(plainRequest(Command::ReadState1, 3), doomed.get(),
                 [&calls](const RequestResult &) { ++calls; });
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), 2, 10000);
    disconnect(c);
    QVERIFY(!doomed);
    QTest::qWait(100);
    QCOMPARE(calls, 0);
}

void tst_SessionCallbacks::droppedWhenOtherThreadContextDies()
{
    BusSession session;
    QSignalSpy done(&session, &BusSession::requestCompleted);
    session.open(fakeBus(300), 115200, relaxedConfig());
    QTRY_VERIFY(session.connection().isOpen());
    QThread other;
    other.start();
    auto *remote = new QObject;
    remote->moveToThread(&other);
    std::atomic<int> calls{0};
    session.send(plainRequest(Command::ReadState1, 3), remote,
                 [&calls](const RequestResult &) { ++calls; });
    remote->deleteLater(); // deleted on its own thread, before the reply is due
    QTRY_COMPARE_WITH_TIMEOUT(done.size(), 1, 10000);
    QTest::qWait(200);
    other.quit();
    QVERIFY(other.wait(5000));
    QCOMPARE(calls.load(), 0);
}

void tst_SessionCallbacks::closedSessionCallsBack()
{
    BusSession session;
    QObject context;
    Calls calls;
    const quint64 t = session.send(plainRequest(Command::ReadState1, 3), &context, calls.record());
    QVERIFY(calls.results.isEmpty()); // the caller holds the ticket first
    QTRY_COMPARE(calls.results.size(), 1);
    QCOMPARE(calls.results.at(0).ticket, t);
    QCOMPARE(calls.results.at(0).status, RequestStatus::Disconnected);
    QTest::qWait(50);
    QCOMPARE(calls.results.size(), 1);
}

void tst_SessionCallbacks::closeEndsCallbacksCancelled()
{
    BusSession session;
    session.open(fakeBus(2000), 115200, relaxedConfig()); // nothing answers before close()
    QTRY_VERIFY(session.connection().isOpen());
    QObject context;
    Calls calls;
    QVector<quint64> tickets;
    for (int i = 0; i < 3; ++i)
        tickets << session.send(plainRequest(Command::ReadState1, 3), &context, calls.record());
    QTest::qWait(50);
    session.close();
    // Delivered before close() returned, once each.
    QCOMPARE(calls.results.size(), 3);
    for (int i = 0; i < 3; ++i) {
        QCOMPARE(calls.results.at(i).ticket, tickets.at(i));
        QCOMPARE(calls.results.at(i).status, RequestStatus::Cancelled);
    }
    QTest::qWait(100);
    QCOMPARE(calls.results.size(), 3);
}

void tst_SessionCallbacks::emergencyStopCallback()
{
    BusSession session;
    QSignalSpy finished(&session, &BusSession::emergencyStopFinished);
    session.open(fakeBus(), 115200, relaxedConfig());
    session.setSeries(3, Series::MF);
    QObject context;
    QVector<QPair<QVector<int>, QVector<int>>> outcomes;
    QVector<QVector<int>> unsent;
    const auto record = [&outcomes, &unsent](const QVector<int> &ack, const QVector<int> &silent,
                                             const QVector<int> &never) {
        outcomes.append({ack, silent});
        unsent.append(never);
    };
    const quint64 t = session.emergencyStop({9}, Command::MotorOff, &context, record);
    QVERIFY(outcomes.isEmpty());
    QTRY_COMPARE_WITH_TIMEOUT(outcomes.size(), 1, 20000);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(0).toULongLong(), t);
    QCOMPARE(outcomes.at(0).first, (QVector<int>{3, 9}));
    QCOMPARE(outcomes.at(0).first, finished.at(0).at(1).value<QVector<int>>());
    QCOMPARE(outcomes.at(0).second, finished.at(0).at(2).value<QVector<int>>());
    QVERIFY(unsent.at(0).isEmpty()); // the link was up: every off went out
    session.close();

    // Closed: every ID silent, reported the same way.
    QObject gone;
    int calls = 0;
    auto dead = std::make_unique<QObject>();
    session.emergencyStop(
        {}, Command::MotorOff, dead.get(),
        [&calls](const QVector<int> &, const QVector<int> &, const QVector<int> &) { ++calls; });
    session.emergencyStop({}, Command::MotorOff, &gone, record);
    dead.reset();
    QTRY_COMPARE(outcomes.size(), 2);
    QVERIFY(outcomes.at(1).first.isEmpty());
    QCOMPARE(outcomes.at(1).second.size(), 32);
    QCOMPARE(unsent.at(1), outcomes.at(1).second); // none of them went out
    QCOMPARE(calls, 0);
}

QTEST_GUILESS_MAIN(tst_SessionCallbacks)
#include "tst_sessioncallbacks.moc"
