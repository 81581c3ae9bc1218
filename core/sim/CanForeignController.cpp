#include "CanForeignController.h"

#include "SimBus.h"
#include "SimCanFront.h"
#include "protocol/CanFrameTime.h"
#include "protocol/CanLayout.h"
#include "protocol/CanRecord.h"

#include <algorithm>
#include <limits>

namespace lk::sim {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
/// A receiver's report of a frame whose CRC failed (linux/can/error.h: CAN_ERR_PROT).
constexpr quint32 kErrorClassProtocol = 0x00000008;
using Outcome = ControllerTransaction::Outcome;
} // namespace

CanForeignController::CanForeignController(const ControllerSpec &spec, SimBus &bus,
                                           SimCanFront &front, int bitRate, double startS)
    : m_spec(spec), m_bus(bus), m_front(front), m_frameS(protocol::can::frameSeconds(bitRate)),
      m_startS(startS), m_round(spec, spec.ids.isEmpty() ? bus.ids() : spec.ids, startS),
      m_nextRequestS(m_round.ids().isEmpty() ? kNever : startS)
{
}

protocol::DecodeContext CanForeignController::contextOf(int id) const
{
    const SimDrive *drive = m_bus.drive(id);
    // An absent drive is asked as an old CAN drive is: nobody answers either way.
    return drive ? SimCanFront::contextOf(*drive)
                 : protocol::DecodeContext{protocol::Series::MF, protocol::Generation::V2_3,
                                           protocol::Link::Can};
}

QList<CanWireFrame> CanForeignController::advanceTo(double nowS)
{
    for (;;) {
        if (!m_inFlight) {
            if (m_nextRequestS > nowS)
                break;
            const double at = m_nextRequestS;
            if (const std::optional<protocol::Request> r = m_round.next(at)) {
                if (!startRequest(*r, at))
                    m_nextRequestS = at + 1e-4; // not on CAN: the round goes on
            } else {
                m_nextRequestS = std::max(m_round.idleUntilS(at), at + 1e-3);
            }
            continue;
        }
        if (!m_inFlight->delivered) {
            if (m_inFlight->t.requestEndS > nowS)
                break;
            deliver();
            continue;
        }
        if (m_inFlight->finishS > nowS)
            break;
        finish();
    }
    m_bus.advanceTo(std::max(nowS, 0.0));
    QList<CanWireFrame> out;
    while (!m_frames.empty() && m_frames.front().atS <= nowS) {
        out.append(m_frames.front());
        m_frames.pop_front();
    }
    return out;
}

double CanForeignController::nextEventS() const
{
    double t = m_nextRequestS;
    if (m_inFlight)
        t = m_inFlight->delivered ? m_inFlight->finishS : m_inFlight->t.requestEndS;
    if (!m_frames.empty())
        t = std::min(t, m_frames.front().atS);
    return t;
}

QList<ControllerTransaction> CanForeignController::takeFinished()
{
    QList<ControllerTransaction> out;
    out.swap(m_finished);
    return out;
}

bool CanForeignController::startRequest(protocol::Request request, double atS)
{
    const protocol::DecodeContext ctx = contextOf(request.id);
    if (auto *speed = std::get_if<protocol::SpeedCommand>(&request.payload);
        speed && ctx.generation == protocol::Generation::V2_35 && !speed->iqLimitRaw)
        speed->iqLimitRaw = protocol::can::kSpeedIqLimitMax;
    const protocol::can::CanEncodeResult encoded = protocol::can::encodeRequest(request, ctx);
    if (!encoded.data)
        return false;
    InFlight f;
    f.t.request = request;
    f.t.context = ctx;
    f.record = protocol::CanRecord::of(*encoded.data).encode();
    f.t.requestS = atS;
    f.t.requestEndS = atS + m_frameS;
    emitFrame(f.t.requestEndS, f.record);
    m_inFlight = f;
    return true;
}

void CanForeignController::deliver()
{
    InFlight &f = *m_inFlight;
    f.delivered = true;
    f.finishS = f.t.requestEndS + m_spec.timeoutS;
    const QList<SimReply> replies = m_front.receive(f.record, f.t.requestEndS);
    if (replies.isEmpty()) {
        f.t.outcome = Outcome::Unanswered;
        return;
    }
    const SimReply &r = replies.first();
    QByteArray bytes = r.bytes;
    double extra = 0;
    if (!m_bus.faults().apply(bytes, extra)) {
        f.t.outcome = Outcome::Dropped; // the drive acted; its reply was lost
        return;
    }
    const double replyStartS = f.t.requestEndS + r.delaySeconds + extra;
    if (bytes != r.bytes) {
        // Spoilt on the bus: every node's CRC check fails and flags it with an error frame.
        protocol::CanRecord err;
        err.canId = kErrorClassProtocol;
        err.flags = protocol::CanRecord::Error;
        err.data = QByteArray(8, '\0');
        ++m_errorFrames;
        emitFrame(replyStartS + m_frameS, err.encode());
        f.t.outcome = Outcome::Garbled;
        return;
    }
    f.t.replyEndS = replyStartS + m_frameS;
    f.t.replyBytes = bytes;
    f.t.outcome = Outcome::Garbled; // unless it decodes as the drive's reply to this request
    if (const std::optional<protocol::CanRecord> rec = protocol::CanRecord::decode(bytes)) {
        if (const std::optional<protocol::Frame> frame = protocol::can::frameOf(rec->canData())) {
            const protocol::ReplyDecodeResult d = protocol::decodeReply(*frame, f.t.context);
            if (d.reply && d.reply->id == f.t.request.id &&
                d.reply->command == f.t.request.command) {
                f.t.outcome = Outcome::Answered;
                f.t.reply = d.reply;
            }
        }
    }
    // The master waits for a reply that comes, however late; the timeout is for none.
    f.finishS = f.t.replyEndS;
    emitFrame(f.t.replyEndS, bytes);
}

void CanForeignController::finish()
{
    ControllerTransaction t = m_inFlight->t;
    const double period = m_spec.rateHz > 0 ? 1.0 / m_spec.rateHz : 0.0;
    m_nextRequestS = std::max(t.requestS + period, m_inFlight->finishS + kTurnaroundS);
    t.requestS -= m_startS;
    t.requestEndS -= m_startS;
    if (t.replyEndS >= 0)
        t.replyEndS -= m_startS;
    m_finished.append(t);
    m_inFlight.reset();
}

void CanForeignController::emitFrame(double atS, const QByteArray &record)
{
    auto it = m_frames.end();
    while (it != m_frames.begin() && std::prev(it)->atS > atS)
        --it;
    m_frames.insert(it, CanWireFrame{atS, record});
}

} // namespace lk::sim
