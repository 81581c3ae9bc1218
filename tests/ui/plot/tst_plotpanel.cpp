#include "PlotPanelTestUtil.h"

#include <plot/CursorReadout.h>
#include <plot/PlotPanel.h>
#include <plot/PollRateControl.h>
#include <plot/StripChart.h>

#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <QtCore/QElapsedTimer>
#include <QtGui/QAction>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QMenu>
#include <QtWidgets/QToolButton>

#include <cmath>

using lk::bus::TelemetryBatch;
using lk::bus::TelemetryField;
using lk::bus::TelemetrySample;
using lk::plottest::batch;
using lk::plottest::sample;
using lk::plottest::showPanel;
using lk::ui::PlotPanel;
using lk::ui::Quantity;
using lk::ui::StripChart;
using lk::ui::TelemetryChannel;
using lk::ui::TelemetryStore;

namespace {

// Waits until no redraw has happened for a while (a loaded machine may delay a due tick).
void waitUntilIdle(const PlotPanel &panel)
{
    QElapsedTimer timer;
    timer.start();
    quint64 last = 0;
    do {
        last = panel.redrawCount();
        QTest::qWait(10 * PlotPanel::kRedrawIntervalMs);
    } while (panel.redrawCount() != last && timer.elapsed() < 10000);
}

QAction *actionNamed(PlotPanel &panel, const QString &text)
{
    for (QAction *a : panel.findChildren<QAction *>()) {
        if (a->text() == text) {
            return a;
        }
    }
    return nullptr;
}

// The newest x trace `index` of `chart` shows, NaN while it is empty (QTRY_ evaluates before
// any redraw).
double lastX(const StripChart *chart, int index = 0)
{
    const QList<QPointF> points = chart->points(index);
    return points.isEmpty() ? qQNaN() : points.last().x();
}

QPoint plotCentre(StripChart *chart)
{
    const QRectF area = chart->chart()->plotArea();
    return chart->mapFromScene(chart->chart()->mapToScene(area.center()));
}

} // namespace

class tst_PlotPanel : public QObject {
    Q_OBJECT
private slots:
    void seriesHoldDecimatedPoints();
    void pauseFreezesChartsButStoreGrows();
    void windowComboChangesRange_data();
    void windowComboChangesRange();
    void hiddenPanelDoesNotRedraw();
    void msDriveShowsPower();
    void overlaidModeHasAxisPerUnit();
    void signalPickerChangesCharts();
    void commandedMenuOffersEveryCommandedSignal();
    void wheelZoomsAndFollowLiveReturns();
    void dragPans();
    void cursorReadoutShowsValues();
    void autoscaleHoldsThenGrows();
    void manualScaleIsKept();
    void pollRateControl();
    void flatSignalThenJumpKeepsTicksBounded();
};

void tst_PlotPanel::seriesHoldDecimatedPoints()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1, 2});
    showPanel(panel);
    for (int k = 0; k < 20; ++k) { // 20 s at 1 kHz for two drives, in 1 s batches
        store.append(batch(1, k, 1000, 0.001));
        store.append(batch(2, k, 1000, 0.001));
    }
    QCOMPARE(panel.charts().size(), 3); // iq, speed, encoder stacked
    QTRY_VERIFY(!panel.charts().first()->points(0).isEmpty());
    for (StripChart *chart : panel.charts()) {
        QCOMPARE(chart->lineSeries().size(), 2);
        for (int i = 0; i < chart->lineSeries().size(); ++i) {
            QTRY_VERIFY(chart->points(i).size() > 0);
            QVERIFY2(chart->points(i).size() <= 2 * chart->width(),
                     qPrintable(QString::number(chart->points(i).size())));
            // The live edge is the real newest sample.
            QCOMPARE(lastX(chart, i), 19.999);
        }
        QCOMPARE(chart->timeAxis()->max(), 19.999);
        QCOMPARE(chart->timeAxis()->max() - chart->timeAxis()->min(), 10.0);
    }
}

