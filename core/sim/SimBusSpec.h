#pragma once

#include "SimDriveModel.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace lk::sim {

/// The drives of a simulated bus, from the `--motors`/`--sim` syntax "3:MF,17:MS,32:MG".
///
/// Each entry is ID:SERIES (ID 1..32, series MS/MF/MG/MH, case-insensitive) or ID:MOTOR with
/// a motor name that starts with a series ("5:MG5010E-i36", "6:MF4015-18bit"), optionally
/// followed by firmware quirks the drive copies ("3:MF+accel-ignored", see FirmwareQuirks).
/// "@2.35" after the model makes a firmware-2.35 drive speaking V2.35 ("1:MS4015@2.35");
/// "@2.3" (the default) a V2.3 one. "+fault=NAME[@START[-END]]" (repeatable) makes the drive
/// raise a protection fault by itself (SimFault: "1:MF+fault=over_temperature@5s").
/// "+resonance=HZ[/DAMPING[/RATIO]]", "+counts=N", "+speed-res=DPS" shape its plant
/// (PlantOptions: "3:MF+resonance=120/0.05+counts=16384").
struct SimBusSpec {
    struct Entry {
        int id = 1;
        SimDriveModel model;
    };
    QList<Entry> drives; ///< in the order given

    /// Parse; on failure returns nullopt and, if `error` is set, one sentence naming the
    /// offending entry (bad ID, duplicate ID, unknown series, empty entry).
    static std::optional<SimBusSpec> parse(const QString &text, QString *error = nullptr);
    /// Adds the faults of lksim's --fault: "ID:FAULT[@START[-END]][,...]" (SimFault) to the
    /// drives given; false with one sentence in `error` for an ID not on the bus or a fault
    /// its generation does not have.
    bool addFaults(const QString &text, QString *error = nullptr);
    /// Back to text ("3:MF,17:MS" or "5:MG5010E-i36" where the motor is not the default).
    QString toString() const;
};

} // namespace lk::sim
