#pragma once

#include <bus/ScanTypes.h>
#include <bus/TelemetrySample.h>
#include <motor/ModelNameInfo.h>

#include <QtCore/QString>

#include <array>
#include <optional>

namespace lk::ui {

/// What the GUI knows about one drive: its identity from the scan and the latest value of
/// every telemetry field, each with the host time it arrived (to grey out stale values).
struct DriveRecord {
    static constexpr int kFieldCount = bus::kTelemetryFieldCount;
    static constexpr qint64 kStaleMs = 1000;

    int id = 0;
    std::optional<protocol::ModelInfo> model; ///< from read_model, when the scan got it
    std::optional<protocol::Series> series;   ///< nullopt: unknown
    motor::ModelNameInfo nameInfo;            ///< gear ratio and encoder bits from the name
    /// The gear ratio the user chose for a drive without a model name (CAN, listening).
    std::optional<double> chosenGearRatio;
    /// Where no model was read (CAN): the generation a reply told (its ID, the 0x9A layout)
    /// or the user chose; nullopt when neither says. On CAN V2_3 is the old generation,
    /// V2_35 V2.36.
    std::optional<protocol::Generation> linkGeneration;
    int baud = 0;                ///< where the scan found it
    bus::TelemetrySample latest; ///< every field ever received, merged; `fields` says which
    std::array<qint64, kFieldCount> updatedMs{}; ///< host ms (BusModel clock) per field; 0 never

    bool has(bus::TelemetryField f) const { return latest.has(f); }
    /// No value, or the last one is older than kStaleMs at `nowMs`.
    bool isStale(bus::TelemetryField f, qint64 nowMs) const;
    qint64 updatedAt(bus::TelemetryField f) const;
    /// Merge the fields a sample carries, stamping them with `nowMs`.
    void apply(const bus::TelemetrySample &sample, qint64 nowMs);

    /// The protocol generation from read_model, else (CAN) the one the link told or the user
    /// chose; nullopt while nothing says.
    std::optional<protocol::Generation> generation() const
    {
        return model ? std::optional(model->generation) : linkGeneration;
    }
    bool reportsPower() const { return series == protocol::Series::MS; }
    bool hasPhaseCurrents() const { return series != protocol::Series::MS; }
    /// The ratio from the motor name ("-i10"), else the one the user chose; nullopt when
    /// neither says.
    std::optional<double> gearRatio() const;
    QString seriesText() const; ///< "MF", or "?" when unknown
    QString modelText() const;  ///< "motor name (driver name)" or empty
    QString firmwareText() const;
    QString hardwareText() const;

    static int fieldIndex(bus::TelemetryField f);
};

} // namespace lk::ui
