#pragma once

#include <bus/TelemetrySample.h>

#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>

namespace lk::record {

/// One telemetry signal as a CSV column: the one place its name, unit and precision are
/// defined (lkstudio's plot export and `lkctl monitor` both write these; docs/CSV.md lists
/// them and a test compares the two).
struct TelemetryColumn {
    const char *key;           ///< column name, snake_case with the unit as suffix (CLI.md)
    const char *unit;          ///< the unit as docs/CSV.md writes it (UTF-8: "A", "°/s", ...)
    bus::TelemetryField field; ///< the sample field that carries it
    int decimals;              ///< digits after the decimal point (the wire's resolution)
    double (*read)(const bus::TelemetrySample &sample);
};

/// The table of telemetry CSV columns, in the order files list them.
class TelemetryColumns {
public:
    /// Every column, in canonical order; a column's index in this list identifies it.
    static const QVector<TelemetryColumn> &all();
    /// Index of the column named `key`, or nullopt.
    static std::optional<int> indexOf(const QString &key);
    /// Indexes of the columns `fields` carry, in canonical order.
    static QVector<int> of(bus::TelemetryFields fields);
    /// One value per column of all(): the sample's value, or NaN where it carries none.
    static QVector<double> values(const bus::TelemetrySample &sample);
    /// Copies the values of `from` that are not NaN over `into` (a later reply of the same
    /// round wins).
    static void merge(QVector<double> &into, const QVector<double> &from);
    /// All NaN: nothing sampled.
    static QVector<double> empty();
};

} // namespace lk::record
