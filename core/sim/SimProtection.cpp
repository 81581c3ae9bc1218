#include "SimProtection.h"

namespace lk::sim {

namespace {
constexpr quint8 kLowVoltageBit = 0x01;
constexpr quint8 kOverVoltageBit = 0x02;
constexpr quint8 kOverTemperatureBit = 0x08;
// How far a scheduled low or over voltage takes the supply beyond the series range, and a
// scheduled over-temperature the motor beyond its trip point: plainly out, as a tripped drive.
constexpr double kSupplyExcessV = 1.0;
constexpr double kTemperatureExcessC = 5.0;
} // namespace

SimProtection::SimProtection(const motor::SeriesLimits &limits, QList<SimFault> faults)
    : m_limits(limits), m_faults(std::move(faults)), m_benchSupplyV(limits.nominalSupplyV)
{
}

void SimProtection::restart()
{
    m_uptimeS = 0;
    m_errorState = 0;
}

void SimProtection::setSupplyVoltage(double volts, DrivePhysics &physics)
{
    m_benchSupplyV = volts;
    showCauses(physics);
}

void SimProtection::advance(double seconds, DrivePhysics &physics)
{
    m_uptimeS += seconds;
    showCauses(physics);
}

quint8 SimProtection::scheduled() const
{
    quint8 bits = 0;
    for (const SimFault &f : m_faults) {
        if (f.activeAt(m_uptimeS))
            bits |= f.mask();
    }
    return bits;
}

void SimProtection::showCauses(DrivePhysics &physics) const
{
    const quint8 now = scheduled();
    double supply = m_benchSupplyV;
    if (now & kLowVoltageBit)
        supply = m_limits.minSupplyV - kSupplyExcessV;
    else if (now & kOverVoltageBit)
        supply = m_limits.maxSupplyV + kSupplyExcessV;
    physics.setSupplyVoltage(supply);
    // Held above the trip point while the cause lasts; afterwards the motor cools by itself.
    const double hot = kOverTemperatureC + kTemperatureExcessC;
    if ((now & kOverTemperatureBit) && physics.temperatureC() < hot)
        physics.setTemperatureC(hot);
}

quint8 SimProtection::causes(const DrivePhysics &physics) const
{
    quint8 bits = scheduled();
    if (physics.supplyVoltage() < m_limits.minSupplyV)
        bits |= kLowVoltageBit;
    if (physics.temperatureC() > kOverTemperatureC)
        bits |= kOverTemperatureBit;
    return bits;
}

quint8 SimProtection::trip(const DrivePhysics &physics)
{
    const quint8 fresh = causes(physics) & static_cast<quint8>(~m_errorState);
    m_errorState |= fresh;
    return fresh;
}

void SimProtection::clear(const DrivePhysics &physics)
{
    quint8 stays = scheduled();
    if (physics.supplyVoltage() < m_limits.minSupplyV)
        stays |= kLowVoltageBit;
    if (physics.temperatureC() >= kOverTemperatureClearC)
        stays |= kOverTemperatureBit;
    m_errorState &= stays;
}

} // namespace lk::sim
