#pragma once

#include <protocol/Command.h>

#include <QtCore/QMetaType>
#include <QtCore/QVector>

namespace lk::bus {

/// What to poll: every command for every ID, round robin.
struct PollPlan {
    QVector<int> ids;
    /// read_* commands only (anything else is dropped from the plan by the worker).
    /// read_state3 is skipped for IDs known to be MS (no phase currents there).
    QVector<protocol::Command> commands = standardCommands();
    /// Full cycles (every ID x command) per second; 0 = as fast as the bus allows.
    double rateHz = 0;

    /// The dashboard's mix: 0x9C, 0x9A, 0x92, 0x9D. A shared list rather than a brace
    /// initialiser here: GCC 12 at -O2 warns (falsely) about the inlined initialiser array.
    static QVector<protocol::Command> standardCommands()
    {
        static const QVector<protocol::Command> kCommands{
            protocol::Command::ReadState2, protocol::Command::ReadState1,
            protocol::Command::ReadMultiTurn, protocol::Command::ReadState3};
        return kCommands;
    }

    /// The default command mix of the dashboard.
    static PollPlan standard(const QVector<int> &ids, double rateHz = 0)
    {
        PollPlan p;
        p.ids = ids;
        p.rateHz = rateHz;
        return p;
    }
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::PollPlan)
