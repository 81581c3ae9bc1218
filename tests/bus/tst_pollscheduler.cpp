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

/// Round robin, no double queueing, focus on one drive, series skips and the rate limit of
/// PollScheduler.
class tst_PollScheduler : public QObject {
    Q_OBJECT
private slots:
    void roundRobin();
    void neverHandsOutAnOutstandingSlot();
    void skipsCommandsTheSeriesLacks();
    void unknownSeriesLearnsWhatItLacks();
    void allSkippedDoesNotSpin();
    void rateLimit();
    void numbersRounds();
    void dropsNonReadsAndBadIds();
    void busLimitFollowsTheMix();
    void focusPollsOneDriveBackToBack();
    void focusKeepsTheOthersRate();
    void focusWithoutOthers();
    void focusTheDriveCannotAnswerLeavesTheBusToOthers();
    void focusBusLimitFollowsItsMix();
    void planWithoutFocusAfterFocus();
    void extraCommandsForTheirIdOnly();
    void extraCommandsOfAnIdOutsideThePlan();
    void focusDriveKeepsToItsFocusCommands();
    void busLimitCountsExtraCommands();
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

void tst_PollScheduler::unknownSeriesLearnsWhatItLacks()
{
    // Drive 1's series is unknown, drive 2 is a known MF. Both leave 0x9D unanswered while
    // answering 0x9C: drive 1 is taken to be of a series without it and asked no more; drive
    // 2's series answers it, so its timeouts stay what they are (a fault to show), and it is
    // still asked. clear() forgets what was learnt.
    PollScheduler s;
    s.setSeriesLookup([](int id) -> std::optional<Series> {
        if (id == 2)
            return Series::MF;
        return std::nullopt;
    });
    s.setPlan(plan({1, 2}, {Command::ReadState2, Command::ReadState3}), 0);
    int mutedAt = 0;
    QVector<QPair<Command, int>> after;
    for (int i = 0; i < 60; ++i) {
        const auto r = s.next(0);
        QVERIFY(r);
        s.completed(r->id, r->command);
        if (mutedAt > 0)
            after.append(key(r));
        if (s.noteAnswer(r->id, r->command, r->command != Command::ReadState3)) {
            QCOMPARE(int(r->id), 1);
            mutedAt = i;
        }
    }
    QVERIFY(mutedAt > 0);
    QVERIFY(s.isMuted(1, Command::ReadState3));
    QVERIFY(!s.isMuted(2, Command::ReadState3));
    QVERIFY(!after.contains(qMakePair(Command::ReadState3, 1)));
    QVERIFY(after.contains(qMakePair(Command::ReadState3, 2)));
    QVERIFY(after.contains(qMakePair(Command::ReadState2, 1)));
    s.clear();
    QVERIFY(!s.isMuted(1, Command::ReadState3));
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

namespace {
// `n` polls at time `t`, each completed at once, as the worker pulls them on an idle bus.
QVector<QPair<Command, int>> pull(PollScheduler &s, int n, double t = 0)
{
    QVector<QPair<Command, int>> got;
    for (int i = 0; i < n; ++i) {
        const auto r = s.next(t);
        got.append(key(r));
        if (r)
            s.completed(r->id, r->command);
    }
    return got;
}
} // namespace

void tst_PollScheduler::focusPollsOneDriveBackToBack()
{
    // Drive 2 in focus with its own commands; drives 1 and 3 share one poll per 3 focus polls.
    PollScheduler s;
    s.setPlan(plan({1, 2, 3}, {Command::ReadState1}, 0)
                  .focusedOn(2, {Command::ReadMultiTurn, Command::ReadState2}, 3),
              0);
    const QVector<QPair<Command, int>> expected{
        {Command::ReadMultiTurn, 2}, {Command::ReadState2, 2}, {Command::ReadMultiTurn, 2},
        {Command::ReadState1, 1},    {Command::ReadState2, 2}, {Command::ReadMultiTurn, 2},
        {Command::ReadState2, 2},    {Command::ReadState1, 3}, {Command::ReadMultiTurn, 2}};
    QCOMPARE(pull(s, expected.size()), expected);
    QCOMPARE(s.plan().focusId, 2);
    QCOMPARE(s.plan().focusCommands,
             (QVector<Command>{Command::ReadMultiTurn, Command::ReadState2}));
}

void tst_PollScheduler::focusKeepsTheOthersRate()
{
    // The plan's rate binds the other drives' rounds only: the focus never waits.
    PollScheduler s;
    s.setPlan(plan({1, 2}, {Command::ReadState2}, 10).focusedOn(2, {Command::ReadState2}, 1), 0);
    QCOMPARE(pull(s, 2),
             (QVector<QPair<Command, int>>{{Command::ReadState2, 2}, {Command::ReadState2, 1}}));
    // Drive 1's round is done until t = 0.1; drive 2 goes on back to back.
    QCOMPARE(pull(s, 3, 0.05), (QVector<QPair<Command, int>>(3, {Command::ReadState2, 2})));
    QCOMPARE(s.nextDueTime(0.05), 0.05);
    QCOMPARE(pull(s, 2, 0.1),
             (QVector<QPair<Command, int>>{{Command::ReadState2, 1}, {Command::ReadState2, 2}}));
}

void tst_PollScheduler::focusWithoutOthers()
{
    // focusOthersEvery 0: only the focus drive is polled; its commands default to the plan's.
    PollScheduler s;
    s.setPlan(plan({1, 2}, {Command::ReadState2, Command::ReadState1}).focusedOn(1, {}, 0), 0);
    const QVector<QPair<Command, int>> got = pull(s, 8);
    for (const auto &k : got)
        QCOMPARE(k.second, 1);
    QCOMPARE(got.count({Command::ReadState1, 1}), 4);
}

void tst_PollScheduler::focusTheDriveCannotAnswerLeavesTheBusToOthers()
{
    PollScheduler s;
    s.setSeriesLookup([](int id) -> std::optional<Series> {
        return id == 2 ? std::optional<Series>(Series::MS) : std::nullopt;
    });
    s.setPlan(plan({1, 2}, {Command::ReadState2}).focusedOn(2, {Command::ReadState3}, 4), 0);
    QCOMPARE(pull(s, 3), (QVector<QPair<Command, int>>(3, {Command::ReadState2, 1})));
}

void tst_PollScheduler::focusBusLimitFollowsItsMix()
{
    // Every 2 focus rounds (2 x 0x92 + 0x9C) two polls of the others (0x9A).
    PollScheduler s;
    s.setPlan(plan({1, 2}, {Command::ReadState1})
                  .focusedOn(2, {Command::ReadMultiTurn, Command::ReadState2}, 2),
              0);
    const QVector<Command> stretch{Command::ReadMultiTurn, Command::ReadState2,
                                   Command::ReadMultiTurn, Command::ReadState2,
                                   Command::ReadState1,    Command::ReadState1};
    const double expected = BusTiming::transactionsPerSecond(stretch, 115200);
    QVERIFY(qAbs(s.busLimitPerSecond(115200) - expected) < 1e-9);
    double stretchS = 0;
    for (Command c : stretch)
        stretchS += BusTiming::transactionTimeS(c, 115200);
    QVERIFY(qAbs(s.cycleLimitHz(115200) - 2 / stretchS) < 1e-9);
}

void tst_PollScheduler::planWithoutFocusAfterFocus()
{
    // Restoring a plain plan after a focused one gives the plain round robin back.
    PollScheduler s;
    const PollPlan dashboard = plan({1, 2}, {Command::ReadState2});
    s.setPlan(dashboard.focusedOn(2, {Command::ReadMultiTurn}, 0), 0);
    pull(s, 3);
    s.setPlan(dashboard, 1);
    QVERIFY(!s.plan().hasFocus());
    QCOMPARE(pull(s, 3, 1),
             (QVector<QPair<Command, int>>{
                 {Command::ReadState2, 1}, {Command::ReadState2, 2}, {Command::ReadState2, 1}}));
}

void tst_PollScheduler::extraCommandsForTheirIdOnly()
{
    // Drive 1's extras follow its commands in its round, without a second 0x92 and without
    // the write; drive 2 keeps the plain mix.
    PollScheduler s;
    PollPlan p = plan({1, 2}, {Command::ReadState2, Command::ReadMultiTurn});
    p.extraCommands[1] = {Command::ReadEncoder, Command::ReadMultiTurn, Command::WriteEncoderOffset,
                          Command::ReadSingleTurn, Command::ReadEncoder};
    s.setPlan(p, 0);
    QCOMPARE(s.plan().extraCommands.value(1),
             (QVector<Command>{Command::ReadEncoder, Command::ReadSingleTurn}));
    QCOMPARE(s.plan().extraCommands.size(), 1);
    QCOMPARE(pull(s, 7), (QVector<QPair<Command, int>>{{Command::ReadState2, 1},
                                                       {Command::ReadMultiTurn, 1},
                                                       {Command::ReadEncoder, 1},
                                                       {Command::ReadSingleTurn, 1},
                                                       {Command::ReadState2, 2},
                                                       {Command::ReadMultiTurn, 2},
                                                       {Command::ReadState2, 1}}));
    // Extras that the commands read already leave nothing to add.
    p.extraCommands[1] = {Command::ReadMultiTurn};
    s.setPlan(p, 1);
    QVERIFY(s.plan().extraCommands.isEmpty());
    QCOMPARE(pull(s, 5, 1), (QVector<QPair<Command, int>>{{Command::ReadState2, 1},
                                                          {Command::ReadMultiTurn, 1},
                                                          {Command::ReadState2, 2},
                                                          {Command::ReadMultiTurn, 2},
                                                          {Command::ReadState2, 1}}));
}

void tst_PollScheduler::extraCommandsOfAnIdOutsideThePlan()
{
    // Without a plan of its own (no ids, no commands) a drive's extras are polled alone;
    // IDs outside 1..32 are dropped.
    PollScheduler s;
    PollPlan p = plan({}, {});
    p.extraCommands[5] = {Command::ReadEncoder, Command::ReadMultiTurn};
    p.extraCommands[40] = {Command::ReadEncoder};
    s.setPlan(p, 0);
    QVERIFY(s.isActive());
    QCOMPARE(s.plan().extraCommands.keys(), QList<int>{5});
    QCOMPARE(pull(s, 3), (QVector<QPair<Command, int>>{{Command::ReadEncoder, 5},
                                                       {Command::ReadMultiTurn, 5},
                                                       {Command::ReadEncoder, 5}}));
    // Beside a plan: after the plan's IDs, and the plan's commands are not its.
    p = plan({1}, {Command::ReadState2});
    p.extraCommands[5] = {Command::ReadState2, Command::ReadEncoder};
    s.setPlan(p, 1);
    QCOMPARE(pull(s, 4, 1), (QVector<QPair<Command, int>>{{Command::ReadState2, 1},
                                                          {Command::ReadState2, 5},
                                                          {Command::ReadEncoder, 5},
                                                          {Command::ReadState2, 1}}));
}

void tst_PollScheduler::focusDriveKeepsToItsFocusCommands()
{
    // A step test's focus is not slowed by the focus drive's extras; another drive's extras
    // are polled in its own (rate-limited) round.
    PollScheduler s;
    PollPlan p = plan({1, 2}, {Command::ReadState2});
    p.extraCommands[1] = {Command::ReadEncoder};
    p.extraCommands[2] = {Command::ReadEncoder};
    s.setPlan(p.focusedOn(2, {Command::ReadMultiTurn}, 1), 0);
    QCOMPARE(pull(s, 6), (QVector<QPair<Command, int>>{{Command::ReadMultiTurn, 2},
                                                       {Command::ReadState2, 1},
                                                       {Command::ReadMultiTurn, 2},
                                                       {Command::ReadEncoder, 1},
                                                       {Command::ReadMultiTurn, 2},
                                                       {Command::ReadState2, 1}}));
}

void tst_PollScheduler::busLimitCountsExtraCommands()
{
    PollScheduler s;
    PollPlan p = plan({1, 2}, {Command::ReadState2});
    p.extraCommands[2] = {Command::ReadEncoder};
    s.setPlan(p, 0);
    const QVector<Command> round{Command::ReadState2, Command::ReadState2, Command::ReadEncoder};
    QVERIFY(qAbs(s.busLimitPerSecond(115200) - BusTiming::transactionsPerSecond(round, 115200)) <
            1e-9);
    double roundS = 0;
    for (Command c : round)
        roundS += BusTiming::transactionTimeS(c, 115200);
    QVERIFY(qAbs(s.cycleLimitHz(115200) - 1 / roundS) < 1e-9);
}

QTEST_APPLESS_MAIN(tst_PollScheduler)
#include "tst_pollscheduler.moc"
