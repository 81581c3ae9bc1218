#pragma once

#include "SimTransport.h"

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

/// A simulated bus behind a BusSession, reachable from outside the bus thread: the session's
/// transport factory (SimTransport::factory, created on the bus thread as every transport)
/// plus a handle on the live simulated drives for tests and demos (unplug, request counters).
/// lkstudio's built-in bus. Shared by the factory and its owner, hence the shared_ptr; safe to
/// use from any thread while the session opens, reopens and closes.
class SimBusHandle {
public:
    /// Four drives, one of each series; drive 3 is an MS4015 on firmware 2.35 (protocol V2.35,
    /// 16-bit encoder range), so a first run shows both protocol generations.
    static QString defaultSpecText() { return QStringLiteral("1:MF,2:MG,3:MS4015@2.35,4:MH"); }

    /// The drives of `spec` on `link`: on CAN (sim::SimCanFront, with CAN wire time) a drive
    /// of generation V2_3 is an old CAN drive, V2_35 a V2.36 one.
    explicit SimBusHandle(const sim::SimBusSpec &spec, protocol::Link link = protocol::Link::Rs485);

    const sim::SimBusSpec &spec() const { return m_spec; }
    protocol::Link link() const { return m_link; }
    /// Faults to inject into every reply (sim::FaultInjector::configure syntax), for training
    /// and demos: "corrupt=0.01,garbage=0.01". Checked by the caller; applied on (re)open.
    void setFaultSpec(const QString &spec);

    /// A factory for BusSession::open; each call makes a fresh simulated bus of the spec.
    static std::function<std::unique_ptr<Transport>(int baud)>
    factory(const std::shared_ptr<SimBusHandle> &self);

    /// Make the link drop as if the adapter was unplugged (any thread).
    bool requestDisconnect();
    /// Run `f` on the bus thread with the live simulated bus and wait for it. Any thread, any
    /// time: false, without running `f`, when no bus is live or the transport dies before `f`
    /// could run. Not from a thread the bus thread is itself waiting for.
    bool withBus(const std::function<void(sim::SimBus &)> &f);
    /// Requests the simulated drive `id` has seen with `command` (-1 when no bus is live).
    int requestCount(int id, protocol::Command command);

private:
    void attach(SimTransport *transport);
    void detach(SimTransport *transport);

    const sim::SimBusSpec m_spec;
    const protocol::Link m_link;
    std::mutex m_mutex; ///< guards the two below; never held while `f` runs or is awaited
    QString m_faultSpec;
    /// The live transport. It is only ever dereferenced under m_mutex (to queue a call to it)
    /// or on its own thread, where it cannot die meanwhile.
    SimTransport *m_transport = nullptr;
};

} // namespace lk::transport
