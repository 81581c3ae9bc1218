#pragma once

#include <bus/TelemetryFieldInfo.h>

#include <QtCore/QString>

#include <optional>

namespace lk::ui {

/// One recorded signal of a drive: a row of the telemetry table (channelColumn), except that
/// Torque holds iq (A) on MF/MG/MH and power on MS drives.
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
    // What another master commanded (a listen-only link), beside what the drive replied.
    CommandedTorque, ///< commanded iq, or open-loop power on MS (as Torque)
    CommandedSpeed,
    CommandedAngle,
    CommandedSingleTurn, ///< the target of 0xA5/0xA6
    CommandedIncrement,  ///< the step of 0xA7/0xA8 (a listener does not know the start)
    CommandedMaxSpeed,   ///< the speed cap of 0xA4/0xA6/0xA8
};
inline constexpr int kTelemetryChannelCount = 16;

/// What a channel measures, which decides its unit and which Y axis it shares.
using Quantity = lk::bus::Quantity;

/// The row of bus::TelemetryFieldInfo::all() a channel records; `power` says the drive
/// reports power instead of iq (MS), which only the Torque channel distinguishes.
int channelColumn(TelemetryChannel channel, bool power);
/// Torque and CommandedTorque hold power on a drive that reports power (MS), iq otherwise.
inline bool hasPowerColumn(TelemetryChannel channel)
{
    return channel == TelemetryChannel::Torque || channel == TelemetryChannel::CommandedTorque;
}
/// The channel that records a row of the table; nullopt for values not plotted (error flags,
/// the V2.35 bus current and motor state).
std::optional<TelemetryChannel> channelOfColumn(int column);
/// The quantity of a channel (its table row's).
Quantity channelQuantity(TelemetryChannel channel, bool power);
/// Translated short name for legends and readouts: "iq", "Power", "Speed", ...
QString channelLabel(TelemetryChannel channel, bool power);
/// Translated name in the signal picker, where Torque stands for both: "iq / power".
QString channelPickerLabel(TelemetryChannel channel);
/// Digits worth showing for the channel's resolution on the wire (the row's readout digits).
int channelDecimals(TelemetryChannel channel, bool power);

/// Translated unit shown on axes and in the readout ("A", "°/s", "counts", ...; may be empty).
QString quantityUnit(Quantity quantity);
/// Translated axis title with the unit, e.g. "Speed (°/s)".
QString quantityTitle(Quantity quantity);

} // namespace lk::ui
