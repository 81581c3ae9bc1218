// The tuning assistant in the Tuning view (#13): a step test on the built-in simulated bus, a
// gain written to RAM, the test repeated with one click, both runs overlaid with their metrics
// and gains; refusals that send nothing; the emergency stop's halt; run files.
#include "DriveTestRig.h"

#include <drive/LoopPlot.h>
#include <drive/ParameterTable.h>
#include <drive/TuningSetV23.h>
#include <drive/TuningView.h>
#include <safety/SoftLimits.h>
#include <tuning/StepOverlayChart.h>
#include <tuning/StepRunList.h>
#include <tuning/StepRunsModel.h>
#include <tuning/StepRunsView.h>
#include <tuning/StepTestPanel.h>

#include <QtCharts/QLineSeries>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QTabWidget>

using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::StepMetricKind;
using lk::ui::StepRunsModel;
using lk::ui::TuningView;
using V23 = lk::ui::TuningSetV23;

namespace {

std::unique_ptr<TuningView> openView(SimRig &rig, int id, const lk::safety::SoftLimits &limits)
{
    auto view = lk::drivetest::showView<TuningView>(rig, id, QSize(1366, 728));
    view->setStepTestLimits([limits](QString *) { return std::optional(limits); });
    if (!QTest::qWaitFor([&] { return view->readComplete() && !view->isBusy(); }, kWaitMs))
        return nullptr;
    return view;
}

lk::safety::SoftLimits limitsOf(SimRig &rig, int id)
{
    return lk::safety::SoftLimits::defaults(rig.motor(id).series);
}

void edit(TuningView &view, int row, int value)
{
    QDoubleSpinBox *box = view.table()->editor(row);
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, QString::number(value));
    QTest::keyClick(box, Qt::Key_Enter);
}

void setSpec(TuningView &view, lk::tuning::StepLoop loop, double from, double to, double s)
{
    lk::tuning::StepTestSpec spec = view.stepTest()->spec();
    spec.loop = loop;
    spec.from = from;
    spec.to = to;
    spec.durationS = s;
    spec.periods = 1;
    view.stepTest()->setSpec(spec);
}

bool waitForRuns(TuningView &view, int count)
{
    return QTest::qWaitFor(
        [&] { return view.runList()->runs().size() >= count && !view.stepTest()->isRunning(); },
        kWaitMs);
}

int motionTo(SimRig &rig, int id)
{
    return rig.count(id, Command::Speed) + rig.count(id, Command::MultiPositionLimited) +
           rig.count(id, Command::MultiPosition);
}

} // namespace

class tst_StepTestView : public QObject {
    Q_OBJECT
private slots:
    void stepWriteRepeatCompare();
    void refusalNamesTheLimitAndSendsNothing();
    void damagedLimitsSendNothing();
    void haltStopsSending();
    void positionStepStartsWhereTheDriveIs();
    void v235DriveKeepsItsKdGains();
    void runsSaveAndLoad();
    void badRunFileAddsNothing();
    void metricDefinitionsOneClickAway();
};

// The technician's loop: step, change a gain, write to RAM, repeat with one click, compare.
void tst_StepTestView::stepWriteRepeatCompare()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(view);
    QVERIFY(!view->findChild<QPushButton *>(QStringLiteral("repeatStepTest"))->isEnabled());
    setSpec(*view, lk::tuning::StepLoop::Speed, 0, 360, 0.6);
    QTest::mouseClick(lk::drivetest::button(*view, "testStep"), Qt::LeftButton);
    QVERIFY(view->stepTest()->isRunning());
    QVERIFY(waitForRuns(*view, 1));
    const lk::tuning::StepRun first = view->runList()->runs().first();
    QVERIFY2(first.trace.edges.size() >= 1, qPrintable(view->stepTest()->statusText()));
    QVERIFY(first.trace.size() > 20);
    QCOMPARE(first.gains.value(QStringLiteral("speed_kp")).toInt(), rig.ramPid(1).speedKp);
    QVERIFY(view->stepTest()->statusText().contains(QStringLiteral("samples at")));
    auto *side = view->findChild<QTabWidget *>(QStringLiteral("tuningSide"));
    QCOMPARE(side->currentIndex(), 1); // the run is shown as it finishes
    QVERIFY(first.stepMetrics().riseTimeS.known());

    // A stiffer speed loop, written to RAM: the marker lands on the live plot.
    const int kp = rig.ramPid(1).speedKp;
    edit(*view, V23::SpeedKp, kp * 2);
    QTest::mouseClick(lk::drivetest::button(*view, "writeRam"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->isBusy() && rig.ramPid(1).speedKp == kp * 2, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!view->plot()->marks(1).isEmpty(), kWaitMs);

    auto *repeat = view->findChild<QPushButton *>(QStringLiteral("repeatStepTest"));
    QTRY_VERIFY_WITH_TIMEOUT(repeat->isEnabled(), kWaitMs);
    QTest::mouseClick(repeat, Qt::LeftButton);
    QVERIFY(waitForRuns(*view, 2));
    const lk::tuning::StepRun second = view->runList()->runs().at(1);
    QCOMPARE(second.spec.to, 360.0);
    QCOMPARE(second.gains.value(QStringLiteral("speed_kp")).toInt(), kp * 2);

    // Both overlaid, in their colours, with the table side by side.
    auto *overlay = view->stepRuns()->overlay();
    QCOMPARE(overlay->runCount(), 2);
    QVERIFY(overlay->responseSeries(0)->count() > 20);
    QVERIFY(overlay->responseSeries(1)->count() > 20);
    QCOMPARE(overlay->responseSeries(1)->pen().color(), StepRunsModel::runColor(2));
    StepRunsModel *model = view->stepRuns()->model();
    QCOMPARE(model->columnCount(), 2);
    const int kpRow = model->keyRow(QStringLiteral("speed_kp"));
    QVERIFY(kpRow >= 0);
    QCOMPARE(model->data(model->index(kpRow, 1)).toString(), QString::number(kp * 2));
    QVERIFY(!model->bestColumns(StepMetricKind::RiseTime).isEmpty());
    // Hiding a run takes it out of the overlay and of the best marks: the run left is
    // compared with nothing, so it is best of nothing.
    QVERIFY(
        model->setData(model->index(StepRunsModel::Overlay, 0), Qt::Unchecked, Qt::CheckStateRole));
    QCOMPARE(overlay->runCount(), 1);
    QVERIFY(model->bestColumns(StepMetricKind::RiseTime).isEmpty());
}

