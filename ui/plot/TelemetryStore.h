#pragma once

#include "SampleRing.h"
#include "TelemetryChannel.h"

#include <bus/TelemetrySample.h>
#include <record/PollCycleIndex.h>

#include <QtCore/QObject>
#include <QtCore/QTimer>
#include <QtCore/QVector>

#include <array>
#include <map>
#include <memory>
#include <optional>

namespace lk::ui {

/// A span of session time in seconds.
struct TimeSpan {
    double begin = 0;
    double end = 0;
    double length() const { return end - begin; }
};

/// Recorded telemetry of every drive (GUI thread): one fixed-capacity SampleRing per
/// (drive id, channel), created when the channel's first sample arrives, so memory follows
/// what is polled. A ring keeps kRetainSeconds (the longest plot window) at the rate its
/// points come, at most its capacity; then the oldest points are overwritten.
class TelemetryStore : public QObject {
    Q_OBJECT
public:
    static constexpr qsizetype kDefaultCapacity = 600000; ///< 10 minutes at 1 kHz
    static constexpr double kRetainSeconds = 600;         ///< the longest plot window

    explicit TelemetryStore(QObject *parent = nullptr);
    explicit TelemetryStore(qsizetype capacityPerChannel, QObject *parent = nullptr);
    ~TelemetryStore() override;

    /// Routes each value a sample carries to its drive's channel (channelOfColumn): iq, or
    /// power on MS drives (a sample carrying Power), both go to TelemetryChannel::Torque. A
    /// drive whose torque kind changes has its torque history dropped: its unit changed.
    void append(const lk::bus::TelemetryBatch &batch);
    /// Drops every drive and frees its memory.
    void clear();
    /// The link dropped: in every channel the next sample starts a new line segment, and the
    /// time in between is an outage.
    void breakLines();

    qsizetype capacity() const { return m_capacity; }
    QVector<int> driveIds() const; ///< ascending
    /// True when the drive's Torque channel holds power (MS); nullopt before its first
    /// torque sample.
    std::optional<bool> torqueIsPower(int id) const;
    /// nullptr when the drive never sent this channel.
    const SampleRing *ring(int id, TelemetryChannel channel) const;
    qsizetype count(int id, TelemetryChannel channel) const;
    /// Earliest and latest time held over all drives and channels; nullopt when empty.
    std::optional<TimeSpan> timeSpan() const;
    /// Value drawn at `time`: the last sample at or before it; nullopt before the first and
    /// inside a gap (nothing was measured then).
    std::optional<double> valueAt(int id, TelemetryChannel channel, double time) const;
    /// See SampleRing::decimate (one segment per stretch between gaps); empty when the drive
    /// never sent the channel.
    LineSegments decimated(int id, TelemetryChannel channel, double t0, double t1, int columns,
                           DecimationMethod method = DecimationMethod::Auto) const;
    /// The channel's outages overlapping [t0, t1] (gaps in its sample times), oldest first.
    QVector<TimeSpan> outages(int id, TelemetryChannel channel, double t0, double t1) const;

    /// Changes on every append or clear: a cheap "did anything change" check.
    quint64 revision() const { return m_revision; }
    /// The poll round of each recorded poll sample (CSV export writes a row per round).
    const lk::record::PollCycleIndex &pollCycles() const { return m_cycles; }
    /// Samples refused because their time ran backwards (or was not finite).
    quint64 rejectedSamples() const { return m_rejected; }

signals:
    /// New data arrived; emitted once per event-loop pass however many batches came.
    void dataAppended();
    void cleared();

private:
    struct Drive {
        Drive() { columns.fill(-1); }
        /// Per channel, the table row its ring holds (-1: none yet); Torque's changes with
        /// the drive's torque kind (iq or power).
        std::array<int, kTelemetryChannelCount> columns;
        std::array<std::unique_ptr<SampleRing>, kTelemetryChannelCount> rings;
    };
    void appendSample(const lk::bus::TelemetrySample &sample);
    void put(Drive &drive, TelemetryChannel channel, double time, double value);

    qsizetype m_capacity;
    std::map<int, Drive> m_drives;
    lk::record::PollCycleIndex m_cycles{m_capacity, kRetainSeconds};
    quint64 m_revision = 0;
    quint64 m_rejected = 0;
    QTimer m_notify; // zero-time single shot: coalesces dataAppended
};

} // namespace lk::ui
