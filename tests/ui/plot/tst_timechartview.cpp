// The chart view's painting: every pixel painted, the view's own background only in the band
// around the chart's.

#include "PlotPanelTestUtil.h"

#include <plot/PlotPanel.h>
#include <plot/StripChart.h>
#include <plot/TelemetryStore.h>

#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>
#include <QtGui/QImage>
#include <QtGui/QPen>
#include <QtTest/QTest>

#include <utility>

using lk::plottest::ShownPanel;
using lk::ui::StripChart;

class tst_TimeChartView : public QObject {
    Q_OBJECT
private slots:
    void everyPixelIsPainted();
    void bandAroundChartIsTheWindowColour();
    void hairlinesPaintWhatOnePixelPensPaint();
};

namespace {

/// The chart rendered over an image filled with a colour no theme uses.
QImage renderOverSentinel(StripChart *chart, QColor sentinel)
{
    QImage image(chart->size(), QImage::Format_ARGB32_Premultiplied);
    image.fill(sentinel);
    chart->QWidget::render(&image, QPoint(), QRegion(), QWidget::DrawChildren); // no window fill
    return image;
}

} // namespace

void tst_TimeChartView::everyPixelIsPainted()
{
    // The view fills only the band around the chart's opaque background; together they must
    // still cover every pixel (the viewport paints opaquely: nothing else fills it).
    ShownPanel shown;
    const QList<StripChart *> charts = shown.panel.charts();
    QVERIFY(!charts.isEmpty());
    QTRY_VERIFY(charts.last()->timeAxis()->max() >= 19.9);
    const QColor sentinel(255, 0, 254);
    for (StripChart *chart : charts) {
        const QImage image = renderOverSentinel(chart, sentinel);
        int unpainted = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x)
                unpainted += image.pixelColor(x, y) == sentinel ? 1 : 0;
        }
        QVERIFY2(unpainted == 0, qPrintable(QStringLiteral("%1 pixels unpainted").arg(unpainted)));
    }
}

void tst_TimeChartView::bandAroundChartIsTheWindowColour()
{
    ShownPanel shown;
    StripChart *chart = shown.panel.charts().first();
    const QImage image = renderOverSentinel(chart, QColor(255, 0, 254));
    const QColor window = chart->palette().color(QPalette::Window);
    const QColor base = chart->palette().color(QPalette::Base);
    QCOMPARE(image.pixelColor(0, 0), window);
    QCOMPARE(image.pixelColor(image.width() - 1, image.height() - 1), window);
    // Inside the chart, left of the plot area and above the first label: the chart's Base.
    const QRectF area = chart->chart()->plotArea();
    const QPoint inside = chart->mapFromScene(chart->chart()->mapToScene(area.topLeft()));
    QCOMPARE(image.pixelColor(inside.x() / 2, inside.y() / 2 + 1), base);
}

// The axes' lines and grids are hairlines (cheaper bounds for the view to ask at each frame):
// the chart must look exactly as with the theme's 1-pixel pens.
void tst_TimeChartView::hairlinesPaintWhatOnePixelPensPaint()
{
    ShownPanel shown;
    shown.panel.setPaused(true); // the same data in both renders
    StripChart *chart = shown.panel.charts().first();
    const QList<QAbstractAxis *> axes = chart->chart()->axes();
    QVERIFY(axes.size() >= 2);
    for (QAbstractAxis *axis : axes)
        QCOMPARE(axis->gridLinePen().widthF(), 0.0);
    const QImage hair = renderOverSentinel(chart, Qt::black);
    for (QAbstractAxis *axis : axes) {
        for (auto [get, set] :
             {std::pair{&QAbstractAxis::linePen, &QAbstractAxis::setLinePen},
              {&QAbstractAxis::gridLinePen, &QAbstractAxis::setGridLinePen},
              {&QAbstractAxis::minorGridLinePen, &QAbstractAxis::setMinorGridLinePen}}) {
            QPen pen = (axis->*get)();
            pen.setWidthF(1.0);
            (axis->*set)(pen);
        }
    }
    const QImage onePixel = renderOverSentinel(chart, Qt::black);
    QCOMPARE(hair.size(), onePixel.size());
    int differ = 0;
    for (int y = 0; y < hair.height(); ++y) {
        for (int x = 0; x < hair.width(); ++x)
            differ += hair.pixel(x, y) != onePixel.pixel(x, y) ? 1 : 0;
    }
    QCOMPARE(differ, 0);
}

QTEST_MAIN(tst_TimeChartView)
#include "tst_timechartview.moc"
