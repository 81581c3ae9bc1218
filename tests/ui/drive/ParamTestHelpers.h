#pragma once

#include "DriveTestRig.h"

#include <drive/ParameterTable.h>
#include <sim/SimParams.h>

#include <QtTest/QTest>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QLabel>

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

/// What a parameter table's "Drive holds" column shows for `row`, found by its object name
/// as a user-level test would; a missing label reads as a text no test expects.
inline QString heldText(const ui::ParameterTable &table, int row)
{
    const auto *label = table.findChild<QLabel *>(QStringLiteral("holds_") + table.field(row).key);
    return label ? label->text() : QStringLiteral("<no holds_%1 label>").arg(table.field(row).key);
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
