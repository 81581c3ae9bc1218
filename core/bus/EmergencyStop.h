#pragma once

#include "BusRequest.h"
#include "RequestResult.h"
#include "StopTargets.h"

#include <QtCore/QVector>

namespace lk::bus {

/// One emergency stop: the motor_off (or motor_stop) requests it sends in the Emergency lane
/// and the tally of which IDs acknowledged and which stayed silent. Every ID of 1..32 gets
/// one; the known and recently commanded ones (StopTargets::first) go first and are asked
/// again `retries` times when silent. The others get one attempt each: most of them are
/// absent, and retrying 28 silent IDs would hold the bus (and the report) for a second.
/// With no known ID at all every ID is retried: any of them may be a drive.
class EmergencyStop {
public:
    /// `halt` is MotorOff (the emergency stop proper) or MotorStop (`lkctl stop all`).
    EmergencyStop(quint64 ticket, StopTargets targets, int retries,
                  protocol::Command halt = protocol::Command::MotorOff);

    QVector<BusRequest> requests() const;
    /// Count one motor_off result; true when it was the last one (then the lists are in
    /// ascending ID order; before, in the order the results came).
    bool record(const RequestResult &result);

    quint64 ticket() const { return m_ticket; }
    /// Halts whose result is still to come.
    int remaining() const { return m_remaining; }
    const QVector<int> &acknowledged() const { return m_acknowledged; }
    const QVector<int> &silent() const { return m_silent; }
    /// The silent IDs whose halt never reached the wire (the link dropped first).
    const QVector<int> &unsent() const { return m_unsent; }

private:
    quint64 m_ticket;
    protocol::Command m_halt;
    StopTargets m_targets;
    int m_retries;
    int m_remaining;
    QVector<int> m_acknowledged, m_silent, m_unsent;
};

} // namespace lk::bus
