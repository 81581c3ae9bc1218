#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include "Series.h"

#include <array>
#include <optional>

namespace lk::protocol {

// Plain values carried by requests and replies, in wire units, with physical-unit accessors.
// Scales from docs/ERRATA.md "Units and ranges (V2.3)".

constexpr double kIqReplyAmpsPerLsb = 33.0 / 2048.0;   ///< iq in replies (V2.3; V2.35 MG/MH)
constexpr double kIqMfV235AmpsPerLsb = 33.0 / 4096.0;  ///< iq of an MF drive on V2.35
constexpr double kIqCommandAmpsPerLsb = 32.0 / 2000.0; ///< iq in the 0xA1 command (V2.3)
constexpr double kPhaseAmpsPerLsb = 1.0 / 64.0;        ///< 0x9D phase currents (V2.3)
constexpr double kCentiUnits = 0.01;                   ///< 0.01 deg, 0.01 dps
constexpr quint8 kBrakeReadCode = 0x10;                ///< 0x8C data byte that only reads

/// Amps per LSB of iq (and, on V2.35, of the 0x9D phase currents) in replies from a drive:
/// V2.35 halves the MF scale (33/4096 A); MG is 66/4096 = 33/2048 A in both generations.
inline double iqReplyAmpsPerLsb(const DecodeContext &c)
{
    return c.generation == Generation::V2_35 && c.series == Series::MF ? kIqMfV235AmpsPerLsb
                                                                       : kIqReplyAmpsPerLsb;
}
/// Amps per LSB of the 0xA1 torque command: V2.3 32/2000 A; V2.35 the reply scale (+-2048 =
/// MF +-16.5 A, MG +-33 A). The builder keeps the stricter raw range of both, +-2000.
inline double iqCommandAmpsPerLsb(const DecodeContext &c)
{
    return c.generation == Generation::V2_35 ? iqReplyAmpsPerLsb(c) : kIqCommandAmpsPerLsb;
}
/// Amps per LSB of the 0x9D phase currents: 1/64 A on V2.3, the iq scale on V2.35.
inline double phaseAmpsPerLsb(const DecodeContext &c)
{
    return c.generation == Generation::V2_35 ? iqReplyAmpsPerLsb(c) : kPhaseAmpsPerLsb;
}

/// Spin direction of single-turn position commands (0 = clockwise, 1 = counter-clockwise).
enum class SpinDirection : quint8 { Clockwise = 0, CounterClockwise = 1 };

/// PI gains of the three loops, 0..255 each (0x30..0x32).
struct PidGains {
    quint8 angleKp = 0, angleKi = 0, speedKp = 0, speedKi = 0, iqKp = 0, iqKi = 0;
    bool operator==(const PidGains &o) const
    {
        return angleKp == o.angleKp && angleKi == o.angleKi && speedKp == o.speedKp &&
               speedKi == o.speedKi && iqKp == o.iqKp && iqKi == o.iqKi;
    }
    bool operator!=(const PidGains &o) const { return !(*this == o); }
};

/// Acceleration in dps/s (0x33 reply, 0x34 both ways); int32 per ERRATA.
struct Acceleration {
    qint32 dps2 = 0;
};

/// Encoder readout (0x90 reply), counts.
struct EncoderReading {
    quint16 encoder = 0, encoderRaw = 0, encoderOffset = 0;
};

/// Encoder offset written with 0x91 (both ways) or reported by newer firmware on 0x19.
struct EncoderOffset {
    quint16 offset = 0;
};

/// 0x19 reply: an echo on V2.3 firmware, the new zero on newer firmware (ERRATA).
struct ZeroWritten {
    std::optional<quint16> encoderOffset;
};

/// Multi-turn rotor angle (0x92 reply), 0.01 deg, positive = clockwise.
struct MultiTurnAngle {
    qint64 raw = 0;
    double degrees() const { return static_cast<double>(raw) * kCentiUnits; }
};

/// Single-turn angle (0x94 reply), 0.01 deg, 0 .. 36000 x gear ratio - 1.
struct SingleTurnAngle {
    quint32 raw = 0;
    double degrees() const { return raw * kCentiUnits; }
};

/// Temperature, voltage and error flags (0x9A and 0x9B replies). The layout depends on the
/// generation (docs/V2.35.md section 5): V2.3 `temp, 0, u16 voltage 0.1 V, 0, 0, err`; V2.35
/// `temp, i16 voltage 0.01 V, i16 bus current 0.01 A, motorState, err`.
struct State1 {
    State1() = default;
    /// A V2.3 reply's three values (tests and the simulator's side).
    State1(qint8 temperature, quint16 voltage, quint8 errors)
        : temperatureC(temperature), voltageRaw(voltage), errorState(errors)
    {
    }
    qint8 temperatureC = 0;
    quint16 voltageRaw = 0; ///< V2.3: uint16 of 0.1 V; V2.35: the int16 of 0.01 V as uint16
    quint8 errorState = 0;
    Generation generation = Generation::V2_3;
    qint16 busCurrentRaw = 0; ///< V2.35 only: 0.01 A
    quint8 motorStateRaw = 0; ///< V2.35 only: 0x00 on, 0x10 off
    /// The seven data bytes as received (empty when built by hand): a reply read before the
    /// drive's generation was known (a scan's first probe) can be read again with as().
    QByteArray wire;
    /// The same reply read with `g`'s layout; itself when no wire bytes were kept.
    State1 as(Generation g) const;
    double voltageV() const
    {
        return generation == Generation::V2_3 ? voltageRaw * 0.1
                                              : static_cast<qint16>(voltageRaw) * 0.01;
    }
    /// Bus current in A: V2.35 only.
    std::optional<double> busCurrentA() const
    {
        if (generation == Generation::V2_3)
            return std::nullopt;
        return busCurrentRaw * 0.01;
    }
    /// Whether the motor is on: V2.35 only, and only for the two documented codes.
    std::optional<bool> motorOn() const
    {
        if (generation == Generation::V2_3 || (motorStateRaw != 0x00 && motorStateRaw != 0x10))
            return std::nullopt;
        return motorStateRaw == 0x00;
    }
    bool lowVoltage() const { return errorState & 0x01; }
    /// Bit 3: over-temperature on V2.3, motor over-temperature on V2.35.
    bool overTemperature() const { return errorState & 0x08; }
};

/// Temperature, torque current or power, speed, encoder (0x9C and every 0xA0..0xA8 reply).
struct State2 {
    qint8 temperatureC = 0;
    qint16 torqueRaw = 0; ///< iq (-2048..2048 = -33..33 A) or, on MS, power (-1000..1000)
    bool isPower = false; ///< set by the decoder from the DecodeContext
    qint16 speedDps = 0;
    quint16 encoder = 0;
    double iqAmpsPerLsb = kIqReplyAmpsPerLsb; ///< set by the decoder (V2.35 MF: 33/4096)
    double iqA() const { return torqueRaw * iqAmpsPerLsb; }
};

/// Temperature and phase currents (0x9D reply, MF/MG/MH only).
struct State3 {
    qint8 temperatureC = 0;
    qint16 iaRaw = 0, ibRaw = 0, icRaw = 0; ///< 1/64 A on V2.3, the iq scale on V2.35
    double ampsPerLsb = kPhaseAmpsPerLsb;   ///< set by the decoder
    double iaA() const { return iaRaw * ampsPerLsb; }
    double ibA() const { return ibRaw * ampsPerLsb; }
    double icA() const { return icRaw * ampsPerLsb; }
};

/// Driver and motor model (0x12 reply, 42 bytes on V2.3, 58 bytes on V2.35).
struct ModelInfo {
    QString driverName; ///< NUL padding removed
    QString motorName;
    quint16 hardwareRaw = 0; ///< shown /10 on V2.3, /100 on V2.35
    quint16 firmwareRaw = 0;
    Generation generation = Generation::V2_3;
    QByteArray motorId;          ///< 12 bytes, V2.35 only
    quint16 motorVersionRaw = 0; ///< V2.35 only
    double hardwareVersion() const { return hardwareRaw / divisor(); }
    double firmwareVersion() const { return firmwareRaw / divisor(); }
    double divisor() const { return generation == Generation::V2_3 ? 10.0 : 100.0; }
};

// Control request payloads, wire units.
struct OpenLoopCommand {
    qint16 power = 0; ///< -850..850 (the stricter of V2.3's +-1000 and V2.35's +-850)
};
struct TorqueCommand {
    qint16 iqRaw = 0; ///< -2000..2000, the stricter range of both generations
    /// Amps per LSB at the scale of the drive it was built for (build::torque(): V2.3 32/2000
    /// A; V2.35 MF 33/4096, MG 66/4096). A request read back from bytes has the V2.3 scale:
    /// the frame does not say which drive it is for.
    double ampsPerLsb = kIqCommandAmpsPerLsb;
    double iqA() const { return iqRaw * ampsPerLsb; }
};
struct SpeedCommand {
    SpeedCommand() = default;
    explicit SpeedCommand(qint32 speed, std::optional<qint16> iqLimit = std::nullopt)
        : speedRaw(speed), iqLimitRaw(iqLimit)
    {
    }
    qint32 speedRaw = 0; ///< 0.01 dps
    /// The torque limit CAN V2.36 carries in 0xA2 (iq units, 1..2048), taken from the soft
    /// limits; no other dialect has the field. A CAN V2.36 0xA2 is never sent without one:
    /// whether a limit of 0 means "unlimited" or "no torque" is unknown (docs/CAN.md).
    std::optional<qint16> iqLimitRaw;
    double speedDps() const { return speedRaw * kCentiUnits; }
};
struct MultiPositionCommand {
    qint64 angleRaw = 0;                ///< 0.01 deg
    std::optional<quint32> maxSpeedRaw; ///< 0.01 dps, 0xA4 only
};
struct SinglePositionCommand {
    SpinDirection direction = SpinDirection::Clockwise;
    quint32 angleRaw = 0; ///< 0..35999 (V2.3, 2 bytes + pad); V2.35 3 bytes up to 36000 x ratio - 1
    std::optional<quint32> maxSpeedRaw; ///< 0xA6 only
};

/// What 0x8C asks of the brake (V2.35).
enum class BrakeAction : quint8 { Engage = 0x00, Release = 0x01, Read = kBrakeReadCode };
struct BrakeCommand {
    BrakeAction action = BrakeAction::Read;
};
/// 0x8C reply: 0x00 brake applied (unpowered), 0x01 released (powered).
struct BrakeState {
    quint8 raw = 0;
    bool released() const { return raw == 0x01; }
};
struct IncrementPositionCommand {
    qint32 angleRaw = 0;                ///< signed 0.01 deg
    std::optional<quint32> maxSpeedRaw; ///< 0xA8 only
};
/// CAN V2.36's 0x95 with an angle: the current position takes this multi-turn angle (RAM).
/// A 0x95 to zero, on any link, has no payload.
struct PositionSet {
    qint32 angleRaw = 0; ///< signed 0.01 deg
};

} // namespace lk::protocol
