#pragma once

#include <bus/TelemetrySample.h>

#include <QtCore/QSet>
#include <QtCore/QtGlobal>

#include <deque>
#include <limits>
#include <map>
#include <optional>

namespace lk::record {

/// Remembers which poll round each recorded poll sample answered, per drive, found again by
/// the sample's time: a recording that keeps only (time, value) points (lkstudio's
/// TelemetryStore) can still be exported one row per round. Samples that answer no poll are
/// not kept. Bounded: per drive it keeps the last `capacity` samples of each polled command,
/// as many as a ring of that capacity can still hold points of, and none older than
/// `retainSeconds` before the newest (the recording keeps that long at least).
class PollCycleIndex {
public:
    /// A poll round: its number and when it began.
    struct Round {
        quint64 cycle = 0;
        double time = 0;
    };

    explicit PollCycleIndex(qsizetype capacity,
                            double retainSeconds = std::numeric_limits<double>::infinity());

    void add(const bus::TelemetrySample &sample);
    /// The round of drive `id`'s poll sample taken at exactly `time`, or nullopt when no
    /// poll sample of that drive has that time (an operator's read, or forgotten).
    std::optional<Round> find(int id, double time) const;
    void clear();

private:
    struct Entry {
        double time;
        Round round;
    };
    struct Drive {
        std::deque<Entry> entries; // ascending time
        QSet<int> commands;        // the polled commands seen: the bound grows with them
    };
    qsizetype m_capacity;
    double m_retainSeconds;
    std::map<int, Drive> m_drives;
};

} // namespace lk::record
