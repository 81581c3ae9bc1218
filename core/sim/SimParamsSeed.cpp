#include "SimParamsSeed.h"

#include "SimBus.h"
#include "SimDrive.h"

namespace lk::sim {

namespace {
/// A well-mixed 64-bit value of (seed, id, n): splitmix64.
quint64 mix(quint32 seed, int id, int n)
{
    quint64 z = (quint64(seed) << 32) ^ (quint64(id) << 8) ^ quint64(n);
    z += 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/// A value in [from, from + span).
qint64 pick(quint32 seed, int id, int n, qint64 from, qint64 span)
{
    return from + qint64(mix(seed, id, n) % quint64(span));
}
} // namespace

SimRom SimParamsSeed::seeded(const SimRom &factory, int id, quint32 seed)
{
    SimRom rom = factory;
    int n = 0;
    auto gain = [&] { return static_cast<quint8>(pick(seed, id, n++, 10, 240)); };
    rom.pid = protocol::PidGains{gain(), gain(), gain(), gain(), gain(), gain()};
    rom.accelDps2 = static_cast<qint32>(pick(seed, id, n++, 1, 100) * 1000);
    rom.encoderZero = static_cast<quint16>(pick(seed, id, n++, 0, 4096));
    SimParams &p = rom.params;
    for (SimParams::Pid *loop : {&p.anglePid, &p.speedPid, &p.currentPid}) {
        for (quint16 &g : *loop)
            g = static_cast<quint16>(pick(seed, id, n++, 0, 1000));
    }
    p.maxTorque = static_cast<qint16>(pick(seed, id, n++, 500, 1500));
    p.maxSpeedRaw = static_cast<qint32>(pick(seed, id, n++, 10, 90) * 10000);
    p.maxAngleRaw = pick(seed, id, n++, 0, 20) * 36000;
    p.currentRamp = static_cast<qint32>(pick(seed, id, n++, 0, 1000));
    p.speedRampDps2 = static_cast<qint32>(pick(seed, id, n++, 5, 50) * 1000);
    return rom;
}

int SimParamsSeed::apply(SimBus &bus, quint32 seed)
{
    int seeded = 0;
    for (int id : bus.ids()) {
        const SimDrive *drive = bus.drive(id);
        const SimDriveModel model = drive->model();
        if (bus.romStore().rom(id, model.series))
            continue; // a stored ROM wins: the drive keeps what was written to it
        bus.romStore().save(id, model.series,
                            SimParamsSeed::seeded(model.factoryRom(id), id, seed));
        bus.removeDrive(id);
        bus.addDrive(id, model); // powers up from the stored ROM
        ++seeded;
    }
    return seeded;
}

} // namespace lk::sim
