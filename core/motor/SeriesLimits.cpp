#include "SeriesLimits.h"

namespace lk::motor {

using protocol::Command;
using protocol::Series;

namespace {

SeriesLimits makeLimits(Series s)
{
    SeriesLimits l;
    l.series = s;
    switch (s) {
    case Series::MS:
        l.minSupplyV = 7.4;
        l.maxSupplyV = 24;
        l.nominalSupplyV = 12;
        l.maxCurrentA = 4;
        l.maxSpeedRpm = 1000;
        l.encoderBits = {12, 18};
        l.defaultEncoderBits = 12;
        // SVPWM drive: open loop power instead of a torque loop, no phase current readout.
        l.hasOpenLoop = true;
        l.hasTorqueLoop = false;
        l.hasPhaseCurrents = false;
        l.repliesCarryPower = true;
        break;
    case Series::MF:
        l.minSupplyV = 12;
        l.maxSupplyV = 36;
        l.nominalSupplyV = 24;
        l.maxCurrentA = 9;
        l.maxSpeedRpm = 3000;
        l.encoderBits = {14, 18};
        l.defaultEncoderBits = 14;
        break;
    case Series::MG:
        l.minSupplyV = 24;
        l.maxSupplyV = 48;
        l.nominalSupplyV = 48;
        l.maxCurrentA = 14;
        l.maxSpeedRpm = 2000;
        l.encoderBits = {18};
        l.defaultEncoderBits = 18;
        l.hasGearbox = true;
        break;
    case Series::MH:
        l.minSupplyV = 12;
        l.maxSupplyV = 24;
        l.nominalSupplyV = 24;
        l.maxCurrentA = 4;
        l.maxSpeedRpm = 3000;
        l.encoderBits = {14};
        l.defaultEncoderBits = 14;
        break;
    }
    return l;
}

} // namespace

const SeriesLimits &seriesLimits(Series series)
{
    static const SeriesLimits table[] = {makeLimits(Series::MS), makeLimits(Series::MF),
                                         makeLimits(Series::MG), makeLimits(Series::MH)};
    return table[static_cast<int>(series)];
}

bool supports(Series series, Command command)
{
    const SeriesLimits &l = seriesLimits(series);
    switch (command) {
    case Command::OpenLoop:
        return l.hasOpenLoop;
    case Command::Torque:
        return l.hasTorqueLoop;
    case Command::ReadState3:
        return l.hasPhaseCurrents;
    default:
        return true;
    }
}

} // namespace lk::motor
