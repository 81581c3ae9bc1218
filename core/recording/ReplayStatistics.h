#pragma once

#include <bus/ListenStatistics.h>
#include <bus/ListenStatisticsCollector.h>
#include <bus/PassivePairing.h>
#include <protocol/CanRecord.h>
#include <protocol/FrameParser.h>

#include <functional>

namespace lk::recording {

/// The statistics of a recording as it plays (bus::ListenStatistics, what lkstudio shows of
/// another master while listening): every frame paired as a listener pairs it
/// (bus::PassivePairing; on CAN with the direction the player told), counted by the listen
/// path's own collector, on the recording's clock. A replay hears the recording tool's own
/// requests and the drives' replies alike, so for an active recording the "master" counted is
/// the tool that recorded. restart() on a seek or a reopened link: the figures then count from
/// there. Pure, no clock of its own.
class ReplayStatistics {
public:
    /// How often snapshotDue() says yes, in the recording's time.
    static constexpr qint64 kPeriodNs = 500'000'000;

    /// A new stream on `link` at `baud` (bit rate on CAN): nothing counted, nothing open.
    void restart(protocol::Link link, int baud, qint64 timeNs);
    /// Sends `parser`'s CAN error frames and frames of no drive here (a CanRecordParser;
    /// others have neither); `otherFrame` then hears each frame of no drive (another master's
    /// multi-motor torque frame: takeMultiTorque).
    void attach(protocol::FrameParser &parser,
                std::function<void(const protocol::CanRecord &)> otherFrame = {});
    void addBytes(qsizetype n) { m_collector.addBytes(n); }
    /// The recorded link reopened: a request still open gets no reply from the new stream.
    void newStream() { m_pairing.reset(); }
    /// One parse event that passed at `timeNs`, its direction told (CAN) and decoded with
    /// `context`. Echoed frames are skipped: the Tx copy of the same frame counts.
    void take(const protocol::ParseEvent &event, const protocol::DecodeContext &context,
              qint64 timeNs);
    /// A multi-motor torque frame (CAN 0x280) at `timeNs`: the 0xA1 request each drive it names
    /// answers as (bus::HeardMultiTorque), each counted a request; their replies pair with
    /// them, and a drive still silent past its window is unanswered.
    void takeMultiTorque(const QVector<protocol::Frame> &torques, qint64 timeNs);
    /// Whether a period of the recording's time passed since the last snapshot.
    bool snapshotDue(qint64 timeNs) const { return timeNs - m_lastSnapshotNs >= kPeriodNs; }
    /// The figures at `timeNs` (rates since the last snapshot); a request whose reply can no
    /// longer come by then is counted unanswered.
    bus::ListenStatistics snapshot(qint64 timeNs);

private:
    bus::PassivePairing m_pairing;
    bus::ListenStatisticsCollector m_collector;
    protocol::Link m_link = protocol::Link::Rs485;
    int m_baud = 0;
    qint64 m_startNs = 0;
    qint64 m_lastSnapshotNs = 0;
};

} // namespace lk::recording
