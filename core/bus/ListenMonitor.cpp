#include "ListenMonitor.h"

#include "BusDiagnostics.h"
#include "HeardMultiTorque.h"

#include <protocol/CanLayout.h>
#include <protocol/CanRecordParser.h>
#include <protocol/Reply.h>
#include <protocol/Request.h>
#include <protocol/Values.h>

namespace lk::bus {

ListenMonitor::ListenMonitor(MotorRegistry &motors, TelemetryBatcher &telemetry,
                             BusDiagnostics &diagnostics, std::shared_ptr<BusClock> clock,
                             QObject *parent)
    : QObject(parent), m_motors(motors), m_telemetry(telemetry), m_diagnostics(diagnostics),
      m_clock(std::move(clock)), m_intake(motors, telemetry)
{
    restart(protocol::Link::Rs485);
}

void ListenMonitor::restart(protocol::Link link)
{
    m_link = link;
    m_parser = protocol::makeFrameParser(link, protocol::LinkEnd::Host);
    if (auto *can = dynamic_cast<protocol::CanRecordParser *>(m_parser.get())) {
        can->setErrorFrameSink([this](const protocol::CanRecord &) { m_stats.canErrorFrame(); });
        can->setOtherFrameSink([this](const protocol::CanRecord &record) {
            m_stats.otherFrame();
            takeMultiTorque(record);
        });
    }
    m_stats.setLink(link);
    m_pairing.setLink(link);
    m_pairing.reset();
}

void ListenMonitor::feed(const QByteArray &bytes, int baud, bool ours)
{
    m_feedOurs = ours;
    m_pairing.setBaud(baud);
    m_stats.addBytes(bytes.size());
    // Every frame of a chunk arrived when the chunk did: that is all the host knows.
    const qint64 nowNs = m_clock->nowNs();
    m_feedNs = nowNs;
    m_parser->feed(bytes, [this, nowNs](const protocol::ParseEvent &ev) { onEvent(ev, nowNs); });
}

PassivePairing::Outcome ListenMonitor::pair(const protocol::ParseEvent &event, qint64 nowNs)
{
    if (m_link != protocol::Link::Can || !event.isFrame)
        return m_pairing.take(event, nowNs);
    const PassivePairing::CanDirections d =
        PassivePairing::canDirections(event, m_motors.decodeContext(event.frame.id));
    return m_pairing.takeCan(event, d.direction, d.openAs, nowNs);
}

void ListenMonitor::noteCanGeneration(const protocol::ParseEvent &event)
{
    const protocol::can::CanData data{*event.canId, protocol::can::bytesOf(event.frame)};
    const std::optional<protocol::Generation> g = protocol::can::generationHint(data);
    if (g && m_motors.learnCanGeneration(event.frame.id, *g))
        emit motorsChanged();
}

void ListenMonitor::onEvent(const protocol::ParseEvent &event, qint64 nowNs)
{
    if (event.echoed)
        return; // our own frame looped back (a replayed active recording): its Tx copy counted
    m_diagnostics.recordParseEvent(event);
    if (!event.isFrame)
        m_stats.fault(event);
    const PassivePairing::Outcome out = pair(event, nowNs);
    // A reply says which CAN generation its drive speaks (its ID, its 0x9A layout) before it
    // is decoded: the decode then reads it with that generation.
    if (out.role == PassivePairing::Outcome::Role::Reply && event.canId)
        noteCanGeneration(event);
    noteUnanswered(out.unanswered);
    noteUnanswered(out.unansweredInGroup);
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

void ListenMonitor::noteUnanswered(const QVector<protocol::Frame> &requests)
{
    for (const protocol::Frame &f : requests)
        m_stats.unanswered(f);
}

void ListenMonitor::takeMultiTorque(const protocol::CanRecord &record)
{
    // Another master's multi-motor torque frame: a torque command to each drive it names that
    // has been seen on the old generation, which answers it as a 0xA1.
    const std::optional<QVector<HeardMultiTorque::Slot>> heard =
        HeardMultiTorque::decode(record, [this](int id) -> std::optional<protocol::DecodeContext> {
            if (!m_motors.all().contains(id))
                return std::nullopt;
            return m_motors.decodeContext(id);
        });
    if (!heard)
        return;
    // The Traffic view reads the frame from its record (TrafficModel: multi_torque).
    protocol::ParseEvent seen;
    seen.isFrame = true;
    seen.bytes = record.encode();
    seen.canId = record.canId;
    m_diagnostics.recordParseEvent(seen);
    const double time = static_cast<double>(m_feedNs) * 1e-9;
    QVector<protocol::Frame> torques;
    for (const HeardMultiTorque::Slot &slot : *heard) {
        torques.append(slot.frame);
        m_stats.request(slot.frame);
        if (m_feedOurs)
            continue; // the recording tool's own command: no sample, as in its session
        const KnownMotor known = m_motors.all().value(slot.request.id);
        if (std::optional<TelemetrySample> s =
                TelemetrySample::fromRequest(slot.request, known.series, known.generation, time))
            m_telemetry.add(*s);
    }
    noteUnanswered(m_pairing.openGroup(torques, m_feedNs));
}

void ListenMonitor::takeRequest(const protocol::Frame &frame, double time)
{
    m_stats.request(frame);
    if (m_feedOurs)
        return; // the recording tool's own command: no sample, as in its session
    const protocol::RequestDecodeResult dec =
        protocol::decodeRequest(frame, m_motors.decodeContext(frame.id));
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
    noteUnanswered(m_pairing.expireGroup(nowNs));
    return m_stats.snapshot(static_cast<double>(nowNs) * 1e-9, baud, m_pairing.counts());
}

} // namespace lk::bus
