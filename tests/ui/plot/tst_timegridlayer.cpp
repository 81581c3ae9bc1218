// The time grid StripChart draws itself (TimeGridLayer) in place of QtCharts' time axis: tick
// times, the hidden axis that holds the range, and labels painted under the bottom strip only.

#include "PlotPanelTestUtil.h"

#include <plot/PlotPanel.h>
#include <plot/StripChart.h>
#include <plot/TelemetryStore.h>
#include <plot/TimeGridLayer.h>

#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>
#include <QtGui/QImage>
#include <QtTest/QTest>

#include <cmath>

using lk::plottest::ShownPanel;
using lk::ui::StripChart;
using lk::ui::TimeGridLayer;

class tst_TimeGridLayer : public QObject {
    Q_OBJECT
private slots:
    void ticks_data();
    void ticks();
    void ticksAreWholeMultiplesFarFromZero();
    void noTicksForAnEmptyRange();
    void bottomStripAloneHasLabels();
    void labelsArePaintedUnderThePlotArea();
};

void tst_TimeGridLayer::ticks_data()
{
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("t1");
    QTest::addColumn<int>("columns");
    QTest::addColumn<QVector<double>>("expected");
    // 1000 px: at most 8 ticks, so 10 s takes a step of 2 (1.25 rounded up to 1, 2, 5 x 10^k).
    QTest::newRow("10 s wide") << 0.0 << 10.0 << 1000 << QVector<double>{0, 2, 4, 6, 8, 10};
    QTest::newRow("sliding") << 3.3 << 13.3 << 1000 << QVector<double>{4, 6, 8, 10, 12};
    // 200 px: two ticks' worth, a step of 5.
    QTest::newRow("narrow") << 0.0 << 10.0 << 200 << QVector<double>{0, 5, 10};
    QTest::newRow("around zero") << -0.3 << 0.3 << 300 << QVector<double>{-0.2, 0, 0.2};
}

void tst_TimeGridLayer::ticks()
{
    QFETCH(double, t0);
    QFETCH(double, t1);
    QFETCH(int, columns);
    QFETCH(QVector<double>, expected);
    const QVector<double> got = TimeGridLayer::ticks(t0, t1, columns);
    QCOMPARE(got.size(), expected.size());
    for (qsizetype i = 0; i < got.size(); ++i) {
        QVERIFY2(std::abs(got[i] - expected[i]) < 1e-9, qPrintable(QString::number(got[i])));
        QVERIFY(!std::signbit(got[i]) || got[i] < 0); // zero is "0", never "-0"
    }
}

void tst_TimeGridLayer::ticksAreWholeMultiplesFarFromZero()
{
    // An hour-long session: the ticks stay on multiples of the step, none missing at the ends.
    const double t0 = 3600.05;
    const double t1 = 3610.05;
    const QVector<double> got = TimeGridLayer::ticks(t0, t1, 1000);
    const double step = TimeGridLayer::tickStep(t1 - t0, 1000);
    QCOMPARE(step, 2.0);
    QCOMPARE(got.size(), 5);
    for (double t : got) {
        QVERIFY(t >= t0 && t <= t1);
        QVERIFY(std::abs(t / step - std::round(t / step)) < 1e-9);
    }
    QVERIFY(got.first() - t0 < step);
    QVERIFY(t1 - got.last() < step);
}

void tst_TimeGridLayer::noTicksForAnEmptyRange()
{
    QVERIFY(TimeGridLayer::ticks(5, 5, 1000).isEmpty());
    QVERIFY(TimeGridLayer::ticks(6, 5, 1000).isEmpty());
    QVERIFY(TimeGridLayer::ticks(std::nan(""), 5, 1000).isEmpty());
}

void tst_TimeGridLayer::bottomStripAloneHasLabels()
{
    ShownPanel shown;
    const QList<StripChart *> charts = shown.panel.charts();
    QVERIFY(charts.size() >= 2);
    for (StripChart *chart : charts) {
        const bool bottom = chart == charts.last();
        QCOMPARE(chart->timeLabelsVisible(), bottom);
        // QtCharts' own time axis holds the range but is never laid out (its labels and grid
        // moved at every frame); it still follows the view.
        QVERIFY(!chart->timeAxis()->isVisible());
        QTRY_VERIFY(chart->timeAxis()->max() >= 19.9);
        const QMargins margins = chart->chart()->margins();
        if (bottom)
            QVERIFY2(margins.bottom() > margins.top() + 10, "room for the labels and the title");
        else
            QCOMPARE(margins.bottom(), margins.top());
    }
}

void tst_TimeGridLayer::labelsArePaintedUnderThePlotArea()
{
    ShownPanel shown;
    const QList<StripChart *> charts = shown.panel.charts();
    QVERIFY(charts.size() >= 2);
    QTRY_VERIFY(charts.last()->timeAxis()->max() >= 19.9);
    // The band under each plot area: dark text on the bottom strip, none under the others
    // (their margin and the light background of the view around them).
    for (StripChart *chart : charts) {
        const QImage image = chart->grab().toImage();
        const QRectF area = chart->chart()->plotArea();
        const QPoint origin = chart->mapFromScene(chart->chart()->mapToScene(area.bottomLeft()));
        const int top = origin.y() + 3;
        const int bottom = std::min(image.height() - 1, top + 14);
        int ink = 0;
        for (int y = top; y <= bottom; ++y) {
            for (int x = origin.x(); x < origin.x() + int(area.width()) && x < image.width(); ++x)
                ink += qGray(image.pixel(x, y)) < 100 ? 1 : 0;
        }
        if (chart == charts.last())
            QVERIFY2(ink > 20, qPrintable(QStringLiteral("%1 pixels of text").arg(ink)));
        else
            QVERIFY2(ink == 0, qPrintable(QStringLiteral("%1 dark pixels").arg(ink)));
    }
}

QTEST_MAIN(tst_TimeGridLayer)
#include "tst_timegridlayer.moc"
