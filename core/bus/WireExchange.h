#pragma once

#include "AdaptiveTimeout.h"
#include "BusClock.h"
#include "BusConfig.h"
#include "BusRequest.h"
#include "LinkTiming.h"
#include "QuietPeriod.h"
#include "RecentLatency.h"
#include "ReplyMatcher.h"
#include "SingleShotTimer.h"

#include <protocol/Checksum.h>
#include <protocol/FrameParser.h>
#include <protocol/Series.h>
#include <protocol/StreamParser.h>

#include <QtCore/QObject>

#include <functional>
#include <memory>
#include <optional>

namespace lk::bus {

class BusDiagnostics;
class MotorRegistry;
class TransportLink;

/// The one request on the half-duplex wire, on the bus thread: sends it, takes its reply out
/// of the byte stream (ReplyMatcher: by command and ID, local echo skipped, a late reply to an
/// earlier request counted and never taken for this one's answer), times it out
/// (AdaptiveTimeout), and after a timeout holds the wire quiet until a late reply can no
/// longer be on its way (QuietPeriod; BusWorker describes the rule). What is sent next, and
/// whether a failed attempt is tried again, is its owner's (BusWorker): each attempt ends
/// through one of Outcomes, with the request already off the wire.
class WireExchange : public QObject {
    Q_OBJECT
public:
    using Pending = PendingRequest;
    struct Outcomes {
        std::function<void(Pending p, protocol::Reply reply, double latencyS)> replied;
        /// No reply in time, or a corrupt or undecodable one.
        std::function<void(Pending p, RequestStatus status, const QString &reason)> failed;
        /// The quiet period's timer ran out: the wire may be free.
        std::function<void()> quietOver;
        /// CAN: a drive's frame told its generation (reply ID or 0x9A layout), before the
        /// frame is decoded, so that it decodes with it.
        std::function<void(int id, protocol::Generation generation)> generationSeen;
    };

    WireExchange(TransportLink &link, const MotorRegistry &motors, BusDiagnostics &diagnostics,
                 std::shared_ptr<BusClock> clock, const SingleShotTimerFactory &timers,
                 const BusConfig &config, QObject *parent = nullptr);
    ~WireExchange() override;

    void setOutcomes(Outcomes outcomes) { m_outcomes = std::move(outcomes); }
    void setConfig(const BusConfig &config);
    /// A new byte stream (the link opened): no partial frame, nothing old expected, and the
    /// frame parser of the link's kind (RS485 bytes or CAN records).
    void restartStream();
    /// Another baud: the latencies seen at the old one say nothing.
    void forgetLatencies()
    {
        m_recentLatency.clear();
        m_timeout.reset();
    }

    /// Puts `p` on the wire (the caller checked isBusy() and holdForQuiet()).
    void send(Pending p);
    /// Takes the request off the wire without an outcome (cancelled, disconnected).
    std::optional<Pending> abort();
    /// Bytes from the link. True when they were the late reply the quiet period waited for,
    /// whole and with nothing after it: the wire is free again.
    bool feed(const QByteArray &bytes);
    /// Whether transmissions must wait now (the quiet period); arms its timer if so.
    bool holdForQuiet();
    /// An emergency stop waits: the request on the wire, or the quiet period after one that
    /// got no reply, holds the wire only until that reply could no longer be on it (wire time
    /// and turnaround from its send), not for the margin a slow link or a late reply earned.
    /// Bytes that do arrive still hold it (QuietPeriod). The caller pumps afterwards.
    void hurry();
    /// Stops both timers (the bus is shut down).
    void stop();

    bool isBusy() const { return m_inflight.has_value(); }
    /// The request on the wire (null: none), e.g. to keep it from being sent again.
    Pending *inflight() { return m_inflight ? &*m_inflight : nullptr; }
    bool isQuiet() const { return m_quiet.isQuiet(m_clock->nowNs()); }
    const AdaptiveTimeout &timeouts() const { return m_timeout; }
    /// When the latest-sent request that got a late reply went out (session clock, seconds;
    /// -1: none yet).
    double lateRequestSentTime() const { return m_lateRequestSentS; }

private:
    int baud() const;
    LinkTiming timing() const;
    double now() const { return static_cast<double>(m_clock->nowNs()) * 1e-9; }
    /// How soon after a send a reply can physically arrive (for the matcher), nanoseconds.
    qint64 earliestReplyNs(protocol::Command command) const;
    void onTimeout();
    void onParseEvent(const protocol::ParseEvent &ev);
    /// CAN: what a drive's frame says about its generation, passed on (Outcomes).
    void noteCanGeneration(const protocol::ParseEvent &ev);
    /// A multi-motor frame on the wire (BusRequest::group): `ev` is the 0xA1 reply of one of
    /// its drives still to answer: taken (true); once all answered, the frame is replied.
    bool takeGroupReply(const protocol::ParseEvent &ev);
    /// The drives of the multi-motor frame on the wire that have not answered yet.
    QVector<int> silentInGroup() const;
    /// `frameBytes`: the reply's length on the wire.
    void takeReply(protocol::Reply reply, int frameBytes);
    /// The request on the wire timed out: hold transmissions until its reply cannot come.
    /// `probe`: it had the short first timeout of a probe (BusRequest::firstTimeoutS);
    /// `emergency`: it was an emergency stop's (only the wire's own time is waited for).
    void beginQuiet(const protocol::Request &request, bool probe, bool emergency);
    /// When the reply to `command` sent at m_sentNs has left the wire at the latest, for a
    /// drive that keeps its turnaround (worker clock).
    qint64 wireFreeNs(protocol::Command command) const;
    void fail(RequestStatus status, const QString &reason);

    TransportLink &m_link;
    const MotorRegistry &m_motors;
    BusDiagnostics &m_diagnostics;
    std::shared_ptr<BusClock> m_clock;
    Outcomes m_outcomes;
    std::unique_ptr<protocol::FrameParser> m_parser;
    std::optional<Pending> m_inflight;
    qint64 m_sentNs = 0;
    qint64 m_deadlineNs = 0; ///< when the reply timer fires for the request on the wire
    bool m_hurried = false;  ///< hurry() cut the request on the wire short
    ReplyMatcher m_matcher;
    AdaptiveTimeout m_timeout;
    RecentLatency m_recentLatency;
    QuietPeriod m_quiet; ///< on the worker clock
    double m_lateRequestSentS = -1;
    std::unique_ptr<SingleShotTimer> m_replyTimer;
    std::unique_ptr<SingleShotTimer> m_quietTimer;
    qint64 m_quietTimerDueNs = 0; ///< when the running quiet timer fires (worker clock)
};

} // namespace lk::bus
