#include "PreciseWake.h"

#include <QtCore/QSocketNotifier>

#include <sys/prctl.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

namespace lk::transport {

namespace {
constexpr qint64 kNsPerSecond = 1000000000;
constexpr unsigned long kTimerSlackNs = 1000;

/// The kernel may fire a timer up to its thread's "timer slack" late (50 us by default), as
/// long as a CAN frame: the thread that waits this precisely asks for 1 us instead.
void tightenTimerSlackOfThisThread()
{
    thread_local bool done = false;
    if (done)
        return;
    done = true;
    ::prctl(PR_SET_TIMERSLACK, kTimerSlackNs, 0, 0, 0);
}
} // namespace

PreciseWake::PreciseWake(QObject *parent) : QObject(parent)
{
    m_fd = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (m_fd < 0)
        return;
    m_notifier = new QSocketNotifier(m_fd, QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &PreciseWake::onReadable);
}

PreciseWake::~PreciseWake()
{
    if (m_fd < 0)
        return;
    delete m_notifier; // before its descriptor is gone
    ::close(m_fd);
}

void PreciseWake::wakeIn(qint64 ns)
{
    if (m_fd < 0)
        return;
    tightenTimerSlackOfThisThread();
    // An all-zero it_value disarms a timerfd: "now" is one nanosecond from now.
    const qint64 wait = ns > 0 ? ns : 1;
    itimerspec spec{};
    spec.it_value.tv_sec = static_cast<time_t>(wait / kNsPerSecond);
    spec.it_value.tv_nsec = static_cast<long>(wait % kNsPerSecond);
    if (::timerfd_settime(m_fd, 0, &spec, nullptr) == 0)
        m_active = true;
}

void PreciseWake::cancel()
{
    if (m_fd < 0 || !m_active)
        return;
    const itimerspec off{};
    ::timerfd_settime(m_fd, 0, &off, nullptr);
    m_active = false;
    // An expiry already counted would still make the descriptor readable: take it now.
    std::uint64_t expirations = 0;
    while (::read(m_fd, &expirations, sizeof expirations) < 0 && errno == EINTR) {
    }
}

void PreciseWake::onReadable()
{
    std::uint64_t expirations = 0;
    const ssize_t n = ::read(m_fd, &expirations, sizeof expirations);
    if (n != static_cast<ssize_t>(sizeof expirations))
        return; // cancelled after it became readable, or EINTR: nothing is due
    m_active = false;
    emit woke();
}

} // namespace lk::transport
