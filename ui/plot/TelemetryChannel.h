#pragma once

#include <QtCore/QString>

namespace lk::ui {

/// One recorded signal of a drive. Torque holds iq (A) on MF/MG/MH and power on MS drives.
enum class TelemetryChannel {
    Torque,
    Speed,
    Encoder,
    MultiTurn,
    SingleTurn,
    Temperature,
    Voltage,
    PhaseA,
    PhaseB,
    PhaseC,
};
inline constexpr int kTelemetryChannelCount = 10;

/// What a channel measures, which decides its unit and which Y axis it shares.
enum class Quantity { Current, Power, Speed, Encoder, Angle, Temperature, Voltage };

/// The quantity of a channel; `power` says the drive reports power instead of iq (MS).
Quantity channelQuantity(TelemetryChannel channel, bool power);
/// Translated short name for legends and readouts: "iq", "Power", "Speed", ...
QString channelLabel(TelemetryChannel channel, bool power);
/// Digits worth showing and exporting for the channel's resolution on the wire.
int channelDecimals(TelemetryChannel channel, bool power);

/// Translated unit shown on axes and in the readout ("A", "°/s", "counts", ...; may be empty).
QString quantityUnit(Quantity quantity);
/// Translated axis title with the unit, e.g. "Speed (°/s)".
QString quantityTitle(Quantity quantity);

} // namespace lk::ui
