#include "ListenMonitor.h"

#include "BusDiagnostics.h"

#include <protocol/Reply.h>
#include <protocol/Request.h>

namespace lk::bus {

ListenMonitor::ListenMonitor(MotorRegistry &motors, TelemetryBatcher &telemetry,
                             BusDiagnostics &diagnostics, std::shared_ptr<BusClock> clock,
                             QObject *parent)
    : QObject(parent), m_motors(motors), m_telemetry(telemetry), m_diagnostics(diagnostics),
      m_clock(std::move(clock)), m_intake(motors, telemetry)
{
}

void ListenMonitor::restart()
{
    m_parser.reset();
    m_pairing.reset();
}

void ListenMonitor::feed(const QByteArray &bytes, int baud)
{
    m_pairing.setBaud(baud);
    m_stats.addBytes(bytes.size());
    // Every frame of a chunk arrived when the chunk did: that is all the host knows.
    const qint64 nowNs = m_clock->nowNs();
    m_parser.feed(bytes, [this, nowNs](const protocol::ParseEvent &ev) { onEvent(ev, nowNs); });
}

void ListenMonitor::onEvent(const protocol::ParseEvent &event, qint64 nowNs)
{
    m_diagnostics.recordParseEvent(event);
    if (!event.isFrame)
        m_stats.fault(event);
    const PassivePairing::Outcome out = m_pairing.take(event, nowNs);
    noteUnanswered(out.unanswered);
    const double time = static_cast<double>(nowNs) * 1e-9;
    switch (out.role) {
    case PassivePairing::Outcome::Role::Request:
        takeRequest(event.frame, time);
        break;
    case PassivePairing::Outcome::Role::Reply:
        m_stats.reply(event.frame, out.request, out.latencyNs);
        takeReply(event.frame, out.request, time);
        break;
    case PassivePairing::Outcome::Role::None:
        break;
    }
}

void ListenMonitor::noteUnanswered(const std::optional<protocol::Frame> &request)
{
    if (request)
        m_stats.unanswered(*request);
}

void ListenMonitor::takeRequest(const protocol::Frame &frame, double time)
{
    m_stats.request(frame);
    const protocol::RequestDecodeResult dec = protocol::decodeRequest(frame);
    if (!dec.request)
        return;
    const KnownMotor known = m_motors.all().value(frame.id);
    if (std::optional<TelemetrySample> s =
            TelemetrySample::fromRequest(*dec.request, known.series, known.generation, time))
        m_telemetry.add(*s);
}

void ListenMonitor::takeReply(const protocol::Frame &frame,
                              const std::optional<protocol::Frame> &request, double time)
{
    const protocol::ReplyDecodeResult dec =
        protocol::decodeReply(frame, m_motors.decodeContext(frame.id));
    if (!dec.reply)
        return;
    // A reply names its drive and command itself: unpaired, it still says what it says.
    ReplyIntake::Asked asked;
    asked.command = static_cast<protocol::Command>(request ? request->command : frame.command);
    bool changed = false;
    m_intake.take(*dec.reply, time, asked, changed);
    if (changed)
        emit motorsChanged();
}

ListenStatistics ListenMonitor::snapshot(int baud)
{
    const qint64 nowNs = m_clock->nowNs();
    m_pairing.setBaud(baud);
    noteUnanswered(m_pairing.expire(nowNs));
    return m_stats.snapshot(static_cast<double>(nowNs) * 1e-9, baud, m_pairing.counts());
}

} // namespace lk::bus