void tst_PlotPanel::pauseFreezesChartsButStoreGrows()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 10000, 0.001));
    StripChart *chart = panel.charts().first();
    QTRY_COMPARE(lastX(chart), 9.999);
    waitUntilIdle(panel);
    const quint64 settled = panel.redrawCount();
    QTest::qWait(20 * PlotPanel::kRedrawIntervalMs);
    QCOMPARE(panel.redrawCount(), settled); // idle: nothing changed, nothing drawn

    QAction *pause = actionNamed(panel, "Pause");
    QVERIFY(pause);
    pause->trigger();
    QVERIFY(panel.isPaused());
    const QList<QPointF> frozen = chart->points(0);
    const double frozenEnd = panel.charts().first()->timeAxis()->max();
    const quint64 redraws = panel.redrawCount();
    store.append(batch(1, 10, 2000, 0.001));
    QCOMPARE(store.count(1, TelemetryChannel::Torque), 12000); // still recording
    QTest::qWait(20 * PlotPanel::kRedrawIntervalMs);
    QCOMPARE(panel.redrawCount(), redraws);
    QCOMPARE(chart->points(0), frozen);
    QCOMPARE(panel.charts().first()->timeAxis()->max(), frozenEnd);

    pause->trigger();
    QVERIFY(!panel.isPaused());
    QTRY_COMPARE(lastX(chart), 11.999);
}

void tst_PlotPanel::windowComboChangesRange_data()
{
    QTest::addColumn<double>("seconds");
    QTest::addColumn<double>("begin");
    QTest::addColumn<double>("end");
    QTest::newRow("5 s") << 5.0 << 15.0 << 20.0;
    QTest::newRow("10 s") << 10.0 << 10.0 << 20.0;
    QTest::newRow("30 s starts at zero") << 30.0 << 0.0 << 30.0;
    QTest::newRow("10 min") << 600.0 << 0.0 << 600.0;
}

void tst_PlotPanel::windowComboChangesRange()
{
    QFETCH(double, seconds);
    QFETCH(double, begin);
    QFETCH(double, end);
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 201, 0.1)); // 0 .. 20 s
    auto *combo = panel.findChild<QComboBox *>();
    QVERIFY(combo);
    QCOMPARE(combo->count(), 6);
    const int index = combo->findData(seconds);
    QVERIFY(index >= 0);
    combo->setCurrentIndex(index);
    QCOMPARE(panel.windowSeconds(), seconds);
    QValueAxis *axis = panel.charts().last()->timeAxis();
    QTRY_VERIFY(qFuzzyCompare(axis->min() + 1, begin + 1) && qFuzzyCompare(axis->max(), end));
}

void tst_PlotPanel::hiddenPanelDoesNotRedraw()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 100, 0.01));
    QTRY_VERIFY(panel.redrawCount() > 0);
    waitUntilIdle(panel);
    panel.hide();
    const quint64 redraws = panel.redrawCount();
    for (int k = 1; k <= 5; ++k) {
        store.append(batch(1, k, 100, 0.01));
        QTest::qWait(4 * PlotPanel::kRedrawIntervalMs);
    }
    QCOMPARE(panel.redrawCount(), redraws);
    panel.show();
    QTRY_VERIFY(panel.redrawCount() > redraws);
    QTRY_COMPARE(lastX(panel.charts().first()), 5.99);
}

void tst_PlotPanel::msDriveShowsPower()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDriveSeries(2, lk::protocol::Series::MS);
    panel.setDrives({2});
    showPanel(panel);
    StripChart *torque = panel.charts().first();
    QTRY_VERIFY(torque->valueAxis(Quantity::Power) != nullptr);
    QCOMPARE(torque->valueAxis(Quantity::Current), nullptr);
    QVERIFY(torque->lineSeries().first()->name().contains("Power"));

    TelemetrySample s;
    s.id = 2;
    s.time = 1.0;
    s.fields = TelemetryField::Power | TelemetryField::Speed;
    s.power = -300;
    store.append({s});
    QTRY_COMPARE(torque->points(0).size(), 1);
    QCOMPARE(torque->points(0).at(0).y(), -300.0);

    // A drive that sends iq is labelled iq whatever it was declared as: the data decides.
    panel.setDriveSeries(4, lk::protocol::Series::MS);
    panel.setDrives({4});
    store.append({sample(4, 1.0, 0.25, 0, 0)});
    QTRY_VERIFY(panel.charts().first()->valueAxis(Quantity::Current) != nullptr);
}

