#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QString>
#include <QtCore/QtGlobal>

#include "Series.h"

#include <optional>

namespace lk::protocol {

// Plain values carried by requests and replies, in wire units, with physical-unit accessors.
// Scales from ERRATA.md "Units and ranges (V2.3)".

constexpr double kIqReplyAmpsPerLsb = 33.0 / 2048.0;   ///< iq in replies
constexpr double kIqCommandAmpsPerLsb = 32.0 / 2000.0; ///< iq in the 0xA1 command
constexpr double kPhaseAmpsPerLsb = 1.0 / 64.0;        ///< 0x9D phase currents
constexpr double kCentiUnits = 0.01;                   ///< 0.01 deg, 0.01 dps

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

/// Temperature, voltage and error flags (0x9A and 0x9B replies).
struct State1 {
    qint8 temperatureC = 0;
    quint16 voltageRaw = 0; ///< 0.1 V
    quint8 errorState = 0;
    double voltageV() const { return voltageRaw * 0.1; }
    bool lowVoltage() const { return errorState & 0x01; }
    bool overTemperature() const { return errorState & 0x08; }
};

/// Temperature, torque current or power, speed, encoder (0x9C and every 0xA0..0xA8 reply).
struct State2 {
    qint8 temperatureC = 0;
    qint16 torqueRaw = 0; ///< iq (-2048..2048 = -33..33 A) or, on MS, power (-1000..1000)
    bool isPower = false; ///< set by the decoder from the DecodeContext
    qint16 speedDps = 0;
    quint16 encoder = 0;
    double iqA() const { return torqueRaw * kIqReplyAmpsPerLsb; }
};

/// Temperature and phase currents (0x9D reply, MF/MG/MH only).
struct State3 {
    qint8 temperatureC = 0;
    qint16 iaRaw = 0, ibRaw = 0, icRaw = 0; ///< 1/64 A
    double iaA() const { return iaRaw * kPhaseAmpsPerLsb; }
    double ibA() const { return ibRaw * kPhaseAmpsPerLsb; }
    double icA() const { return icRaw * kPhaseAmpsPerLsb; }
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
    qint16 power = 0; ///< -1000..1000
};
struct TorqueCommand {
    qint16 iqRaw = 0; ///< -2000..2000 = -32..32 A
    double iqA() const { return iqRaw * kIqCommandAmpsPerLsb; }
};
struct SpeedCommand {
    qint32 speedRaw = 0; ///< 0.01 dps
    double speedDps() const { return speedRaw * kCentiUnits; }
};
struct MultiPositionCommand {
    qint64 angleRaw = 0;                ///< 0.01 deg
    std::optional<quint32> maxSpeedRaw; ///< 0.01 dps, 0xA4 only
};
struct SinglePositionCommand {
    SpinDirection direction = SpinDirection::Clockwise;
    quint16 angleRaw = 0;               ///< 0..35999
    std::optional<quint32> maxSpeedRaw; ///< 0xA6 only
};
struct IncrementPositionCommand {
    qint32 angleRaw = 0;                ///< signed 0.01 deg
    std::optional<quint32> maxSpeedRaw; ///< 0xA8 only
};

} // namespace lk::protocol
