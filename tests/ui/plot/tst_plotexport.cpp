// The plot panel's exports: CSV of what is plotted (everything or the visible range) and PNG
// of the charts, and the errors a failed write reports.

#include "PlotPanelTestUtil.h"

#include <plot/PlotPanel.h>
#include <plot/StripChart.h>
#include <plot/TelemetryStore.h>

#include <QtCharts/QLineSeries>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtGui/QImage>
#include <QtTest/QTest>

using lk::plottest::batch;
using lk::plottest::sample;
using lk::plottest::showPanel;
using lk::ui::PlotPanel;
using lk::ui::TelemetryChannel;
using lk::ui::TelemetryStore;

namespace {

QList<QStringList> readCsv(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    QList<QStringList> rows;
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (!line.isEmpty()) {
            rows.append(QString::fromUtf8(line).split(','));
        }
    }
    return rows;
}

} // namespace

class tst_PlotExport : public QObject {
    Q_OBJECT
private slots:
    void exportCsvWritesPlottedColumns();
    void exportCsvVisibleRange();
    void exportPngWritesImage();
    void exportReportsErrors();
};

void tst_PlotExport::exportCsvWritesPlottedColumns()
{
    TelemetryStore store;
    for (int k = 0; k < 10; ++k) {
        store.append({sample(3, k * 0.01, k * 0.5, k * 10, k)});
        store.append({sample(4, 0.005 + k * 0.01, -k, k, k)});
    }
    PlotPanel panel(&store);
    panel.setDrives({3, 4});
    panel.setChannelVisible(TelemetryChannel::Encoder, false);
    QTemporaryDir dir;
    const QString path = dir.filePath("plot.csv");
    QCOMPARE(panel.exportCsv(path, PlotPanel::ExportScope::Everything), QString());
    const QList<QStringList> rows = readCsv(path);
    QCOMPARE(rows.size(), 21);
    QCOMPARE(rows.first().join(','),
             QString("time_s,id3_iq_a,id3_speed_dps,id4_iq_a,id4_speed_dps"));
    double previous = -1;
    for (int r = 1; r < rows.size(); ++r) {
        const QStringList &cells = rows.at(r);
        QCOMPARE(cells.size(), 5);
        const double t = cells.at(0).toDouble();
        QVERIFY(t > previous);
        previous = t;
        const int k = (r - 1) / 2;
        const bool drive3 = (r - 1) % 2 == 0; // drive 3 at 0, 0.01, ...; drive 4 in between
        QCOMPARE(cells.at(0), QString::number(drive3 ? k * 0.01 : 0.005 + k * 0.01, 'f', 6));
        QCOMPARE(cells.at(1).isEmpty(), !drive3);
        QCOMPARE(cells.at(3).isEmpty(), drive3);
        if (drive3) {
            QCOMPARE(cells.at(1).toDouble(), k * 0.5);
            QCOMPARE(cells.at(2).toDouble(), k * 10.0);
        } else {
            QCOMPARE(cells.at(3).toDouble(), double(-k));
            QCOMPARE(cells.at(4).toDouble(), double(k));
        }
    }
}

void tst_PlotExport::exportCsvVisibleRange()
{
    TelemetryStore store;
    store.append(batch(1, 0, 201, 0.1)); // 0 .. 20 s at 10 Hz
    PlotPanel panel(&store);
    panel.setDrives({1});
    panel.setWindowSeconds(5);
    QTemporaryDir dir;
    const QString path = dir.filePath("visible.csv");
    QCOMPARE(panel.exportCsv(path, PlotPanel::ExportScope::VisibleRange), QString());
    const QList<QStringList> rows = readCsv(path);
    QCOMPARE(rows.first().join(','), QString("time_s,id1_iq_a,id1_speed_dps,id1_encoder_counts"));
    QCOMPARE(rows.size(), 1 + 51); // 15.0 .. 20.0 inclusive
    QCOMPARE(rows.at(1).at(0), QString("15.000000"));
    QCOMPARE(rows.last().at(0), QString("20.000000"));
    QCOMPARE(rows.last().at(3), QString::number(int(20.0 * 100) % 16384));
}

void tst_PlotExport::exportPngWritesImage()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 1000, 0.01));
    QTRY_VERIFY(panel.charts().first()->lineSeries().first()->count() > 0);
    QTemporaryDir dir;
    const QString path = dir.filePath("plot.png");
    QCOMPARE(panel.exportPng(path), QString());
    const QImage image(path);
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), panel.charts().first()->parentWidget()->size());
    // Not a blank picture: the plotted lines and axes use more than one colour.
    const QRgb first = image.pixel(0, 0);
    bool varied = false;
    for (int y = 0; y < image.height() && !varied; y += 3) {
        for (int x = 0; x < image.width() && !varied; x += 3) {
            varied = image.pixel(x, y) != first;
        }
    }
    QVERIFY(varied);
}

void tst_PlotExport::exportReportsErrors()
{
    TelemetryStore store;
    store.append(batch(1, 0, 10, 0.1));
    PlotPanel panel(&store);
    panel.setDrives({1});
    showPanel(panel);
    QVERIFY(!panel.exportCsv("/nonexistent-lk-dir/a.csv", PlotPanel::ExportScope::Everything)
                 .isEmpty());
    QVERIFY(!panel.exportPng("/nonexistent-lk-dir/a.png").isEmpty());
}

QTEST_MAIN(tst_PlotExport)
#include "tst_plotexport.moc"
