// The step runs compared (ui/tuning): only runs that measure a metric alike are compared,
// power is labelled as power, and the overlay zooms, pans and reads out like the live plots.

#include "StepRunFactory.h"

#include <panels/Format.h>
#include <plot/TimeChartView.h>
#include <tuning/MetricText.h>
#include <tuning/StepOverlayChart.h>
#include <tuning/StepRunList.h>
#include <tuning/StepRunsModel.h>
#include <tuning/StepRunsView.h>

#include <QtCharts/QChart>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <QtTest/QtTest>
#include <QtWidgets/QToolButton>

using namespace lk;
using namespace lk::tuningtest;
using lk::ui::StepMetricKind;
using lk::ui::StepRunsModel;

namespace {

QPoint plotPoint(ui::TimeChartView *view, double share)
{
    const QRectF area = view->chart()->plotArea();
    const QPointF at(area.left() + share * area.width(), area.center().y());
    return view->mapFromScene(view->chart()->mapToScene(at));
}

void wheel(ui::TimeChartView *view, QPoint at, int delta)
{
    QWheelEvent e(at, view->viewport()->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton,
                  Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view->viewport(), &e);
}

bool near(double a, double b, double tolerance = 1e-9)
{
    return std::abs(a - b) <= tolerance * std::max(1.0, std::abs(b));
}

/// The chart on screen at a size where its gestures have room.
bool showChart(ui::StepOverlayChart &chart)
{
    chart.resize(900, 600);
    chart.show();
    return QTest::qWaitForWindowExposed(&chart);
}

ui::OverlayRun overlay(const QString &label, const RunShape &shape)
{
    return {label, Qt::blue, makeRun(shape).trace};
}

} // namespace

class tst_StepRunsView : public QObject {
    Q_OBJECT
private slots:
    void runsOfAnotherLoopAreNotCompared();
    void powerAndCurrentAreComparedApart();
    void powerHasAnAxisOfItsOwn();
    void wheelZoomsDragPansResetRestores();
    void selectingARangeShowsIt();
    void hoverReadsEveryRunAtTheCursor();
    void loadedRunsKeepTheirNumbersAndNames();
};

void tst_StepRunsView::runsOfAnotherLoopAreNotCompared()
{
    ui::StepRunList runs;
    RunShape speed;
    speed.tau = 0.05;
    runs.add(makeRun(speed));
    RunShape position;
    position.loop = tuning::StepLoop::Position;
    position.tau = 0.01; // the fastest rise of all, but of a position step
    runs.add(makeRun(position));
    speed.tau = 0.08;
    runs.add(makeRun(speed));
    StepRunsModel model(&runs);
    const int row = StepRunsModel::metricRow(StepMetricKind::RiseTime);
    QCOMPARE(model.bestColumns(StepMetricKind::RiseTime), QVector<int>{0});
    QVERIFY(model.data(model.index(row, 0), Qt::FontRole).value<QFont>().bold());
    QVERIFY(!model.data(model.index(row, 1), Qt::FontRole).value<QFont>().bold());
    QVERIFY(model.data(model.index(row, 1), Qt::ToolTipRole)
                .toString()
                .contains(QStringLiteral("Not compared")));
    // A run alone in its loop is best of nothing, however good its numbers.
    runs.setShown(runs.keyAt(2), false);
    QVERIFY(model.bestColumns(StepMetricKind::RiseTime).isEmpty());
}

void tst_StepRunsView::powerAndCurrentAreComparedApart()
{
    ui::StepRunList runs;
    RunShape mf;
    mf.effort = 2.0;
    runs.add(makeRun(mf));           // column 0: 2 A
    runs.add(makeRun(msPower(134))); // column 1: power 134
    runs.add(makeRun(msPower(300))); // column 2: power 300, same drive model
    StepRunsModel model(&runs);
    const int row = StepRunsModel::metricRow(StepMetricKind::PeakEffort);
    QCOMPARE(model.headerData(row, Qt::Vertical).toString(), QStringLiteral("Peak iq or power"));
    QCOMPARE(model.data(model.index(row, 0)).toString(), ui::Format::withUnit(2.0, 2, "A"));
    QCOMPARE(model.data(model.index(row, 1)).toString(), ui::Format::power(134));
    QVERIFY(model.data(model.index(row, 1)).toString().endsWith(ui::Format::powerUnit()));
    // 134 beats 300 among the MS4015's powers; 2 A stands alone.
    QCOMPARE(model.bestColumns(StepMetricKind::PeakEffort), QVector<int>{1});
    // Another MS model's power is relative to another maximum: not compared either.
    tuning::StepRun other = makeRun(msPower(50));
    other.model = QStringLiteral("MS5010");
    runs.add(other);
    QCOMPARE(model.bestColumns(StepMetricKind::PeakEffort), QVector<int>{1});
    // Times compare across the effort units: the same loop, in seconds.
    QCOMPARE(model.bestColumns(StepMetricKind::RiseTime), (QVector<int>{0, 1, 2, 3}));
    // Only power: named so.
    ui::StepRunList ms;
    ms.add(makeRun(msPower(0)));
    StepRunsModel msModel(&ms);
    QCOMPARE(msModel.headerData(row, Qt::Vertical).toString(), QStringLiteral("Peak power"));
    QCOMPARE(msModel.data(msModel.index(row, 0)).toString(), ui::Format::power(0));
}

