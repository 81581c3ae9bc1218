#pragma once

#include "ControllerSpec.h"

#include "protocol/Request.h"

#include <QtCore/QHash>
#include <QtCore/QList>

#include <optional>

namespace lk::sim {

/// What lksim's foreign master asks next (ControllerSpec): a round visits each ID in turn,
/// its setpoint slot (a due move, else the speed sine), then each poll command. The same
/// whatever the link: ForeignController (RS485) and CanForeignController (CAN) both ask it.
/// Time is the caller's, seconds on the bus clock.
class ControllerRound {
public:
    /// After a move, a drive gets no speed setpoint for the move's duration and this long.
    static constexpr double kMoveSettleS = 0.1;

    /// `ids` empty: nothing is ever asked. `startS`: when the master began (t = 0 of the sine
    /// and of the move period).
    ControllerRound(const ControllerSpec &spec, QList<int> ids, double startS);

    /// The next request at `atS`; nullopt when only setpoints are asked and none is due.
    std::optional<protocol::Request> next(double atS);
    /// With nothing due at `atS` (only setpoints, all held): when one next is.
    double idleUntilS(double atS) const;
    const QList<int> &ids() const { return m_ids; }
    double startS() const { return m_startS; }

private:
    std::optional<protocol::Request> setpoint(int id, double atS);

    ControllerSpec m_spec;
    QList<int> m_ids;
    double m_startS;
    int m_idIndex = 0;
    int m_itemIndex = 0; ///< 0: the setpoint slot; 1..: spec.poll[i - 1]
    QHash<int, int> m_movesSent;
    QHash<int, double> m_holdUntilS;
};

} // namespace lk::sim
