#include "RecordingReplay.h"

#include <bus/PassivePairing.h>
#include <protocol/Reply.h>
#include <recording/RecordedFrameParser.h>

namespace lk::ui {

using recording::RecordEvent;

RecordingReplay::RecordingReplay(QObject *parent) : QObject(parent) {}

RecordingReplay::~RecordingReplay() = default;

bool RecordingReplay::open(const QString &path, recording::ReplayTransport::Options options,
                           QString *error)
{
    close();
    auto transport = std::make_unique<recording::ReplayTransport>(path, std::move(options));
    QString failure;
    const auto failed =
        connect(transport.get(), &transport::Transport::errorOccurred, this,
                [&failure](const transport::TransportError &e) { failure = e.message; });
    connect(transport.get(), &transport::Transport::bytesReceived, this, &RecordingReplay::onBytes);
    connect(transport.get(), &recording::ReplayTransport::recordPlayed, this,
            &RecordingReplay::onRecord);
    connect(transport.get(), &recording::ReplayTransport::finished, this,
            &RecordingReplay::finished);
    m_seen.clear();
    m_context.clear();
    m_transport = std::move(transport);
    m_path = path;
    if (!m_transport->open()) {
        disconnect(failed);
        m_transport.reset();
        m_path.clear();
        if (error)
            *error = failure;
        return false;
    }
    disconnect(failed); // it writes to this call's local
    m_link = recording::linkOf(m_transport->header());
    restartParser();
    setContext(m_transport->header().context);
    return true;
}

void RecordingReplay::close()
{
    if (m_transport)
        m_transport->close();
    m_transport.reset();
    m_path.clear();
}

recording::RecordingError RecordingReplay::damage() const
{
    return m_transport ? m_transport->damage() : recording::RecordingError{};
}

double RecordingReplay::durationSeconds() const
{
    return m_transport ? double(m_transport->durationNs()) * 1e-9 : 0;
}

double RecordingReplay::positionSeconds() const
{
    return m_transport ? double(m_transport->positionNs()) * 1e-9 : 0;
}

bool RecordingReplay::isPaused() const
{
    return m_transport && m_transport->isPaused();
}

bool RecordingReplay::isFinished() const
{
    return !m_transport || m_transport->isFinished();
}

double RecordingReplay::speed() const
{
    return m_transport ? m_transport->speed() : 1.0;
}

void RecordingReplay::play()
{
    if (m_transport)
        m_transport->play();
}

void RecordingReplay::pause()
{
    if (m_transport)
        m_transport->pause();
}

void RecordingReplay::setSpeed(double speed)
{
    if (m_transport)
        m_transport->setSpeed(speed);
}

void RecordingReplay::seek(double seconds)
{
    if (!m_transport)
        return;
    restartParser(); // a frame cut by the jump is no frame
    m_transport->seek(qint64(seconds * 1e9));
    emit positionChanged(positionSeconds());
}

void RecordingReplay::loadAll()
{
    if (m_transport)
        m_transport->setFastForward(true);
}

void RecordingReplay::setContext(const recording::ContextSnapshot &context)
{
    m_context = context;
    for (const recording::DriveContext &d : context) {
        if (!m_seen.contains(d.id))
            m_seen.append(d.id);
    }
    emit drivesChanged(context);
}

void RecordingReplay::onRecord(const RecordEvent &record)
{
    if (record.kind == RecordEvent::Kind::Context)
        setContext(record.context);
    else if (record.kind == RecordEvent::Kind::Link)
        restartParser(); // a reopened link starts a new stream
}

void RecordingReplay::restartParser()
{
    m_parser = protocol::makeFrameParser(m_link, protocol::LinkEnd::Host);
}

protocol::DecodeContext RecordingReplay::contextOf(int id) const
{
    protocol::DecodeContext c;
    c.link = m_link;
    for (const recording::DriveContext &d : m_context) {
        if (d.id == id) {
            c.series = d.series.value_or(protocol::Series::MF);
            c.generation = d.generation;
        }
    }
    return c;
}

void RecordingReplay::onBytes(const QByteArray &bytes)
{
    const double time = positionSeconds();
    bus::TrafficBatch traffic;
    bus::TelemetryBatch telemetry;
    if (!m_parser)
        return;
    m_parser->feed(bytes,
                   [&](const protocol::ParseEvent &e) { onFrame(e, time, &traffic, &telemetry); });
    if (!traffic.isEmpty())
        emit trafficCaptured(traffic);
    if (!telemetry.isEmpty())
        emit telemetryReceived(telemetry);
    emit positionChanged(time);
}

void RecordingReplay::onFrame(const protocol::ParseEvent &event, double time,
                              bus::TrafficBatch *traffic, bus::TelemetryBatch *telemetry)
{
    protocol::ParseEvent e = event;
    if (m_link == protocol::Link::Can && e.isFrame && !e.echoed) {
        e.direction = bus::PassivePairing::canDirections(e, contextOf(e.frame.id)).direction;
        // As the live engine does: the reply's ID or layout names the generation it decodes with.
        if (e.direction != protocol::FrameDirection::Request &&
            recording::learnCanGeneration(m_context, e))
            emit drivesChanged(m_context);
    }
    bus::TrafficEvent row;
    row.time = time;
    row.bytes = e.bytes;
    if (!e.isFrame) {
        row.kind = bus::TrafficEvent::Kind::Fault;
        row.error = e.error;
        traffic->append(row);
        return;
    }
    const protocol::DecodeContext context = contextOf(e.frame.id);
    row.kind = bus::TrafficEvent::Kind::Frame;
    row.id = e.frame.id;
    row.command = e.frame.command;
    row.frame = e.frame;
    row.context = context;
    traffic->append(row);
    if (e.direction != protocol::FrameDirection::Reply)
        return;
    const auto reply = protocol::decodeReply(e.frame, context);
    if (!reply.reply)
        return;
    if (const auto s = bus::TelemetrySample::fromReply(*reply.reply, time)) {
        if (!m_seen.contains(s->id)) {
            m_seen.append(s->id);
            emit driveSeen(s->id);
        }
        telemetry->append(*s);
    }
}

} // namespace lk::ui
