#pragma once

#include "TelemetrySample.h"

#include <QtCore/QString>
#include <QtCore/QVector>

#include <optional>
#include <variant>

namespace lk::bus {

/// What a telemetry value measures: its display unit and which plot axis it shares.
enum class Quantity { Current, Power, Speed, Encoder, Angle, Temperature, Voltage, State };

/// One telemetry value (a signal) as every consumer sees it: the CSV/JSON column of lkctl
/// monitor and the plot export, the plot's channel label and axis, the cursor readout's
/// precision, and the sample member that holds it. TelemetryFieldInfo::all() is the one table
/// of them; a field has one row, PhaseCurrents three (ia, ib, ic).
struct TelemetryFieldInfo {
    /// The TelemetrySample member that holds the value.
    using Member =
        std::variant<int TelemetrySample::*, double TelemetrySample::*, bool TelemetrySample::*>;
    /// Translation context of `label` (QT_TRANSLATE_NOOP in the table, translated in ui/).
    static constexpr const char *kLabelContext = "lk::bus::TelemetryFieldInfo";

    TelemetryField field; ///< the flag that says a sample carries the value
    const char *key;      ///< column name, snake_case with the unit as suffix (CLI.md, CSV.md)
    const char *unit;     ///< the unit as docs/CSV.md writes it (UTF-8: "A", "°/s", ...)
    Quantity quantity;
    int decimals;        ///< CSV/JSON digits after the point: the wire's resolution
    int displayDecimals; ///< digits a live readout shows
    bool v235Only;       ///< only firmware 2.35 drives report it
    const char *label;   ///< short English name for legends and readouts, untranslated
    Member member;

    double value(const TelemetrySample &sample) const;
    /// Copies this value from `from` into `into` (not the `fields` flag).
    void copy(TelemetrySample &into, const TelemetrySample &from) const;

    /// Every value, in the canonical column order; a row's index identifies it.
    static const QVector<TelemetryFieldInfo> &all();
    /// Index of the row named `key`, or nullopt.
    static std::optional<int> indexOf(const QString &key);
    /// Indexes of the rows `fields` carry, in canonical order.
    static QVector<int> of(TelemetryFields fields);
};

} // namespace lk::bus