void tst_PlotPanel::overlaidModeHasAxisPerUnit()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1, 3});
    showPanel(panel);
    store.append(batch(1, 0, 500, 0.01));
    store.append(batch(3, 0, 500, 0.01));
    QAction *overlay = actionNamed(panel, "Overlay");
    QVERIFY(overlay);
    overlay->trigger();
    QCOMPARE(panel.layoutMode(), PlotPanel::Layout::Overlaid);
    QTRY_COMPARE(panel.charts().size(), 1);
    StripChart *chart = panel.charts().first();
    QTRY_COMPARE(chart->lineSeries().size(), 6);
    QVERIFY(chart->valueAxis(Quantity::Current));
    QVERIFY(chart->valueAxis(Quantity::Speed));
    QVERIFY(chart->valueAxis(Quantity::Encoder));
    QCOMPARE(chart->valueAxis(Quantity::Current)->alignment(), Qt::AlignLeft);
    QCOMPARE(chart->valueAxis(Quantity::Speed)->alignment(), Qt::AlignRight);
    QTRY_VERIFY(chart->points(int(chart->lineSeries().size()) - 1).size() > 0);
    overlay->trigger();
    QTRY_COMPARE(panel.charts().size(), 3);
}

void tst_PlotPanel::signalPickerChangesCharts()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    QCheckBox *multiTurn = nullptr;
    QCheckBox *speed = nullptr;
    for (QCheckBox *box : panel.findChildren<QCheckBox *>()) {
        if (box->text() == "Multi-turn angle") {
            multiTurn = box;
        } else if (box->text() == "Speed") {
            speed = box;
        }
    }
    QVERIFY(multiTurn && speed);
    multiTurn->setChecked(true);
    speed->setChecked(false);
    QVERIFY(panel.isChannelVisible(TelemetryChannel::MultiTurn));
    QVERIFY(!panel.isChannelVisible(TelemetryChannel::Speed));
    QTRY_COMPARE(panel.charts().size(), 3);
    QCOMPARE(panel.charts().at(0)->traces().first().channel, TelemetryChannel::Torque);
    QCOMPARE(panel.charts().at(1)->traces().first().channel, TelemetryChannel::Encoder);
    QCOMPARE(panel.charts().at(2)->traces().first().channel, TelemetryChannel::MultiTurn);
    QVERIFY(panel.charts().at(2)->valueAxis(Quantity::Angle));
}

void tst_PlotPanel::commandedMenuOffersEveryCommandedSignal()
{
    // The six commanded signals (0xA5..0xA8's target, step and speed cap among them) are in the
    // picker's "Commanded" menu; the button counts those shown.
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    auto *button = panel.findChild<QToolButton *>(QStringLiteral("commandedSignals"));
    QVERIFY(button && button->menu());
    QCOMPARE(button->menu()->actions().size(), PlotPanel::commandedChannels().size());
    QCOMPARE(button->text(), QStringLiteral("Commanded"));
    QAction *singleTurn = nullptr;
    for (QAction *action : button->menu()->actions()) {
        if (action->text() == channelPickerLabel(TelemetryChannel::CommandedSingleTurn))
            singleTurn = action;
    }
    QVERIFY(singleTurn);
    singleTurn->setChecked(true);
    QVERIFY(panel.isChannelVisible(TelemetryChannel::CommandedSingleTurn));
    QCOMPARE(button->text(), QStringLiteral("Commanded (1)"));
    QTRY_COMPARE(panel.charts().size(), 4);
    QCOMPARE(panel.charts().at(3)->traces().first().channel, TelemetryChannel::CommandedSingleTurn);
    // Set from code, the menu follows.
    panel.setChannelVisible(TelemetryChannel::CommandedMaxSpeed, true);
    QCOMPARE(button->text(), QStringLiteral("Commanded (2)"));
    panel.setChannelVisible(TelemetryChannel::CommandedSingleTurn, false);
    QVERIFY(!singleTurn->isChecked());
    QCOMPARE(button->text(), QStringLiteral("Commanded (1)"));
}

