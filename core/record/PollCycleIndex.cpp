#include "PollCycleIndex.h"

#include <algorithm>

namespace lk::record {

PollCycleIndex::PollCycleIndex(qsizetype capacity, double retainSeconds)
    : m_capacity(std::max<qsizetype>(1, capacity)), m_retainSeconds(retainSeconds)
{
}

void PollCycleIndex::add(const bus::TelemetrySample &sample)
{
    if (sample.cycle == 0) {
        return;
    }
    Drive &drive = m_drives[sample.id];
    if (!drive.entries.empty() && sample.time < drive.entries.back().time) {
        return; // out of order: the recording refuses it too
    }
    drive.commands.insert(int(sample.source));
    drive.entries.push_back({sample.time, {sample.cycle, sample.cycleTime}});
    // Every polled command answers once a round, so the last capacity x commands entries
    // hold the last `capacity` samples of each.
    const size_t bound = size_t(m_capacity) * size_t(drive.commands.size());
    const double oldest = sample.time - m_retainSeconds;
    while (drive.entries.size() > bound || drive.entries.front().time < oldest) {
        drive.entries.pop_front();
    }
}

std::optional<PollCycleIndex::Round> PollCycleIndex::find(int id, double time) const
{
    const auto drive = m_drives.find(id);
    if (drive == m_drives.end()) {
        return std::nullopt;
    }
    const std::deque<Entry> &entries = drive->second.entries;
    const auto it = std::lower_bound(entries.begin(), entries.end(), time,
                                     [](const Entry &e, double t) { return e.time < t; });
    if (it == entries.end() || it->time != time) {
        return std::nullopt;
    }
    return it->round;
}

void PollCycleIndex::clear()
{
    m_drives.clear();
}

} // namespace lk::record
