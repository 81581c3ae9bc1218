#include "SimulatedBus.h"

#include <sim/SimBus.h>
#include <transport/SimTransport.h>

#include <QtCore/QMetaObject>
#include <QtCore/QThread>

namespace lk::ui {

SimulatedBus::SimulatedBus(const sim::SimBusSpec &spec) : m_spec(spec) {}

bus::TransportFactory SimulatedBus::factory(const std::shared_ptr<SimulatedBus> &self)
{
    return [self](int baud) -> std::unique_ptr<transport::Transport> {
        transport::SimSettings settings;
        settings.spec = self->m_spec;
        settings.faultSpec = self->m_faultSpec;
        std::unique_ptr<transport::Transport> t = transport::SimTransport::factory(settings)(baud);
        auto *raw = qobject_cast<transport::SimTransport *>(t.get());
        self->attach(raw);
        // No context object: runs directly on the bus thread while the transport dies.
        QObject::connect(raw, &QObject::destroyed, [self, raw] { self->detach(raw); });
        return t;
    };
}

void SimulatedBus::attach(transport::SimTransport *transport)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_transport = transport;
}

void SimulatedBus::detach(transport::SimTransport *transport)
{
    const std::lock_guard<std::mutex> lock(m_mutex);
    if (m_transport == transport)
        m_transport = nullptr;
}

bool SimulatedBus::requestDisconnect()
{
    return withBus([](sim::SimBus &bus) { bus.faults().requestDisconnect(); });
}

bool SimulatedBus::withBus(const std::function<void(sim::SimBus &)> &f)
{
    transport::SimTransport *t = nullptr;
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        t = m_transport;
    }
    if (!t)
        return false;
    if (t->thread() == QThread::currentThread()) {
        f(t->bus());
        return true;
    }
    // The lock is not held while waiting: the bus thread takes it when a transport dies.
    return QMetaObject::invokeMethod(
        t, [t, &f] { f(t->bus()); }, Qt::BlockingQueuedConnection);
}

int SimulatedBus::requestCount(int id, protocol::Command command)
{
    int n = -1;
    withBus([&](sim::SimBus &bus) { n = bus.requestCount(id, command); });
    return n;
}

} // namespace lk::ui