void tst_StepRunsView::powerHasAnAxisOfItsOwn()
{
    ui::StepOverlayChart chart;
    chart.setRuns({overlay("MF", RunShape{}), overlay("MS", msPower(400))});
    QChart *effort = chart.effortView()->chart();
    const QList<QAbstractAxis *> axes = effort->axes(Qt::Vertical);
    QCOMPARE(axes.size(), 2);
    QAbstractAxis *current = nullptr;
    QAbstractAxis *power = nullptr;
    for (QAbstractAxis *a : axes)
        (a->titleText() == QStringLiteral("Power (rel.)") ? power : current) = a;
    QVERIFY(power && current);
    QCOMPARE(current->titleText(), QStringLiteral("iq (A)"));
    const QList<QAbstractSeries *> lines = effort->series();
    QCOMPARE(lines.size(), 2);
    QVERIFY(lines.at(0)->attachedAxes().contains(current));
    QVERIFY(lines.at(1)->attachedAxes().contains(power));
    // The power axis spans the power, not the current.
    QVERIFY(static_cast<QValueAxis *>(power)->max() >= 400);
    QVERIFY(static_cast<QValueAxis *>(current)->max() < 100);
    // Power alone: one axis, named power.
    chart.setRuns({overlay("MS", msPower(400))});
    QCOMPARE(effort->axes(Qt::Vertical).size(), 1);
    QCOMPARE(effort->axes(Qt::Vertical).first()->titleText(), QStringLiteral("Power (rel.)"));
}

void tst_StepRunsView::wheelZoomsDragPansResetRestores()
{
    ui::StepOverlayChart chart;
    QVERIFY(showChart(chart));
    chart.setRuns({overlay("A", RunShape{})});
    const ui::TimeSpan all = chart.dataRange();
    QVERIFY(near(all.begin, -0.1) && near(all.end, 0.9));
    auto *reset = chart.findChild<QToolButton *>(QStringLiteral("stepResetZoom"));
    QVERIFY(reset && !reset->isEnabled());

    ui::TimeChartView *response = chart.responseView();
    wheel(response, plotPoint(response, 0.5), 120 * 3); // three notches in
    const double zoomed = all.length() * std::pow(0.8, 3);
    QVERIFY2(near(chart.shownRange().length(), zoomed),
             qPrintable(QString::number(chart.shownRange().length())));
    for (ui::TimeChartView *v : {chart.responseView(), chart.effortView()}) {
        QVERIFY(near(v->timeAxis()->min(), chart.shownRange().begin));
        QVERIFY(near(v->timeAxis()->max(), chart.shownRange().end));
    }
    QVERIFY(reset->isEnabled());

    // Dragging right shows earlier times, on both charts.
    const ui::TimeSpan before = chart.shownRange();
    const QPoint from = plotPoint(chart.effortView(), 0.5);
    const QPoint to = from + QPoint(80, 0);
    const double perPixel = before.length() / chart.effortView()->chart()->plotArea().width();
    QTest::mousePress(chart.effortView()->viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(chart.effortView()->viewport(), to);
    QTest::mouseRelease(chart.effortView()->viewport(), Qt::LeftButton, {}, to);
    QVERIFY(near(chart.shownRange().begin, before.begin - 80 * perPixel, 1e-6));
    QVERIFY(near(chart.responseView()->timeAxis()->min(), chart.shownRange().begin));

    QTest::mouseClick(reset, Qt::LeftButton);
    QVERIFY(near(chart.shownRange().begin, all.begin) && near(chart.shownRange().end, all.end));
    QVERIFY(near(chart.responseView()->timeAxis()->max(), all.end));
    QVERIFY(!reset->isEnabled());
}

void tst_StepRunsView::selectingARangeShowsIt()
{
    ui::StepOverlayChart chart;
    QVERIFY(showChart(chart));
    chart.setRuns({overlay("A", RunShape{})});
    ui::TimeChartView *view = chart.responseView();
    const QPoint from = plotPoint(view, 0.1);
    const QPoint to = plotPoint(view, 0.2);
    const double t0 = view->timeAxis()->min() + 0.1 * chart.dataRange().length();
    const double t1 = view->timeAxis()->min() + 0.2 * chart.dataRange().length();
    QTest::mousePress(view->viewport(), Qt::RightButton, {}, from);
    QTest::mouseMove(view->viewport(), to);
    QTest::mouseRelease(view->viewport(), Qt::RightButton, {}, to);
    const double pixel = chart.dataRange().length() / view->chart()->plotArea().width();
    QVERIFY(std::abs(chart.shownRange().begin - t0) < 2 * pixel);
    QVERIFY(std::abs(chart.shownRange().end - t1) < 2 * pixel);
}

void tst_StepRunsView::hoverReadsEveryRunAtTheCursor()
{
    ui::StepOverlayChart chart;
    QVERIFY(showChart(chart));
    const tuning::StepRun a = makeRun(RunShape{});
    const tuning::StepRun b = makeRun(msPower(250, 0.02));
    chart.setRuns({{"Run A", Qt::blue, a.trace}, {"Run B", Qt::red, b.trace}});
    QCoreApplication::processEvents(); // the charts lay out their new axes
    QVERIFY(!chart.readoutText().startsWith(QStringLiteral("t = ")));
    ui::TimeChartView *view = chart.effortView();
    QTest::mouseMove(view->viewport(), plotPoint(view, 0.25));
    QTRY_VERIFY(chart.cursorTime().has_value());
    QCOMPARE(chart.responseView()->cursorTime(), chart.cursorTime());
    QCOMPARE(chart.effortView()->cursorTime(), chart.cursorTime());
    const double t = *chart.cursorTime();
    QVERIFY2(std::abs(t - (-0.1 + 0.25)) < 0.01, qPrintable(QString::number(t)));
    // The sample at or before the cursor (t from the step: trace time t + 0.1).
    const int i = int(std::floor((t + 0.1) / 0.005 + 1e-9));
    const QString text = chart.readoutText();
    QVERIFY2(text.startsWith(QStringLiteral("t = %1 s").arg(t, 0, 'f', 3)), qPrintable(text));
    QVERIFY2(
        text.contains(
            QStringLiteral("Run A: Speed %1 dps, iq 2.000 A").arg(a.trace.value.at(i), 0, 'f', 1)),
        qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("Run B: Speed %1 dps, Power 250 %2")
                               .arg(b.trace.value.at(i), 0, 'f', 1)
                               .arg(ui::Format::powerUnit())),
             qPrintable(text));
    QTest::mouseMove(view->viewport(), QPoint(1, 1)); // off the plot area
    QTRY_VERIFY(!chart.cursorTime().has_value());
}

