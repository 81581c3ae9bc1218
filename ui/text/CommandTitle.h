#pragma once

#include <protocol/Command.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

namespace lk::text {

/// The name a user reads for a protocol command: "Multi-turn position with speed limit",
/// translated. The snake_case names (CommandTable::name, CLI.md) are for lkctl, JSON and the
/// traffic view's command column; everywhere else in the GUI a command goes by this one.
/// QtCore only, in lktext: VerdictText names a refused command by it in the GUI.
class CommandTitle {
    Q_DECLARE_TR_FUNCTIONS(lk::text::CommandTitle)
public:
    /// "Multi-turn position with speed limit"; the code ("0xA4") for a value outside the
    /// command table.
    static QString name(protocol::Command command);
    /// "Multi-turn position with speed limit (0xA4)".
    static QString withCode(protocol::Command command);
    /// "Multi-motor torque (0x280)": the old CAN generation's frame for drives 1..4
    /// (docs/CAN.md section 4.2), which is no command of the table (it has no drive ID).
    static QString multiTorque();
};

} // namespace lk::text
