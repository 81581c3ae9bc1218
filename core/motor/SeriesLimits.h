#pragma once

#include "protocol/Command.h"
#include "protocol/Series.h"

#include <QtCore/QList>

namespace lk::motor {

/// What one drive series can do, from the series table of the spec (docs/ERRATA.md).
struct SeriesLimits {
    protocol::Series series = protocol::Series::MF;
    double minSupplyV = 0; ///< below this the drive raises low-voltage protection
    double maxSupplyV = 0;
    double nominalSupplyV = 0; ///< what a bench supply is usually set to (simulator default)
    double maxCurrentA = 0;    ///< limit of the closed loops (not of 0xA0/0xA1, ERRATA)
    double maxSpeedRpm = 0;
    QList<int> encoderBits; ///< resolutions the series is sold with
    int defaultEncoderBits = 14;
    bool hasOpenLoop = false;       ///< 0xA0 (MS only)
    bool hasTorqueLoop = true;      ///< 0xA1 (not on MS)
    bool hasPhaseCurrents = true;   ///< 0x9D (not on MS)
    bool repliesCarryPower = false; ///< MS replies carry power, not iq
    bool hasGearbox = false;        ///< MG: ratio in the motor name ("-i10")

    double maxSpeedDps() const { return maxSpeedRpm * 6.0; } ///< 1 rpm = 6 deg/s
};

/// The limits of a series (a static table: the reference stays valid).
const SeriesLimits &seriesLimits(protocol::Series series);

/// Whether a drive of this series implements the command; a drive that does not stays silent.
bool supports(protocol::Series series, protocol::Command command);

} // namespace lk::motor
