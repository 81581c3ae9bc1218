#include "PtyBusServer.h"

#include "PtyDevice.h"

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
    : m_pty(pty), m_bus(bus), m_options(options)
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

void PtyBusServer::onInput(const QByteArray &bytes, double now)
{
    log("<-", bytes);
    m_lastInputAt = now;
    const QList<sim::SimReply> replies = m_bus.receive(bytes, now);
    for (const sim::SimReply &reply : replies) {
        double due = now + reply.delaySeconds;
        if (m_options.emulateWireTime) {
            const double replyWire = sim::SimBus::wireSeconds(reply.bytes.size(), m_options.baud);
            due += requestWireSeconds(static_cast<quint8>(reply.command)) + replyWire;
            due = std::max(due, m_wireFreeAt + replyWire); // half duplex: one talker at a time
            m_wireFreeAt = due;
        }
        // Replies keep their order even when a fault delays one of them.
        if (!m_pending.empty())
            due = std::max(due, m_pending.back().due);
        m_pending.push_back(Pending{due, reply.bytes});
    }
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

int PtyBusServer::run(const std::atomic<bool> &stop)
{
    // Replies are timed to the microsecond; the kernel's default timer slack (50 us) would let
    // every timed wake-up come late by up to that much, a third of a 1 Mbps transaction.
    prctl(PR_SET_TIMERSLACK, 1UL);
    pollfd pfd{m_pty.masterFd(), POLLIN, 0};
    while (!stop.load()) {
        double now = monotonicSeconds();
        if (!flushDue(now)) {
            std::fprintf(stderr, "lksim: %s\n", qPrintable(m_pty.errorString()));
            return 1;
        }
        // Sleep until input arrives, the next reply is due, or 50 ms pass (to let physics
        // and the stop flag move on).
        double wait = 0.05;
        if (!m_pending.empty())
            wait = std::clamp(m_pending.front().due - now, 0.0, wait);
        if (m_options.busyPoll && m_lastInputAt >= 0 && now - m_lastInputAt < kBusyWindowS)
            wait = 0;
        timespec ts{static_cast<time_t>(wait), static_cast<long>(std::fmod(wait, 1.0) * 1e9)};
        const int n = ppoll(&pfd, 1, &ts, nullptr);
        if (n < 0 && errno != EINTR) {
            std::perror("lksim: ppoll");
            return 1;
        }
        now = monotonicSeconds();
        if (n > 0 && (pfd.revents & POLLIN)) {
            const QByteArray bytes = m_pty.readAvailable();
            if (!bytes.isEmpty())
                onInput(bytes, now);
        } else if (now - m_lastAdvanceAt >= kAdvanceStepS) {
            m_bus.advanceTo(now); // physics needs no finer steps; spinning must not run it
            m_lastAdvanceAt = now;
        }
    }
    return 0;
}

} // namespace lk::app
