// The plot panel's exports: CSV of what is plotted (everything or the visible range) and PNG
// of the charts, and the errors a failed write reports.

#include "../../support/FileSizeLimit.h"
#include "PlotPanelTestUtil.h"

#include <plot/PlotExporter.h>
#include <plot/PlotPanel.h>
#include <plot/SeriesColors.h>
#include <plot/StripChart.h>
#include <plot/TelemetryStore.h>

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QSet>
#include <QtCore/QTemporaryDir>
#include <QtGui/QImage>
#include <QtTest/QTest>
#include <QtWidgets/QMenu>
#include <QtWidgets/QToolButton>

using lk::plottest::batch;
using lk::plottest::sample;
using lk::plottest::showPanel;
using lk::ui::PlotPanel;
using lk::ui::TelemetryChannel;
using lk::ui::TelemetryStore;

using lk::ui::PlotExporter;

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

/// `sample()` as a poll reply of round `round` (rounds begin every 100 ms).
lk::bus::TelemetrySample polled(int id, int round, double offsetS, double iq)
{
    lk::bus::TelemetrySample s = sample(id, round * 0.1 + offsetS, iq, 10 * round, round);
    s.cycle = quint64(round);
    s.cycleTime = round * 0.1;
    return s;
}

/// Two drives polled in one round each 100 ms, rounds 1..3: drive 4's reply of round 2 is
/// lost, and an operator's read of drive 3 (no round) comes between rounds 2 and 3.
void recordRounds(TelemetryStore &store)
{
    store.append({polled(3, 1, 0.002, 0.5), polled(4, 1, 0.004, -0.5)});
    store.append({polled(3, 2, 0.002, 1.0), sample(3, 0.25, 9.0, 99, 99)});
    store.append({polled(3, 3, 0.002, 1.5), polled(4, 3, 0.004, -1.5)});
}

/// The panel's whole CSV export ("Everything recorded") as text; "<failed>" on an error.
QByteArray exportEverything(const PlotPanel &panel)
{
    QTemporaryDir dir;
    const QString path = dir.filePath("export.csv");
    if (!panel.exportCsv(path, PlotPanel::ExportScope::Everything).isEmpty())
        return "<failed>";
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("<failed>");
}

QAction *menuAction(PlotPanel &panel, const QString &startsWith)
{
    for (QToolButton *b : panel.findChildren<QToolButton *>()) {
        if (b->menu()) {
            for (QAction *a : b->menu()->actions()) {
                if (a->text().startsWith(startsWith))
                    return a;
            }
        }
    }
    return nullptr;
}

/// Drive 1 plotted with 10 s of samples, drawn: what a PNG export pictures.
void plotTenSeconds(TelemetryStore &store, PlotPanel &panel)
{
    panel.setDrives({1});
    showPanel(panel);
    store.append(batch(1, 0, 1000, 0.01));
    QTRY_VERIFY(panel.charts().first()->points(0).size() > 0);
}

} // namespace

class tst_PlotExport : public QObject {
    Q_OBJECT
private slots:
    void exportCsvWritesPlottedColumns();
    void exportCsvVisibleRange();
    void exportCsvRowPerPollRound();
    void exportCsvLongLayoutFromTheMenu();
    void exportPngWritesImage();
    void pngTitleNamesSignalsDrivesAndTime();
    void diskFullKeepsTheEarlierPng();
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
    QCOMPARE(rows.first().join(','), QString("time_s,id1_iq_a,id1_speed_dps,id1_encoder"));
    QCOMPARE(rows.size(), 1 + 51); // 15.0 .. 20.0 inclusive
    QCOMPARE(rows.at(1).at(0), QString("15.000000"));
    QCOMPARE(rows.last().at(0), QString("20.000000"));
    QCOMPARE(rows.last().at(3), QString::number(int(20.0 * 100) % 16384));
}

void tst_PlotExport::exportCsvRowPerPollRound()
{
    TelemetryStore store;
    recordRounds(store);
    PlotPanel panel(&store);
    panel.setDrives({3, 4});
    panel.setChannelVisible(TelemetryChannel::Encoder, false);
    QCOMPARE(panel.csvLayout(), PlotPanel::CsvLayout::Wide);
    // One row per round at the round's time, both drives in it; a lost reply is an empty
    // cell; the operator's read has a row of its own at its own time.
    QCOMPARE(exportEverything(panel),
             QByteArray("time_s,id3_iq_a,id3_speed_dps,id4_iq_a,id4_speed_dps\n"
                        "0.100000,0.5000,10,-0.5000,10\n"
                        "0.200000,1.0000,20,,\n"
                        "0.250000,9.0000,99,,\n"
                        "0.300000,1.5000,30,-1.5000,30\n"));
}

void tst_PlotExport::exportCsvLongLayoutFromTheMenu()
{
    TelemetryStore store;
    recordRounds(store);
    PlotPanel panel(&store);
    panel.setDrives({3, 4});
    panel.setChannelVisible(TelemetryChannel::Encoder, false);
    QAction *longLayout = menuAction(panel, "Long");
    QVERIFY(longLayout && longLayout->isCheckable() && !longLayout->isChecked());
    longLayout->trigger();
    QCOMPARE(panel.csvLayout(), PlotPanel::CsvLayout::Long);
    QVERIFY(!menuAction(panel, "Wide")->isChecked());
    QCOMPARE(exportEverything(panel), QByteArray("time_s,id,iq_a,speed_dps\n"
                                                 "0.100000,3,0.5000,10\n"
                                                 "0.100000,4,-0.5000,10\n"
                                                 "0.200000,3,1.0000,20\n"
                                                 "0.250000,3,9.0000,99\n"
                                                 "0.300000,3,1.5000,30\n"
                                                 "0.300000,4,-1.5000,30\n"));
}