// Runs come back from a file as they were saved: "Run 3" stays "Run 3", a named run keeps its
// name; a run of this session is numbered after them; a loaded run whose title the session
// already shows says which file it came from.
void tst_StepRunsView::loadedRunsKeepTheirNumbersAndNames()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("monday.lkruns.json"));
    {
        ui::StepRunList monday;
        ui::StepRunsView view(&monday);
        for (int i = 0; i < 4; ++i)
            monday.add(makeRun(RunShape{}));
        monday.remove(monday.keyAt(0)); // Run 1 and Run 2 dropped: 3 and 4 are kept
        monday.remove(monday.keyAt(0));
        tuning::StepRun named = makeRun(RunShape{});
        named.label = QStringLiteral("stiffer");
        monday.add(named); // Run 5, named
        QCOMPARE(view.saveRuns(path), QString());
    }
    ui::StepRunList runs;
    ui::StepRunsView view(&runs);
    QCOMPARE(view.loadRuns(path), QString());
    QCOMPARE(runs.runs().size(), 3);
    QCOMPARE(runs.runs().at(0).number, 3);
    QCOMPARE(runs.runs().at(1).number, 4);
    QCOMPARE(runs.runs().at(2).number, 5);
    StepRunsModel *model = view.model();
    QCOMPARE(model->headerData(0, Qt::Horizontal).toString(), QStringLiteral("Run 3"));
    QCOMPARE(model->headerData(1, Qt::Horizontal).toString(), QStringLiteral("Run 4"));
    QCOMPARE(model->headerData(2, Qt::Horizontal).toString(), QStringLiteral("stiffer"));
    QCOMPARE(view.overlay()->responseSeries(0)->name(), QStringLiteral("Run 3"));
    // This session's next run follows the numbers shown.
    const int key = runs.add(makeRun(RunShape{}));
    QCOMPARE(runs.find(key)->number, 6);
    // The same file again: the same titles, told apart by the file.
    QCOMPARE(view.loadRuns(path), QString());
    QCOMPARE(runs.runs().at(4).number, 3);
    QCOMPARE(model->headerData(4, Qt::Horizontal).toString(),
             QStringLiteral("Run 3 (monday.lkruns.json)"));
    // Each run keeps a colour of its own.
    QVERIFY(model->headerData(0, Qt::Horizontal, Qt::DecorationRole) !=
            model->headerData(4, Qt::Horizontal, Qt::DecorationRole));
}

QTEST_MAIN(tst_StepRunsView)
#include "tst_steprunsview.moc"
