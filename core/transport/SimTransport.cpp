#include "SimTransport.h"

#include <QtCore/QCoreApplication>

#include "PreciseWake.h"

#include "sim/SimBus.h"
#include "sim/SimCanFront.h"

#include <protocol/CanFrameTime.h>
#include <protocol/CanRecord.h>

#include <QtCore/QMetaObject>
#include <QtCore/QTimer>

#include <algorithm>
#include <cmath>

namespace lk::transport {

namespace {
constexpr qint64 kNsPerMs = 1000000;
constexpr double kNsPerSecond = 1e9;
constexpr int kHousekeepingMs = 100;
} // namespace

SimTransport::SimTransport(std::unique_ptr<sim::SimBus> bus, QObject *parent)
    : Transport(parent), m_bus(std::move(bus)), m_wake(new PreciseWake(this)),
      m_timer(new QTimer(this)), m_housekeeping(new QTimer(this))
{
    Q_ASSERT(m_bus);
    m_clock.start();
    m_timer->setSingleShot(true);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &SimTransport::deliverDue);
    connect(m_wake, &PreciseWake::woke, this, &SimTransport::deliverDue);
    m_housekeeping->setInterval(kHousekeepingMs);
    connect(m_housekeeping, &QTimer::timeout, this, &SimTransport::housekeeping);
}

SimTransport::~SimTransport() = default;

std::function<std::unique_ptr<Transport>(int)> SimTransport::factory(SimSettings settings)
{
    return [settings](int baud) -> std::unique_ptr<Transport> {
        auto bus = sim::SimBus::fromSpec(settings.spec, settings.romDirectory);
        if (!settings.faultSpec.isEmpty())
            bus->faults().configure(settings.faultSpec);
        auto t = std::make_unique<SimTransport>(std::move(bus));
        t->setLink(settings.link);
        t->setBaud(baud);
        t->setWireTimeEmulation(true);
        return t;
    };
}

QString SimTransport::description() const
{
    const int n = static_cast<int>(m_bus->ids().size());
    if (m_link == protocol::Link::Can)
        return n == 1 ? QCoreApplication::translate("lk::transport::SimTransport",
                                                    "Simulated CAN bus (1 drive) @ %1 bit/s")
                            .arg(m_baud)
                      : QCoreApplication::translate("lk::transport::SimTransport",
                                                    "Simulated CAN bus (%1 drives) @ %2 bit/s")
                            .arg(n)
                            .arg(m_baud);
    return n == 1 ? QCoreApplication::translate("lk::transport::SimTransport",
                                                "Simulated bus (1 drive)")
                  : QCoreApplication::translate("lk::transport::SimTransport",
                                                "Simulated bus (%1 drives)")
                        .arg(n);
}

void SimTransport::setBaud(int baud)
{
    if (baud > 0)
        m_baud = baud;
}

void SimTransport::setLink(protocol::Link link)
{
    m_link = link;
    if (link == protocol::Link::Can && !m_canFront)
        m_canFront = std::make_unique<sim::SimCanFront>(*m_bus);
    else if (link != protocol::Link::Can)
        m_canFront.reset();
}

QList<sim::SimReply> SimTransport::receive(const QByteArray &bytes, double nowSeconds)
{
    return m_canFront ? m_canFront->receive(bytes, nowSeconds) : m_bus->receive(bytes, nowSeconds);
}

void SimTransport::setReplyDelay(double seconds)
{
    m_bus->setReplyDelay(seconds);
}

double SimTransport::replyDelay() const
{
    return m_bus->replyDelay();
}

void SimTransport::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

bool SimTransport::open()
{
    if (m_state == State::Open)
        return true;
    m_bus->faults().takeDisconnect(); // a request from before this connection is stale
    m_bus->dropPartialInput();
    m_pending.clear();
    m_wireFreeNs = 0;
    m_housekeeping->start();
    setState(State::Open);
    return true;
}

void SimTransport::close()
{
    m_pending.clear();
    m_timer->stop();
    m_wake->cancel();
    m_housekeeping->stop();
    setState(State::Closed);
}

