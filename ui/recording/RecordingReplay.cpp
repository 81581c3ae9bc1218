#include "RecordingReplay.h"

#include <bus/HeardMultiTorque.h>
#include <bus/PassivePairing.h>
#include <protocol/Reply.h>
#include <protocol/Request.h>
#include <recording/RecordedFrameParser.h>

#include <utility>

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
    connect(transport.get(), &recording::ReplayTransport::chunkPlayed, this,
            &RecordingReplay::onBytes);
    connect(transport.get(), &recording::ReplayTransport::recordPlayed, this,
            &RecordingReplay::onRecord);
    connect(transport.get(), &recording::ReplayTransport::batchPlayed, this,
            &RecordingReplay::handOnBatch);
    connect(transport.get(), &recording::ReplayTransport::finished, this, [this] {
        emitStatistics(); // the figures at the end
        emit finished();
    });
    m_seen.clear();
    m_context.clear();
    m_known.clear();
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
    m_statistics.restart(m_link, m_transport->header().baud, 0);
    restartParser();
    setContext(m_transport->header().context);
    emitStatistics();
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
    // The figures count from the new place: what came before it is not heard again.
    m_statistics.restart(m_link, m_transport->header().baud, positionNs());
    emitStatistics();
    emit positionChanged(positionSeconds());
}

void RecordingReplay::loadAll()
{
    if (m_transport)
        m_transport->setFastForward(true);
}

qint64 RecordingReplay::positionNs() const
{
    return m_transport ? m_transport->positionNs() : 0;
}

void RecordingReplay::emitStatistics()
{
    if (m_transport)
        emit listenStatisticsUpdated(m_statistics.snapshot(positionNs()));
}

void RecordingReplay::setContext(const recording::ContextSnapshot &context)
{
    m_context = context;
    for (const recording::DriveContext &d : context) {
        if (!m_seen.contains(d.id))
            m_seen.append(d.id);
        bus::KnownMotor &m = m_known[d.id];
        m.id = d.id;
        if (d.series)
            m.series = d.series;
        m.generation = m.model ? m.model->generation : d.generation;
        m.generationSeen = true; // the recording says it: the session knew it then
        m.identityChosen = d.chosen;
    }
    handOnRows(); // what came before the change reaches the views first
    emit drivesChanged(context);
    emit knownMotorsChanged(m_known);
}

void RecordingReplay::learnModel(const protocol::Reply &reply)
{
    const auto *model = std::get_if<protocol::ModelInfo>(&reply.payload);
    if (!model)
        return;
    bus::KnownMotor &m = m_known[reply.id];
    if (m.model && m.model->motorName == model->motorName &&
        m.model->driverName == model->driverName && m.model->firmwareRaw == model->firmwareRaw)
        return;
    m.id = reply.id;
    m.model = *model;
    m.generation = model->generation;
    handOnRows();
    emit knownMotorsChanged(m_known);
}

void RecordingReplay::onRecord(const RecordEvent &record)
{
    if (record.kind == RecordEvent::Kind::Context)
        setContext(record.context);
    else if (record.kind == RecordEvent::Kind::Link) {
        restartParser(); // a reopened link starts a new stream
        m_statistics.newStream();
    }
}

