#include "RotorParams.h"

namespace lk::sim {

RotorParams RotorParams::forSeries(protocol::Series series)
{
    // Back-EMF at the series' maximum speed stays below the nominal supply so that the
    // closed loops can reach the maximum speed, as the real drives do.
    RotorParams p;
    switch (series) {
    case protocol::Series::MS: // gimbal motor, 12 V: high resistance, small current
        p.inertia = 2e-5;
        p.torqueConstant = 0.05;
        p.resistance = 2.0;
        p.inductance = 1.0e-3;
        p.polePairs = 7;
        break;
    case protocol::Series::MF:
        break;
    case protocol::Series::MG: // geared: larger rotor, gearbox inertia and friction
        p.inertia = 1e-4;
        p.torqueConstant = 0.1;
        p.resistance = 0.5;
        p.inductance = 0.4e-3;
        p.viscousFriction = 3e-5;
        p.coulombFriction = 1e-2;
        p.thermalCapacity = 30;
        p.thermalResistance = 1.5;
        p.polePairs = 10;
        break;
    case protocol::Series::MH:
        p.inertia = 4e-5;
        p.torqueConstant = 0.04;
        p.resistance = 1.5;
        p.inductance = 0.6e-3;
        p.thermalResistance = 3.0; // hollow shaft, small frame: cools worse
        p.polePairs = 10;
        break;
    }
    return p;
}

} // namespace lk::sim
