#pragma once

#include "DriveTestRig.h"

#include <sim/SimParams.h>

#include <QtTest/QTest>
#include <QtWidgets/QDoubleSpinBox>

namespace lk::drivetest {

/// The V2.35 parameters a simulated drive holds in RAM.
inline sim::SimParams ramParams(SimRig &rig, int id)
{
    return rig.read<sim::SimParams>(id, [](const sim::SimDrive &d) { return d.ramParams(); });
}

/// The V2.35 parameters a simulated drive holds in ROM.
inline sim::SimParams romParams(SimRig &rig, int id)
{
    return rig.read<sim::SimParams>(id, [](const sim::SimDrive &d) { return d.rom().params; });
}

/// 0x42 and 0x44 frames drive `id` received.
inline int paramWrites(SimRig &rig, int id)
{
    return rig.count(id, protocol::Command::WriteParamRam) +
           rig.count(id, protocol::Command::WriteParamRom);
}

/// Types `value` into a parameter table's edit field as a user would.
inline void typeInto(QDoubleSpinBox *box, const QString &value)
{
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, value);
    QTest::keyClick(box, Qt::Key_Enter); // keyboard tracking is off: commits on Enter
}

} // namespace lk::drivetest
