#pragma once

#include "ControllerRound.h"
#include "ControllerSpec.h"
#include "ControllerTransaction.h"

#include <QtCore/QByteArray>
#include <QtCore/QHash>
#include <QtCore/QList>
#include <QtCore/QString>

#include <deque>
#include <optional>

namespace lk::sim {

class SimBus;

/// Bytes that passed on the simulated wire; `atS` is when their last byte left it.
struct WireChunk {
    double atS = 0;
    QByteArray bytes;
};

/// A simulated foreign master on a SimBus (lksim `--controller`): it polls reads and sends
/// setpoints as ControllerSpec says, on the bus clock, one request at a time (half duplex:
/// it waits for each reply, or for its timeout when none comes). Everything is timed at the
/// baud (8N1): a request reaches the drives when its last byte has left; the reply starts the
/// drive's turnaround (SimBus reply delay, faults included) later and takes its wire time.
///
/// What passes on the wire comes out in bus order, as an RS485 tap sees it (advanceTo), and
/// each finished request with its outcome is a ControllerTransaction (takeFinished): the
/// ground truth for a listen-only monitor. Bytes of another master (the tool on lksim's pty)
/// are put on the same wire (secondMaster): on an idle wire the drives answer them, over the
/// controller's traffic both frames are lost. Time is the caller's clock in seconds; the
/// class never reads a clock itself. Not thread-safe.
class ForeignController {
public:
    /// The master's pause between a reply's last byte and its next request.
    static constexpr double kTurnaroundS = 0.0001;
    /// After a move, a drive gets no speed setpoint for the move's duration and this long.
    static constexpr double kMoveSettleS = ControllerRound::kMoveSettleS;

    /// `startS`: the bus clock when the master sends its first request. `ids` in the spec
    /// empty: every drive on the bus.
    ForeignController(const ControllerSpec &spec, SimBus &bus, int baud, double startS);

    /// Run the master up to `nowS` (the drives' physics too); returns the bytes whose last
    /// byte left the wire by then, in wire order: requests and replies, the second master's
    /// frames' replies included.
    QList<WireChunk> advanceTo(double nowS);
    /// When advanceTo next has something to do: a request starts or ends, a reply ends, a
    /// timeout expires.
    double nextEventS() const;
    /// The transactions finished since the last call, in order.
    QList<ControllerTransaction> takeFinished();

    /// What another master's bytes met on the wire.
    struct SecondMaster {
        bool collided = false;
        bool duringReply = false; ///< collided with a reply on the wire (else a request or a
                                  ///< drive about to answer)
        QString what;             ///< for the log: what it collided with, or "idle wire"
    };
    /// Bytes another master puts on the wire from `nowS` (call advanceTo(nowS) first). Over
    /// the controller's request or reply both are lost (the transaction ends Collided; the
    /// drives act on neither request); a request of the controller that begins while they or
    /// their replies are on the wire is lost too (Collided, the drive never gets it). On an
    /// idle wire the drives get them at their last byte, and their replies appear in
    /// advanceTo's output. Known simplification: a frame that began on an idle wire reaches
    /// the drives even when the controller's next request then overlaps it.
    SecondMaster secondMaster(const QByteArray &bytes, double nowS);

    const QList<int> &ids() const { return m_round.ids(); }
    int baud() const { return m_baud; }

private:
    struct InFlight {
        ControllerTransaction t;
        QByteArray bytes;
        bool delivered = false; ///< given to the drives (at requestEndS)
        bool lost = false;      ///< another master hit the request: the drives never get it
        double replyStartS = 0; ///< the reply's first byte (noise included)
        double finishS = 0;     ///< when the master moves on (reply end or timeout)
    };
    struct Window {
        double startS = 0;
        double endS = 0;
    };

    void startRequest(const protocol::Request &request, double atS);
    void deliver();
    void classifyReply(const QByteArray &bytes);
    void finish();
    void emitChunk(double atS, const QByteArray &bytes);
    bool foreignBusy(double startS, double endS) const;
    double wire(qsizetype bytes) const;
    protocol::DecodeContext contextOf(int id) const;

    ControllerSpec m_spec;
    SimBus &m_bus;
    int m_baud;
    double m_startS;
    ControllerRound m_round;
    double m_nextRequestS;
    std::optional<InFlight> m_inFlight;
    std::deque<WireChunk> m_chunks;      ///< on the wire, not yet handed out; by atS
    std::deque<Window> m_foreignWindows; ///< the second master's frames and their replies
    QList<ControllerTransaction> m_finished;
};

} // namespace lk::sim
