#include "TapBusServer.h"

#include "PtyBusServer.h"
#include "PtyDevice.h"

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
constexpr double kMaxSleepS = 0.05; ///< wake at least this often for the stop flag and physics
using Outcome = sim::ControllerTransaction::Outcome;
} // namespace

TapBusServer::TapBusServer(PtyDevice &pty, sim::SimBus &bus, const sim::ControllerSpec &spec,
                           const Options &options)
    : m_pty(pty), m_bus(bus), m_spec(spec), m_options(options), m_stats(options.statsFile),
      m_log(options.logFile)
{
}

bool TapBusServer::open()
{
    return m_log.open() && writeStats(true);
}

bool TapBusServer::writeStats(bool running)
{
    if (m_stats.write(m_wire, m_bus.faults().injectedCount(sim::Fault::FirmwareChecksum), running))
        return true;
    std::fprintf(stderr, "lksim: %s\n", qPrintable(m_stats.errorString()));
    return false;
}

void TapBusServer::log(const char *direction, const QByteArray &bytes) const
{
    if (m_options.verbose)
        std::fprintf(stderr, "%s %s\n", direction, bytes.toHex(' ').toUpper().constData());
}

void TapBusServer::record(const QList<sim::ControllerTransaction> &done)
{
    if (done.isEmpty())
        return;
    const qint64 collisionsSoFar = m_wire.collisions();
    for (const sim::ControllerTransaction &t : done) {
        ++m_wire.requests;
        if (t.outcome == Outcome::Collided) // lost to the second master: one collision each
            ++(t.replyBytes.isEmpty() ? m_wire.collisionsBefore : m_wire.collisionsDuring);
        if (!t.replyBytes.isEmpty())
            ++m_wire.replies;
    }
    if (m_wire.collisions() != collisionsSoFar)
        writeStats(true); // the collision count is always current
    m_log.record(done);
}

void TapBusServer::advance(double now)
{
    for (const sim::WireChunk &c : m_controller->advanceTo(now))
        m_pending.push_back(Pending{c.atS + m_options.adapterLatencyS, c.bytes});
    record(m_controller->takeFinished());
}

void TapBusServer::onSecondMaster(const QByteArray &bytes, double now)
{
    log("<-", bytes);
    advance(now); // the wire as it is now, before these bytes join it
    ++m_secondMasterWrites;
    const sim::ForeignController::SecondMaster m = m_controller->secondMaster(bytes, now);
    if (m.collided)
        ++m_secondMasterCollisions;
    std::fprintf(stderr, "lksim: second master: %lld bytes (%s) written to the pty %s %s\n",
                 static_cast<long long>(bytes.size()), bytes.toHex(' ').toUpper().constData(),
                 m.collided ? "collided with" : "came on", qPrintable(m.what));
}

bool TapBusServer::flushDue(double now)
{
    while (!m_pending.empty() && m_pending.front().due <= now) {
        log("->", m_pending.front().bytes);
        const qsizetype discarded = m_pty.writeDiscardingUnread(m_pending.front().bytes);
        if (discarded < 0)
            return false;
        m_tapBytesDiscarded += discarded;
        m_pending.pop_front();
    }
    return true;
}

int TapBusServer::run(const std::atomic<bool> &stop, std::atomic<bool> &dumpStats)
{
    prctl(PR_SET_TIMERSLACK, 1UL); // frames are timed to the microsecond
    m_controller.emplace(m_spec, m_bus, m_options.baud, PtyBusServer::monotonicSeconds());
    pollfd pfd{m_pty.masterFd(), POLLIN, 0};
    while (!stop.load()) {
        if (dumpStats.exchange(false))
            writeStats(true);
        double now = PtyBusServer::monotonicSeconds();
        advance(now);
        if (!flushDue(now)) {
            std::fprintf(stderr, "lksim: %s\n", qPrintable(m_pty.errorString()));
            writeStats(false);
            return 1;
        }
        double next = m_controller->nextEventS();
        if (!m_pending.empty())
            next = std::min(next, m_pending.front().due);
        const double wait = std::clamp(next - now, 0.0, kMaxSleepS);
        timespec ts{static_cast<time_t>(wait), static_cast<long>(std::fmod(wait, 1.0) * 1e9)};
        const int n = ppoll(&pfd, 1, &ts, nullptr);
        if (n < 0 && errno != EINTR) {
            std::perror("lksim: ppoll");
            writeStats(false);
            return 1;
        }
        if (n > 0 && (pfd.revents & POLLIN)) {
            now = PtyBusServer::monotonicSeconds();
            const QByteArray bytes = m_pty.readAvailable();
            if (!bytes.isEmpty())
                onSecondMaster(bytes, now);
        }
    }
    writeStats(false);
    return 0;
}

QString TapBusServer::summary() const
{
    return QStringLiteral("lksim: controller: %1; second master: %2 writes, %3 of them over "
                          "the controller's frames; %4 bytes of the tap discarded unread")
        .arg(m_log.outcomesText())
        .arg(m_secondMasterWrites)
        .arg(m_secondMasterCollisions)
        .arg(m_tapBytesDiscarded);
}

} // namespace lk::app
