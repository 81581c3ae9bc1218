#pragma once

#include "Request.h"

namespace lk::protocol::build {

// Typed request builders. Each validates every argument against the wire range of the spec
// and ERRATA.md and returns a FieldError naming the field and its range instead of clamping.
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
BuildResult openLoop(int id, qint64 power);              ///< -1000..1000 (MS)
BuildResult torque(int id, double iqA);                  ///< -32..32 A
BuildResult speed(int id, double speedDps);              ///< int32 of 0.01 dps
BuildResult multiPosition(int id, double angleDeg);      ///< int64 of 0.01 deg
BuildResult multiPosition(int id, double angleDeg, double maxSpeedDps);
BuildResult singlePosition(int id, SpinDirection dir, double angleDeg); ///< 0..359.99 deg
BuildResult singlePosition(int id, SpinDirection dir, double angleDeg, double maxSpeedDps);
BuildResult incrementPosition(int id, double deltaDeg); ///< int32 of 0.01 deg
BuildResult incrementPosition(int id, double deltaDeg, double maxSpeedDps);

/// The ID check shared by every builder: 1..32.
std::optional<FieldError> checkId(int id);

} // namespace lk::protocol::build
