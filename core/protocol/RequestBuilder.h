#pragma once

#include "Request.h"

namespace lk::protocol::build {

// Typed request builders. Each validates every argument against its wire range in the field
// table (ProtocolFields.h: the spec and docs/ERRATA.md, the stricter bound where V2.3 and V2.35
// differ) and returns a FieldError naming the field and its range instead of clamping.
// Physical arguments (A, dps, deg) are rounded to the nearest wire unit; NaN and infinities
// are refused. Field names follow CLI.md.

/// Any command whose request carries no data (reads, motor_off/stop/run, clear_errors,
/// clear_angle, write_zero_rom, read_model). Refuses commands that need data.
BuildResult plain(Command command, int id);
BuildResult writePid(int id, int angleKp, int angleKi, int speedKp, int speedKi, int iqKp, int iqKi,
                     bool rom);
BuildResult writePid(int id, const PidGains &gains, bool rom);
BuildResult writeAcceleration(int id, qint64 accelDps2); ///< 0..2147483647 dps/s
BuildResult writeEncoderOffset(int id, qint64 offset);   ///< 0..65535 counts
/// -850..850 (MS): the stricter of V2.3's +-1000 and V2.35's +-850.
BuildResult openLoop(int id, qint64 power);
/// Torque at the scale of the drive in `context`: V2.3 32 A / 2000 LSB (-32..32 A); V2.35 MF
/// 33/4096 A, MG 66/4096 A per LSB. The raw value stays within +-2000, the stricter of both
/// generations. The only torque builder: a torque is never built without knowing the drive.
BuildResult torque(int id, double iqA, const DecodeContext &context);
BuildResult speed(int id, double speedDps); ///< int32 of 0.01 dps
/// A speed command for the drive of `context`. On CAN V2.36 the frame carries a torque limit
/// (docs/CAN.md): `torqueLimitA`, the soft limits' max torque, in iq units rounded down
/// (never above what the user allowed), at most 2048; a limit under one iq unit is refused,
/// as 0 is never sent. Other dialects have no such field and ignore it.
BuildResult speed(int id, double speedDps, const DecodeContext &context, double torqueLimitA);
BuildResult multiPosition(int id, double angleDeg); ///< int64 of 0.01 deg
BuildResult multiPosition(int id, double angleDeg, double maxSpeedDps);
BuildResult singlePosition(int id, SpinDirection dir, double angleDeg); ///< 0..359.99 deg
BuildResult singlePosition(int id, SpinDirection dir, double angleDeg, double maxSpeedDps);
BuildResult incrementPosition(int id, double deltaDeg); ///< int32 of 0.01 deg
BuildResult incrementPosition(int id, double deltaDeg, double maxSpeedDps);

// V2.35 only (docs/V2.35.md sections 4.2 and 6).
BuildResult readParam(int id, ParamId param);
/// PID loop parameter (angle_pid, speed_pid, iq_pid): Kp, Ki, Kd each 0..65535.
BuildResult writeParamPid(int id, ParamId param, qint64 kp, qint64 ki, qint64 kd, bool rom);
/// A one-number parameter in its physical unit: max_torque (iq command units 0..2048),
/// max_speed (dps, 0.01 dps on the wire), current_ramp (0..32767, unit undocumented),
/// speed_ramp (dps/s), max_angle_low/high (the half of `value` deg as int64 of 0.01 deg).
BuildResult writeParam(int id, ParamId param, double value, bool rom);
BuildResult brake(int id, BrakeAction action);

// CAN V2.36 only (docs/CAN.md section 4.1): 0xC0 reads a control parameter, 0xC1 writes it to
// RAM. There is no ROM write. Sent to anything but a CAN V2.36 drive they are refused, nothing
// sent (LinkCodec, MotorRegistry).
BuildResult readControlParam(int id, ControlParamId param);
/// A PID control parameter (angle_pid, speed_pid, iq_pid): Kp, Ki, Kd each 0..65535.
BuildResult writeControlParamPid(int id, ControlParamId param, qint64 kp, qint64 ki, qint64 kd);
/// A one-number control parameter in the unit of its field (ProtocolFields::ofControlParam):
/// the torque limit in iq units 0..2048, the speed limit in dps (0.01 dps on the wire), the
/// angle limit in deg (0.01 deg), the current ramp raw (unit unknown), the speed ramp dps/s.
BuildResult writeControlParam(int id, ControlParamId param, double value);
/// The write of a value read or built before (the bytes as they are; the ID checked).
BuildResult writeControlParam(int id, const ControlParameter &value);

/// The ID check shared by every builder: 1..32.
std::optional<FieldError> checkId(int id);

} // namespace lk::protocol::build
