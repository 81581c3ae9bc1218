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
    QVector<protocol::Command> commands{
        protocol::Command::ReadState2, protocol::Command::ReadState1,
        protocol::Command::ReadMultiTurn, protocol::Command::ReadState3};
    /// Full cycles (every ID x command) per second; 0 = as fast as the bus allows.
    double rateHz = 0;

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
