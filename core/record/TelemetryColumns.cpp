#include "TelemetryColumns.h"

#include <algorithm>
#include <limits>

namespace lk::record {

const QVector<TelemetryColumn> &TelemetryColumns::all()
{
    // One column, one resolution, for drives of both generations in one file: the finer one.
    // (The bus table gives V2.3's 0.1 V; 24.37 V from a V2.35 drive must not read 24.4.)
    static const QVector<TelemetryColumn> columns = [] {
        QVector<TelemetryColumn> rows = bus::TelemetryFieldInfo::all();
        for (TelemetryColumn &row : rows) {
            if (row.field == bus::TelemetryField::Voltage)
                row.decimals = std::max(row.decimals, kV235VoltageDecimals);
        }
        return rows;
    }();
    return columns;
}

QVector<double> TelemetryColumns::empty()
{
    return QVector<double>(all().size(), std::numeric_limits<double>::quiet_NaN());
}

QVector<double> TelemetryColumns::values(const bus::TelemetrySample &sample)
{
    QVector<double> out = empty();
    const QVector<TelemetryColumn> &columns = all();
    for (int i = 0; i < columns.size(); ++i) {
        if (sample.has(columns.at(i).field)) {
            out[i] = columns.at(i).value(sample);
        }
    }
    return out;
}

} // namespace lk::record
