// The frequency-domain assistant of the Tuning view (#25) on the built-in simulated bus: a
// sweep kept and drawn as a Bode plot, the checks that send nothing (gains not read, the
// question declined, a soft limit, an angle range), Esc mid-sweep and mid-search (stream halted,
// motor off, the gains read back in RAM), and suggested gains written only when clicked.
#include "DriveTestRig.h"

#include <drive/ConfirmDialog.h>
#include <drive/FrequencyResponseView.h>
#include <drive/FrequencyTuningView.h>
#include <drive/GainSearchView.h>
#include <drive/TuningView.h>
#include <safety/SoftLimits.h>
#include <tuning/BodeChart.h>
#include <tuning/FrequencyRunList.h>
#include <tuning/StepOverlayChart.h>
#include <tuning/StepTestPanel.h>

#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableWidget>

using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::FrequencyResponseView;
using lk::ui::GainSearchView;
using lk::ui::TuningView;

namespace {

struct Opened {
    std::unique_ptr<TuningView> view;
    FrequencyResponseView *sweep = nullptr;
    GainSearchView *search = nullptr;
};

Opened openView(SimRig &rig, int id, const lk::safety::SoftLimits &limits, bool waitForRead = true)
{
    Opened o;
    o.view = lk::drivetest::showView<TuningView>(rig, id, QSize(1366, 728));
    o.view->setStepTestLimits([limits](QString *) { return std::optional(limits); });
    auto *tab = o.view->findChild<lk::ui::FrequencyTuningView *>();
    o.sweep = tab->response();
    o.search = tab->search();
    if (waitForRead &&
        !QTest::qWaitFor([&] { return o.view->readComplete() && !o.view->isBusy(); }, kWaitMs))
        o.view.reset();
    return o;
}

lk::safety::SoftLimits limitsOf(SimRig &rig, int id)
{
    return lk::safety::SoftLimits::defaults(rig.motor(id).series);
}

lk::tuning::FrequencySweepSpec shortSweep(double perPointS)
{
    lk::tuning::FrequencySweepSpec s;
    s.operatingPoint = 200;
    s.amplitude = 60;
    s.fromHz = 2;
    s.toHz = 20;
    s.points = 3;
    s.minPointS = perPointS;
    return s;
}

int motionTo(SimRig &rig, int id)
{
    return rig.count(id, Command::Speed) + rig.count(id, Command::MultiPositionLimited) +
           rig.count(id, Command::MultiPosition) + rig.count(id, Command::Torque);
}

bool motorOn(SimRig &rig, int id)
{
    return rig.read<bool>(id, [](const lk::sim::SimDrive &d) { return d.motorOn(); });
}

bool samePid(const lk::protocol::PidGains &a, const lk::protocol::PidGains &b)
{
    return a.angleKp == b.angleKp && a.angleKi == b.angleKi && a.speedKp == b.speedKp &&
           a.speedKi == b.speedKi && a.iqKp == b.iqKp && a.iqKi == b.iqKi;
}

/// Answers every confirmation with `yes` and keeps what was asked.
struct Answers {
    QVector<ConfirmRequest> asked;
    ConfirmDialog::ScopedPolicy policy;
    explicit Answers(bool yes)
        : policy([this, yes](const ConfirmRequest &r) {
              asked.append(r);
              return yes;
          })
    {
    }
};

} // namespace

class tst_FrequencyTuningView : public QObject {
    Q_OBJECT
private slots:
    void sweepIsKeptAndDrawn();
    void refusalsSendNothing_data();
    void refusalsSendNothing();
    void positionLoopNeedsAnAngleWindow();
    void positionPeakSpeedRefusedBeforeTheQuestion();
    void escMidSweepRestoresGainsAndTurnsOff();
    void escMidSearchRestoresGainsAndTurnsOff();
    void suggestionIsWrittenOnlyWhenClicked();
    void positionSearchWritesTheAngleGainsOnlyWhenClicked();
};

