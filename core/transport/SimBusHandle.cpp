#include "SimBusHandle.h"

#include <sim/SimBus.h>

#include <QtCore/QMetaObject>
#include <QtCore/QThread>

#include <future>

namespace lk::transport {

namespace {

/// The answer to one queued withBus() call. The queued functor holds the only reference, so
/// the ticket dies with it: after the call ran, or when Qt drops the call because its receiver
/// (the transport) died first (~QObject deletes the events posted to it). Either way the
/// waiting thread learns it, and never waits for a call that can no longer run.
class Ticket {
public:
    Ticket() = default;
    Ticket(const Ticket &) = delete;
    Ticket &operator=(const Ticket &) = delete;
    ~Ticket()
    {
        if (!m_answered)
            m_ran.set_value(false);
    }

    std::future<bool> future() { return m_ran.get_future(); }
    void ran()
    {
        m_answered = true;
        m_ran.set_value(true);
    }

private:
    std::promise<bool> m_ran;
    bool m_answered = false;
};

} // namespace

SimBusHandle::SimBusHandle(const sim::SimBusSpec &spec, protocol::Link link)
    : m_spec(spec), m_link(link)
{
}

void SimBusHandle::setFaultSpec(const QString &spec)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_faultSpec = spec;
}

std::function<std::unique_ptr<Transport>(int)>
SimBusHandle::factory(const std::shared_ptr<SimBusHandle> &self)
{
    return [self](int baud) -> std::unique_ptr<Transport> {
        SimSettings settings;
        settings.spec = self->m_spec;
        settings.link = self->m_link;
        {
            const std::lock_guard<std::mutex> lock(self->m_mutex);
            settings.faultSpec = self->m_faultSpec;
        }
        std::unique_ptr<Transport> t = SimTransport::factory(settings)(baud);
        auto *sim = qobject_cast<SimTransport *>(t.get());
        self->attach(sim);
        // No context object: runs directly on the bus thread while the transport dies.
        QObject::connect(sim, &QObject::destroyed, [self, sim] { self->detach(sim); });
        return t;
    };
}

void SimBusHandle::attach(SimTransport *transport)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_transport = transport;
}

void SimBusHandle::detach(SimTransport *transport)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    if (m_transport == transport)
        m_transport = nullptr;
}

bool SimBusHandle::requestDisconnect()
{
    return withBus([](sim::SimBus &bus) { bus.faults().requestDisconnect(); });
}

bool SimBusHandle::withBus(const std::function<void(sim::SimBus &)> &f)
{
    SimTransport *here = nullptr; // the transport, when it lives on this very thread
    auto ticket = std::make_shared<Ticket>();
    std::future<bool> ran = ticket->future();
    {
        // Under the lock the transport's QObject is alive: a dying transport emits destroyed
        // (detach(), under this lock) before Qt deletes the events posted to it. So the call
        // is queued on a live object, and from then on Qt either runs it on the bus thread,
        // where the transport is alive, or drops it with the transport. The lock is not held
        // while waiting: the bus thread takes it when a transport dies.
        const std::lock_guard<std::mutex> lock(m_mutex);
        SimTransport *t = m_transport;
        if (!t)
            return false;
        if (t->thread() == QThread::currentThread()) {
            here = t;
        } else {
            QMetaObject::invokeMethod(
                t,
                [t, &f, ticket] {
                    f(t->bus());
                    ticket->ran();
                },
                Qt::QueuedConnection);
            ticket.reset(); // the queued call holds the last reference
        }
    }
    if (here) {
        // Only this thread can destroy it, and it is busy here. f may call withBus again.
        f(here->bus());
        return true;
    }
    return ran.get();
}

int SimBusHandle::requestCount(int id, protocol::Command command)
{
    int n = -1;
    withBus([&](sim::SimBus &bus) { n = bus.requestCount(id, command); });
    return n;
}

} // namespace lk::transport
