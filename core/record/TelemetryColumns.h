#pragma once

#include <bus/TelemetryFieldInfo.h>

#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::record {

/// A telemetry CSV column: a row of the telemetry table (its key, unit and decimals).
using TelemetryColumn = bus::TelemetryFieldInfo;

/// Telemetry as CSV columns (lkstudio's plot export and `lkctl monitor` both write these;
/// docs/CSV.md lists them and a test compares the two): the rows of
/// bus::TelemetryFieldInfo::all(), a round's values as one number per column.
class TelemetryColumns {
public:
    /// V2.35 drives send the supply voltage in 0.01 V (docs/V2.35.md section 5).
    static constexpr int kV235VoltageDecimals = 2;
    /// Every column, in canonical order; a column's index in this list identifies it. The
    /// rows of bus::TelemetryFieldInfo::all(), with the decimals of a column set to the finest
    /// resolution any generation sends: voltage_v 2 (V2.35's 0.01 V; a V2.3 0.1 V value
    /// reads the same with a trailing 0).
    static const QVector<TelemetryColumn> &all();
    /// Index of the column named `key`, or nullopt.
    static std::optional<int> indexOf(const QString &key)
    {
        return bus::TelemetryFieldInfo::indexOf(key);
    }
    /// Indexes of the columns `fields` carry, in canonical order.
    static QVector<int> of(bus::TelemetryFields fields)
    {
        return bus::TelemetryFieldInfo::of(fields);
    }
    /// One value per column of all(): the sample's value, or NaN where it carries none.
    static QVector<double> values(const bus::TelemetrySample &sample);
    /// All NaN: nothing sampled.
    static QVector<double> empty();
};

} // namespace lk::record
