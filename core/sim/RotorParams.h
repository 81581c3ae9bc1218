#pragma once

#include "protocol/Series.h"

namespace lk::sim {

/// Electrical, mechanical and thermal constants of a simulated motor, SI units, rotor side.
/// Values are plausible for the series' typical frame size, not datasheet figures.
struct RotorParams {
    double inertia = 5e-5;          ///< kg m^2 (MG: includes the reflected gearbox)
    double torqueConstant = 0.06;   ///< Nm/A, also the back-EMF constant in V s/rad
    double resistance = 1.0;        ///< ohm, phase-to-neutral equivalent in the q axis
    double inductance = 0.5e-3;     ///< H
    double viscousFriction = 1e-5;  ///< Nm per rad/s
    double coulombFriction = 4e-3;  ///< Nm
    double thermalCapacity = 15;    ///< J/K of the winding
    double thermalResistance = 2.5; ///< K/W to ambient
    int polePairs = 14;

    static RotorParams forSeries(protocol::Series series);
};

} // namespace lk::sim