void tst_FrequencyTuningView::sweepIsKeptAndDrawn()
{
    SimRig rig;
    QVERIFY(rig.open());
    Opened o = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(o.view);
    const lk::protocol::PidGains before = rig.ramPid(1);
    Answers yes(true);
    o.sweep->setSpec(shortSweep(0.3));
    QVERIFY(o.sweep->travelText().contains(QStringLiteral("turns")));
    QVERIFY2(o.sweep->runSweep(), qPrintable(o.sweep->statusText()));
    QCOMPARE(yes.asked.size(), 1);
    QCOMPARE(yes.asked.first().key, QStringLiteral("frequency_sweep"));
    QVERIFY(yes.asked.first().reason.contains(QStringLiteral("260 dps"))); // 200 + 60
    QTRY_VERIFY_WITH_TIMEOUT(!o.sweep->isRunning(), kWaitMs);
    QVERIFY2(o.sweep->runs()->runs().size() == 1, qPrintable(o.sweep->statusText()));
    const lk::tuning::FrequencyResponse &r = o.sweep->runs()->runs().first().response;
    QVERIFY(!r.points.isEmpty());
    QCOMPARE(o.sweep->chart()->runCount(), 1);
    QCOMPARE(o.sweep->chart()->magnitudePoints(0)->count(), r.points.size());
    QCOMPARE(o.sweep->chart()->phasePoints(0)->count(), r.points.size());
    QVERIFY(o.sweep->chart()->figuresText().startsWith(QStringLiteral("Run 1: ")));
    QVERIFY(o.sweep->chart()->pointText(0, 0).contains(QStringLiteral("Fit quality")));
    QVERIFY2(o.sweep->statusText().contains(
                 QStringLiteral("back in RAM; drive 1 holds 0 dps, its motor stays on")),
             qPrintable(o.sweep->statusText()));
    QVERIFY(samePid(rig.ramPid(1), before));
}

void tst_FrequencyTuningView::refusalsSendNothing_data()
{
    QTest::addColumn<bool>("readFirst");
    QTest::addColumn<bool>("answer");
    QTest::addColumn<double>("maxSpeedDps"); // 0: the series' default
    QTest::addColumn<bool>("angleRange");
    QTest::addColumn<bool>("trySearch"); // the search checks the limits in its runner
    QTest::addColumn<QString>("status");
    QTest::addColumn<int>("questions");
    // Its read is on the bus, not answered yet: nothing runs on gains not read.
    QTest::newRow("gains not read")
        << false << true << 0.0 << false << true << "have not been read on this connection" << 0;
    QTest::newRow("question declined")
        << true << false << 0.0 << false << true << "Cancelled: nothing was sent." << 2;
    // The operating point (200 dps) is beyond the limit: refused before the question.
    QTest::newRow("speed limit") << true << true << 150.0 << false << false << "Refused at 200 dps"
                                 << 0;
    QTest::newRow("angle range") << true << true << 0.0 << true << true << "angle range" << 0;
}

void tst_FrequencyTuningView::refusalsSendNothing()
{
    QFETCH(bool, readFirst);
    QFETCH(bool, answer);
    QFETCH(double, maxSpeedDps);
    QFETCH(bool, angleRange);
    QFETCH(bool, trySearch);
    QFETCH(QString, status);
    QFETCH(int, questions);
    SimRig rig;
    QVERIFY(rig.open());
    lk::safety::SoftLimits limits = limitsOf(rig, 1);
    if (maxSpeedDps > 0)
        limits.maxSpeedDps = maxSpeedDps;
    if (angleRange) {
        limits.minAngleDeg = -3600;
        limits.maxAngleDeg = 3600;
    }
    Opened o = openView(rig, 1, limits, readFirst);
    QVERIFY(o.view);
    QCOMPARE(o.view->readComplete(), readFirst);
    Answers answers(answer);
    o.sweep->setSpec(shortSweep(0.3));
    QVERIFY(!o.sweep->runSweep());
    QVERIFY2(o.sweep->statusText().contains(status), qPrintable(o.sweep->statusText()));
    if (maxSpeedDps > 0)
        QVERIFY2(o.sweep->statusText().contains(QString::number(maxSpeedDps)),
                 qPrintable(o.sweep->statusText()));
    if (trySearch) {
        QVERIFY(!o.search->runSearch());
        QVERIFY2(o.search->statusText().contains(status), qPrintable(o.search->statusText()));
    }
    QCOMPARE(answers.asked.size(), questions);
    if (questions > 0)
        QVERIFY(answers.asked.last().reason.contains(QStringLiteral("turns")));
    QVERIFY(rig.barrier());
    QCOMPARE(motionTo(rig, 1), 0);
}

