#pragma once

#include <bus/TransportFactory.h>
#include <protocol/Command.h>
#include <sim/SimBusSpec.h>

#include <QtCore/QString>

#include <functional>
#include <memory>
#include <mutex>

namespace lk::sim {
class SimBus;
}
namespace lk::transport {
class SimTransport;
}

namespace lk::ui {

/// The built-in simulated bus of lkstudio: a transport factory over SimTransport (created on
/// the bus thread, as every transport) plus a handle that reaches the simulated drives from
/// the GUI thread, for tests and demos (unplug, request counters). Shared by the factory and
/// its owner, hence the shared_ptr and the lock.
class SimulatedBus {
public:
    /// Four drives, one of each series; drive 3 is an MS4015 on firmware 2.35 (protocol V2.35,
    /// 16-bit encoder range), so a first run shows both protocol generations.
    static QString defaultSpecText() { return QStringLiteral("1:MF,2:MG,3:MS4015@2.35,4:MH"); }

    explicit SimulatedBus(const sim::SimBusSpec &spec);

    const sim::SimBusSpec &spec() const { return m_spec; }
    /// Faults to inject into every reply (sim::FaultInjector::configure syntax), for training
    /// and demos: "corrupt=0.01,garbage=0.01". Checked by the caller; applied on (re)open.
    void setFaultSpec(const QString &spec) { m_faultSpec = spec; }

    /// A factory for BusSession::open; each call makes a fresh simulated bus of the spec.
    static bus::TransportFactory factory(const std::shared_ptr<SimulatedBus> &self);

    /// Make the link drop as if the adapter was unplugged (any thread).
    bool requestDisconnect();
    /// Run `f` on the bus thread with the live simulated bus and wait for it. Call it only
    /// while the session is open (the transport lives as long as that). False if none.
    bool withBus(const std::function<void(sim::SimBus &)> &f);
    /// Requests the simulated drive `id` has seen with `command` (-1 when no bus is live).
    int requestCount(int id, protocol::Command command);

private:
    void attach(transport::SimTransport *transport);
    void detach(transport::SimTransport *transport);

    sim::SimBusSpec m_spec;
    QString m_faultSpec;
    std::mutex m_mutex;
    transport::SimTransport *m_transport = nullptr; ///< lives on the bus thread
};

} // namespace lk::ui
