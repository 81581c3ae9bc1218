#include "ReplayDecoder.h"

#include "RecordedFrameParser.h"
#include <bus/HeardMultiTorque.h>
#include <bus/PassivePairing.h>
#include <protocol/Reply.h>
#include <protocol/Request.h>

#include <QtCore/QThreadPool>

#include <optional>
#include <utility>

namespace lk::recording {

using lk::recording::RecordEvent;

ReplayDecoder::ReplayDecoder(QObject *parent) : QObject(parent) {}

ReplayDecoder::~ReplayDecoder() = default;

bool ReplayDecoder::open(const QString &path, ReplayTransport::Options options, QString *error)
{
    close();
    auto transport = std::make_unique<ReplayTransport>(path, std::move(options));
    QString failure;
    const auto failed =
        connect(transport.get(), &transport::Transport::errorOccurred, this,
                [&failure](const transport::TransportError &e) { failure = e.message; });
    transport->setChunkHandler(
        [this](const QByteArray &bytes, bool transmitted) { onBytes(bytes, transmitted); });
    // Direct: a worker playing the transport (Load all) must decode on its own thread.
    connect(transport.get(), &ReplayTransport::recordPlayed, this, &ReplayDecoder::onRecord,
            Qt::DirectConnection);
    connect(transport.get(), &ReplayTransport::batchPlayed, this, &ReplayDecoder::handOnBatch,
            Qt::DirectConnection);
    connect(
        transport.get(), &ReplayTransport::finished, this,
        [this] {
            emitStatistics(); // the figures at the end
            emit finished();
        },
        Qt::DirectConnection);
    m_seen.clear();
    m_context.clear();
    m_contextsValid = false;
    m_known.clear();
    m_traffic.clear(); // a batch cut short by a close belongs to no file
    m_trafficCounts = {};
    m_telemetry.clear();
    m_keepTail = false;
    m_tail.clear();
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
    m_link = linkOf(m_transport->header());
    m_statistics.restart(m_link, m_transport->header().baud, 0);
    restartParser();
    setContext(m_transport->header().context);
    emitStatistics();
    return true;
}

void ReplayDecoder::close()
{
    if (m_transport)
        m_transport->close();
    m_transport.reset();
    m_path.clear();
    m_traffic.clear();
    m_trafficCounts = {};
    m_telemetry.clear();
    m_keepTail = false;
    m_tail.clear();
    m_loadingAll = false;
    m_statisticsHeld = false;
}

void ReplayDecoder::beginLoadAll(qsizetype trafficRowsKept)
{
    m_loadingAll = true;
    m_statisticsClock.start();
    keepTrafficTail(trafficRowsKept);
    // An hour drops millions of rows, each freed long after it was built: a cache miss per
    // byte array, an eighth of the decoding thread's time. Freed on another thread instead.
    if (!m_disposal) {
        m_disposal = std::make_unique<QThreadPool>();
        m_disposal->setMaxThreadCount(1);
    }
    m_tail.setDisposal([this](bus::TrafficBatch &&rows) {
        if (m_disposalsQueued.load() >= kDisposalsQueued) {
            rows = {}; // the disposal lags: freed here rather than queued without bound
            return;
        }
        ++m_disposalsQueued;
        m_disposal->start([this, rows = std::move(rows)]() mutable {
            rows = {};
            --m_disposalsQueued;
        });
    });
    if (m_transport)
        m_transport->setReadAhead(true);
}

void ReplayDecoder::endLoadAll()
{
    if (m_transport)
        m_transport->setReadAhead(false);
    m_tail.setDisposal({});
    if (m_disposal)
        m_disposal->waitForDone(); // the memory is back when the load is over
    releaseTrafficTail();
    m_loadingAll = false;
    if (m_statisticsHeld)
        emitStatistics(); // where it stopped (at the end, the finished one was sent already)
}

void ReplayDecoder::keepTrafficTail(qsizetype rows)
{
    m_keepTail = rows > 0;
    m_tail.setLimit(rows);
    m_trafficCounts = {};
    if (m_keepTail)
        m_trafficCounts.add(m_traffic); // rows of the batch under way, if any
}

void ReplayDecoder::releaseTrafficTail()
{
    m_keepTail = false;
    m_trafficCounts = {};
    const bus::TrafficCounts dropped = m_tail.takeDropped();
    bus::TrafficBatch rows = m_tail.takeRows();
    if (dropped.events > 0)
        emit trafficDropped(dropped);
    if (!rows.isEmpty())
        emit trafficCaptured(rows);
}

RecordingError ReplayDecoder::damage() const
{
    return m_transport ? m_transport->damage() : RecordingError{};
}

double ReplayDecoder::durationSeconds() const
{
    return m_transport ? double(m_transport->durationNs()) * 1e-9 : 0;
}

double ReplayDecoder::positionSeconds() const
{
    return m_transport ? double(m_transport->positionNs()) * 1e-9 : 0;
}

bool ReplayDecoder::isPaused() const
{
    return m_transport && m_transport->isPaused();
}

bool ReplayDecoder::isFinished() const
{
    return !m_transport || m_transport->isFinished();
}

double ReplayDecoder::speed() const
{
    return m_transport ? m_transport->speed() : 1.0;
}

void ReplayDecoder::play()
{
    if (m_transport)
        m_transport->play();
}

void ReplayDecoder::pause()
{
    if (m_transport)
        m_transport->pause();
}

void ReplayDecoder::setSpeed(double speed)
{
    if (m_transport)
        m_transport->setSpeed(speed);
}

void ReplayDecoder::seek(double seconds)
{
    if (!m_transport)
        return;
    restartParser(); // a frame cut by the jump is no frame
    handOnRows();    // what came before the jump, before what comes after it
    m_transport->seek(qint64(seconds * 1e9));
    // The figures count from the new place: what came before it is not heard again.
    m_statistics.restart(m_link, m_transport->header().baud, positionNs());
    emitStatistics();
    emit positionChanged(positionSeconds());
}

bool ReplayDecoder::playNextBatch()
{
    return m_transport && m_transport->playNextBatch();
}

qint64 ReplayDecoder::positionNs() const
{
    return m_transport ? m_transport->positionNs() : 0;
}

void ReplayDecoder::emitStatistics()
{
    m_statisticsHeld = false;
    if (m_transport)
        emit listenStatisticsUpdated(m_statistics.snapshot(positionNs()));
}

void ReplayDecoder::setContext(const ContextSnapshot &context)
{
    m_context = context;
    m_contextsValid = false;
    for (const DriveContext &d : context) {
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

void ReplayDecoder::learnModel(const protocol::Reply &reply)
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

void ReplayDecoder::onRecord(const RecordEvent &record)
{
    if (record.kind == RecordEvent::Kind::Context)
        setContext(record.context);
    else if (record.kind == RecordEvent::Kind::Link) {
        restartParser(); // a reopened link starts a new stream
        m_statistics.newStream();
    }
}

void ReplayDecoder::restartParser()
{
    m_parser = protocol::makeFrameParser(m_link, protocol::LinkEnd::Host);
    m_statistics.attach(*m_parser,
                        [this](const protocol::CanRecord &record) { takeOtherFrame(record); });
}

protocol::DecodeContext ReplayDecoder::contextOf(int id) const
{
    // Asked a few times per frame: a table rebuilt when the context changes, not a search.
    if (id < 0 || id >= int(m_contexts.size())) // no frame carries such an ID
        return decodeContextOf(m_context, id, m_link);
    if (!m_contextsValid) {
        for (size_t i = 0; i < m_contexts.size(); ++i)
            m_contexts[i] = decodeContextOf(m_context, int(i), m_link);
        m_contextsValid = true;
    }
    return m_contexts[size_t(id)];
}

void ReplayDecoder::takeCommand(const protocol::Frame &frame)
{
    const protocol::RequestDecodeResult dec = protocol::decodeRequest(frame, contextOf(frame.id));
    if (dec.request)
        takeCommand(*dec.request);
}

void ReplayDecoder::takeCommand(const protocol::Request &request)
{
    // Live, a listen-only session samples another master's commands (bus::ListenMonitor); the
    // tool's own commands are no samples, in a session or in its replay.
    std::optional<protocol::Series> series;
    for (const DriveContext &d : m_context) {
        if (d.id == request.id)
            series = d.series;
    }
    if (auto s = bus::TelemetrySample::fromRequest(request, series,
                                                   contextOf(request.id).generation, m_chunkTime))
        m_telemetry.append(std::move(*s));
}

void ReplayDecoder::takeOtherFrame(const protocol::CanRecord &record)
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
    addRow(std::move(row));
    QVector<protocol::Frame> torques;
    for (const bus::HeardMultiTorque::Slot &slot : *heard) {
        torques.append(slot.frame);
        if (!m_transmitted)
            takeCommand(slot.request);
    }
    m_statistics.takeMultiTorque(torques, qint64(m_chunkTime * 1e9));
}

void ReplayDecoder::onBytes(const QByteArray &bytes, bool transmitted)
{
    m_transmitted = transmitted;
    m_chunkTime = positionSeconds();
    if (!m_parser)
        return;
    m_statistics.addBytes(bytes.size());
    m_parser->feed(bytes, [this](const protocol::ParseEvent &e) { onFrame(e); });
}

void ReplayDecoder::addRow(bus::TrafficEvent &&row)
{
    if (m_keepTail)
        m_trafficCounts.add(row); // while the row is at hand, not when its batch is dropped
    m_traffic.append(std::move(row));
}

void ReplayDecoder::handOnRows()
{
    // The next batch is sized like this one: Load all's batches of thousands of rows then
    // grow no list row by row.
    if (!m_traffic.isEmpty()) {
        const qsizetype rows = m_traffic.size();
        if (m_keepTail)
            m_tail.append(std::exchange(m_traffic, {}), std::exchange(m_trafficCounts, {}));
        else
            emit trafficCaptured(std::exchange(m_traffic, {}));
        m_traffic.reserve(rows);
    }
    if (!m_telemetry.isEmpty()) {
        const qsizetype samples = m_telemetry.size();
        emit telemetryReceived(std::exchange(m_telemetry, {}));
        m_telemetry.reserve(samples);
    }
}

void ReplayDecoder::handOnBatch()
{
    handOnRows();
    if (m_statistics.snapshotDue(positionNs())) {
        if (!m_loadingAll || m_statisticsClock.elapsed() >= kLoadAllStatisticsMs) {
            emitStatistics();
            m_statisticsClock.restart();
        } else {
            m_statisticsHeld = true;
        }
    }
    emit positionChanged(positionSeconds());
}

void ReplayDecoder::onFrame(const protocol::ParseEvent &event)
{
    // On CAN the direction is told as a listener tells it: a copy of the event carries it.
    std::optional<protocol::ParseEvent> told;
    if (m_link == protocol::Link::Can && event.isFrame && !event.echoed) {
        told = event;
        told->direction =
            bus::PassivePairing::canDirections(*told, contextOf(told->frame.id)).direction;
        // As the live engine does: the reply's ID or layout names the generation it decodes with.
        if (told->direction != protocol::FrameDirection::Request &&
            learnCanGeneration(m_context, *told))
            setContext(m_context);
    }
    const protocol::ParseEvent &e = told ? *told : event;
    m_statistics.take(event, contextOf(e.frame.id), qint64(m_chunkTime * 1e9));
    bus::TrafficEvent row;
    row.time = m_chunkTime;
    row.bytes = e.bytes;
    if (!e.isFrame) {
        row.kind = bus::TrafficEvent::Kind::Fault;
        row.error = e.error;
        addRow(std::move(row));
        return;
    }
    const protocol::DecodeContext context = contextOf(e.frame.id);
    row.kind = bus::TrafficEvent::Kind::Frame;
    row.id = e.frame.id;
    row.command = e.frame.command;
    row.frame = e.frame;
    row.context = context;
    addRow(std::move(row));
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

} // namespace lk::recording
