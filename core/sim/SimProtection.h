#pragma once

#include "DrivePhysics.h"
#include "SimFault.h"
#include "motor/SeriesLimits.h"

#include <QtCore/QList>

namespace lk::sim {

/// The protection of one simulated drive: the errorState flags, what raises them (supply
/// below the series minimum, motor above kOverTemperatureC, and the drive's scheduled
/// SimFaults) and what clears them (0x9B, once the cause has gone). A scheduled fault also shows
/// in what the drive reports: low or over voltage in the supply, motor over-temperature in
/// the temperature. Flags latch until cleared; the drive switches its output off on a new one.
class SimProtection {
public:
    static constexpr double kOverTemperatureC = 85.0;      ///< protection trips above this
    static constexpr double kOverTemperatureClearC = 80.0; ///< 0x9B clears bit3 below this

    SimProtection(const motor::SeriesLimits &limits, QList<SimFault> faults);

    /// Power-up: the clock restarts at 0 and no flag is set.
    void restart();
    /// Time passes: scheduled causes come and go, and show in `physics` (supply, temperature).
    void advance(double seconds, DrivePhysics &physics);
    /// Latches the causes present now; returns the flags that were not set before (the drive
    /// switches off on any).
    quint8 trip(const DrivePhysics &physics);
    /// 0x9B: clears the flags whose cause has gone.
    void clear(const DrivePhysics &physics);

    quint8 errorState() const { return m_errorState; }
    double uptimeS() const { return m_uptimeS; }
    const QList<SimFault> &faults() const { return m_faults; }
    /// The supply the bench gives (a scheduled low or over voltage overrides it meanwhile).
    void setSupplyVoltage(double volts, DrivePhysics &physics);

private:
    quint8 causes(const DrivePhysics &physics) const;
    quint8 scheduled() const;
    void showCauses(DrivePhysics &physics) const;

    const motor::SeriesLimits &m_limits;
    QList<SimFault> m_faults;
    double m_uptimeS = 0;
    double m_benchSupplyV;
    quint8 m_errorState = 0;
};

} // namespace lk::sim