void tst_PlotPanel::wheelZoomsAndFollowLiveReturns()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 3001, 0.01)); // 0 .. 30 s
    StripChart *chart = panel.charts().first();
    QTRY_COMPARE(chart->timeAxis()->max(), 30.0);
    QVERIFY(panel.isFollowingLive());

    const QPoint at = plotCentre(chart);
    QWheelEvent wheel(at, chart->viewport()->mapToGlobal(at), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(chart->viewport(), &wheel);
    QVERIFY(!panel.isFollowingLive());
    QVERIFY(qFuzzyCompare(panel.visibleRange().length(), 8.0)); // one notch: 80 %
    QTRY_VERIFY(qFuzzyCompare(chart->timeAxis()->max() - chart->timeAxis()->min(), 8.0));
    // Every stacked chart shows the same time.
    for (StripChart *other : panel.charts()) {
        QTRY_COMPARE(other->timeAxis()->min(), chart->timeAxis()->min());
    }

    QAction *follow = actionNamed(panel, "Follow live");
    QVERIFY(follow && follow->isEnabled());
    store.append(batch(1, 30.01, 100, 0.01));
    follow->trigger();
    QVERIFY(panel.isFollowingLive());
    QVERIFY(!follow->isEnabled());
    QTRY_VERIFY(qFuzzyCompare(chart->timeAxis()->max(), 31.0));
}

void tst_PlotPanel::dragPans()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 3001, 0.01));
    StripChart *chart = panel.charts().first();
    QTRY_COMPARE(chart->timeAxis()->max(), 30.0);
    const QPoint from = plotCentre(chart);
    const QPoint to = from + QPoint(100, 0);
    const double secondsPerPixel = 10.0 / chart->chart()->plotArea().width();
    QTest::mousePress(chart->viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(chart->viewport(), to);
    QTest::mouseRelease(chart->viewport(), Qt::LeftButton, {}, to);
    QVERIFY(!panel.isFollowingLive());
    QVERIFY(std::abs(panel.visibleRange().end - (30 - 100 * secondsPerPixel)) < 1e-6);
    QTRY_VERIFY(std::abs(chart->timeAxis()->max() - panel.visibleRange().end) < 1e-9);
}

void tst_PlotPanel::cursorReadoutShowsValues()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 1001, 0.01));
    auto *readout = panel.findChild<lk::ui::CursorReadout *>();
    QVERIFY(readout);
    QTRY_VERIFY(readout->text().startsWith("Latest"));
    StripChart *chart = panel.charts().first();
    QTest::mouseMove(chart->viewport(), plotCentre(chart));
    QTRY_VERIFY(chart->cursorTime().has_value());
    QVERIFY(std::abs(*chart->cursorTime() - 5.0) < 0.1); // the centre of 0 .. 10 s
    for (StripChart *other : panel.charts()) {
        QCOMPARE(other->cursorTime(), chart->cursorTime());
    }
    QVERIFY(readout->text().startsWith("t = "));
    QVERIFY(readout->text().contains("ID 1:"));
    const double iq = *store.valueAt(1, TelemetryChannel::Torque, *chart->cursorTime());
    QVERIFY2(readout->text().contains(QString::number(iq, 'f', 3)), qPrintable(readout->text()));
}

void tst_PlotPanel::autoscaleHoldsThenGrows()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 1000, 0.01)); // iq = sin: -1 .. 1
    QValueAxis *axis = panel.charts().first()->valueAxis(Quantity::Current);
    QVERIFY(axis);
    QTRY_VERIFY(axis->min() <= -0.99 && axis->max() >= 0.99);
    const double min = axis->min(), max = axis->max();
    QVERIFY2(max - min < 4, "the range fits the data");
    const quint64 redraws = panel.redrawCount();
    store.append(batch(1, 10, 100, 0.01)); // more of the same: the scale holds still
    QTRY_VERIFY(panel.redrawCount() > redraws);
    QCOMPARE(axis->min(), min);
    QCOMPARE(axis->max(), max);
    store.append({sample(1, 11.5, 25.0, 0, 0)}); // a spike beyond the range: it grows
    QTRY_VERIFY(axis->max() >= 25.0);
}