void tst_FrequencyTuningView::positionLoopNeedsAnAngleWindow()
{
    // Without an angle window the position loop is not offered; with one it runs around where
    // the drive is, and the chart overlays only the runs of the loop chosen.
    SimRig rig;
    QVERIFY(rig.open());
    lk::safety::SoftLimits limits = limitsOf(rig, 1);
    {
        Opened o = openView(rig, 1, limits);
        QVERIFY(o.view);
        QVERIFY(!o.sweep->positionOffered());
        QVERIFY(!o.sweep->setLoop(lk::tuning::SweepLoop::Position));
        QCOMPARE(o.sweep->loop(), lk::tuning::SweepLoop::Speed);
    }
    limits.minAngleDeg = -1e5;
    limits.maxAngleDeg = 1e5;
    Opened o = openView(rig, 1, limits);
    QVERIFY(o.view);
    QVERIFY(o.sweep->positionOffered());
    lk::tuning::FrequencySweepSpec spec = shortSweep(0.3);
    spec.loop = lk::tuning::SweepLoop::Position;
    spec.operatingPoint.reset();
    spec.amplitude = 4;
    o.sweep->setSpec(spec);
    QCOMPARE(o.sweep->loop(), lk::tuning::SweepLoop::Position);
    QVERIFY2(o.sweep->travelText().contains(QStringLiteral("either side of where it is")),
             qPrintable(o.sweep->travelText()));
    const lk::protocol::PidGains before = rig.ramPid(1);
    Answers yes(true);
    QVERIFY2(o.sweep->runSweep(), qPrintable(o.sweep->statusText()));
    QCOMPARE(yes.asked.first().key, QStringLiteral("frequency_sweep_position"));
    QTRY_VERIFY_WITH_TIMEOUT(!o.sweep->isRunning(), kWaitMs);
    QVERIFY2(o.sweep->runs()->runs().size() == 1, qPrintable(o.sweep->statusText()));
    QCOMPARE(o.sweep->runs()->runs().first().spec.loop, lk::tuning::SweepLoop::Position);
    QVERIFY(rig.count(1, Command::MultiPositionLimited) > 100);
    QCOMPARE(rig.count(1, Command::Speed), 0);
    QVERIFY2(o.sweep->statusText().contains(QStringLiteral("holds the angle it started at")),
             qPrintable(o.sweep->statusText()));
    QVERIFY(samePid(rig.ramPid(1), before));
    QCOMPARE(o.sweep->chart()->runCount(), 1);
    // The legend: the run, its drive, loop, gains and date.
    const QStringList legend = o.sweep->chart()->legendLabels();
    QCOMPARE(legend.size(), 1);
    QVERIFY2(legend.first().startsWith(QStringLiteral("Run 1: drive 1, position loop, Kp ")),
             qPrintable(legend.first()));
    // Saved, opened again beside it, then taken off the chart.
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("run.lkfreq.json"));
    QVERIFY(o.sweep->saveRun(o.sweep->runs()->keyAt(0), file));
    QVERIFY2(o.sweep->openRun(file), qPrintable(o.sweep->statusText()));
    QCOMPARE(o.sweep->chart()->runCount(), 2);
    QCOMPARE(o.sweep->chart()->legendLabels().size(), 2);
    QFile bad(dir.filePath(QStringLiteral("bad.lkfreq.json")));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    QFile saved(file);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    bad.write(saved.readAll().replace("\"position\"", "\"angle\""));
    bad.close();
    QVERIFY(!o.sweep->openRun(bad.fileName()));
    QVERIFY2(o.sweep->statusText().contains(
                 QStringLiteral("loop is \"angle\": it must be \"speed\" or \"position\"")),
             qPrintable(o.sweep->statusText()));
    QCOMPARE(o.sweep->runs()->runs().size(), 2);
    QCOMPARE(o.sweep->chosenRun(), o.sweep->runs()->keyAt(1));
    o.sweep->findChild<QPushButton *>(QStringLiteral("removeSweepRun"))->click();
    QCOMPARE(o.sweep->runs()->runs().size(), 1);
    QCOMPARE(o.sweep->chart()->runCount(), 1);
    // A speed run and a position run do not share the axes.
    QVERIFY(o.sweep->setLoop(lk::tuning::SweepLoop::Speed));
    QCOMPARE(o.sweep->chart()->runCount(), 0);
}

