#include "SimBus.h"

#include "protocol/Checksum.h"
#include "protocol/Request.h"

namespace lk::sim {

SimBus::SimBus(const QString &romDirectory, quint32 seed) : m_rom(romDirectory), m_faults(seed) {}

SimBus::~SimBus() = default;

std::unique_ptr<SimBus> SimBus::fromSpec(const SimBusSpec &spec, const QString &romDirectory,
                                         quint32 seed)
{
    auto bus = std::make_unique<SimBus>(romDirectory, seed);
    for (const SimBusSpec::Entry &e : spec.drives)
        bus->addDrive(e.id, e.model);
    return bus;
}

SimDrive *SimBus::addDrive(int id, const SimDriveModel &model)
{
    if (id < protocol::kMinId || id > protocol::kMaxId || m_drives.count(id))
        return nullptr;
    const std::optional<SimRom> rom = m_rom.rom(id, model.series); // none: factory ROM
    auto drive = std::make_unique<SimDrive>(id, model, rom);
    drive->setRomWrittenHandler([this](int driveId, protocol::Series series, const SimRom &r) {
        m_rom.save(driveId, series, r);
    });
    SimDrive *raw = drive.get();
    m_drives.emplace(id, std::move(drive));
    return raw;
}

bool SimBus::removeDrive(int id)
{
    return m_drives.erase(id) > 0;
}

SimDrive *SimBus::drive(int id)
{
    const auto it = m_drives.find(id);
    return it == m_drives.end() ? nullptr : it->second.get();
}

const SimDrive *SimBus::drive(int id) const
{
    const auto it = m_drives.find(id);
    return it == m_drives.end() ? nullptr : it->second.get();
}

QList<int> SimBus::ids() const
{
    QList<int> out;
    for (const auto &entry : m_drives)
        out.append(entry.first);
    return out;
}

void SimBus::advanceTo(double nowSeconds)
{
    if (!m_clockStarted) {
        m_clockStarted = true;
        m_now = nowSeconds;
        return;
    }
    if (!(nowSeconds > m_now))
        return;
    const double dt = nowSeconds - m_now;
    m_now = nowSeconds;
    for (auto &entry : m_drives)
        entry.second->advance(dt);
}

void SimBus::restart()
{
    m_parser.reset();
    for (auto &entry : m_drives)
        entry.second->restart();
}

QList<SimReply> SimBus::receive(const char *data, qsizetype size, double nowSeconds)
{
    advanceTo(nowSeconds);
    QList<SimReply> out;
    m_parser.feed(data, size, [&](const protocol::ParseEvent &e) { onParseEvent(e, out); });
    return out;
}

void SimBus::onParseEvent(const protocol::ParseEvent &event, QList<SimReply> &out)
{
    if (!event.isFrame) {
        ++m_counters.parseErrors;
        return;
    }
    const protocol::RequestDecodeResult decoded = protocol::decodeRequest(event.frame);
    if (!decoded.request) {
        ++m_counters.notRequests;
        return;
    }
    dispatch(*decoded.request, out);
}

void SimBus::dispatch(const protocol::Request &request, QList<SimReply> &out)
{
    const int id = request.id;
    ++m_counters.requests;
    countRequest(id, request.command);

    SimDrive *target = drive(id);
    if (target && m_faults.isSilenced(id)) {
        m_faults.countSilenced();
        return;
    }
    const std::optional<protocol::Reply> reply = target ? target->handle(request) : std::nullopt;
    if (!reply) {
        ++m_counters.unanswered;
        return;
    }
    SimReply r;
    r.bytes = reply->encode();
    r.delaySeconds = m_replyDelay;
    r.id = id;
    r.command = request.command;
    if (request.command == protocol::Command::MultiPositionLimited &&
        target->generation() == protocol::Generation::V2_35)
        m_faults.applyFirmwareChecksumBug(r.bytes);
    if (!m_faults.apply(r.bytes, r.delaySeconds))
        return;
    ++m_counters.replies;
    out.append(r);
}

void SimBus::countRequest(int id, protocol::Command command)
{
    ++m_perId[id];
    ++m_perIdAndCommand[id << 8 | static_cast<quint8>(command)];
}

int SimBus::requestCount(int id) const
{
    return m_perId.value(id);
}

int SimBus::requestCount(int id, protocol::Command command) const
{
    return m_perIdAndCommand.value(id << 8 | static_cast<quint8>(command));
}

void SimBus::resetCounters()
{
    m_perId.clear();
    m_perIdAndCommand.clear();
    m_counters = SimBusCounters{};
    m_faults.resetCounts();
}

double SimBus::wireSeconds(qsizetype bytes, int baud)
{
    return baud > 0 ? static_cast<double>(bytes) * 10.0 / baud : 0.0;
}

} // namespace lk::sim
