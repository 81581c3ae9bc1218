#pragma once

#include "FirmwareQuirks.h"
#include "PlantOptions.h"
#include "SimFault.h"
#include "motor/ModelNameInfo.h"
#include "protocol/Series.h"

#include <QtCore/QList>
#include <QtCore/QString>

#include <optional>

namespace lk::sim {

struct SimRom;

/// Identity of a simulated drive, as its 0x12 reply shows it, and its protocol generation.
struct SimDriveModel {
    protocol::Series series = protocol::Series::MF;
    QString driverName;       ///< at most 20 Latin-1 characters, e.g. "LK-MF4015-DRV"
    QString motorName;        ///< e.g. "MF4015"; gear ratio and encoder bits are read from it
    quint16 hardwareRaw = 10; ///< shown /10: 1.0 (V2.35: /100, 300 = 3.00)
    quint16 firmwareRaw = 23; ///< shown /10: 2.3 (V2.35: /100, 235 = 2.35)
    /// V2.3 (default) or V2.35: firmware 2.35 and later speak docs/V2.35.md's protocol.
    protocol::Generation generation = protocol::Generation::V2_3;
    quint16 motorVersionRaw = 0; ///< V2.35 only
    /// Switch to firmware 2.35 (hw 3.00, motor 2.00, fw 2.35, as the captured MS4015 reports;
    /// an MS40xx motor's driver is the captured DS40R7).
    void useFirmware235();
    /// What a new drive of this model holds in ROM: the defaults, and on V2.35 a factory
    /// encoder zero that is not 0 (one per ID) and a Max Power within MS's +-1000.
    SimRom factoryRom(int id) const;
    FirmwareQuirks quirks;  ///< firmware oddities this drive copies (none by default)
    QList<SimFault> faults; ///< protection faults it raises by itself (none by default)
    PlantOptions plant;     ///< resonance and sensor quantisation ("+resonance=..."; none)

    /// Gear ratio and encoder resolution implied by the motor name (series default otherwise).
    motor::ModelNameInfo nameInfo() const;

    /// A typical model of the series: MS5005 (12 bit), MF4015 (14 bit), MG5010E-i10 (18 bit),
    /// MH7015 (14 bit).
    static SimDriveModel forSeries(protocol::Series series);
    /// A model from a motor name with a series prefix ("MG5010E-i36", "MF4015-18bit");
    /// nullopt when the name names no series.
    static std::optional<SimDriveModel> forMotorName(const QString &motorName);
};

} // namespace lk::sim
