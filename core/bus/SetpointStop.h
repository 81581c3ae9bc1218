#pragma once

#include "LinkMode.h"

#include <protocol/FieldError.h>
#include <safety/MotionGuard.h>

#include <QtCore/QMetaType>

#include <optional>

namespace lk::bus {

/// Why a setpoint stream ended (the UI words it).
enum class SetpointStopReason {
    Requested,     ///< stopSetpointStream(): the user or the view
    Replaced,      ///< another stream started
    Refused,       ///< a setpoint failed the builder or the motion limits: nothing of it sent
    EmergencyStop, ///< an emergency stop, before its first motor_off was queued
    Cancelled,     ///< the bus cancelled a setpoint (it may not send more)
    Disconnected,  ///< the link went away (or was not open at the start)
    Closed,        ///< the session closed
    BusChanged,    ///< the port was reopened at another baud
    SpeedLimit,    ///< the speed watch stopped its drive past the soft speed limit (SpeedWatch)
};

/// How a setpoint stream ended: the reason, what it sent, and for a refusal the typed
/// verdict (or the builder's field error).
struct SetpointStop {
    quint64 stream = 0; ///< SetpointStreamPlan::stream
    SetpointStopReason reason = SetpointStopReason::Requested;
    qint64 emitted = 0;      ///< setpoints handed to the bus
    qint64 skipped = 0;      ///< ticks skipped while the previous setpoint was queued or in flight
    safety::Verdict verdict; ///< Refused by a limit: which one
    std::optional<protocol::FieldError> fieldError; ///< Refused by the builder: which field
    /// Refused because the session listens only (reason Refused, nothing sent, no verdict).
    SendRefusal refusal = SendRefusal::None;

    /// The stream `stream` a listen-only session refused: it never started, sent nothing.
    static SetpointStop refusedListenOnly(quint64 stream)
    {
        SetpointStop s;
        s.stream = stream;
        s.reason = SetpointStopReason::Refused;
        s.refusal = SendRefusal::ListenOnly;
        return s;
    }
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::SetpointStop)