void tst_PlotPanel::manualScaleIsKept()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 1000, 0.01));
    StripChart *chart = panel.charts().first();
    QValueAxis *axis = chart->valueAxis(Quantity::Current);
    QVERIFY(axis);
    QTRY_VERIFY(panel.redrawCount() > 0 && axis->min() <= -0.99 && axis->max() >= 0.99);
    waitUntilIdle(panel);
    const double span = axis->max() - axis->min();
    const QPoint at = plotCentre(chart);
    QWheelEvent wheel(at, chart->viewport()->mapToGlobal(at), QPoint(), QPoint(0, -120),
                      Qt::NoButton, Qt::ControlModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(chart->viewport(), &wheel); // Ctrl+wheel: scale values by hand
    QVERIFY(!panel.autoscale());
    QVERIFY(qFuzzyCompare(axis->max() - axis->min(), span * 1.25));
    const double min = axis->min(), max = axis->max();
    const quint64 redraws = panel.redrawCount();
    store.append({sample(1, 10.5, 50.0, 0, 0)});
    QTRY_VERIFY(panel.redrawCount() > redraws);
    QCOMPARE(axis->min(), min);
    QCOMPARE(axis->max(), max);
    panel.setAutoscale(true);
    QTRY_VERIFY(axis->max() >= 50.0);
}

void tst_PlotPanel::pollRateControl()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    auto *control = panel.findChild<lk::ui::PollRateControl *>();
    QVERIFY(control);
    auto *spin = control->findChild<QDoubleSpinBox *>();
    auto *max = control->findChild<QCheckBox *>();
    QVERIFY(spin && max);
    QSignalSpy spy(&panel, &PlotPanel::pollRateRequested);
    spin->setValue(200);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.last().at(0).toDouble(), 200.0);
    max->setChecked(true);
    QCOMPARE(spy.count(), 2);
    QCOMPARE(spy.last().at(0).toDouble(), 0.0);
    QVERIFY(!spin->isEnabled());

    panel.setPollRate(50); // shows the rate in use: no request
    QCOMPARE(spy.count(), 2);
    QCOMPARE(control->pollRate(), 50.0);
    QVERIFY(!max->isChecked());

    panel.setBusLimit(485.0, 242.5);
    QVERIFY(control->busLimitText().contains("485"));
    QVERIFY(control->busLimitText().contains("242.5"));
    QVERIFY(!control->busLimitText().contains("above"));
    spin->setValue(300);
    QVERIFY(control->busLimitText().contains("above"));
}

// A motor at rest gives a near-flat trace (axis range ~0.001); a jump to a real range must not
// make QtCharts lay out one tick per old interval (millions: the GUI froze), and neither must
// the jump back.
void tst_PlotPanel::flatSignalThenJumpKeepsTicksBounded()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    TelemetryBatch flat;
    for (int i = 0; i < 200; ++i)
        flat.append(sample(1, i * 0.01, 0.0, (i % 2) * 0.001, 0));
    store.append(flat);
    StripChart *chart = panel.charts().at(1); // speed
    QTRY_VERIFY(chart->valueAxis(Quantity::Speed) != nullptr);
    QTRY_VERIFY(chart->points(0).size() > 0);
    TelemetryBatch jump;
    for (int i = 0; i < 200; ++i)
        jump.append(sample(1, 2 + i * 0.01, 0.0, 5000.0 * (i % 2), 0));
    store.append(jump);
    QValueAxis *axis = chart->valueAxis(Quantity::Speed);
    QTRY_VERIFY(axis->max() >= 5000.0);
    QVERIFY(axis->tickType() == QValueAxis::TicksDynamic);
    QVERIFY((axis->max() - axis->min()) / axis->tickInterval() < 50);
    TelemetryBatch back;
    for (int i = 0; i < 2000; ++i)
        back.append(sample(1, 4 + i * 0.01, 0.0, (i % 2) * 0.001, 0));
    store.append(back);
    panel.setWindowSeconds(5);
    QTRY_VERIFY(axis->max() < 1.0);
    QVERIFY((axis->max() - axis->min()) / axis->tickInterval() < 50);
}

QTEST_MAIN(tst_PlotPanel)
#include "tst_plotpanel.moc"
