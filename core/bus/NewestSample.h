#pragma once

#include "TelemetrySample.h"

namespace lk::bus {

/// The newest sample of drive `id` in `batch` that carries `field`, or null: a batch is in
/// arrival order, and a view that shows a drive's present state wants only its last word.
const TelemetrySample *newestSample(const TelemetryBatch &batch, int id, TelemetryField field);

} // namespace lk::bus