void tst_StepTestView::refusalNamesTheLimitAndSendsNothing()
{
    SimRig rig;
    QVERIFY(rig.open());
    lk::safety::SoftLimits limits = limitsOf(rig, 1);
    limits.maxSpeedDps = 200;
    auto view = openView(rig, 1, limits);
    QVERIFY(view);
    QVERIFY(rig.barrier());
    const int before = motionTo(rig, 1);
    setSpec(*view, lk::tuning::StepLoop::Speed, 0, 360, 0.5);
    QTest::mouseClick(lk::drivetest::button(*view, "testStep"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!view->stepTest()->isRunning(), kWaitMs);
    const QString status = view->stepTest()->statusText();
    QVERIFY2(status.startsWith(QStringLiteral("Refused")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("speed")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("Nothing was sent")), qPrintable(status));
    QVERIFY(rig.barrier());
    QCOMPARE(motionTo(rig, 1), before);
    QVERIFY(view->runList()->runs().isEmpty());
}

void tst_StepTestView::damagedLimitsSendNothing()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(view);
    view->setStepTestLimits([](QString *why) {
        *why = QStringLiteral("Refused: the soft limits stored for drive 1 are damaged.");
        return std::optional<lk::safety::SoftLimits>();
    });
    QVERIFY(rig.barrier());
    const int before = motionTo(rig, 1);
    QVERIFY(!view->stepTest()->runTest());
    QVERIFY(view->stepTest()->statusText().contains(QStringLiteral("damaged")));
    QVERIFY(rig.barrier());
    QCOMPARE(motionTo(rig, 1), before);
}

// The emergency stop halts local motion first: the test sends no further setpoint.
void tst_StepTestView::haltStopsSending()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(view);
    setSpec(*view, lk::tuning::StepLoop::Speed, 0, 360, 2.0);
    QVERIFY(view->stepTest()->runTest());
    QTRY_VERIFY_WITH_TIMEOUT(rig.count(1, Command::Speed) >= 1, kWaitMs);
    view->haltLocalMotion(QStringLiteral("Emergency stop."));
    QVERIFY(!view->stepTest()->isRunning());
    QVERIFY(rig.barrier());
    const int sent = rig.count(1, Command::Speed);
    QTest::qWait(2500); // the test's remaining setpoints were due in this time
    QVERIFY(rig.barrier());
    QCOMPARE(rig.count(1, Command::Speed), sent);
    QVERIFY(view->stepTest()->statusText().contains(QStringLiteral("stopped")));
    QVERIFY(view->runList()->runs().isEmpty());
}

