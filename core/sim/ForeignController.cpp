#include "ForeignController.h"

#include "SimBus.h"
#include "protocol/StreamParser.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lk::sim {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr double kForgetWindowsS = 1.0; ///< the second master's frames older than this are gone
using Outcome = ControllerTransaction::Outcome;
} // namespace

ForeignController::ForeignController(const ControllerSpec &spec, SimBus &bus, int baud,
                                     double startS)
    : m_spec(spec), m_bus(bus), m_baud(baud), m_startS(startS),
      m_round(spec, spec.ids.isEmpty() ? bus.ids() : spec.ids, startS), m_nextRequestS(startS)
{
    if (m_round.ids().isEmpty())
        m_nextRequestS = kNever;
}

double ForeignController::wire(qsizetype bytes) const
{
    return SimBus::wireSeconds(bytes, m_baud);
}

protocol::DecodeContext ForeignController::contextOf(int id) const
{
    const SimDrive *drive = m_bus.drive(id);
    return drive ? drive->context() : protocol::DecodeContext{};
}

QList<WireChunk> ForeignController::advanceTo(double nowS)
{
    for (;;) {
        if (!m_inFlight) {
            if (m_nextRequestS > nowS)
                break;
            const double at = m_nextRequestS;
            if (const std::optional<protocol::Request> r = m_round.next(at)) {
                startRequest(*r, at);
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
    m_bus.advanceTo(nowS);
    while (!m_foreignWindows.empty() && m_foreignWindows.front().endS < nowS - kForgetWindowsS)
        m_foreignWindows.pop_front();
    QList<WireChunk> out;
    while (!m_chunks.empty() && m_chunks.front().atS <= nowS) {
        out.append(m_chunks.front());
        m_chunks.pop_front();
    }
    return out;
}

double ForeignController::nextEventS() const
{
    double t = m_nextRequestS;
    if (m_inFlight)
        t = m_inFlight->delivered ? m_inFlight->finishS : m_inFlight->t.requestEndS;
    if (!m_chunks.empty())
        t = std::min(t, m_chunks.front().atS);
    return t;
}

QList<ControllerTransaction> ForeignController::takeFinished()
{
    QList<ControllerTransaction> out;
    out.swap(m_finished);
    return out;
}

void ForeignController::startRequest(const protocol::Request &request, double atS)
{
    InFlight f;
    f.t.request = request;
    f.t.context = contextOf(request.id);
    f.bytes = request.encode();
    f.t.requestS = atS;
    f.t.requestEndS = atS + wire(f.bytes.size());
    // A frame of the second master (or a reply to one) still on the wire spoils this one.
    f.lost = foreignBusy(atS, f.t.requestEndS);
    emitChunk(f.t.requestEndS, f.bytes);
    m_inFlight = f;
}

void ForeignController::deliver()
{
    InFlight &f = *m_inFlight;
    f.delivered = true;
    f.finishS = f.t.requestEndS + m_spec.timeoutS;
    if (f.lost) {
        f.t.outcome = Outcome::Collided;
        return;
    }
    // The drives' parser must not join the end of an interrupted frame of the second master
    // to this request: on a real wire that frame was cut off.
    m_bus.dropPartialInput();
    const int dropsBefore = m_bus.faults().injectedCount(Fault::DropReply);
    const QList<SimReply> replies = m_bus.receive(f.bytes, f.t.requestEndS);
    if (replies.isEmpty()) {
        f.t.outcome = m_bus.faults().injectedCount(Fault::DropReply) != dropsBefore
                          ? Outcome::Dropped
                          : Outcome::Unanswered;
        return;
    }
    const SimReply &r = replies.first();
    f.replyStartS = f.t.requestEndS + r.delaySeconds;
    f.t.replyEndS = f.replyStartS + wire(r.bytes.size());
    f.t.replyBytes = r.bytes;
    classifyReply(r.bytes);
    if (foreignBusy(f.replyStartS, f.t.replyEndS)) {
        f.t.outcome = Outcome::Collided;
        f.t.reply.reset();
    }
    // The master waits for a reply that comes, however late; the timeout is for none.
    f.finishS = f.t.replyEndS;
    emitChunk(f.t.replyEndS, r.bytes);
}

void ForeignController::classifyReply(const QByteArray &bytes)
{
    ControllerTransaction &t = m_inFlight->t;
    bool spoilt = false;
    std::optional<protocol::Reply> reply;
    const auto sink = [&](const protocol::ParseEvent &e) {
        if (!e.isFrame) {
            if (!reply && !spoilt && e.error == protocol::ParseError::Garbage)
                t.noiseBytes += static_cast<int>(e.bytes.size()); // noise before the reply
            else
                spoilt = true;
            return;
        }
        const protocol::ReplyDecodeResult d = protocol::decodeReply(e.frame, t.context);
        if (reply || !d.reply || d.reply->id != t.request.id ||
            d.reply->command != t.request.command)
            spoilt = true;
        else
            reply = d.reply;
    };
    protocol::StreamParser parser;
    parser.feed(bytes, sink);
    parser.finish(sink);
    t.outcome = reply && !spoilt ? Outcome::Answered : Outcome::Garbled;
    if (t.outcome == Outcome::Answered)
        t.reply = reply;
}

void ForeignController::finish()
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

void ForeignController::emitChunk(double atS, const QByteArray &bytes)
{
    auto it = m_chunks.end();
    while (it != m_chunks.begin() && std::prev(it)->atS > atS)
        --it;
    m_chunks.insert(it, WireChunk{atS, bytes});
}

bool ForeignController::foreignBusy(double startS, double endS) const
{
    return std::any_of(m_foreignWindows.begin(), m_foreignWindows.end(),
                       [&](const Window &w) { return w.startS < endS && startS < w.endS; });
}

ForeignController::SecondMaster ForeignController::secondMaster(const QByteArray &bytes,
                                                                double nowS)
{
    SecondMaster out;
    // The bytes go on the wire as lksim reads them: what they meet is on the wire now (the
    // transaction in flight) or starts before they end (the controller's next request, which
    // startRequest() finds lost). Transactions already logged are never changed.
    const double endS = nowS + wire(bytes.size());
    if (m_inFlight && !m_inFlight->lost && m_inFlight->t.outcome != Outcome::Collided) {
        InFlight &f = *m_inFlight;
        const QString frame = QStringLiteral("ID %1's %2 %3 of the controller")
                                  .arg(f.t.request.id)
                                  .arg(protocol::CommandTable::name(f.t.request.command));
        if (!f.delivered) { // its request is on the wire until requestEndS
            out.collided = true;
            f.lost = true;
            out.what = frame.arg(QStringLiteral("request"));
        } else if (f.t.replyEndS > nowS) {
            out.collided = true;
            out.duringReply = nowS >= f.replyStartS;
            f.t.outcome = Outcome::Collided;
            f.t.reply.reset();
            out.what = frame.arg(out.duringReply ? QStringLiteral("reply")
                                                 : QStringLiteral("reply (about to begin)"));
        }
    }
    if (!out.collided && foreignBusy(nowS, endS)) {
        out.collided = true;
        out.duringReply = true;
        out.what = QStringLiteral("a reply to its own earlier request");
    }
    m_foreignWindows.push_back(Window{nowS, endS}); // on the wire, whole or spoilt
    if (out.collided)
        return out;
    double wireFreeS = endS;
    for (const SimReply &r : m_bus.receive(bytes, endS)) {
        const double replyStartS = std::max(endS + r.delaySeconds, wireFreeS);
        wireFreeS = replyStartS + wire(r.bytes.size());
        m_foreignWindows.push_back(Window{replyStartS, wireFreeS});
        emitChunk(wireFreeS, r.bytes);
    }
    out.what = QStringLiteral("an idle wire: the drives got them");
    return out;
}

} // namespace lk::sim
