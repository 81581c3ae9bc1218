#pragma once

#include <bus/TelemetrySample.h>
#include <record/TelemetryColumns.h>

#include <QtCore/QVector>

#include <cmath>

namespace lk::testsupport {

/// What a telemetry sample says: its drive, source and every column (NaN where it has none),
/// comparable so that a replay's samples can be checked against the live session's.
struct SampleValues {
    int id = 0;
    int source = 0;
    QVector<double> columns;
    bool operator==(const SampleValues &o) const
    {
        if (id != o.id || source != o.source || columns.size() != o.columns.size())
            return false;
        for (int i = 0; i < columns.size(); ++i)
            if (!(columns[i] == o.columns[i] ||
                  (std::isnan(columns[i]) && std::isnan(o.columns[i]))))
                return false;
        return true;
    }
};

inline SampleValues sampleValuesOf(const bus::TelemetrySample &s)
{
    return SampleValues{s.id, int(s.source), record::TelemetryColumns::values(s)};
}

} // namespace lk::testsupport
