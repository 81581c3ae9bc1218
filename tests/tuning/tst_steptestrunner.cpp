#include <bus/BusSession.h>
#include <bus/PollScheduler.h>
#include <protocol/RequestBuilder.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <transport/SimTransport.h>
#include <tuning/StepTestRunner.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <cmath>

using namespace lk;
using namespace lk::bus;
using namespace lk::tuning;
using protocol::Command;
using protocol::Series;

namespace {

constexpr int kWaitMs = 30000; // a loaded 2-core machine; never a timing assertion

/// The built-in simulated bus, as lkstudio's default: drives 3 (MF) and 17 (MS).
TransportFactory simFactory()
{
    return [](int baud) -> std::unique_ptr<transport::Transport> {
        auto bus = sim::SimBus::fromSpec(*sim::SimBusSpec::parse(QStringLiteral("3:MF,17:MS")));
        auto t = std::make_unique<transport::SimTransport>(std::move(bus));
        t->setBaud(baud);
        return t;
    };
}

bool isMotion(Command c)
{
    return c == Command::Speed ||
           (c >= Command::MultiPosition && c <= Command::IncrementPositionLimited);
}

/// Every motion command the session completed (each request completes exactly once).
int motionCount(const QSignalSpy &completed)
{
    int n = 0;
    for (const auto &args : completed)
        n += isMotion(args.at(0).value<RequestResult>().request.command) ? 1 : 0;
    return n;
}

StepTestSpec spec(StepLoop loop, double from, double to, int periods = 1)
{
    StepTestSpec s;
    s.id = 3;
    s.loop = loop;
    s.from = from;
    s.to = to;
    s.durationS = 0.3;
    s.preRollS = 0.2;
    s.periods = periods;
    return s;
}

/// A session on the simulated bus with drive 3 known as MF and 17 as MS.
struct Rig {
    BusSession session;
    QSignalSpy completed{&session, &BusSession::requestCompleted};
    QSignalSpy statistics{&session, &BusSession::statisticsUpdated};
    StepTestRunner runner{session};
    QSignalSpy finished{&runner, &StepTestRunner::finished};
    QSignalSpy failed{&runner, &StepTestRunner::failed};
    Rig()
    {
        session.open(simFactory());
        session.setSeries(3, Series::MF);
        session.setSeries(17, Series::MS);
    }
    StepTestResult waitForEnd()
    {
        if (!QTest::qWaitFor([this] { return finished.size() + failed.size() > 0; }, kWaitMs))
            return {};
        return (finished.isEmpty() ? failed : finished).at(0).at(0).value<StepTestResult>();
    }
    std::optional<double> readAngle()
    {
        const quint64 t = session.send(*protocol::build::plain(Command::ReadMultiTurn, 3).request);
        std::optional<double> angle;
        (void)QTest::qWaitFor(
            [&] {
                for (const auto &args : completed) {
                    const auto r = args.at(0).value<RequestResult>();
                    if (r.ticket == t && r.ok() && r.reply)
                        angle = std::get<protocol::MultiTurnAngle>(r.reply->payload).degrees();
                }
                return angle.has_value();
            },
            kWaitMs);
        return angle;
    }
};

void checkTrace(const StepTestResult &r, int edges)
{
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.trace.edges.size(), edges);
    QVERIFY2(r.trace.size() >= 10, qPrintable(QString::number(r.trace.size())));
    QCOMPARE(r.trace.value.size(), r.trace.size());
    QCOMPARE(r.trace.effort.size(), r.trace.size());
    for (int i = 1; i < r.trace.size(); ++i)
        QVERIFY(r.trace.time.at(i) >= r.trace.time.at(i - 1));
    // Edges and samples share the bus clock: each edge lies inside the trace.
    for (const StepEdge &e : r.trace.edges) {
        QVERIFY(e.time >= r.trace.time.first());
        QVERIFY(e.time <= r.trace.time.last());
    }
    for (const StepSent &s : r.sent)
        QVERIFY(s.acknowledged);
    QVERIFY(r.sampleRateHz > 0);
}

} // namespace

/// StepTestRunner against the built-in simulator: traces, refusals, abort and the poll plan.
class tst_StepTestRunner : public QObject {
    Q_OBJECT
private slots:
    void speedStep();
    void positionStep();
    void refusedPlanSendsNothing();
    void silentDriveSendsNothing();
    void abortStopsSending();
    void previousPollPlanIsRestored();
    void withoutAPlanPollingStopsAgain();
};

