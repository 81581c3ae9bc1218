#include <bus/BusTiming.h>
#include <bus/PollScheduler.h>

#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::bus;
using protocol::Command;
using protocol::Series;

namespace {
PollPlan plan(QVector<int> ids, QVector<Command> commands, double rateHz = 0)
{
    PollPlan p;
    p.ids = std::move(ids);
    p.commands = std::move(commands);
    p.rateHz = rateHz;
    return p;
}

QPair<Command, int> key(const std::optional<protocol::Request> &r)
{
    return r ? qMakePair(r->command, int(r->id)) : qMakePair(Command::ReadModel, -1);
}
} // namespace

/// Round robin, no double queueing, series skips and the rate limit of PollScheduler.
class tst_PollScheduler : public QObject {
    Q_OBJECT
private slots:
    void roundRobin();
    void neverHandsOutAnOutstandingSlot();
    void skipsCommandsTheSeriesLacks();
    void allSkippedDoesNotSpin();
    void rateLimit();
    void numbersRounds();
    void dropsNonReadsAndBadIds();
    void busLimitFollowsTheMix();
};

void tst_PollScheduler::roundRobin()
{
    PollScheduler s;
    s.setPlan(plan({1, 2}, {Command::ReadState2, Command::ReadState1}), 0);
    const QVector<QPair<Command, int>> expected{{Command::ReadState2, 1},
                                                {Command::ReadState1, 1},
                                                {Command::ReadState2, 2},
                                                {Command::ReadState1, 2},
                                                {Command::ReadState2, 1}};
    for (const auto &e : expected) {
        const auto r = s.next(0);
        QCOMPARE(key(r), e);
        s.completed(r->id, r->command);
    }
}

void tst_PollScheduler::neverHandsOutAnOutstandingSlot()
{
    PollScheduler s;
    s.setPlan(plan({1}, {Command::ReadState2, Command::ReadState1}), 0);
    const auto a = s.next(0);
    const auto b = s.next(0);
    QVERIFY(a && b);
    QVERIFY(key(a) != key(b));
    QCOMPARE(s.outstanding(), 2);
    QVERIFY(!s.next(0));
    QVERIFY(std::isinf(s.nextDueTime(0)));
    s.completed(1, Command::ReadState2);
    QCOMPARE(key(s.next(0)), qMakePair(Command::ReadState2, 1));
    QVERIFY(!s.next(0));
}

void tst_PollScheduler::skipsCommandsTheSeriesLacks()
{
    PollScheduler s;
    s.setSeriesLookup([](int id) -> std::optional<Series> {
        if (id == 2)
            return Series::MS;
        return std::nullopt; // unknown: polled, a silent drive just times out
    });
    s.setPlan(plan({1, 2}, {Command::ReadState3, Command::ReadState2}), 0);
    QVector<QPair<Command, int>> got;
    for (int i = 0; i < 6; ++i) {
        const auto r = s.next(0);
        QVERIFY(r);
        got.append(key(r));
        s.completed(r->id, r->command);
    }
    QVERIFY(!got.contains(qMakePair(Command::ReadState3, 2)));
    QVERIFY(got.contains(qMakePair(Command::ReadState3, 1)));
    QVERIFY(got.contains(qMakePair(Command::ReadState2, 2)));
}

void tst_PollScheduler::allSkippedDoesNotSpin()
{
    PollScheduler s;
    s.setSeriesLookup([](int) -> std::optional<Series> { return Series::MS; });
    s.setPlan(plan({1}, {Command::ReadState3}), 0);
    QVERIFY(s.isActive());
    QVERIFY(!s.next(0));
    QVERIFY(std::isinf(s.nextDueTime(0)));
}

void tst_PollScheduler::rateLimit()
{
    PollScheduler s;
    s.setPlan(plan({1}, {Command::ReadState2, Command::ReadState1}, 10), 0);
    // A whole cycle goes back to back, then waits for the next 1/10 s.
    auto r = s.next(0);
    s.completed(r->id, r->command);
    r = s.next(0.001);
    QVERIFY(r);
    s.completed(r->id, r->command);
    QVERIFY(!s.next(0.05));
    QCOMPARE(s.nextDueTime(0.05), 0.1);
    r = s.next(0.1);
    QCOMPARE(key(r), qMakePair(Command::ReadState2, 1));
    s.completed(r->id, r->command);
    // A late cycle starts at once (as fast as the bus allows) and re-anchors the period.
    r = s.next(0.35);
    QVERIFY(r);
    s.completed(r->id, r->command);
    QCOMPARE(s.nextDueTime(0.36), 0.36); // the rest of the cycle is due now
}

void tst_PollScheduler::numbersRounds()
{
    // Every poll of a round has the round's number and start time; a new plan is a new round.
    PollScheduler s;
    s.setPlan(plan({1, 2}, {Command::ReadState2}, 10), 0.5);
    QCOMPARE(s.cycle(), quint64(1));
    for (double t : {0.5, 0.502}) {
        const auto r = s.next(t);
        QVERIFY(r);
        QCOMPARE(s.cycle(), quint64(1));
        QCOMPARE(s.cycleStart(), 0.5);
        s.completed(r->id, r->command);
    }
    const auto r = s.next(0.6);
    QCOMPARE(key(r), qMakePair(Command::ReadState2, 1));
    QCOMPARE(s.cycle(), quint64(2));
    QCOMPARE(s.cycleStart(), 0.6);
    s.setPlan(plan({1}, {Command::ReadState1}), 0.61);
    QCOMPARE(s.cycle(), quint64(3));
    QCOMPARE(s.cycleStart(), 0.61);
}

void tst_PollScheduler::dropsNonReadsAndBadIds()
{
    PollScheduler s;
    s.setPlan(
        plan({0, 1, 33, 1}, {Command::Speed, Command::MotorOff, Command::ReadState2,
                             Command::ReadState2, Command::ClearErrors, Command::WritePidRom}),
        0);
    QCOMPARE(s.plan().ids, QVector<int>{1});
    QCOMPARE(s.plan().commands, QVector<Command>{Command::ReadState2});
    s.clear();
    QVERIFY(!s.isActive());
    QVERIFY(!s.next(0));
}

void tst_PollScheduler::busLimitFollowsTheMix()
{
    PollScheduler s;
    s.setSeriesLookup([](int id) -> std::optional<Series> {
        return id == 2 ? std::optional<Series>(Series::MS) : std::nullopt;
    });
    s.setPlan(plan({1, 2}, {Command::ReadState2, Command::ReadState3}), 0);
    const double expected = BusTiming::transactionsPerSecond(
        {Command::ReadState2, Command::ReadState3, Command::ReadState2}, 115200);
    QVERIFY(qAbs(s.busLimitPerSecond(115200) - expected) < 1e-9);
}

QTEST_APPLESS_MAIN(tst_PollScheduler)
#include "tst_pollscheduler.moc"
