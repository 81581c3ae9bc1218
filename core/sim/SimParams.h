#pragma once

#include "DrivePhysics.h"
#include "protocol/ControlParameter.h"
#include "protocol/Parameter.h"
#include "protocol/Values.h"

#include <QtCore/QtGlobal>

#include <array>
#include <optional>

namespace lk::sim {

/// The V2.35 setting parameters (ParamIDs 0x96..0x9E, docs/V2.35.md section 6) of one simulated
/// drive: one copy lives in RAM, one in ROM. A CAN V2.36 drive reads and writes the same
/// values as its control parameters (0xC0/0xC1, docs/CAN.md section 4.1), in RAM only.
struct SimParams {
    using Pid = std::array<quint16, 3>; ///< Kp, Ki, Kd
    Pid anglePid{100, 100, 0};
    Pid speedPid{50, 40, 0};
    Pid currentPid{50, 50, 0};
    qint16 maxTorque = 2000; ///< iq command units (+-2048 full scale)
    qint32 maxSpeedRaw = 0;  ///< 0.01 dps; the drive sets its series maximum when 0
    qint64 maxAngleRaw = 0;  ///< 0.01 deg; 0 = no angle limit in this simulator
    qint32 currentRamp = 0;  ///< int16 on RS485 (0x9D), int32 on CAN V2.36 (0x24)
    qint32 speedRampDps2 = 20000;

    /// The 0x40 reply value; nullopt for a ParamID the table does not have.
    std::optional<protocol::ParameterValue> read(quint8 paramId) const;
    /// Apply a 0x42/0x44 value; false (the drive's failure flag) for an unknown ParamID.
    bool write(const protocol::ParameterValue &value);
    /// The 0xC0 reply value (CAN V2.36); nullopt for an ID the table does not have. The int64
    /// angle limit reads as int32, saturated.
    std::optional<protocol::ControlParameter> readControl(quint8 paramId) const;
    /// Apply a 0xC1 value; false for an unknown ID.
    bool writeControl(const protocol::ControlParameter &value);
    /// The gains the physics uses (it models V2.3's 0..255 gains: larger values saturate).
    protocol::PidGains physicsGains() const;
    /// The Kd of each loop (the physics saturates them at 255 as well).
    DerivativeGains derivativeGains() const;

    bool operator==(const SimParams &o) const;
    bool operator!=(const SimParams &o) const { return !(*this == o); }
};

} // namespace lk::sim
