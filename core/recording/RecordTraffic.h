#pragma once

#include "RecordingFormat.h"

#include <bus/TrafficEvent.h>

namespace lk::recording {

/// Records as the Traffic view shows them: tx chunks parsed into Sent events, rx chunks into
/// Frame and Fault events (RecordedFrameParser), link events and drops as Notes; every frame
/// carries the decode context its ID had at that moment. `context`: the one in force before
/// the first record.
bus::TrafficBatch trafficEventsOf(const QVector<RecordEvent> &records, ContextSnapshot context);

} // namespace lk::recording
