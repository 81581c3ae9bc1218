#include "TelemetryChannel.h"

#include <QtCore/QCoreApplication>

namespace lk::ui {

Quantity channelQuantity(TelemetryChannel channel, bool power)
{
    switch (channel) {
    case TelemetryChannel::Torque:
        return power ? Quantity::Power : Quantity::Current;
    case TelemetryChannel::Speed:
        return Quantity::Speed;
    case TelemetryChannel::Encoder:
        return Quantity::Encoder;
    case TelemetryChannel::MultiTurn:
    case TelemetryChannel::SingleTurn:
        return Quantity::Angle;
    case TelemetryChannel::Temperature:
        return Quantity::Temperature;
    case TelemetryChannel::Voltage:
        return Quantity::Voltage;
    case TelemetryChannel::PhaseA:
    case TelemetryChannel::PhaseB:
    case TelemetryChannel::PhaseC:
        return Quantity::Current;
    }
    return Quantity::Current;
}

// Free functions have no tr(): plain translate() calls with literal text, which lupdate reads.
QString channelLabel(TelemetryChannel channel, bool power)
{
    switch (channel) {
    case TelemetryChannel::Torque:
        return power ? QCoreApplication::translate("lk::ui::TelemetryChannel", "Power")
                     : QCoreApplication::translate("lk::ui::TelemetryChannel", "iq");
    case TelemetryChannel::Speed:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Speed");
    case TelemetryChannel::Encoder:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Encoder");
    case TelemetryChannel::MultiTurn:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Multi-turn angle");
    case TelemetryChannel::SingleTurn:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Single-turn angle");
    case TelemetryChannel::Temperature:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Temperature");
    case TelemetryChannel::Voltage:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Voltage");
    case TelemetryChannel::PhaseA:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Phase A");
    case TelemetryChannel::PhaseB:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Phase B");
    case TelemetryChannel::PhaseC:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Phase C");
    }
    return {};
}

int channelDecimals(TelemetryChannel channel, bool power)
{
    switch (channel) {
    case TelemetryChannel::Torque:
        return power ? 0 : 4; // iq steps are 33/2048 A; power is an integer
    case TelemetryChannel::Speed:
        return 2;
    case TelemetryChannel::Encoder:
    case TelemetryChannel::Temperature:
        return 0;
    case TelemetryChannel::MultiTurn:
    case TelemetryChannel::SingleTurn:
    case TelemetryChannel::Voltage:
        return 2;
    case TelemetryChannel::PhaseA:
    case TelemetryChannel::PhaseB:
    case TelemetryChannel::PhaseC:
        return 4; // 1/64 A steps
    }
    return 6;
}

QString quantityUnit(Quantity quantity)
{
    switch (quantity) {
    case Quantity::Current:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "A");
    case Quantity::Power:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "rel.");
    case Quantity::Speed:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "°/s");
    case Quantity::Encoder:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "counts");
    case Quantity::Angle:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "°");
    case Quantity::Temperature:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "°C");
    case Quantity::Voltage:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "V");
    }
    return {};
}

QString quantityTitle(Quantity quantity)
{
    switch (quantity) {
    case Quantity::Current:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Current (A)");
    case Quantity::Power:
        return QCoreApplication::translate("lk::ui::TelemetryChannel",
                                           "Power (rel.)"); // -1000..1000: fits a short axis
    case Quantity::Speed:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Speed (°/s)");
    case Quantity::Encoder:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Encoder (counts)");
    case Quantity::Angle:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Angle (°)");
    case Quantity::Temperature:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Temperature (°C)");
    case Quantity::Voltage:
        return QCoreApplication::translate("lk::ui::TelemetryChannel", "Voltage (V)");
    }
    return {};
}

} // namespace lk::ui
