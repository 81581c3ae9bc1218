#include "TelemetryStore.h"

#include <limits>

namespace lk::ui {

TelemetryStore::TelemetryStore(QObject *parent) : TelemetryStore(kDefaultCapacity, parent) {}

TelemetryStore::TelemetryStore(qsizetype capacityPerChannel, QObject *parent)
    : QObject(parent), m_capacity(std::max<qsizetype>(1, capacityPerChannel))
{
    m_notify.setSingleShot(true);
    m_notify.setInterval(0);
    connect(&m_notify, &QTimer::timeout, this, &TelemetryStore::dataAppended);
}

TelemetryStore::~TelemetryStore() = default;

void TelemetryStore::append(const lk::bus::TelemetryBatch &batch)
{
    if (batch.isEmpty()) {
        return;
    }
    for (const lk::bus::TelemetrySample &sample : batch) {
        appendSample(sample);
    }
    ++m_revision;
    if (!m_notify.isActive()) {
        m_notify.start();
    }
}

void TelemetryStore::appendSample(const lk::bus::TelemetrySample &sample)
{
    Drive &drive = m_drives[sample.id];
    m_cycles.add(sample);
    const QVector<lk::bus::TelemetryFieldInfo> &rows = lk::bus::TelemetryFieldInfo::all();
    // Every column of the table the sample carries, without a list per sample: a replay's
    // "Load all" puts millions of samples through here.
    for (int column = 0; column < rows.size(); ++column) {
        if (!sample.fields.testFlag(rows.at(column).field)) {
            continue;
        }
        const std::optional<TelemetryChannel> channel = channelOfColumn(column);
        if (!channel) {
            continue; // not plotted
        }
        int &recorded = drive.columns[size_t(*channel)];
        if (recorded >= 0 && recorded != column) {
            // iq and power share Torque: the old points would be read in the new unit.
            drive.rings[size_t(*channel)].reset();
        }
        recorded = column;
        put(drive, *channel, sample.time, rows.at(column).value(sample));
    }
}

void TelemetryStore::put(Drive &drive, TelemetryChannel channel, double time, double value)
{
    auto &ring = drive.rings[size_t(channel)];
    if (!ring) {
        ring = std::make_unique<SampleRing>(m_capacity, kRetainSeconds);
    }
    if (!ring->append(time, value)) {
        ++m_rejected;
    }
}

void TelemetryStore::breakLines()
{
    for (auto &entry : m_drives) {
        for (auto &ring : entry.second.rings) {
            if (ring) {
                ring->breakLine();
            }
        }
    }
}

void TelemetryStore::clear()
{
    m_drives.clear();
    m_cycles.clear();
    ++m_revision;
    m_notify.stop();
    emit cleared();
}

QVector<int> TelemetryStore::driveIds() const
{
    QVector<int> ids;
    ids.reserve(qsizetype(m_drives.size()));
    for (const auto &entry : m_drives) {
        ids.append(entry.first);
    }
    return ids;
}

std::optional<bool> TelemetryStore::torqueIsPower(int id) const
{
    const auto it = m_drives.find(id);
    if (it == m_drives.end()) {
        return std::nullopt;
    }
    const int column = it->second.columns[size_t(TelemetryChannel::Torque)];
    if (column < 0) {
        return std::nullopt;
    }
    return column == channelColumn(TelemetryChannel::Torque, true);
}

const SampleRing *TelemetryStore::ring(int id, TelemetryChannel channel) const
{
    const auto it = m_drives.find(id);
    return it == m_drives.end() ? nullptr : it->second.rings[size_t(channel)].get();
}

qsizetype TelemetryStore::count(int id, TelemetryChannel channel) const
{
    const SampleRing *r = ring(id, channel);
    return r ? r->size() : 0;
}

std::optional<TimeSpan> TelemetryStore::timeSpan() const
{
    TimeSpan span{std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity()};
    for (const auto &entry : m_drives) {
        for (const auto &ring : entry.second.rings) {
            if (ring && !ring->isEmpty()) {
                span.begin = std::min(span.begin, ring->timeAt(0));
                span.end = std::max(span.end, ring->timeAt(ring->size() - 1));
            }
        }
    }
    if (span.begin > span.end) {
        return std::nullopt;
    }
    return span;
}

std::optional<double> TelemetryStore::valueAt(int id, TelemetryChannel channel, double time) const
{
    const SampleRing *r = ring(id, channel);
    if (!r) {
        return std::nullopt;
    }
    const qsizetype after = r->upperBound(time);
    if (after == 0 || r->inGap(time)) {
        return std::nullopt;
    }
    return r->valueAt(after - 1);
}

LineSegments TelemetryStore::decimated(int id, TelemetryChannel channel, double t0, double t1,
                                       int columns, DecimationMethod method) const
{
    const SampleRing *r = ring(id, channel);
    return r ? r->decimate(t0, t1, columns, method) : LineSegments{};
}

QVector<TimeSpan> TelemetryStore::outages(int id, TelemetryChannel channel, double t0,
                                          double t1) const
{
    QVector<TimeSpan> out;
    if (const SampleRing *r = ring(id, channel)) {
        for (const SampleGap &g : r->gaps(t0, t1)) {
            out.append(TimeSpan{g.from, g.to});
        }
    }
    return out;
}

} // namespace lk::ui