void tst_StepTestRunner::speedStep()
{
    Rig rig;
    QVERIFY(
        rig.runner.start(spec(StepLoop::Speed, 0, 360), safety::SoftLimits::defaults(Series::MF)));
    QVERIFY(!rig.runner.start(spec(StepLoop::Speed, 0, 360), {})); // one at a time
    const StepTestResult r = rig.waitForEnd();
    checkTrace(r, 1);
    QCOMPARE(r.trace.loop, StepLoop::Speed);
    QCOMPARE(r.trace.edges.first().from, 0.0);
    QCOMPARE(r.trace.edges.first().to, 360.0);
    QVERIFY(!r.trace.effortIsPower);
    // Pre-roll, step, return to FROM; nothing else moved the drive.
    QCOMPARE(r.sent.size(), 3);
    QCOMPARE(r.sent.last().setpoint.role, StepSetpoint::Role::Return);
    QCOMPARE(motionCount(rig.completed), 3);
    // Every speed sample carries the current (0x9C and the 0xA2 replies do).
    for (double e : r.trace.effort)
        QVERIFY(!StepTrace::isMissing(e));
    // The drive answered: it was turning towards 360 dps by the end of the step.
    double peak = 0;
    for (double v : r.trace.value)
        peak = std::max(peak, v);
    QVERIFY2(peak > 100, qPrintable(QString::number(peak)));
    QVERIFY(r.startValue);
    QCOMPARE(r.bound, safety::SpeedBound::Command);
}

void tst_StepTestRunner::positionStep()
{
    Rig rig;
    const std::optional<double> angle = rig.readAngle();
    QVERIFY(angle);
    QVERIFY(rig.runner.start(spec(StepLoop::Position, *angle + 10, *angle + 100),
                             safety::SoftLimits::defaults(Series::MF)));
    const StepTestResult r = rig.waitForEnd();
    checkTrace(r, 1);
    QCOMPARE(r.trace.loop, StepLoop::Position);
    QCOMPARE(r.sent.size(), 2); // a position test holds at TO: no return
    for (const StepSent &s : r.sent)
        QCOMPARE(s.setpoint.request.command, Command::MultiPositionLimited);
    QCOMPARE(motionCount(rig.completed), 2);
    QVERIFY(r.startValue);
    QVERIFY(std::fabs(*r.startValue - *angle) < 1);
    // The angle comes from 0x92; its effort from the same round's 0x9C, known for most.
    int withEffort = 0;
    for (double e : r.trace.effort)
        withEffort += StepTrace::isMissing(e) ? 0 : 1;
    QVERIFY2(withEffort > 0, "no angle sample carried the round's current");
    QCOMPARE(r.bound, safety::SpeedBound::SoftLimit);
}

void tst_StepTestRunner::refusedPlanSendsNothing()
{
    Rig rig;
    safety::SoftLimits limits = safety::SoftLimits::defaults(Series::MF);
    limits.maxSpeedDps = 200;
    QVERIFY(rig.runner.start(spec(StepLoop::Speed, 0, 360), limits));
    const StepTestResult r = rig.waitForEnd();
    QCOMPARE(rig.failed.size(), 1);
    QCOMPARE(r.failure, StepTestFailure::Refused);
    QCOMPARE(r.refusal.verdict.kind, safety::LimitKind::SoftSpeed);
    QVERIFY2(r.message.contains(QLatin1String("nothing was sent")), qPrintable(r.message));
    QVERIFY(!r.anythingSent());
    QTest::qWait(300); // anything sent would have completed by now
    QCOMPARE(motionCount(rig.completed), 0);
    QVERIFY(!rig.session.pollPlan()); // never focused
}

void tst_StepTestRunner::silentDriveSendsNothing()
{
    Rig rig;
    StepTestSpec s = spec(StepLoop::Position, 0, 90);
    s.id = 9; // no such drive
    QVERIFY(rig.runner.start(s, safety::SoftLimits::defaults(Series::MF)));
    const StepTestResult r = rig.waitForEnd();
    QCOMPARE(r.failure, StepTestFailure::Silent);
    QVERIFY2(r.message.contains(QLatin1String("read_multi_turn")), qPrintable(r.message));
    QCOMPARE(motionCount(rig.completed), 0);
}

