#pragma once

#include "TrafficEvent.h"

#include <QtCore/QMetaType>

#include <array>

namespace lk::bus {

/// How many traffic events of each kind were seen: what a traffic log counts, the rows it
/// still shows and the rows it had to drop alike.
struct TrafficCounts {
    static constexpr int kParseErrorKinds = 6; ///< protocol::ParseError values
    std::array<quint64, kParseErrorKinds> faults{};
    quint64 timeouts = 0;
    quint64 sent = 0;
    quint64 frames = 0;
    quint64 events = 0; ///< every event counted, notes included

    void add(const TrafficEvent &event);
    void add(const TrafficBatch &batch);
    TrafficCounts &operator+=(const TrafficCounts &other);
    quint64 faultTotal() const;
};

} // namespace lk::bus

Q_DECLARE_METATYPE(lk::bus::TrafficCounts)