void tst_StepTestView::positionStepStartsWhereTheDriveIs()
{
    SimRig rig;
    QVERIFY(rig.open());
    rig.session.startPolling(lk::bus::PollPlan::standard({1}, 50));
    auto view = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(view);
    QTRY_VERIFY_WITH_TIMEOUT(
        view->plot()->store()->count(1, lk::ui::TelemetryChannel::MultiTurn) > 0, kWaitMs);
    const double here = rig.multiTurnDeg(1);
    // Choosing the position loop fills FROM and TO in from where the drive is.
    view->stepTest()->findChild<QComboBox *>(QStringLiteral("stepLoop"))->setCurrentIndex(1);
    QCOMPARE(view->stepTest()->spec().loop, lk::tuning::StepLoop::Position);
    QVERIFY(std::abs(view->stepTest()->spec().from - here) < 2);
    QCOMPARE(view->stepTest()->spec().to - view->stepTest()->spec().from, 90.0);
    lk::tuning::StepTestSpec spec = view->stepTest()->spec();
    spec.durationS = 0.6;
    view->stepTest()->setSpec(spec);
    QVERIFY(view->stepTest()->runTest());
    QVERIFY(waitForRuns(*view, 1));
    const lk::tuning::StepRun run = view->runList()->runs().first();
    QCOMPARE(run.spec.loop, lk::tuning::StepLoop::Position);
    QVERIFY(run.trace.size() > 5);
    QCOMPARE(rig.count(1, Command::MultiPosition), 0); // always the speed-limited form
}

// A firmware 2.35 drive (MS: power, not iq) is stepped the same way; its run keeps the Kd
// gains its generation has, under lkctl's names.
void tst_StepTestView::v235DriveKeepsItsKdGains()
{
    SimRig rig(QStringLiteral("1:MS4015@2.35"));
    QVERIFY(rig.open());
    auto view = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(view);
    setSpec(*view, lk::tuning::StepLoop::Speed, 0, 300, 0.4);
    QVERIFY(view->stepTest()->runTest());
    QVERIFY2(waitForRuns(*view, 1), qPrintable(view->stepTest()->statusText()));
    const lk::tuning::StepRun run = view->runList()->runs().first();
    QCOMPARE(run.generation, QStringLiteral("v2.35"));
    QVERIFY(run.trace.effortIsPower);
    for (const char *key : {"angle_kd", "speed_kp", "speed_kd", "iq_kd"})
        QVERIFY2(run.gains.contains(QLatin1String(key)), key);
    QCOMPARE(run.effortLimit, std::optional<double>(1000.0));
    QCOMPARE(view->stepRuns()->model()->headerData(
                 StepRunsModel::metricRow(StepMetricKind::PeakEffort), Qt::Vertical),
             QVariant(QStringLiteral("Peak power")));
}

void tst_StepTestView::runsSaveAndLoad()
{
    SimRig rig;
    QVERIFY(rig.open());
    auto view = openView(rig, 1, limitsOf(rig, 1));
    QVERIFY(view);
    setSpec(*view, lk::tuning::StepLoop::Speed, 0, 300, 0.4);
    QVERIFY(view->stepTest()->runTest());
    QVERIFY(waitForRuns(*view, 1));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bench.lkruns.json"));
    QCOMPARE(view->stepRuns()->saveRuns(path), QString());
    QVERIFY(QFile::exists(path));
    QCOMPARE(view->stepRuns()->loadRuns(path), QString());
    QCOMPARE(view->runList()->runs().size(), 2);
    const lk::tuning::StepRun &a = view->runList()->runs().at(0);
    const lk::tuning::StepRun &b = view->runList()->runs().at(1);
    QCOMPARE(b.number, a.number); // loaded runs keep the number they were saved with
    QCOMPARE(b.trace.size(), a.trace.size());
    QCOMPARE(b.gains, a.gains);
    // The files keep times to the microsecond: the metrics come back to within that.
    QVERIFY(std::abs(*b.stepMetrics().riseTimeS.value - *a.stepMetrics().riseTimeS.value) < 1e-5);
}

void tst_StepTestView::badRunFileAddsNothing()
{
    lk::ui::StepRunList runs;
    lk::ui::StepRunsView view(&runs);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.lkruns.json"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format":"lkstudio-step-runs","version":1,"runs":[{"drive_id":"x"}]})");
    f.close();
    const QString error = view.loadRuns(path);
    QVERIFY(!error.isEmpty());
    QVERIFY2(error.contains(QStringLiteral("bad.lkruns.json")), qPrintable(error));
    QVERIFY(view.statusText().contains(QStringLiteral("Nothing was added")));
    QVERIFY(runs.runs().isEmpty());
}

void tst_StepTestView::metricDefinitionsOneClickAway()
{
    lk::ui::StepRunList runs;
    StepRunsModel model(&runs);
    const int row = StepRunsModel::metricRow(StepMetricKind::Overshoot);
    const QString tip = model.headerData(row, Qt::Vertical, Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(QStringLiteral("% of the step")), qPrintable(tip));
    for (StepMetricKind k : lk::ui::MetricText::all())
        QVERIFY(!lk::ui::MetricText::definition(k, false).isEmpty());
    QCOMPARE(lk::ui::MetricText::gap(lk::tuning::MetricGap::NeverSettled),
             QStringLiteral("never settled"));
}

QTEST_MAIN(tst_StepTestView)
#include "tst_steptestview.moc"
