#pragma once

#include "FaultInjector.h"
#include "SimBusSpec.h"
#include "SimDrive.h"
#include "SimRomStore.h"
#include "protocol/Command.h"
#include "protocol/StreamParser.h"

#include <QtCore/QByteArray>
#include <QtCore/QHash>
#include <QtCore/QList>

#include <map>
#include <memory>

namespace lk::sim {

/// One reply the simulated bus puts on the wire.
struct SimReply {
    QByteArray bytes;        ///< the frame, possibly with injected faults or garbage prefix
    double delaySeconds = 0; ///< turnaround after the request ends (reply delay + faults)
    int id = 0;
    protocol::Command command = protocol::Command::ReadState2;
};

/// Traffic counters of a SimBus, for tests and lksim statistics.
struct SimBusCounters {
    qint64 requests = 0;    ///< well-formed requests seen on the bus, any ID
    qint64 replies = 0;     ///< replies put on the wire (after drops)
    qint64 parseErrors = 0; ///< stream faults in the host's bytes (garbage, bad checksums...)
    qint64 notRequests = 0; ///< valid frames that are not requests (reply layouts, unknown)
    qint64 unanswered = 0;  ///< requests to absent IDs or unsupported commands
};

/// A simulated RS485 bus of up to 32 drives: host bytes in, reply bytes out.
///
/// Parses the host's byte stream (any chunking, garbage tolerated), decodes requests,
/// dispatches them to the addressed drive and encodes the replies; absent IDs and commands
/// the series lacks get no reply, as on a real bus. Time is the caller's monotonic clock in
/// seconds: every call first advances all drives' physics to it. Not thread-safe.
class SimBus {
public:
    static constexpr double kDefaultReplyDelay = 0.0002; ///< drives answer within 0.5 ms

    /// romDirectory: where drives' ROM is persisted (empty: memory only). seed: faults' RNG.
    explicit SimBus(const QString &romDirectory = {}, quint32 seed = 1);
    ~SimBus();
    SimBus(const SimBus &) = delete;
    SimBus &operator=(const SimBus &) = delete;

    /// A bus with the drives of a spec ("3:MF,17:MS").
    static std::unique_ptr<SimBus> fromSpec(const SimBusSpec &spec,
                                            const QString &romDirectory = {}, quint32 seed = 1);

    /// Add a drive (powered on with its stored ROM). nullptr if the ID is not 1..32 or taken.
    SimDrive *addDrive(int id, const SimDriveModel &model);
    bool removeDrive(int id);
    SimDrive *drive(int id);
    const SimDrive *drive(int id) const;
    QList<int> ids() const; ///< ascending

    /// Host bytes in; replies out, in order. Advances physics to nowSeconds first.
    QList<SimReply> receive(const char *data, qsizetype size, double nowSeconds);
    QList<SimReply> receive(const QByteArray &bytes, double nowSeconds)
    {
        return receive(bytes.constData(), bytes.size(), nowSeconds);
    }
    /// Let simulated time pass up to nowSeconds (earlier times are ignored).
    void advanceTo(double nowSeconds);
    double now() const { return m_now; }
    /// Power-cycle every drive; a partial frame from the host is dropped.
    void restart();
    /// Forget a partial frame from the host (the link was reopened).
    void dropPartialInput() { m_parser.reset(); }

    void setReplyDelay(double seconds) { m_replyDelay = seconds < 0 ? 0 : seconds; }
    double replyDelay() const { return m_replyDelay; }
    FaultInjector &faults() { return m_faults; }
    const FaultInjector &faults() const { return m_faults; }
    SimRomStore &romStore() { return m_rom; }

    // Counters (since construction or resetCounters()).
    int requestCount(int id) const;
    int requestCount(int id, protocol::Command command) const;
    /// Counts a request that reached a drive by another front (SimCanFront), so that the counts
    /// above hold on every link.
    void countRequest(int id, protocol::Command command);
    const SimBusCounters &counters() const { return m_counters; }
    void resetCounters();

    /// Seconds `bytes` take on an 8N1 wire (10 bits per byte) at `baud`.
    static double wireSeconds(qsizetype bytes, int baud);

private:
    void onParseEvent(const protocol::ParseEvent &event, QList<SimReply> &out);
    void dispatch(const protocol::Request &request, QList<SimReply> &out);

    std::map<int, std::unique_ptr<SimDrive>> m_drives;
    SimRomStore m_rom;
    FaultInjector m_faults;
    protocol::StreamParser m_parser;
    double m_now = 0;
    bool m_clockStarted = false;
    double m_replyDelay = kDefaultReplyDelay;
    QHash<int, int> m_perId;           ///< requests per ID (frames may carry any ID byte)
    QHash<int, int> m_perIdAndCommand; ///< key: id << 8 | command
    SimBusCounters m_counters;
};

} // namespace lk::sim
