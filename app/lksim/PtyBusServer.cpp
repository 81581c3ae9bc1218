#include "PtyBusServer.h"

#include "PtyDevice.h"
#include "PtyLagProbe.h"
#include "RunQueueDelay.h"

#include <protocol/Checksum.h>
#include <protocol/Command.h>
#include <sim/SimBus.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <poll.h>
#include <sys/prctl.h>

namespace lk::app {

namespace {
constexpr double kBusyWindowS = 0.02;   ///< spin this long after the host's last request
constexpr double kAdvanceStepS = 0.001; ///< physics steps while nothing else happens
} // namespace

PtyBusServer::PtyBusServer(PtyDevice &pty, sim::SimBus &bus, const Options &options)
    : m_pty(pty), m_bus(bus), m_options(options), m_stats(options.statsFile)
{
}

double PtyBusServer::monotonicSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

double PtyBusServer::requestWireSeconds(quint8 command) const
{
    const protocol::CommandInfo *info = protocol::CommandTable::find(command);
    const int len = info ? info->requestLength : 0;
    return sim::SimBus::wireSeconds(protocol::kHeaderSize + len + (len > 0 ? 1 : 0),
                                    m_options.baud);
}

void PtyBusServer::log(const char *direction, const QByteArray &bytes) const
{
    if (m_options.verbose)
        std::fprintf(stderr, "%s %s\n", direction, bytes.toHex(' ').toUpper().constData());
}

void PtyBusServer::onInput(const QByteArray &bytes, double now, double blindS)
{
    log("<-", bytes);
    m_lastInputAt = now;
    // Byte by byte, so that each request is judged on its own: the second of two requests
    // read at once collides with the reply the first one asked for (the host sent it before
    // that reply could have reached it).
    for (qsizetype i = 0; i < bytes.size(); ++i) {
        if (!m_collision)
            m_collision = m_wire.overlapAt(now);
        m_frameBytes.append(bytes.at(i));
        const qint64 requestsBefore = m_bus.counters().requests;
        const QList<sim::SimReply> replies = m_bus.receive(bytes.constData() + i, 1, now);
        if (m_bus.counters().requests != requestsBefore)
            noteRequestEnd(now);
        const sim::SimBusCounters &c = m_bus.counters();
        const qint64 events = c.requests + c.parseErrors + c.notRequests;
        if (events != m_frameEvents) { // a frame or a fault ended with this byte
            m_frameEvents = events;
            m_frameBytes.clear();
            m_collision.reset();
        }
        for (const sim::SimReply &reply : replies)
            schedule(reply, now, blindS);
    }
}

void PtyBusServer::noteRequestEnd(double now)
{
    m_wire.requestEnded(m_collision, now);
    if (!m_collision)
        return;
    std::fprintf(stderr, "lksim: %s: request %s arrived %s\n",
                 m_collision->unjudged ? "unjudged overlap" : "collision",
                 m_frameBytes.toHex(' ').toUpper().constData(),
                 qPrintable(m_collision->describe()));
    writeStats(true);
}

void PtyBusServer::schedule(const sim::SimReply &reply, double now, double blindS)
{
    double wireEnd = now + reply.delaySeconds;
    double replyWire = 0;
    if (m_options.emulateWireTime) {
        replyWire = sim::SimBus::wireSeconds(reply.bytes.size(), m_options.baud);
        wireEnd += requestWireSeconds(static_cast<quint8>(reply.command)) + replyWire;
        wireEnd = std::max(wireEnd, m_wireFreeAt + replyWire); // half duplex: one talker
        m_wireFreeAt = wireEnd;
    }
    m_wire.replyScheduled(wireEnd - replyWire, wireEnd, reply.id,
                          static_cast<quint8>(reply.command), blindS, now);
    // Replies keep their order even when a fault delays one of them.
    double due = wireEnd + m_options.adapterLatencyS;
    if (!m_pending.empty())
        due = std::max(due, m_pending.back().due);
    m_pending.push_back(Pending{due, reply.bytes});
}

qint64 PtyBusServer::badChecksumReplies() const
{
    return m_bus.faults().injectedCount(sim::Fault::FirmwareChecksum);
}

bool PtyBusServer::writeStats(bool running)
{
    if (m_stats.write(m_wire.counters(), badChecksumReplies(), running))
        return true;
    std::fprintf(stderr, "lksim: %s\n", qPrintable(m_stats.errorString()));
    return false;
}

bool PtyBusServer::flushDue(double now)
{
    while (!m_pending.empty() && m_pending.front().due <= now) {
        log("->", m_pending.front().bytes);
        if (!m_pty.writeAll(m_pending.front().bytes))
            return false;
        m_pending.pop_front();
    }
    return true;
}

int PtyBusServer::run(const std::atomic<bool> &stop, std::atomic<bool> &dumpStats)
{
    // Replies are timed to the microsecond; the kernel's default timer slack (50 us) would let
    // every timed wake-up come late by up to that much, a third of a 1 Mbps transaction.
    prctl(PR_SET_TIMERSLACK, 1UL);
    std::optional<PtyLagProbe> lagProbe;
    if (m_options.ptyLagProbePeriodS > 0) {
        lagProbe.emplace(m_options.ptyLagProbePeriodS);
        if (!lagProbe->open()) {
            std::fprintf(stderr, "lksim: pty lag probe: %s\n", qPrintable(lagProbe->errorString()));
            return 1;
        }
    }
    pollfd pfds[2] = {{m_pty.masterFd(), POLLIN, 0},
                      {lagProbe ? lagProbe->readFd() : -1, POLLIN, 0}};
    const nfds_t nfds = lagProbe ? 2 : 1;
    const RunQueueDelay runQueue;         // opened here: it measures the thread that serves
    double lookedAt = monotonicSeconds(); // when lksim last saw that no input was waiting
    while (!stop.load()) {
        if (dumpStats.exchange(false))
            writeStats(true);
        double now = monotonicSeconds();
        if (!flushDue(now)) {
            std::fprintf(stderr, "lksim: %s\n", qPrintable(m_pty.errorString()));
            writeStats(false);
            return 1;
        }
        // Sleep until input arrives, the next reply is due, or 50 ms pass (to let physics
        // and the stop flag move on).
        double wait = 0.05;
        if (!m_pending.empty())
            wait = std::clamp(m_pending.front().due - now, 0.0, wait);
        if (lagProbe)
            wait = std::min(wait, lagProbe->untilNextSendS(now));
        if (m_options.busyPoll && m_lastInputAt >= 0 && now - m_lastInputAt < kBusyWindowS)
            wait = 0;
        timespec ts{static_cast<time_t>(wait), static_cast<long>(std::fmod(wait, 1.0) * 1e9)};
        const double pollAt = monotonicSeconds();
        const double waitedBefore = runQueue.seconds();
        const int n = ppoll(pfds, nfds, &ts, nullptr);
        if (n < 0 && errno != EINTR) {
            std::perror("lksim: ppoll");
            writeStats(false);
            return 1;
        }
        now = monotonicSeconds();
        // Input may have arrived while lksim worked since it last looked, or while it waited
        // for a CPU after ppoll should have woken it: that much earlier than `now`. Before
        // that the kernel may have held it in the pty, as long as it held the canary.
        double blindS = (pollAt - lookedAt) + (runQueue.seconds() - waitedBefore);
        lookedAt = now;
        if (lagProbe) {
            if (!lagProbe->service(now)) {
                std::fprintf(stderr, "lksim: pty lag probe: %s\n",
                             qPrintable(lagProbe->errorString()));
                writeStats(false);
                return 1;
            }
            blindS = std::max(blindS, lagProbe->heldS(now));
        }
        if (n > 0 && (pfds[0].revents & POLLIN)) {
            const QByteArray bytes = m_pty.readAvailable();
            if (!bytes.isEmpty())
                onInput(bytes, now, blindS);
        } else if (now - m_lastAdvanceAt >= kAdvanceStepS) {
            m_bus.advanceTo(now); // physics needs no finer steps; spinning must not run it
            m_lastAdvanceAt = now;
        }
    }
    writeStats(false);
    return 0;
}

} // namespace lk::app
