// The position loop's gain search (issue #25): the candidates change the angle gains only, a
// search needs an angle window, and the runner on the built-in simulator at 1 Mbaud: a faster
// rise than the gains read within the overshoot bound, the steps inside the window (down when
// there is no room above), nothing left written, the drive holding the angle it started at,
// and the abort path (motor off, the gains read back in RAM).
#include "GainSearchRig.h"

#include <safety/SoftLimits.h>

#include <cmath>

using namespace lk;
using namespace lk::tuning;
using lk::test::GainSearchRig;
using lk::test::kWaitMs;
using protocol::Command;
using protocol::Series;

namespace {

LoopGains readGains()
{
    LoopGains g;
    g.angle = {100, 100, 0};
    g.speed = {50, 40, 0};
    g.current = {50, 50, 0};
    g.accelerationDps2 = 20000;
    return g;
}

CandidateScore scored(const LoopGains &g, double rise, double overshoot, CandidateVerdict v)
{
    CandidateScore s;
    s.gains = g;
    s.errorAreaS = rise;
    s.metrics.riseTimeS = Metric::of(rise);
    s.metrics.overshootPct = Metric::of(overshoot);
    s.verdict = v;
    return s;
}

/// The series' limits with an angle window from `below` to `above` degrees around `angle`.
safety::SoftLimits window(Series series, double angle, double below, double above)
{
    safety::SoftLimits l = safety::SoftLimits::defaults(series);
    l.minAngleDeg = angle - below;
    l.maxAngleDeg = angle + above;
    return l;
}

bool sentMotion(const QSignalSpy &completed)
{
    for (const auto &args : completed) {
        const Command c = args.at(0).value<bus::RequestResult>().request.command;
        if (c == Command::MultiPositionLimited || c == Command::MultiPosition ||
            c == Command::Speed)
            return true;
    }
    return false;
}

} // namespace

class tst_GainSearchPosition : public QObject {
    Q_OBJECT
private slots:
    void candidatesChangeTheAngleGainsOnly();
    void specCheck_data();
    void specCheck();
    void noWindowSendsNothing();
    void searchBeatsTheGainsRead_data();
    void searchBeatsTheGainsRead();
    void stepsGoDownWithoutRoomAbove();
    void abortRestoresAndTurnsOff();
};

void tst_GainSearchPosition::candidatesChangeTheAngleGainsOnly()
{
    // The speed search's climb on the angle gains: Ki down by 1.5 in a row while the overshoot
    // falls, the next row's Kp x1.3 from the Ki accepted; the speed and current loops as read.
    GainSearchStrategy s(readGains(), 5, 20, StepLoop::Position);
    QCOMPARE(s.loop(), StepLoop::Position);
    QCOMPARE(s.next()->angle, readGains().angle);
    s.record(scored(*s.next(), 0.040, 9, CandidateVerdict::Overshoot));
    QCOMPARE(s.next()->angle, (PidTriple{100, 67, 0}));
    s.record(scored(*s.next(), 0.038, 4, CandidateVerdict::Accepted));
    QCOMPARE(s.next()->angle, (PidTriple{130, 67, 0}));
    s.record(scored(*s.next(), 0.030, 3, CandidateVerdict::Accepted));
    QCOMPARE(s.next()->angle, (PidTriple{169, 67, 0}));
    for (const CandidateScore &c : s.scores()) {
        QCOMPARE(c.gains.speed, readGains().speed);
        QCOMPARE(c.gains.current, readGains().current);
        QCOMPARE(c.gains.accelerationDps2, readGains().accelerationDps2);
    }
    QCOMPARE(*s.best(), 2);
    // V2.3's angle gains are uint8: the climb stops at 255.
    LoopGains high = readGains();
    high.angle.kp = 250;
    GainSearchStrategy top(high, 5, 20, StepLoop::Position);
    top.record(scored(*top.next(), 0.02, 1, CandidateVerdict::Accepted));
    QCOMPARE(int(top.next()->angle.kp), 255);
    top.record(scored(*top.next(), 0.01, 1, CandidateVerdict::Accepted));
    QVERIFY(!top.next());
}

