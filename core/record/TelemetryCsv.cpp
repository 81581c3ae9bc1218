#include "TelemetryCsv.h"

#include "CsvWriter.h"
#include "TelemetryColumns.h"

#include <algorithm>

namespace lk::record {

TelemetryCsv TelemetryCsv::wide(const QVector<Cell> &cells)
{
    TelemetryCsv csv;
    csv.m_layout = CsvLayout::Wide;
    csv.m_cells = cells;
    return csv;
}

TelemetryCsv TelemetryCsv::longLayout(QVector<int> columns)
{
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    TelemetryCsv csv;
    csv.m_layout = CsvLayout::Long;
    csv.m_columns = columns;
    return csv;
}

QString TelemetryCsv::wideName(int id, int column)
{
    return QStringLiteral("id%1_%2").arg(id).arg(
        QLatin1String(TelemetryColumns::all()[column].key));
}

QByteArray TelemetryCsv::header() const
{
    QByteArray h = "time_s";
    if (m_layout == CsvLayout::Wide) {
        for (const Cell &c : m_cells) {
            h += ',' + wideName(c.id, c.column).toLatin1();
        }
    } else {
        h += ",id";
        for (int c : m_columns) {
            h += ',' + QByteArray(TelemetryColumns::all()[c].key);
        }
    }
    return h + '\n';
}

QByteArray TelemetryCsv::cell(const QVector<double> &values, int column) const
{
    return CsvWriter::formatNumber(values.at(column), TelemetryColumns::all()[column].decimals);
}

QList<QByteArray> TelemetryCsv::rows(const CycleValues &cycle) const
{
    const QByteArray time = CsvWriter::formatNumber(cycle.time, kTimeDecimals);
    QList<QByteArray> out;
    if (m_layout == CsvLayout::Wide) {
        QByteArray line = time;
        bool any = false;
        for (const Cell &c : m_cells) {
            line += ',';
            const auto drive = cycle.drives.find(c.id);
            if (drive != cycle.drives.end()) {
                const QByteArray text = cell(drive->second, c.column);
                any = any || !text.isEmpty();
                line += text;
            }
        }
        if (any) {
            out.append(line + '\n');
        }
        return out;
    }
    for (const auto &[id, values] : cycle.drives) {
        QByteArray line = time + ',' + QByteArray::number(id);
        bool any = false;
        for (int c : m_columns) {
            const QByteArray text = cell(values, c);
            any = any || !text.isEmpty();
            line += ',' + text;
        }
        if (any) {
            out.append(line + '\n');
        }
    }
    return out;
}

QString TelemetryCsv::layoutName(CsvLayout layout)
{
    return layout == CsvLayout::Wide ? QStringLiteral("wide") : QStringLiteral("long");
}

std::optional<CsvLayout> TelemetryCsv::layoutFromName(const QString &name)
{
    for (CsvLayout l : {CsvLayout::Wide, CsvLayout::Long}) {
        if (name == layoutName(l)) {
            return l;
        }
    }
    return std::nullopt;
}

} // namespace lk::record
