#include "StopTargets.h"

#include <protocol/Checksum.h>

#include <algorithm>
#include <array>

namespace lk::bus {

namespace {
/// The valid IDs of `ids` not in `taken`, ascending, each once; they join `taken`.
QVector<int> tier(const QList<int> &ids, std::array<bool, protocol::kMaxId + 1> &taken)
{
    QVector<int> out;
    for (int id : ids) {
        if (id >= protocol::kMinId && id <= protocol::kMaxId && !taken[id]) {
            taken[id] = true;
            out.append(id);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}
} // namespace

StopTargets StopTargets::of(const QVector<int> &urgent, const QList<int> &known)
{
    std::array<bool, protocol::kMaxId + 1> taken{};
    StopTargets t;
    t.first = tier(urgent, taken); // before `known`'s tier: it takes the urgent ones first
    t.first += tier(known, taken);
    for (int id = protocol::kMinId; id <= protocol::kMaxId; ++id) {
        if (!taken[id])
            t.others.append(id);
    }
    return t;
}

} // namespace lk::bus
