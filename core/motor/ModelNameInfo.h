#pragma once

#include "protocol/Series.h"

#include <QtCore/QString>

#include <optional>

namespace lk::motor {

/// What a motor name such as "MG5010E-i10", "MF4015-14bit" or "MS5005" tells about the motor.
struct ModelNameInfo {
    QString name;                           ///< the name as given, trimmed
    std::optional<protocol::Series> series; ///< from the MS/MF/MG/MH prefix; nullopt if none
    double gearRatio = 1.0;                 ///< "-i10" -> 10; 1 without a gearbox suffix
    bool gearFromName = false;              ///< the ratio was written in the name
    int encoderBits = 14;                   ///< from "14bit"/"18bit", else the series default
    bool encoderBitsFromName = false;       ///< the resolution was written in the name

    /// Counts per rotor turn as the drive reports them (see encoderCountsPerTurn()).
    int countsPerTurn() const;

    /// Parse a motor name; never fails, unknown parts keep their defaults (14 bit, ratio 1).
    static ModelNameInfo parse(const QString &motorName);
};

/// Encoder counts per turn as reported on the wire: 2^bits for up to 16 bits; 18-bit models
/// report their top 16 bits, so anything above 16 bits reads 0..65535 (docs/ERRATA.md).
int encoderCountsPerTurn(int bits);

/// Default encoder resolution of a series (MS 12, MF 14, MG 18, MH 14 bit).
int defaultEncoderBits(protocol::Series series);

} // namespace lk::motor