void tst_GainSearchPosition::specCheck_data()
{
    QTest::addColumn<bool>("windowSet");
    QTest::addColumn<bool>("bode");
    QTest::addColumn<int>("periods");
    QTest::addColumn<QString>("error");
    QTest::newRow("window") << true << false << 3 << QString();
    QTest::newRow("no window") << false << false << 3 << "needs an angle window";
    QTest::newRow("bode") << true << true << 3 << "Bode step measures the speed loop";
    QTest::newRow("one step") << true << false << 1 << "ends where it began";
}

void tst_GainSearchPosition::specCheck()
{
    QFETCH(bool, windowSet);
    QFETCH(bool, bode);
    QFETCH(int, periods);
    QFETCH(QString, error);
    GainSearchSpec s = GainSearchSpec::forPosition(3);
    s.measureBode = bode;
    s.periods = periods;
    QCOMPARE(s.loop, StepLoop::Position);
    const safety::SoftLimits limits =
        windowSet ? window(Series::MF, 0, 90, 90) : safety::SoftLimits::defaults(Series::MF);
    const QString why = s.check(limits);
    QVERIFY2(error.isEmpty() ? why.isEmpty() : why.contains(error), qPrintable(why));
    // The steps start at the angle read and end there (a square ends on FROM).
    const StepTestSpec step = s.step(1234.5);
    QCOMPARE(step.loop, StepLoop::Position);
    QCOMPARE(step.from, 1234.5);
    QCOMPARE(step.to, 1234.5 + GainSearchSpec::kPositionStepDeg);
}

void tst_GainSearchPosition::noWindowSendsNothing()
{
    GainSearchRig rig;
    QVERIFY(
        rig.runner.start(GainSearchSpec::forPosition(3), safety::SoftLimits::defaults(Series::MF)));
    const GainSearchResult r = rig.waitForEnd();
    QCOMPARE(r.failure, StepTestFailure::BadSpec);
    QVERIFY2(r.message.contains(QLatin1String("angle window")), qPrintable(r.message));
    QCOMPARE(r.outcome.end, SearchEnd::BadSpec);
    QCOMPARE(r.outcome.drive, DriveLeft::Untouched);
    QVERIFY(r.candidates.isEmpty());
    QVERIFY(!sentMotion(rig.completed));
}

void tst_GainSearchPosition::searchBeatsTheGainsRead_data()
{
    QTest::addColumn<int>("id");
    QTest::newRow("MF V2.3") << 3;
    QTest::newRow("MG V2.35") << 5;
}

