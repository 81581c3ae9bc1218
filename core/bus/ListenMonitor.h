#pragma once

#include "BusClock.h"
#include "ListenStatistics.h"
#include "ListenStatisticsCollector.h"
#include "PassivePairing.h"
#include "ReplyIntake.h"

#include <protocol/CanRecord.h>
#include <protocol/FrameParser.h>

#include <QtCore/QByteArray>
#include <QtCore/QObject>

#include <memory>

namespace lk::bus {

class BusDiagnostics;

/// The passive side of a listen-only session, on the bus thread: takes the bytes another
/// master and its drives put on the bus (both directions on one stream), pairs requests with
/// replies (PassivePairing), and makes of them what an active session makes of its own:
/// observed replies go through the same ReplyIntake (drives appear, generation and series are
/// learnt, telemetry samples into the same batcher), the other master's commands become
/// commanded-value samples (TelemetrySample::fromRequest), frames reach the traffic capture,
/// and ListenStatistics counts what that master does. On CAN the link's records are parsed
/// (CanRecordParser), the reply ID and layout tell requests from replies
/// (PassivePairing::canDirections), a reply names its drive's generation
/// (can::generationHint), error frames are counted, and another master's multi-motor torque
/// frame (0x280) is a torque command to each known drive of the old generation it names,
/// paired with their 0xA1 replies.
class ListenMonitor : public QObject {
    Q_OBJECT
public:
    ListenMonitor(MotorRegistry &motors, TelemetryBatcher &telemetry, BusDiagnostics &diagnostics,
                  std::shared_ptr<BusClock> clock, QObject *parent = nullptr);

    /// A new byte stream on `link` (the link opened): the link's frame parser, no partial
    /// frame, no open request.
    void restart(protocol::Link link);
    /// Bytes from the link, at the link's `baud` (it sets the silence that ends a pairing).
    /// `ours`: a replayed recording's bytes its tool sent. They pair and count as any, but
    /// their commands are no commanded-value samples, as in the session that sent them.
    void feed(const QByteArray &bytes, int baud, bool ours = false);
    /// The statistics now (rates since the last call); also ends a request whose reply can no
    /// longer come (silence).
    ListenStatistics snapshot(int baud);
    /// Slack on the reply window for the adapter's latency (PassivePairing::setSlackS).
    void setSlackS(double slackS) { m_pairing.setSlackS(slackS); }
    const PassivePairing::Counts &counts() const { return m_pairing.counts(); }

signals:
    /// The drives known changed (a drive seen for the first time, its model or generation).
    void motorsChanged();

private:
    double now() const { return static_cast<double>(m_clock->nowNs()) * 1e-9; }
    void onEvent(const protocol::ParseEvent &event, qint64 nowNs);
    PassivePairing::Outcome pair(const protocol::ParseEvent &event, qint64 nowNs);
    void noteCanGeneration(const protocol::ParseEvent &event);
    void takeRequest(const protocol::Frame &frame, double time);
    void takeReply(const protocol::Frame &frame, const std::optional<protocol::Frame> &request,
                   double time);
    void noteUnanswered(const std::optional<protocol::Frame> &request);
    void noteUnanswered(const QVector<protocol::Frame> &requests);
    void takeMultiTorque(const protocol::CanRecord &record);

    MotorRegistry &m_motors;
    TelemetryBatcher &m_telemetry;
    BusDiagnostics &m_diagnostics;
    std::shared_ptr<BusClock> m_clock;
    ReplyIntake m_intake;
    protocol::Link m_link = protocol::Link::Rs485;
    std::unique_ptr<protocol::FrameParser> m_parser;
    PassivePairing m_pairing;
    ListenStatisticsCollector m_stats;
    qint64 m_feedNs = 0;     ///< when the chunk being parsed arrived
    bool m_feedOurs = false; ///< the chunk being parsed is one the recording's tool sent
};

} // namespace lk::bus