void tst_StepTestRunner::abortStopsSending()
{
    Rig rig;
    QVERIFY(rig.runner.start(spec(StepLoop::Speed, 0, 180, 5),
                             safety::SoftLimits::defaults(Series::MF)));
    // Abort once the pre-roll and the first edge have gone out (11 setpoints planned).
    QVERIFY(QTest::qWaitFor([&] { return motionCount(rig.completed) >= 2; }, kWaitMs));
    rig.runner.abort();
    QCOMPARE(rig.failed.size(), 1);
    const StepTestResult r = rig.failed.at(0).at(0).value<StepTestResult>();
    QCOMPARE(r.failure, StepTestFailure::Aborted);
    QVERIFY(r.sent.size() < rig.runner.plan().setpoints().size());
    QVERIFY2(r.message.contains(QLatin1String("keeps its last command")), qPrintable(r.message));
    QVERIFY(!rig.runner.isRunning());
    // The whole test would have taken 3.2 s: nothing beyond what was handed over goes out.
    QTest::qWait(1500);
    QCOMPARE(motionCount(rig.completed), r.sent.size());
}

void tst_StepTestRunner::previousPollPlanIsRestored()
{
    Rig rig;
    const PollPlan dashboard = PollPlan::standard({3, 17}, 20);
    rig.session.startPolling(dashboard);
    // The worker reports the bus limit of the mix it polls, in polls and in rounds per second:
    // their ratio, polls per round, tells the dashboard's plan (7 polls: drive 17 is an MS,
    // without 0x9D) from the focus (9 polls of which 8 are drive 3's rounds).
    PollScheduler expected;
    expected.setSeriesLookup([&](int id) { return rig.session.series(id); });
    expected.setPlan(dashboard, 0);
    const double dashboardLimit =
        expected.busLimitPerSecond(115200) / expected.cycleLimitHz(115200);
    QCOMPARE(qRound(dashboardLimit), 7);
    const auto lastLimit = [&] {
        if (rig.statistics.isEmpty())
            return 0.0;
        const auto s = rig.statistics.last().at(0).value<BusStatistics>();
        return s.pollCycleLimitHz > 0 ? s.pollLimitPerSecond / s.pollCycleLimitHz : 0.0;
    };
    QVERIFY(
        QTest::qWaitFor([&] { return std::fabs(lastLimit() - dashboardLimit) < 1e-6; }, kWaitMs));
    QSignalSpy started(&rig.runner, &StepTestRunner::started);
    StepTestSpec s = spec(StepLoop::Speed, 0, 90);
    s.durationS = 1.5; // long enough for a statistics snapshot (2 Hz) during the focus
    QVERIFY(rig.runner.start(s, safety::SoftLimits::defaults(Series::MF)));
    QVERIFY(QTest::qWaitFor([&] { return !started.isEmpty(); }, kWaitMs));
    QVERIFY(rig.session.pollPlan()->hasFocus());
    QVERIFY(QTest::qWaitFor(
        [&] { return std::fabs(lastLimit() - dashboardLimit) > 1e-6 || !rig.finished.isEmpty(); },
        kWaitMs));
    QVERIFY2(rig.finished.isEmpty(), "no statistics snapshot while the focus lasted");
    const StepTestResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(rig.session.pollPlan()->hasFocus(), false);
    QCOMPARE(rig.session.pollPlan()->ids, dashboard.ids);
    QCOMPARE(rig.session.pollPlan()->rateHz, dashboard.rateHz);
    QVERIFY(
        QTest::qWaitFor([&] { return std::fabs(lastLimit() - dashboardLimit) < 1e-6; }, kWaitMs));
}

void tst_StepTestRunner::withoutAPlanPollingStopsAgain()
{
    Rig rig;
    QSignalSpy polling(&rig.session, &BusSession::pollingChanged);
    QVERIFY(
        rig.runner.start(spec(StepLoop::Speed, 0, 90), safety::SoftLimits::defaults(Series::MF)));
    const StepTestResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    QVERIFY(!rig.session.pollPlan());
    QVERIFY(QTest::qWaitFor([&] { return polling.size() >= 2; }, kWaitMs));
    QCOMPARE(polling.first().at(0).toBool(), true);
    QCOMPARE(polling.last().at(0).toBool(), false);
}

QTEST_GUILESS_MAIN(tst_StepTestRunner)
#include "tst_steptestrunner.moc"
