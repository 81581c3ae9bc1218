#pragma once

#include "SetpointWaveform.h"

#include <protocol/Series.h>
#include <safety/MotionPlanner.h>
#include <safety/SoftLimits.h>

#include <QtCore/QMetaType>

#include <optional>

namespace lk::bus {

/// What a setpoint stream sends and what bounds it: the waveform, the drive, and everything
/// the motion gate needs to check each setpoint on the bus thread (the series, the drive's
/// soft limits and, for position targets, the angle the GUI read before the start).
struct SetpointStreamPlan {
    quint64 stream = 0; ///< the handle BusSession::startSetpointStream gave it
    int id = 0;         ///< the drive
    SetpointWaveform::Settings settings;
    std::optional<protocol::Series> series;
    safety::SoftLimits limits;
    /// Every position setpoint is checked from this angle (one output turn at most): the
    /// waveform stays around where the drive was when it started.
    safety::DrivePosition position;
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::SetpointStreamPlan)
