#pragma once

#include "SimRomStore.h"

#include <QtCore/QtGlobal>

namespace lk::sim {

class SimBus;

/// Distinct parameters for simulated drives, so that a bus of them has something to compare,
/// back up and restore (lksim --param-seed): the same seed and ID always give the same values.
class SimParamsSeed {
public:
    /// `factory` with its gains, acceleration, encoder zero and (V2.35) parameter table varied
    /// by `seed` and `id`, each within the range its command allows.
    static SimRom seeded(const SimRom &factory, int id, quint32 seed);
    /// Gives every drive of `bus` whose ROM store holds nothing for it the seeded ROM (stored,
    /// so with a ROM directory it persists) and powers it up with it. Drives with a stored ROM
    /// keep it. Returns how many drives were seeded.
    static int apply(SimBus &bus, quint32 seed);
};

} // namespace lk::sim
