#include "ListenTable.h"

#include <record/TelemetryColumns.h>

namespace lk::lkctl {

namespace {
QVector<int> everyColumn()
{
    QVector<int> columns;
    for (int i = 0; i < record::TelemetryColumns::all().size(); ++i)
        columns.append(i);
    return columns;
}
} // namespace

ListenTable::ListenTable(MonitorFormat format)
    : m_format(format), m_csv(record::TelemetryCsv::longLayout(everyColumn()))
{
}

QByteArray ListenTable::header() const
{
    return m_format == MonitorFormat::Json ? QByteArray() : m_csv.header();
}

QList<QByteArray> ListenTable::add(const bus::TelemetrySample &sample)
{
    record::CycleValues values;
    values.time = sample.time;
    values.drives.emplace(sample.id, record::TelemetryColumns::values(sample));
    return m_format == MonitorFormat::Json ? MonitorTable::jsonRows(values) : m_csv.rows(values);
}

} // namespace lk::lkctl