void RecordingReplay::restartParser()
{
    m_parser = protocol::makeFrameParser(m_link, protocol::LinkEnd::Host);
    m_statistics.attach(*m_parser,
                        [this](const protocol::CanRecord &record) { takeOtherFrame(record); });
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

void RecordingReplay::takeCommand(const protocol::Frame &frame)
{
    const protocol::RequestDecodeResult dec = protocol::decodeRequest(frame, contextOf(frame.id));
    if (dec.request)
        takeCommand(*dec.request);
}

void RecordingReplay::takeCommand(const protocol::Request &request)
{
    // Live, a listen-only session samples another master's commands (bus::ListenMonitor); the
    // tool's own commands are no samples, in a session or in its replay.
    std::optional<protocol::Series> series;
    for (const recording::DriveContext &d : m_context) {
        if (d.id == request.id)
            series = d.series;
    }
    if (auto s = bus::TelemetrySample::fromRequest(request, series,
                                                   contextOf(request.id).generation, m_chunkTime))
        m_telemetry.append(std::move(*s));
}

void RecordingReplay::takeOtherFrame(const protocol::CanRecord &record)
{
    // As the live listener does (bus::ListenMonitor): each drive seen so far on the old
    // generation takes its slot as a torque command and answers it as a 0xA1.
    const auto heard = bus::HeardMultiTorque::decode(
        record, [this](int id) -> std::optional<protocol::DecodeContext> {
            if (!m_seen.contains(id))
                return std::nullopt;
            return contextOf(id);
        });
    if (!heard)
        return;
    bus::TrafficEvent row;
    row.kind = bus::TrafficEvent::Kind::Frame; // as onFrame shows every recorded frame
    row.time = m_chunkTime;
    row.bytes = record.encode();
    row.context.link = m_link; // TrafficModel reads the slots from the record
    m_traffic.append(std::move(row));
    QVector<protocol::Frame> torques;
    for (const bus::HeardMultiTorque::Slot &slot : *heard) {
        torques.append(slot.frame);
        if (!m_transmitted)
            takeCommand(slot.request);
    }
    m_statistics.takeMultiTorque(torques, qint64(m_chunkTime * 1e9));
}

void RecordingReplay::onBytes(const QByteArray &bytes, bool transmitted)
{
    m_transmitted = transmitted;
    m_chunkTime = positionSeconds();
    if (!m_parser)
        return;
    m_statistics.addBytes(bytes.size());
    m_parser->feed(bytes, [this](const protocol::ParseEvent &e) { onFrame(e); });
}

void RecordingReplay::handOnRows()
{
    if (!m_traffic.isEmpty())
        emit trafficCaptured(std::exchange(m_traffic, {}));
    if (!m_telemetry.isEmpty())
        emit telemetryReceived(std::exchange(m_telemetry, {}));
}

void RecordingReplay::handOnBatch()
{
    handOnRows();
    if (m_statistics.snapshotDue(positionNs()))
        emitStatistics();
    emit positionChanged(positionSeconds());
}

void RecordingReplay::onFrame(const protocol::ParseEvent &event)
{
    protocol::ParseEvent e = event;
    if (m_link == protocol::Link::Can && e.isFrame && !e.echoed) {
        e.direction = bus::PassivePairing::canDirections(e, contextOf(e.frame.id)).direction;
        // As the live engine does: the reply's ID or layout names the generation it decodes with.
        if (e.direction != protocol::FrameDirection::Request &&
            recording::learnCanGeneration(m_context, e))
            setContext(m_context);
    }
    m_statistics.take(event, contextOf(e.frame.id), qint64(m_chunkTime * 1e9));
    bus::TrafficEvent row;
    row.time = m_chunkTime;
    row.bytes = e.bytes;
    if (!e.isFrame) {
        row.kind = bus::TrafficEvent::Kind::Fault;
        row.error = e.error;
        m_traffic.append(std::move(row));
        return;
    }
    const protocol::DecodeContext context = contextOf(e.frame.id);
    row.kind = bus::TrafficEvent::Kind::Frame;
    row.id = e.frame.id;
    row.command = e.frame.command;
    row.frame = e.frame;
    row.context = context;
    m_traffic.append(std::move(row));
    if (e.direction == protocol::FrameDirection::Request && !m_transmitted && !e.echoed)
        takeCommand(e.frame);
    if (e.direction != protocol::FrameDirection::Reply)
        return;
    const auto reply = protocol::decodeReply(e.frame, context);
    if (!reply.reply)
        return;
    learnModel(*reply.reply);
    if (auto s = bus::TelemetrySample::fromReply(*reply.reply, m_chunkTime)) {
        if (!m_seen.contains(s->id)) {
            m_seen.append(s->id);
            handOnRows();
            emit driveSeen(s->id);
        }
        m_telemetry.append(std::move(*s));
    }
}

} // namespace lk::ui