void tst_PlotExport::exportPngWritesImage()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    plotTenSeconds(store, panel);
    if (QTest::currentTestFailed())
        return;
    QTemporaryDir dir;
    const QString path = dir.filePath("plot.png");
    const QDateTime before = QDateTime::currentDateTime();
    QCOMPARE(panel.exportPng(path), QString());
    const QImage image(path);
    QVERIFY(!image.isNull());
    // The plot under a title line: what, which drive, when.
    const QSize chartArea = panel.charts().first()->parentWidget()->size();
    QCOMPARE(image.width(), chartArea.width());
    QVERIFY(image.height() > chartArea.height());
    const QString title = image.text(QStringLiteral("Title"));
    QCOMPARE(title,
             PlotExporter::pngTitle(panel.plottedTraces(),
                                    QDateTime::fromString(title.right(19), "yyyy-MM-dd HH:mm:ss")));
    QVERIFY2(title.contains(QStringLiteral(" \u2014 drive 1 \u2014 ")), qPrintable(title));
    const QDateTime stamped = QDateTime::fromString(title.right(19), "yyyy-MM-dd HH:mm:ss");
    QVERIFY2(stamped.isValid() && stamped.secsTo(before) <= 1 &&
                 stamped.secsTo(QDateTime::currentDateTime()) >= 0,
             qPrintable(title));
    // The band above the plot holds the title's text: more than the background's colour.
    const int band = image.height() - chartArea.height();
    QSet<QRgb> bandColours;
    for (int y = 0; y < band; ++y) {
        for (int x = 0; x < image.width() / 2; ++x)
            bandColours.insert(image.pixel(x, y));
    }
    QVERIFY2(bandColours.size() > 1, "an empty title band");
    // Not a blank picture: the plotted lines and axes use more than one colour.
    const QRgb first = image.pixel(0, 0);
    bool varied = false;
    for (int y = 0; y < image.height() && !varied; y += 3) {
        for (int x = 0; x < image.width() && !varied; x += 3) {
            varied = image.pixel(x, y) != first;
        }
    }
    QVERIFY(varied);
    // The lines themselves are in the picture, in their trace's colour (they are drawn by the
    // chart's own item, not by QtCharts' series).
    const QRgb trace = lk::ui::SeriesColors::at(0).rgb();
    int tracePixels = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x)
            tracePixels += (image.pixel(x, y) & 0xffffff) == (trace & 0xffffff) ? 1 : 0;
    }
    QVERIFY2(tracePixels > 100, qPrintable(QString::number(tracePixels)));
}

void tst_PlotExport::pngTitleNamesSignalsDrivesAndTime()
{
    using lk::ui::PlotTrace;
    using lk::ui::TelemetryChannel;
    const QDateTime when(QDate(2026, 11, 27), QTime(14, 5, 9));
    const QVector<PlotTrace> traces{{3, TelemetryChannel::Speed, false},
                                    {1, TelemetryChannel::Torque, false},
                                    {1, TelemetryChannel::Speed, false},
                                    {17, TelemetryChannel::Torque, true}};
    QCOMPARE(PlotExporter::pngTitle(traces, when),
             QStringLiteral("Speed, iq, Power \u2014 drives 1, 3, 17 \u2014 2026-11-27 14:05:09"));
    QCOMPARE(PlotExporter::pngTitle({traces.first()}, when),
             QStringLiteral("Speed \u2014 drive 3 \u2014 2026-11-27 14:05:09"));
    QCOMPARE(PlotExporter::pngTitle({}, when),
             QStringLiteral("nothing plotted \u2014 2026-11-27 14:05:09"));
}

void tst_PlotExport::diskFullKeepsTheEarlierPng()
{
    TelemetryStore store;
    PlotPanel panel(&store);
    plotTenSeconds(store, panel);
    if (QTest::currentTestFailed())
        return;
    QTemporaryDir dir;
    const QString path = dir.filePath("plot.png");
    {
        QFile earlier(path);
        QVERIFY(earlier.open(QIODevice::WriteOnly));
        earlier.write("earlier picture");
    }
    const QString probe = dir.filePath("probe.png");
    QCOMPARE(panel.exportPng(probe), QString());
    const qint64 size = QFileInfo(probe).size();
    QVERIFY(QFile::remove(probe));
    {
        // One byte short of the picture: only the last flush fails (the end of a file stays
        // in QSaveFile's buffer until then, and Qt 6.4's commit() renames it regardless).
        const lk::testsupport::FileSizeLimit diskFull(rlim_t(size - 1));
        QVERIFY(diskFull.isActive());
        QVERIFY(!panel.exportPng(path).isEmpty());
    }
    QFile kept(path);
    QVERIFY(kept.open(QIODevice::ReadOnly));
    QCOMPARE(kept.readAll(), QByteArray("earlier picture"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"plot.png"});
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
