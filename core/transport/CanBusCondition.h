#pragma once

#include <QtCore/QMetaType>

namespace lk::transport {

/// The state of the CAN bus as the controller sees it (ISO 11898 fault confinement, plus
/// the frame nobody acknowledged). None of them closes the link: they are states of an open
/// link with a sentence and a fix, not a "link lost".
enum class CanBusCondition {
    Good,
    Warning,       ///< error counters past 96: frames still get through
    ErrorPassive,  ///< error counters past 127
    BusOff,        ///< the controller stopped sending
    NoAcknowledge, ///< a frame went unacknowledged: no drive, or another bit rate
};

/// "good", "warning", "error_passive", "bus_off", "no_ack": the words of lkctl's JSON.
inline const char *canBusConditionName(CanBusCondition c)
{
    switch (c) {
    case CanBusCondition::Good:
        return "good";
    case CanBusCondition::Warning:
        return "warning";
    case CanBusCondition::ErrorPassive:
        return "error_passive";
    case CanBusCondition::BusOff:
        return "bus_off";
    case CanBusCondition::NoAcknowledge:
        return "no_ack";
    }
    return "good";
}

} // namespace lk::transport

Q_DECLARE_METATYPE(lk::transport::CanBusCondition)