void tst_GainSearchPosition::searchBeatsTheGainsRead()
{
    QFETCH(int, id);
    GainSearchRig rig;
    const std::optional<LoopGains> before = rig.gains(id);
    const std::optional<double> start = rig.angle(id);
    QVERIFY(before && start);
    const safety::SoftLimits limits = window(*rig.session.series(id), *start, 90, 90);
    QVERIFY(rig.runner.start(GainSearchSpec::forPosition(id), limits));
    const GainSearchResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.direction, 1);
    QVERIFY(r.startAngle && std::abs(*r.startAngle - *start) < 0.1);
    for (const CandidateScore &c : r.candidates) {
        qInfo("angle Kp %3d Ki %3d (%.0f Hz): area %.2f ms, rise %s ms, overshoot %s %%, "
              "verdict %d",
              c.gains.angle.kp, c.gains.angle.ki, c.metrics.sampleRateHz, c.errorAreaS * 1e3,
              qPrintable(QString::number(c.metrics.riseTimeS.value.value_or(-1) * 1e3)),
              qPrintable(QString::number(c.metrics.overshootPct.value.value_or(-1))),
              int(c.verdict));
        QCOMPARE(c.gains.speed, before->speed); // the position loop's gains only
        QVERIFY(c.trace.size() > 50 && c.trace.edges.size() >= 2);
        // Every step inside the window: FROM the angle read, TO 10 deg above it.
        for (const StepEdge &e : c.trace.edges) {
            QVERIFY(std::min(e.from, e.to) >= *start - 0.01);
            QVERIFY(std::max(e.from, e.to) <= *start + GainSearchSpec::kPositionStepDeg + 0.01);
        }
    }
    qInfo("%.1f s for %d candidates", r.seconds, int(r.candidates.size()));
    QVERIFY(r.baseline && r.best);
    const CandidateScore &base = r.candidates[*r.baseline];
    const CandidateScore &best = r.candidates[*r.best];
    QVERIFY(best.accepted());
    QVERIFY2(best.riseS() < base.riseS(), qPrintable(r.message));
    QVERIFY(*best.metrics.overshootPct.value <= 5);
    QVERIFY(best.gains.angle.kp > before->angle.kp);
    QCOMPARE(r.outcome.end, SearchEnd::Finished);
    QCOMPARE(r.outcome.drive, DriveLeft::HoldsAngle);
    QCOMPARE(r.outcome.angleDeg, *r.startAngle);
    QVERIFY(r.outcome.gainsRestored);
    // Nothing written until asked; the drive holds the angle it started at.
    QCOMPARE(rig.gains(id), before);
    const std::optional<double> end = rig.angle(id);
    QVERIFY(end);
    QVERIFY2(std::abs(*end - *start) < 0.5, qPrintable(QString::number(*end - *start)));
}

void tst_GainSearchPosition::stepsGoDownWithoutRoomAbove()
{
    GainSearchRig rig;
    const std::optional<double> start = rig.angle(3);
    QVERIFY(start);
    GainSearchSpec s = GainSearchSpec::forPosition(3);
    s.maxCandidates = 2;
    QVERIFY(rig.runner.start(s, window(Series::MF, *start, 90, 3)));
    const GainSearchResult r = rig.waitForEnd();
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.direction, -1);
    QCOMPARE(r.candidates.size(), 2);
    for (const CandidateScore &c : r.candidates)
        for (const StepEdge &e : c.trace.edges)
            QVERIFY(std::min(e.from, e.to) >= *start - GainSearchSpec::kPositionStepDeg - 0.01 &&
                    std::max(e.from, e.to) <= *start + 0.01);
    const std::optional<double> end = rig.angle(3);
    QVERIFY(end && std::abs(*end - *start) < 0.5);
}

void tst_GainSearchPosition::abortRestoresAndTurnsOff()
{
    GainSearchRig rig;
    const std::optional<LoopGains> before = rig.gains(5);
    const std::optional<double> start = rig.angle(5);
    QVERIFY(before && start);
    QVERIFY(rig.runner.start(GainSearchSpec::forPosition(5), window(Series::MG, *start, 90, 90)));
    // Mid-search: the second candidate's gains are in RAM.
    QVERIFY(QTest::qWaitFor([&] { return rig.scored.size() >= 1; }, kWaitMs));
    QTest::qWait(100);
    rig.runner.abort();
    const GainSearchResult r = rig.waitForEnd();
    QCOMPARE(r.failure, StepTestFailure::Aborted);
    QVERIFY2(r.message.contains(QLatin1String("drive 5 is off")), qPrintable(r.message));
    QCOMPARE(r.outcome.end, SearchEnd::AbortedByUser);
    QCOMPARE(r.outcome.drive, DriveLeft::Off);
    QVERIFY(r.outcome.gainsRestored);
    QCOMPARE(rig.gains(5), before);
    const std::optional<double> iq = rig.current(5);
    QVERIFY(iq && *iq == 0.0);
}

QTEST_GUILESS_MAIN(tst_GainSearchPosition)
#include "tst_gainsearchposition.moc"
