#include "StopTargets.h"

#include <protocol/Checksum.h>

#include <algorithm>

namespace lk::bus {

StopTargets StopTargets::of(const QVector<int> &priority, const QList<int> &known)
{
    StopTargets t;
    for (const QList<int> &ids : {priority, known}) {
        for (int id : ids) {
            if (id >= protocol::kMinId && id <= protocol::kMaxId)
                t.first.append(id);
        }
    }
    std::sort(t.first.begin(), t.first.end());
    t.first.erase(std::unique(t.first.begin(), t.first.end()), t.first.end());
    for (int id = protocol::kMinId; id <= protocol::kMaxId; ++id) {
        if (!std::binary_search(t.first.cbegin(), t.first.cend(), id))
            t.others.append(id);
    }
    return t;
}

} // namespace lk::bus
