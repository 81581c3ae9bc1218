#pragma once

#include "RecordedFrameParser.h"
#include "RecordingFormat.h"

#include <bus/TrafficEvent.h>

#include <optional>

namespace lk::recording {

/// Records as the Traffic view shows them: tx chunks parsed into Sent events, rx chunks into
/// Frame and Fault events (RecordedFrameParser), link events and drops as Notes; every frame
/// carries the decode context its ID had at that moment. `context`: the one in force before
/// the first record.
bus::TrafficBatch trafficEventsOf(const QVector<RecordEvent> &records, ContextSnapshot context);

/// The Traffic view's row of one parsed frame or fault of a recording (for a converter that
/// parses records as they come, RecordedFrameParser's sink).
bus::TrafficEvent trafficEventOf(const RecordedFrame &frame);
/// The Note row of a link event or a drop record; nullopt for any other record.
std::optional<bus::TrafficEvent> noteEventOf(const RecordEvent &record);

} // namespace lk::recording
