#pragma once

namespace lk::safety {

/// Which speed bound a command went out with (VerdictText::speedBound words it).
enum class SpeedBound {
    None,         ///< the command carries no speed (torque, open loop, motor_run)
    Command,      ///< a speed command: its own speed, within the speed limit
    SoftLimit,    ///< a position move at the user's speed limit (none was given)
    SeriesTop,    ///< ... at the series' top speed, which is lower than the speed limit
    UserMaxSpeed, ///< a position move at the lower max speed the user gave
};

} // namespace lk::safety
