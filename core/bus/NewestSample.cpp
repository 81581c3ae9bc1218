#include "NewestSample.h"

namespace lk::bus {

const TelemetrySample *newestSample(const TelemetryBatch &batch, int id, TelemetryField field)
{
    for (auto it = batch.crbegin(); it != batch.crend(); ++it) {
        if (it->id == id && it->has(field))
            return &*it;
    }
    return nullptr;
}

} // namespace lk::bus