qint64 SimTransport::wireNs(qsizetype bytes) const
{
    if (!m_wireTime)
        return 0;
    if (m_link == protocol::Link::Can) // one CAN frame per record, 8 data bytes each
        return std::llround(static_cast<double>(bytes / protocol::CanRecord::kSize) *
                            protocol::can::frameSeconds(m_baud) * kNsPerSecond);
    return std::llround(sim::SimBus::wireSeconds(bytes, m_baud) * kNsPerSecond);
}

void SimTransport::write(const QByteArray &bytes)
{
    if (m_state != State::Open || bytes.isEmpty() || refuseWriteIfReadOnly(bytes))
        return;
    if (m_bus->faults().takeDisconnect()) {
        goDisconnected();
        return;
    }
    const qint64 now = m_clock.nsecsElapsed();
    const QList<sim::SimReply> replies = receive(bytes, now / kNsPerSecond);
    // Half duplex: the request waits for the wire, each reply follows its turnaround and
    // never overlaps the one before it.
    const qint64 requestEnd = std::max(now, m_wireFreeNs) + wireNs(bytes.size());
    m_wireFreeNs = requestEnd;
    for (const sim::SimReply &r : replies) {
        const qint64 turnaround = std::llround(r.delaySeconds * kNsPerSecond);
        const qint64 start = std::max(requestEnd + turnaround, m_wireFreeNs);
        const qint64 due = start + wireNs(r.bytes.size());
        m_wireFreeNs = due;
        m_pending.push_back(Pending{r.bytes, due});
    }
    schedule();
}

void SimTransport::schedule()
{
    if (m_pending.empty()) {
        m_timer->stop();
        m_wake->cancel();
        return;
    }
    const qint64 remaining = m_pending.front().dueNs - m_clock.nsecsElapsed();
    if (remaining > 0 && m_wake->isValid()) {
        // The thread sleeps until the reply is due, to the microsecond, as it sleeps until a
        // real adapter's frame arrives: looking on every turn of the event loop instead kept
        // a core busy (the whole bus thread of lkstudio --can sim).
        m_timer->stop();
        m_wake->wakeIn(remaining); // QElapsedTimer and the timerfd share CLOCK_MONOTONIC
        return;
    }
    if (remaining >= kNsPerMs) {
        // Whole milliseconds only, so the timer never fires late; the rest is polled.
        m_timer->start(static_cast<int>(remaining / kNsPerMs));
        return;
    }
    m_timer->stop();
    postCheck(); // due, or due within a millisecond: QTimer cannot wait that precisely
}

void SimTransport::postCheck()
{
    if (m_checkPosted)
        return;
    m_checkPosted = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_checkPosted = false;
            deliverDue();
        },
        Qt::QueuedConnection);
}

void SimTransport::deliverDue()
{
    ++m_wakeups;
    while (m_state == State::Open && !m_pending.empty() &&
           m_pending.front().dueNs <= m_clock.nsecsElapsed()) {
        const QByteArray bytes = m_pending.front().bytes;
        m_pending.pop_front();
        emit bytesReceived(bytes); // a receiver may write() or close() from here
    }
    if (m_state == State::Open)
        schedule();
}

void SimTransport::housekeeping()
{
    if (m_bus->faults().takeDisconnect()) {
        goDisconnected();
        return;
    }
    // Keeps physics catch-up short when the host is quiet.
    m_bus->advanceTo(m_clock.nsecsElapsed() / kNsPerSecond);
}

void SimTransport::goDisconnected()
{
    m_pending.clear();
    m_timer->stop();
    m_wake->cancel();
    m_housekeeping->stop();
    // The cause first, as a serial port says it: the state's reason then names it.
    emit errorOccurred(
        TransportError{TransportError::Kind::Unplugged,
                       QCoreApplication::translate(
                           "lk::transport::SimTransport",
                           "The simulated bus was disconnected (fault injection). Open it again "
                           "to reconnect.")});
    setState(State::Disconnected);
}

} // namespace lk::transport
