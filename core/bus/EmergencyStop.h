#pragma once

#include "BusRequest.h"
#include "RequestResult.h"

#include <QtCore/QVector>

namespace lk::bus {

/// One emergency stop: the motor_off (or motor_stop) requests it sends in the Emergency lane
/// and the tally of which IDs acknowledged and which stayed silent.
class EmergencyStop {
public:
    /// `halt` is MotorOff (the emergency stop proper) or MotorStop (`lkctl stop all`).
    EmergencyStop(quint64 ticket, QVector<int> targets, int retries,
                  protocol::Command halt = protocol::Command::MotorOff);

    QVector<BusRequest> requests() const;
    /// Count one motor_off result; true when it was the last one (then both lists are in
    /// ascending ID order).
    bool record(const RequestResult &result);

    quint64 ticket() const { return m_ticket; }
    const QVector<int> &acknowledged() const { return m_acknowledged; }
    const QVector<int> &silent() const { return m_silent; }

private:
    quint64 m_ticket;
    protocol::Command m_halt;
    QVector<int> m_targets;
    int m_retries;
    int m_remaining;
    QVector<int> m_acknowledged, m_silent;
};

} // namespace lk::bus
