#pragma once

#include "ControllerRound.h"
#include "ControllerSpec.h"
#include "ControllerTransaction.h"

#include <QtCore/QByteArray>
#include <QtCore/QList>

#include <deque>
#include <optional>

namespace lk::sim {

class SimBus;
class SimCanFront;

/// One frame on the simulated CAN bus, as a CanRecord (protocol/CanRecord.h); `atS` is when
/// its last bit left the bus: when the other nodes have it.
struct CanWireFrame {
    double atS = 0;
    QByteArray record;
};

/// lksim's foreign master on CAN (`--can ... --controller SPEC`): it asks what ControllerRound
/// says, one request at a time, each on 0x140+ID in the addressed drive's CAN layout, and
/// the drives answer through the SimCanFront it shares with lksim's other hosts. It waits for
/// each reply however late, or its timeout when none comes, as the RS485 master does.
///
/// Frames take their time at the bit rate (protocol::can::frameSeconds); a reply follows its
/// drive's turnaround. The bus's faults apply to replies as CAN makes them happen: a dropped
/// reply never comes (Dropped), a late one comes late, and a corrupted one (corrupt, length,
/// garbage) fails every node's CRC check: an error frame is on the bus instead (a record with
/// the Error flag; lksim's CanTransport does not write it) and the reply never reaches anyone
/// (Garbled). A V2.36 drive's speed setpoint carries the full torque
/// limit (kSpeedIqLimitMax), as a machine configured so would send. A request the drive's CAN
/// generation cannot carry (read_model on CAN) is not sent and not logged.
///
/// Frames come out in bus order (advanceTo) for the caller to put on the bus; each finished
/// request is a ControllerTransaction (takeFinished): the ground truth for a listener on the
/// same bus. Time is the caller's clock in seconds; not thread-safe.
class CanForeignController {
public:
    /// The master's pause between a reply and its next request.
    static constexpr double kTurnaroundS = 0.0001;

    CanForeignController(const ControllerSpec &spec, SimBus &bus, SimCanFront &front, int bitRate,
                         double startS);

    /// Run the master and the drives up to `nowS`; the frames complete by then, in bus order.
    QList<CanWireFrame> advanceTo(double nowS);
    /// When advanceTo next has something to do.
    double nextEventS() const;
    /// The transactions finished since the last call, in order.
    QList<ControllerTransaction> takeFinished();
    /// Error frames put on the bus for corrupted replies.
    qint64 errorFrames() const { return m_errorFrames; }

private:
    struct InFlight {
        ControllerTransaction t;
        QByteArray record;
        bool delivered = false;
        double finishS = 0;
    };

    bool startRequest(protocol::Request request, double atS);
    void deliver();
    void finish();
    void emitFrame(double atS, const QByteArray &record);
    protocol::DecodeContext contextOf(int id) const;

    ControllerSpec m_spec;
    SimBus &m_bus;
    SimCanFront &m_front;
    double m_frameS;
    double m_startS;
    ControllerRound m_round;
    double m_nextRequestS;
    std::optional<InFlight> m_inFlight;
    std::deque<CanWireFrame> m_frames; ///< on the bus, not yet handed out; by atS
    QList<ControllerTransaction> m_finished;
    qint64 m_errorFrames = 0;
};

} // namespace lk::sim
