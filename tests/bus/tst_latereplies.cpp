// Late replies and the quiet period on BusWorker (split from tst_busworker): a reply after its
// timeout widens only its own drive's margin and decays; after a timeout the wire stays quiet
// until a late reply can no longer be on it, and the late reply is counted, never matched.

#include "BusTestUtil.h"

#include <bus/BusMetaTypes.h>
#include <bus/BusWorker.h>
#include <protocol/RequestBuilder.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <memory>
#include <optional>

using namespace lk;
using namespace lk::bus;
using namespace lk::bustest;
using protocol::Command;
using protocol::Series;

/// BusWorker on the test thread over a scripted FakeTransport, on a clock the test advances.
class tst_LateReplies : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerBusMetaTypes(); }
    void lateReplyWidensMargin();
    void lateLiftDecays();
    void quietPeriodHoldsTheRetry();
    void lateReplyInQuietPeriodIsCountedNotMatched();
    void slowWriteKeepsPromptReplyItsOwn();
};

void tst_LateReplies::lateReplyWidensMargin()
{
    // Drive 1 and drive 2 both answer after 150 ms, far beyond the 5 ms margin. Drive 1's
    // late reply lifts drive 1's timeout, so that it is waited for next time; drive 2's
    // timeout, and the link's margin, stay where they were: one late drive does not stall
    // the others (drive 2's request times out as soon as before).
    BusConfig c = relaxedConfig();
    c.minMarginMs = c.initialMarginMs = 5;
    c.maxMarginMs = 400;
    WorkerRig rig(
        [](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            t.drives().add(2, Series::MF);
            t.setReplyDelayMs(150);
        },
        c, 115200, RigTime::Manual);
    const double before = rig.worker->currentMarginMs();
    const quint64 ticket = rig.send(plainRequest(Command::ReadState1, 1), Priority::Operator, 0);
    QVERIFY(rig.runUntil([&] { return rig.result(ticket); }, 5000));
    QCOMPARE(rig.result(ticket)->status, RequestStatus::Timeout);
    rig.runUntil([&] { return rig.worker->statisticsSnapshot().bus.lateReplies == 1; }, 5000);
    QCOMPARE(rig.worker->statisticsSnapshot().bus.lateReplies, quint64(1));
    QCOMPARE(rig.worker->currentMarginMs(), before);
    QVERIFY2(rig.worker->replyTimeoutS(Command::ReadState1, 1) > 0.2,
             qPrintable(QString::number(rig.worker->replyTimeoutS(Command::ReadState1, 1))));
    QVERIFY(rig.worker->replyTimeoutS(Command::ReadState1, 2) < 0.02);
    const double sent = rig.nowMs();
    const quint64 other = rig.send(plainRequest(Command::ReadState1, 2), Priority::Operator, 0);
    QVERIFY(rig.runUntil([&] { return rig.result(other); }, 5000));
    QCOMPARE(rig.result(other)->status, RequestStatus::Timeout);
    QVERIFY2(rig.nowMs() - sent < 20, qPrintable(QString::number(rig.nowMs() - sent)));
}

void tst_LateReplies::lateLiftDecays()
{
    // After its late reply, drive 1 answers quickly again: each reply in time halves the
    // lift, and it is gone once it is smaller than the least margin.
    BusConfig c = relaxedConfig();
    c.minMarginMs = c.initialMarginMs = 5;
    c.maxMarginMs = 400;
    FakeTransport *transport = nullptr;
    WorkerRig rig(
        [&transport](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            t.setReplyDelayMs(150);
            transport = &t;
        },
        c, 115200, RigTime::Manual);
    const quint64 ticket = rig.send(plainRequest(Command::ReadState1, 1), Priority::Operator, 0);
    QVERIFY(rig.runUntil([&] { return rig.result(ticket); }, 5000));
    rig.runUntil([&] { return rig.worker->statisticsSnapshot().bus.lateReplies == 1; }, 5000);
    transport->setReplyDelayMs(1);
    int replies = 0;
    double lastTimeoutMs = 0;
    for (; replies < 20; ++replies) {
        const quint64 t = rig.send(plainRequest(Command::ReadState1, 1), Priority::Operator, 0);
        QVERIFY(rig.runUntil([&] { return rig.result(t); }, 5000));
        QCOMPARE(rig.result(t)->status, RequestStatus::Ok);
        lastTimeoutMs = rig.worker->replyTimeoutS(Command::ReadState1, 1) * 1e3;
        if (lastTimeoutMs < 20)
            break;
    }
    QVERIFY2(replies <= 8, qPrintable(QString::number(replies)));
    QVERIFY2(lastTimeoutMs < 20, qPrintable(QString::number(lastTimeoutMs)));
}

namespace {
/// Timeouts and quiet periods long enough that the timers below fall clearly between them.
BusConfig quietTestConfig()
{
    BusConfig c = relaxedConfig();
    c.minMarginMs = c.initialMarginMs = 40;
    return c;
}
} // namespace

