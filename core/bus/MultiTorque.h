#pragma once

#include "RequestResult.h"

#include <protocol/Request.h>

#include <QtCore/QByteArray>
#include <QtCore/QMetaType>
#include <QtCore/QVector>

namespace lk::bus {

/// The old CAN generation's multi-motor torque frame (0x280, docs/CAN.md section 4.2) as one
/// request: the torque of up to four drives (IDs 1..4) in one frame. Each drive in the drive's
/// "Broadcast Mode" answers on its own ID with the 0xA1 motion reply, in ascending ID order.
/// The frame has a slot for each of IDs 1..4: a slot not named carries 0 (zero torque).
struct MultiTorqueRequest {
    /// One torque request (Command::Torque, built for its drive: build::torque) per drive.
    QVector<protocol::Request> torques;
};

/// How a multi-motor torque frame ended, delivered once (BusSession::multiTorqueCompleted).
struct MultiTorqueResult {
    quint64 ticket = 0;
    /// Ok: every drive named answered. Timeout: at least one stayed silent (its own result
    /// says which). Error with attempts 0: refused, nothing sent (`reason` names the drive
    /// and the limit). Cancelled, Disconnected: as for any request.
    RequestStatus status = RequestStatus::Error;
    QString reason;
    SendRefusal refusal = SendRefusal::None;
    int attempts = 0; ///< 1 once the frame went on the wire (it is never sent twice)
    /// One per drive named, ascending ID: its 0xA1 reply (Ok), Timeout when it stayed
    /// silent, or the frame's status when the frame was not sent or was cut short.
    QVector<RequestResult> drives;
    bool ok() const { return status == RequestStatus::Ok; }
    bool refused() const { return attempts == 0 && status == RequestStatus::Error; }
};

/// The CAN record (CanRecord) of the 0x280 frame: each drive's iqRaw in its slot, 0 in the
/// slots not named. Empty when `torques` do not fit the frame (MultiTorqueGuard refuses those
/// first): an ID outside 1..4 or named twice, a request that is not a torque, a value beyond
/// +-2000.
QByteArray encodeMultiTorque(const QVector<protocol::Request> &torques);

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::MultiTorqueResult)
