#include "ReplayStatistics.h"

#include <protocol/CanRecordParser.h>

#include <utility>

namespace lk::recording {

void ReplayStatistics::restart(protocol::Link link, int baud, qint64 timeNs)
{
    m_link = link;
    m_baud = baud;
    m_pairing = bus::PassivePairing{};
    m_pairing.setLink(link);
    m_pairing.setBaud(baud > 0 ? baud : 115200);
    m_collector.reset();
    m_collector.setLink(link);
    // Rates and times count from here: the collector's clock starts at 0 with it.
    m_startNs = timeNs;
    m_lastSnapshotNs = timeNs;
}

void ReplayStatistics::attach(protocol::FrameParser &parser,
                              std::function<void(const protocol::CanRecord &)> otherFrame)
{
    if (auto *can = dynamic_cast<protocol::CanRecordParser *>(&parser)) {
        can->setErrorFrameSink(
            [this](const protocol::CanRecord &) { m_collector.canErrorFrame(); });
        can->setOtherFrameSink(
            [this, otherFrame = std::move(otherFrame)](const protocol::CanRecord &record) {
                m_collector.otherFrame();
                if (otherFrame)
                    otherFrame(record);
            });
    }
}

void ReplayStatistics::takeMultiTorque(const QVector<protocol::Frame> &torques, qint64 timeNs)
{
    const QVector<protocol::Frame> silent = m_pairing.openGroup(torques, timeNs);
    for (const protocol::Frame &f : silent) // const: an empty list is not given storage
        m_collector.unanswered(f);
    for (const protocol::Frame &f : torques)
        m_collector.request(f);
}

void ReplayStatistics::take(const protocol::ParseEvent &event,
                            const protocol::DecodeContext &context, qint64 timeNs)
{
    if (event.echoed)
        return;
    if (!event.isFrame)
        m_collector.fault(event);
    bus::PassivePairing::Outcome out;
    if (m_link == protocol::Link::Can && event.isFrame) {
        const bus::PassivePairing::CanDirections d =
            bus::PassivePairing::canDirections(event, context);
        out = m_pairing.takeCan(event, d.direction, d.openAs, timeNs);
    } else {
        out = m_pairing.take(event, timeNs);
    }
    if (out.unanswered)
        m_collector.unanswered(*out.unanswered);
    for (const protocol::Frame &f : std::as_const(out.unansweredInGroup)) // no detach per frame
        m_collector.unanswered(f);
    if (out.role == bus::PassivePairing::Outcome::Role::Request)
        m_collector.request(event.frame);
    else if (out.role == bus::PassivePairing::Outcome::Role::Reply)
        m_collector.reply(event.frame, out.request, out.latencyNs);
}

bus::ListenStatistics ReplayStatistics::snapshot(qint64 timeNs)
{
    if (const std::optional<protocol::Frame> late = m_pairing.expire(timeNs))
        m_collector.unanswered(*late);
    const QVector<protocol::Frame> expired = m_pairing.expireGroup(timeNs);
    for (const protocol::Frame &f : expired)
        m_collector.unanswered(f);
    m_lastSnapshotNs = timeNs;
    return m_collector.snapshot(static_cast<double>(timeNs - m_startNs) * 1e-9, m_baud,
                                m_pairing.counts());
}

} // namespace lk::recording
