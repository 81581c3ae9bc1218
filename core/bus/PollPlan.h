#pragma once

#include <protocol/Command.h>

#include <QtCore/QMap>
#include <QtCore/QMetaType>
#include <QtCore/QVector>

namespace lk::bus {

/// What to poll: every command for every ID, round robin; optionally with a focus on one drive.
///
/// With a focus (focusId 1..32) that drive's focusCommands are polled back to back, as fast as
/// the bus allows (rateHz does not slow them), and the other IDs of `ids` keep their own round
/// robin of `commands` (at most rateHz rounds a second, as without a focus), one of their polls
/// after every focusOthersEvery focus polls: a step test gets the bus's full rate while the
/// dashboard of the other drives stays alive.
///
/// extraCommands add reads for single drives (a view that shows more of one drive than the
/// dashboard does) to that drive's round, without a second poll of what `commands` reads.
struct PollPlan {
    QVector<int> ids;
    /// read_* commands only (anything else is dropped from the plan by the worker).
    /// read_state3 is skipped for IDs known to be MS (no phase currents there), and for a
    /// drive of unknown series once it has left it unanswered while answering the others
    /// (UnansweredPolls).
    QVector<protocol::Command> commands = standardCommands();
    /// Full cycles (every ID x command) per second; 0 = as fast as the bus allows.
    double rateHz = 0;
    /// The drive polled back to back; 0 (or an ID outside 1..32): no focus.
    int focusId = 0;
    /// Read commands polled for focusId, in this order; empty: `commands`.
    QVector<protocol::Command> focusCommands;
    /// One poll of another drive after this many focus polls; 0: the others are not polled
    /// while the focus lasts.
    int focusOthersEvery = kDefaultFocusOthersEvery;
    static constexpr int kDefaultFocusOthersEvery = 8;
    /// Read commands polled for one ID after `commands` in that ID's round; those `commands`
    /// already reads are not polled twice. An ID not in `ids` is polled for its extras alone.
    /// The focus drive polls its focusCommands only: a step test keeps the bus's full rate.
    QMap<int, QVector<protocol::Command>> extraCommands;

    bool hasFocus() const { return focusId > 0; }

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

    /// This plan with a focus on `id`'s `commands` (see above); the other IDs keep theirs.
    PollPlan focusedOn(int id, const QVector<protocol::Command> &commands,
                       int othersEvery = kDefaultFocusOthersEvery) const
    {
        PollPlan p = *this;
        p.focusId = id;
        p.focusCommands = commands;
        p.focusOthersEvery = othersEvery;
        return p;
    }
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::PollPlan)
