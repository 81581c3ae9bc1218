#pragma once

#include <QtCore/QString>
#include <QtCore/QStringList>

namespace lk::sim {

/// Firmware behaviours seen on real drives (ERRATA "What real drives do") that a simulated
/// drive can be asked to copy, so the tool's read-back checks meet them before a technician does.
///
/// Named in a bus spec after the model: "3:MF+accel-ignored+clear-angle-ignored".
struct FirmwareQuirks {
    /// 0x34 is acknowledged but has no effect, and 0x33 reads 0.
    bool accelIgnored = false;
    /// 0x95 is acknowledged but the multi-turn angle is unchanged.
    bool clearAngleIgnored = false;
    /// 0x42/0x44 are answered with the failure flag (1) and change nothing (V2.35 drives).
    bool paramWriteRefused = false;

    /// Turn on the quirk called `name`; false when no quirk has that name.
    bool enable(const QString &name);
    /// The names of the quirks that are on, in a fixed order.
    QStringList names() const;
    /// Every quirk name, for help and error texts.
    static QStringList allNames();
};

} // namespace lk::sim
