#pragma once

#include <protocol/Series.h>

#include <QtCore/QJsonObject>

#include <optional>

namespace lk::safety {

/// The user's own limits for one drive, checked before any command that can move it.
///
/// Angles and speeds are rotor values, as on the wire. Torque and open-loop power are not
/// limited by the drive itself (ERRATA.md), so their defaults are deliberately low; speed
/// defaults to the series maximum, positions are unbounded until the user sets a range.
struct SoftLimits {
    double maxTorqueA = 1.0;           ///< |iq| for torque commands
    int maxPower = 200;                ///< |power| for open-loop commands (of 1000, MS)
    double maxSpeedDps = 0;            ///< |speed| and max-speed arguments; 0 = series maximum
    std::optional<double> minAngleDeg; ///< multi-turn target range, rotor degrees
    std::optional<double> maxAngleDeg;
    std::optional<double> maxIncrementDeg; ///< |increment| of one incremental move

    /// Safe defaults for a series: a quarter of the series current, power 200 of 1000,
    /// the series' top speed.
    static SoftLimits defaults(protocol::Series series);

    QJsonObject toJson() const;
    /// Missing keys keep `fallback`'s values; values of the wrong type or sign are refused
    /// (nullopt, with the key named in `error`).
    static std::optional<SoftLimits> fromJson(const QJsonObject &json, const SoftLimits &fallback,
                                              QString *error = nullptr);
    bool operator==(const SoftLimits &o) const;
};

} // namespace lk::safety
