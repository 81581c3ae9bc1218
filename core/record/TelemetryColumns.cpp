#include "TelemetryColumns.h"

#include <limits>

namespace lk::record {

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
