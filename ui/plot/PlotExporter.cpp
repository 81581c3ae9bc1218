#include "PlotExporter.h"

#include <record/CsvWriter.h>

#include <QtCore/QSaveFile>
#include <QtGui/QImageWriter>
#include <QtGui/QPixmap>
#include <QtWidgets/QWidget>

namespace lk::ui {

QString PlotExporter::columnName(const PlotTrace &trace)
{
    return QStringLiteral("id%1_%2").arg(trace.driveId).arg(channelKey(trace.channel, trace.power));
}

QString PlotExporter::exportCsv(const TelemetryStore &store, const QVector<PlotTrace> &traces,
                                TimeSpan span, const QString &path)
{
    QVector<lk::record::CsvSeries> columns;
    columns.reserve(traces.size());
    for (const PlotTrace &trace : traces) {
        lk::record::CsvSeries column;
        column.name = columnName(trace);
        column.decimals = channelDecimals(trace.channel, trace.power);
        if (const SampleRing *ring = store.ring(trace.driveId, trace.channel)) {
            const qsizetype begin = ring->lowerBound(span.begin);
            const qsizetype end = ring->upperBound(span.end);
            column.times.reserve(std::max<qsizetype>(0, end - begin));
            column.values.reserve(std::max<qsizetype>(0, end - begin));
            ring->forEachSpan(begin, end, [&](const double *t, const double *v, qsizetype n) {
                for (qsizetype i = 0; i < n; ++i) {
                    column.times.append(t[i]);
                    column.values.append(v[i]);
                }
            });
        }
        columns.append(std::move(column));
    }
    return lk::record::CsvWriter::writeAligned(path, columns);
}

QString PlotExporter::exportPng(QWidget *widget, const QString &path)
{
    const QImage image = widget->grab().toImage();
    QSaveFile file(path); // as for CSV: the whole image or nothing
    if (!file.open(QIODevice::WriteOnly)) {
        return tr("Cannot open %1: %2").arg(path, file.errorString());
    }
    QImageWriter writer(&file, "png");
    if (!writer.write(image)) {
        file.cancelWriting();
        return tr("Cannot write %1: %2").arg(path, writer.errorString());
    }
    if (!file.commit()) {
        return tr("Cannot write %1: %2").arg(path, file.errorString());
    }
    return {};
}

} // namespace lk::ui