void tst_LateReplies::quietPeriodHoldsTheRetry()
{
    // ID 9 is silent. Timeout ~43 ms after the write, then a quiet period of at least 40 ms
    // (the margin floor): a marker timer due at 64 ms from the write fires before the quiet
    // ends (the test's clock fires timers in due order).
    auto markerFired = std::make_shared<bool>(false);
    auto firedAtRetry = std::make_shared<std::optional<bool>>();
    WorkerRig rig(
        [markerFired, firedAtRetry](FakeTransport &t) {
            FakeTransport *tp = &t;
            t.setResponder([=](const protocol::Frame &, int index) {
                if (index == 0)
                    tp->after(64, [markerFired] { *markerFired = true; });
                else if (index == 1)
                    *firedAtRetry = *markerFired;
                return QByteArray();
            });
        },
        quietTestConfig(), 115200, RigTime::Manual);
    const quint64 t = rig.send(plainRequest(Command::ReadState1, 9), Priority::Operator, 1);
    QVERIFY(rig.runUntil([&] { return rig.result(t); }, 10000));
    QCOMPARE(rig.result(t)->status, RequestStatus::Timeout);
    QCOMPARE(rig.result(t)->attempts, 2);
    QVERIFY(firedAtRetry->has_value());
    QVERIFY2(**firedAtRetry, "the retry went out while a late reply could still be on the wire");
}

void tst_LateReplies::lateReplyInQuietPeriodIsCountedNotMatched()
{
    // ID 1 answers its first read_state1 late and slowly: the first bytes 60 ms after the
    // write (after the ~43 ms timeout, inside the quiet period that ends >= 83 ms), the rest
    // at 95 ms, after the quiet period would have ended had the first bytes not restarted it.
    // The next request (to ID 2) must wait until the late reply is complete, and that late
    // reply is counted, not taken for ID 2's answer.
    auto lateSeenAtNextWrite = std::make_shared<std::optional<quint64>>();
    BusWorker *worker = nullptr;
    WorkerRig rig(
        [&worker, lateSeenAtNextWrite](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            t.drives().add(2, Series::MF);
            FakeTransport *tp = &t;
            t.setResponder([=, &worker](const protocol::Frame &req, int index) {
                if (index == 0) {
                    const QByteArray late = tp->defaultReply(req);
                    // Emitted directly (not through inject(), which queues once more): the
                    // bytes arrive exactly in timer order.
                    tp->after(60, [tp, late] { emit tp->bytesReceived(late.left(4)); });
                    tp->after(95, [tp, late] { emit tp->bytesReceived(late.mid(4)); });
                    return QByteArray();
                }
                if (index == 1)
                    *lateSeenAtNextWrite = worker->lateReplyCount();
                return tp->defaultReply(req);
            });
        },
        quietTestConfig(), 115200, RigTime::Manual);
    worker = rig.worker.get();
    const quint64 first = rig.send(plainRequest(Command::ReadState1, 1), Priority::Operator, 0);
    const quint64 next = rig.send(plainRequest(Command::ReadState1, 2), Priority::Operator, 0);
    QVERIFY(rig.runUntil([&] { return rig.result(next); }, 10000));
    QCOMPARE(rig.result(first)->status, RequestStatus::Timeout);
    QVERIFY(lateSeenAtNextWrite->has_value());
    QCOMPARE(**lateSeenAtNextWrite, quint64(1)); // the whole late reply came before the write
    QCOMPARE(rig.result(next)->status, RequestStatus::Ok);
    QCOMPARE(int(rig.result(next)->reply->id), 2);
    const BusStatistics st = rig.worker->statisticsSnapshot();
    QCOMPARE(st.bus.lateReplies, quint64(1));
    QCOMPARE(st.perId.value(1).lateReplies, quint64(1));
    QCOMPARE(st.bus.unexpectedFrames, quint64(0));
    QCOMPARE(st.bus.replies, quint64(1));
}

void tst_LateReplies::slowWriteKeepsPromptReplyItsOwn()
{
    // Drive 1 answers read_state1 2 ms after each write; one reply is lost. Then a write takes
    // 3 ms to return (a preempted thread, or the in-process simulator computing its reply inside
    // write()), and the reply is there 1 ms after it returned: 4 ms after the write began, later
    // than the 1.6 ms its bytes and ours need on the wire at 115200 baud. That reply is this
    // request's, not the late answer to the lost one. (Measured from the write's return, it
    // looked too soon, was taken for the late reply, and every retry after it timed out alike.)
    auto slowWrite = std::make_shared<bool>(false);
    WorkerRig *rigAtWrite = nullptr;
    WorkerRig rig(
        [slowWrite, &rigAtWrite](FakeTransport &t) {
            t.drives().add(1, Series::MF);
            FakeTransport *tp = &t;
            t.setResponder([=, &rigAtWrite](const protocol::Frame &req, int index) {
                if (index == 3)
                    return QByteArray(); // lost
                const QByteArray reply = tp->defaultReply(req);
                if (*slowWrite)
                    rigAtWrite->timers->clock()->advanceMs(3);
                tp->after(*slowWrite ? 1 : 2, [tp, reply] { emit tp->bytesReceived(reply); });
                return QByteArray();
            });
        },
        quietTestConfig(), 115200, RigTime::Manual);
    rigAtWrite = &rig;
    const auto readState = [&rig] {
        const quint64 t = rig.send(plainRequest(Command::ReadState1, 1), Priority::Operator, 0);
        return rig.runUntil([&] { return rig.result(t); }, 10000) ? rig.result(t)->status
                                                                  : RequestStatus::Error;
    };
    for (int i = 0; i < 3; ++i)
        QCOMPARE(readState(), RequestStatus::Ok);
    QCOMPARE(readState(), RequestStatus::Timeout);
    *slowWrite = true;
    for (int i = 0; i < 3; ++i)
        QCOMPARE(readState(), RequestStatus::Ok);
    const BusStatistics st = rig.worker->statisticsSnapshot();
    QCOMPARE(st.bus.lateReplies, quint64(0));
    QCOMPARE(st.bus.replies, quint64(6));
}

QTEST_GUILESS_MAIN(tst_LateReplies)
#include "tst_latereplies.moc"
