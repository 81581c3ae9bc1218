#include "PlotExporter.h"

#include "PlotPanel.h"

#include <record/CsvWriter.h>
#include <record/TelemetryColumns.h>
#include <system/AtomicFile.h>

#include <QtGui/QFontMetrics>
#include <QtGui/QImageWriter>
#include <QtGui/QPainter>
#include <QtGui/QPixmap>
#include <QtWidgets/QWidget>

#include <algorithm>

namespace lk::ui {

using lk::record::CycleValues;
using lk::record::TelemetryColumns;
using lk::record::TelemetryCsv;

namespace {

/// The row a point goes to: its poll round (the round's time and number), or, for a point
/// that answered no poll, its own time with round 0.
struct RowKey {
    double time;
    quint64 cycle;
    bool operator<(const RowKey &o) const
    {
        return time < o.time || (time == o.time && cycle < o.cycle);
    }
    bool operator==(const RowKey &o) const { return time == o.time && cycle == o.cycle; }
};

struct KeyedPoint {
    RowKey key;
    double value;
};

/// A trace's points in `span`, each with the row it belongs to, in row order.
QVector<KeyedPoint> keyedPoints(const TelemetryStore &store, const PlotTrace &trace, TimeSpan span)
{
    QVector<KeyedPoint> points;
    const SampleRing *ring = store.ring(trace.driveId, trace.channel);
    if (!ring) {
        return points;
    }
    const qsizetype begin = ring->lowerBound(span.begin);
    const qsizetype end = ring->upperBound(span.end);
    points.reserve(std::max<qsizetype>(0, end - begin));
    ring->forEachSpan(begin, end, [&](const double *t, const double *v, qsizetype n) {
        for (qsizetype i = 0; i < n; ++i) {
            const auto round = store.pollCycles().find(trace.driveId, t[i]);
            points.append({round ? RowKey{round->time, round->cycle} : RowKey{t[i], 0}, v[i]});
        }
    });
    // A round's time precedes its replies, so an operator's read between two polls can sort
    // after the next poll's point: mostly ordered already, a stable sort keeps the later of
    // two points of one round last (it wins the cell, as in lkctl monitor).
    std::stable_sort(points.begin(), points.end(),
                     [](const KeyedPoint &a, const KeyedPoint &b) { return a.key < b.key; });
    return points;
}

TelemetryCsv layoutFor(const QVector<PlotTrace> &traces, lk::record::CsvLayout layout)
{
    QVector<TelemetryCsv::Cell> cells;
    QVector<int> columns;
    for (const PlotTrace &trace : traces) {
        cells.append({trace.driveId, PlotExporter::columnOf(trace)});
        columns.append(PlotExporter::columnOf(trace));
    }
    return layout == lk::record::CsvLayout::Wide ? TelemetryCsv::wide(cells)
                                                 : TelemetryCsv::longLayout(columns);
}

/// `image` under a band with `title`, in the widget's colours and a bold form of its font.
QImage withTitle(const QImage &image, const QString &title, const QPalette &palette, QFont font)
{
    font.setBold(true);
    const QFontMetrics metrics(font);
    const int margin = metrics.height() / 2;
    const int band = metrics.height() + 2 * margin;
    const qreal dpr = image.devicePixelRatio();
    QImage out(image.width(), image.height() + int(band * dpr),
               QImage::Format_ARGB32_Premultiplied);
    out.setDevicePixelRatio(dpr);
    out.fill(palette.color(QPalette::Window));
    QPainter p(&out);
    p.setFont(font);
    p.setPen(palette.color(QPalette::WindowText));
    const QRect textRect(margin, 0, int(image.width() / dpr) - 2 * margin, band);
    p.drawText(textRect, Qt::AlignVCenter | Qt::AlignLeft,
               metrics.elidedText(title, Qt::ElideRight, textRect.width()));
    p.drawImage(QPointF(0, band), image);
    return out;
}

} // namespace

int PlotExporter::columnOf(const PlotTrace &trace)
{
    return channelColumn(trace.channel, trace.power);
}

QString PlotExporter::exportCsv(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                                TimeSpan span, const QString &path, lk::record::CsvLayout layout)
{
    const TelemetryCsv csv = layoutFor(traces, layout);
    lk::record::CsvWriter writer(path);
    if (QString error = writer.begin(csv.header()); !error.isEmpty()) {
        return error;
    }
    QVector<QVector<KeyedPoint>> points;
    for (const PlotTrace &trace : traces) {
        points.append(keyedPoints(store, trace, span));
    }
    QVector<qsizetype> cursor(points.size(), 0);
    for (;;) {
        // k-way merge: the next row is the smallest key any trace has not written yet.
        std::optional<RowKey> next;
        for (qsizetype i = 0; i < points.size(); ++i) {
            if (cursor[i] < points[i].size() && (!next || points[i][cursor[i]].key < *next)) {
                next = points[i][cursor[i]].key;
            }
        }
        if (!next) {
            break;
        }
        CycleValues row;
        row.time = next->time;
        for (qsizetype i = 0; i < points.size(); ++i) {
            const PlotTrace &trace = traces.at(i);
            for (; cursor[i] < points[i].size() && points[i][cursor[i]].key == *next; ++cursor[i]) {
                auto drive = row.drives.try_emplace(trace.driveId, TelemetryColumns::empty());
                drive.first->second[columnOf(trace)] = points[i][cursor[i]].value;
            }
        }
        for (const QByteArray &line : csv.rows(row)) {
            writer.write(line);
        }
    }
    return writer.finish();
}

QString PlotExporter::pngTitle(const QVector<PlotTrace> &traces, const QDateTime &when)
{
    QStringList what;
    QVector<int> drives;
    for (const PlotTrace &t : traces) {
        const QString label = channelLabel(t.channel, t.power);
        if (!what.contains(label))
            what << label;
        if (!drives.contains(t.driveId))
            drives << t.driveId;
    }
    std::sort(drives.begin(), drives.end());
    QStringList ids;
    for (int id : drives)
        ids << QString::number(id);
    const QString signalsText =
        what.isEmpty() ? tr("nothing plotted") : what.join(QStringLiteral(", "));
    const QString drivesText = drives.size() == 1
                                   ? tr("drive %1").arg(ids.first())
                                   : tr("drives %1").arg(ids.join(QStringLiteral(", ")));
    const QString whenText = when.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
    if (drives.isEmpty())
        return QStringLiteral("%1 \u2014 %2").arg(signalsText, whenText);
    return QStringLiteral("%1 \u2014 %2 \u2014 %3").arg(signalsText, drivesText, whenText);
}

QString PlotExporter::exportPng(QWidget *widget, const QString &path)
{
    // The plot panel the widget belongs to knows what it shows.
    for (QWidget *w = widget; w; w = w->parentWidget()) {
        if (const auto *panel = qobject_cast<const PlotPanel *>(w))
            return exportPng(widget, path,
                             pngTitle(panel->plottedTraces(), QDateTime::currentDateTime()));
    }
    return exportPng(widget, path, QString());
}

QString PlotExporter::exportPng(QWidget *widget, const QString &path, const QString &title)
{
    QImage image = widget->grab().toImage();
    if (!title.isEmpty())
        image = withTitle(image, title, widget->palette(), widget->font());
    system::AtomicFile file(path); // as for CSV: the whole image or nothing
    if (!file.open()) {
        return tr("Cannot open %1: %2").arg(path, file.errorString());
    }
    QImageWriter writer(file.device(), "png");
    if (!title.isEmpty())
        writer.setText(QStringLiteral("Title"), title); // for viewers and scripts too
    if (!writer.write(image)) {
        file.fail(writer.errorString());
    }
    if (!file.commit()) {
        return tr("Cannot write %1: %2").arg(path, file.errorString());
    }
    return {};
}

} // namespace lk::ui
