#pragma once

#include <protocol/Series.h>

#include <QtCore/QByteArray>
#include <QtCore/QJsonObject>

#include <optional>

namespace lk::safety {

/// The user's own limits for one drive, checked before any command that can move it.
///
/// Angles and speeds are rotor values, as on the wire. Torque and open-loop power are not
/// limited by the drive itself (docs/ERRATA.md), so their defaults are deliberately low. The speed
/// limit always exists: it bounds speed commands and is the max speed of every position move
/// that names none. Positions are unbounded until the user sets a range (each move is still
/// held to one output turn by MotionPlanner).
struct SoftLimits {
    /// The speed limit of SoftLimits{} and of a drive whose series is unknown: the top speed
    /// of the slowest series (MS, 1000 rpm), stated here rather than left open.
    static constexpr double kUnknownSeriesSpeedDps = 6000;

    double maxTorqueA = 1.0;                     ///< |iq| for torque commands
    int maxPower = 200;                          ///< |power| for open-loop commands (of 1000, MS)
    double maxSpeedDps = kUnknownSeriesSpeedDps; ///< |speed| and every position move's speed
    std::optional<double> minAngleDeg;           ///< multi-turn target range, rotor degrees
    std::optional<double> maxAngleDeg;
    std::optional<double> maxIncrementDeg; ///< |increment| of one incremental move

    /// Safe defaults for a series: a quarter of the series current, power 200 of 1000, and
    /// the series' top speed as the (visible) speed limit.
    static SoftLimits defaults(protocol::Series series);
    /// defaults() for a known series; SoftLimits{} (kUnknownSeriesSpeedDps) otherwise.
    static SoftLimits defaults(std::optional<protocol::Series> series);

    QJsonObject toJson() const;
    /// Missing keys keep `fallback`'s values. Unknown keys, wrong types and values out of
    /// range are refused (nullopt) with the key and its allowed range named in `error`.
    static std::optional<SoftLimits> fromJson(const QJsonObject &json, const SoftLimits &fallback,
                                              QString *error = nullptr);
    /// fromJson() of a JSON text, which also refuses text that is not one JSON object and a
    /// key written twice (QJsonObject alone would keep one of them silently).
    static std::optional<SoftLimits>
    fromJsonText(const QByteArray &text, const SoftLimits &fallback, QString *error = nullptr);
    /// The keys fromJson() accepts, for messages.
    static QString keyList();
    bool operator==(const SoftLimits &o) const;
};

} // namespace lk::safety