void tst_FrequencyTuningView::positionPeakSpeedRefusedBeforeTheQuestion()
{
    SimRig rig;
    QVERIFY(rig.open());
    lk::safety::SoftLimits limits = limitsOf(rig, 1);
    limits.minAngleDeg = -1e5;
    limits.maxAngleDeg = 1e5;
    limits.maxSpeedDps = 1000;
    Opened o = openView(rig, 1, limits);
    QVERIFY(o.view);
    lk::tuning::FrequencySweepSpec spec = shortSweep(0.3);
    spec.loop = lk::tuning::SweepLoop::Position;
    spec.amplitude = 5;
    spec.toHz = 40; // 2 pi x 40 x 5 = 1257 dps
    o.sweep->setSpec(spec);
    Answers yes(true);
    QVERIFY(!o.sweep->runSweep());
    QVERIFY2(o.sweep->statusText().contains(QStringLiteral("Refused at 1,257 dps")),
             qPrintable(o.sweep->statusText()));
    QVERIFY2(o.sweep->statusText().contains(QStringLiteral("1000")),
             qPrintable(o.sweep->statusText()));
    QCOMPARE(yes.asked.size(), 0);
    QVERIFY(rig.barrier());
    QCOMPARE(motionTo(rig, 1), 0);
}

// Esc reaches the sweep through the Tuning view's halt (DriveViews::haltLocalMotion).
void tst_FrequencyTuningView::escMidSweepRestoresGainsAndTurnsOff()
{
    SimRig rig;
    QVERIFY(rig.open());
    Opened o = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(o.view);
    const lk::protocol::PidGains before = rig.ramPid(1);
    Answers yes(true);
    o.sweep->setSpec(shortSweep(5)); // long enough to stop in the middle
    QVERIFY(o.sweep->runSweep());
    QTRY_VERIFY_WITH_TIMEOUT(rig.count(1, Command::Speed) > 100, kWaitMs);
    QVERIFY(motorOn(rig, 1));
    // Meanwhile no gain write and no step test: the sweep puts the gains it read back.
    const auto button = [&](const char *name) {
        return o.view->findChild<QPushButton *>(QLatin1String(name));
    };
    QVERIFY(!button("read")->isEnabled());
    QVERIFY(!button("writeRam")->isEnabled());
    QVERIFY(!o.view->findChild<lk::ui::StepTestPanel *>()->isEnabled());
    o.view->haltLocalMotion(QStringLiteral("Emergency stop."));
    QTRY_VERIFY_WITH_TIMEOUT(!o.sweep->isRunning(), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(o.view->findChild<lk::ui::StepTestPanel *>()->isEnabled(), kWaitMs);
    const QString status = o.sweep->statusText();
    QVERIFY2(status.startsWith(QStringLiteral("Stopped.")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("acknowledged")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("back in RAM")), qPrintable(status));
    QVERIFY(rig.barrier());
    const int sent = rig.count(1, Command::Speed);
    QTest::qWait(500); // the sweep's next setpoints were due in this time
    QVERIFY(rig.barrier());
    QCOMPARE(rig.count(1, Command::Speed), sent);
    QVERIFY(!motorOn(rig, 1));
    QVERIFY(samePid(rig.ramPid(1), before));
    QVERIFY(o.sweep->runs()->runs().isEmpty());
}

void tst_FrequencyTuningView::escMidSearchRestoresGainsAndTurnsOff()
{
    SimRig rig;
    QVERIFY(rig.open());
    Opened o = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(o.view);
    const lk::protocol::PidGains before = rig.ramPid(1);
    Answers yes(true);
    QVERIFY(o.search->runSearch());
    // Mid-search: a candidate other than the gains read is in the drive.
    QTRY_VERIFY_WITH_TIMEOUT(!samePid(rig.ramPid(1), before), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(motorOn(rig, 1), kWaitMs);
    o.view->haltLocalMotion(QStringLiteral("Emergency stop."));
    QTRY_VERIFY_WITH_TIMEOUT(!o.search->isRunning(), kWaitMs);
    const QString status = o.search->statusText();
    QVERIFY2(status.startsWith(QStringLiteral("Stopped.")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("back in RAM")), qPrintable(status));
    QVERIFY(rig.barrier());
    const int sent = motionTo(rig, 1);
    QTest::qWait(500);
    QVERIFY(rig.barrier());
    QCOMPARE(motionTo(rig, 1), sent);
    QVERIFY(!motorOn(rig, 1));
    QVERIFY(samePid(rig.ramPid(1), before));
    QVERIFY(!o.search->findChild<QPushButton *>(QStringLiteral("writeSuggestedRam"))->isEnabled());
}

void tst_FrequencyTuningView::suggestionIsWrittenOnlyWhenClicked()
{
    SimRig rig;
    QVERIFY(rig.open());
    Opened o = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(o.view);
    const lk::protocol::PidGains before = rig.ramPid(1);
    const lk::protocol::PidGains rom = rig.romPid(1);
    Answers yes(true);
    lk::tuning::GainSearchSpec spec = o.search->spec();
    spec.maxCandidates = 8;
    // A loaded host jitters the steps' samples: a wide bound keeps a suggestion likely.
    spec.maxOvershootPct = 25;
    spec.measureBode = false; // the Bode of both: tst_gainsearchbodeview
    o.search->setSpec(spec);
    QVERIFY(o.search->runSearch());
    QTRY_VERIFY_WITH_TIMEOUT(!o.search->isRunning(), kWaitMs);
    QVERIFY2(o.search->result() && o.search->result()->ok(), qPrintable(o.search->statusText()));
    QCOMPARE(o.search->candidates()->rowCount(), o.search->result()->candidates.size());
    QVERIFY(o.search->candidates()->rowCount() >= 1);
    const std::optional<lk::tuning::LoopGains> best = o.search->best();
    QVERIFY2(best, qPrintable(o.search->statusText()));
    // The step of the gains read beside the best's, each with its edges.
    const int bestIndex = *o.search->result()->best;
    qInfo("%d candidates, the best is #%d: speed Kp %d Ki %d (read: Kp %d Ki %d)",
          int(o.search->result()->candidates.size()), bestIndex, best->speed.kp, best->speed.ki,
          before.speedKp, before.speedKi);
    QCOMPARE(o.search->overlay()->runCount(), bestIndex > 0 ? 2 : 1);
    QVERIFY(o.search->overlay()->responseSeries(0)->count() > 20);
    QCOMPARE(o.search->findChild<QTableWidget *>(QStringLiteral("bestVsRead"))->item(0, 1)->text(),
             QString::number(best->speed.kp));
    // The search ended: the drive holds the gains it had, whatever it tried.
    QVERIFY(rig.barrier());
    QVERIFY(samePid(rig.ramPid(1), before));
    const int writesBefore = rig.count(1, Command::WritePidRam);
    QTest::qWait(300);
    QVERIFY(rig.barrier());
    QCOMPARE(rig.count(1, Command::WritePidRam), writesBefore); // nothing until the click
    auto *writeRom = o.search->findChild<QPushButton *>(QStringLiteral("writeSuggestedRom"));
    QVERIFY(!writeRom->isEnabled()); // ROM comes after RAM
    QVERIFY(!o.search->writeBestToRom());

    auto *writeRam = o.search->findChild<QPushButton *>(QStringLiteral("writeSuggestedRam"));
    QVERIFY(writeRam->isEnabled());
    QTest::mouseClick(writeRam, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(rig.count(1, Command::WritePidRam) > writesBefore, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!o.view->isBusy() && rig.ramPid(1).speedKp == best->speed.kp &&
                                 rig.ramPid(1).speedKi == best->speed.ki,
                             kWaitMs);
    QCOMPARE(rig.ramPid(1).angleKp, before.angleKp); // only the speed loop's Kp and Ki
    QCOMPARE(rig.ramPid(1).iqKi, before.iqKi);
    QVERIFY(samePid(rig.romPid(1), rom));

    // ROM: the Tuning view's confirmation; declining writes nothing.
    QTRY_VERIFY_WITH_TIMEOUT(writeRom->isEnabled(), kWaitMs);
    {
        Answers no(false);
        QVERIFY(o.search->writeBestToRom());
        QCOMPARE(no.asked.size(), 1);
        QCOMPARE(no.asked.first().key, QStringLiteral("write_pid_rom"));
    }
    QVERIFY(rig.barrier());
    QVERIFY(samePid(rig.romPid(1), rom));
    Answers yesAgain(true); // the scoped answer above took every policy with it
    QVERIFY(o.search->writeBestToRom());
    QCOMPARE(yesAgain.asked.size(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(rig.romPid(1).speedKp == best->speed.kp && !o.view->isBusy(), kWaitMs);
}

// The position loop's search: offered only with an angle window; it changes and suggests the
// angle gains, leaves the gains read in RAM and the drive at its angle, and writes the angle
// Kp and Ki (nothing else) only when Write to RAM is clicked.
void tst_FrequencyTuningView::positionSearchWritesTheAngleGainsOnlyWhenClicked()
{
    SimRig rig;
    QVERIFY(rig.open());
    lk::safety::SoftLimits limits = limitsOf(rig, 1);
    lk::tuning::GainSearchSpec spec = lk::tuning::GainSearchSpec::forPosition(1);
    spec.maxCandidates = 6;
    spec.maxOvershootPct = 25; // a loaded host jitters the samples: a suggestion stays likely
    {
        Opened o = openView(rig, 1, limits);
        QVERIFY(o.view);
        o.search->setSpec(spec);
        // Without a window the loop stays the speed loop's, and its choice is disabled.
        QCOMPARE(o.search->spec().loop, lk::tuning::StepLoop::Speed);
        QVERIFY(!o.search->findChild<QComboBox *>(QStringLiteral("searchLoop"))->isEnabled());
    }
    limits.minAngleDeg = -1e5;
    limits.maxAngleDeg = 1e5;
    Opened o = openView(rig, 1, limits);
    QVERIFY(o.view);
    o.search->setSpec(spec);
    QCOMPARE(o.search->spec().loop, lk::tuning::StepLoop::Position);
    const lk::protocol::PidGains before = rig.ramPid(1);
    Answers yes(true);
    QVERIFY2(o.search->runSearch(), qPrintable(o.search->statusText()));
    QCOMPARE(yes.asked.first().key, QStringLiteral("gain_search_position"));
    QTRY_VERIFY_WITH_TIMEOUT(!o.search->isRunning(), kWaitMs);
    QVERIFY2(o.search->result() && o.search->result()->ok(), qPrintable(o.search->statusText()));
    QVERIFY2(o.search->statusText().contains(QStringLiteral("the angle it started at")),
             qPrintable(o.search->statusText()));
    QVERIFY(rig.count(1, Command::MultiPositionLimited) > 0);
    QCOMPARE(rig.count(1, Command::Speed), 0); // position steps only, and no return by speed
    const std::optional<lk::tuning::LoopGains> best = o.search->best();
    QVERIFY2(best, qPrintable(o.search->statusText()));
    qInfo("%d candidates: angle Kp %d Ki %d (read: Kp %d Ki %d)",
          int(o.search->result()->candidates.size()), best->angle.kp, best->angle.ki,
          before.angleKp, before.angleKi);
    auto *compare = o.search->findChild<QTableWidget *>(QStringLiteral("bestVsRead"));
    QCOMPARE(compare->verticalHeaderItem(0)->text(), QStringLiteral("Angle Kp"));
    QCOMPARE(compare->item(0, 1)->text(), QString::number(best->angle.kp));
    QVERIFY(rig.barrier());
    QVERIFY(samePid(rig.ramPid(1), before)); // nothing kept until the click
    auto *writeRam = o.search->findChild<QPushButton *>(QStringLiteral("writeSuggestedRam"));
    QVERIFY(writeRam->isEnabled());
    QTest::mouseClick(writeRam, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!o.view->isBusy() && rig.ramPid(1).angleKp == best->angle.kp &&
                                 rig.ramPid(1).angleKi == best->angle.ki,
                             kWaitMs);
    QCOMPARE(rig.ramPid(1).speedKp, before.speedKp); // only the angle Kp and Ki
    QCOMPARE(rig.ramPid(1).speedKi, before.speedKi);
}

QTEST_MAIN(tst_FrequencyTuningView)
#include "tst_frequencytuningview.moc"
