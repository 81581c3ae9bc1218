#pragma once

#include <bus/BusSession.h>
#include <fleet/FleetReader.h>
#include <fleet/FleetRestore.h>
#include <protocol/RequestBuilder.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <sim/SimDrive.h>
#include <transport/SimBusHandle.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>

#include <functional>
#include <memory>

namespace lk::fleettest {

/// Waits on a loaded 2-core machine: generous, never a timing assertion.
constexpr int kWaitMs = 30000;

/// A BusSession on the in-process simulated bus, with the simulated drives at hand.
class FleetRig {
public:
    /// On CAN (`link`), a drive of generation V2_3 is an old CAN drive, V2_35 a V2.36 one.
    explicit FleetRig(const QString &spec, protocol::Link link = protocol::Link::Rs485)
        : sim(std::make_shared<transport::SimBusHandle>(*sim::SimBusSpec::parse(spec), link))
    {
    }
    ~FleetRig() { session.close(); }

    bool open()
    {
        bus::BusConfig config;
        config.minMarginMs = 100; // a loaded machine must never turn a late reply into silence
        config.initialMarginMs = 100;
        config.maxMarginMs = 400;
        session.open(transport::SimBusHandle::factory(sim), 115200, config);
        return QTest::qWaitFor([this] { return session.connection().isOpen(); }, kWaitMs);
    }

    void withBus(const std::function<void(sim::SimBus &)> &f) { sim->withBus(f); }
    void withDrive(int id, const std::function<void(sim::SimDrive &)> &f)
    {
        sim->withBus([&](sim::SimBus &bus) {
            if (sim::SimDrive *d = bus.drive(id))
                f(*d);
        });
    }
    int count(int id, protocol::Command command) { return sim->requestCount(id, command); }
    /// A read whose completion means every request queued before it has been through the bus.
    bool barrier(int id = 1)
    {
        bool done = false;
        session.send(*protocol::build::plain(protocol::Command::ReadState1, id).request, &session,
                     [&done](const bus::RequestResult &) { done = true; });
        return QTest::qWaitFor([&done] { return done; }, kWaitMs);
    }

    /// Reads `ids` with a FleetReader and returns the snapshots.
    QVector<fleet::DriveSnapshot> read(const QVector<int> &ids)
    {
        fleet::FleetReader reader(&session);
        QSignalSpy done(&reader, &fleet::FleetReader::finished);
        reader.start(ids);
        // A signal sent before the wait (a refusal is immediate) must not cost the whole wait.
        if (done.isEmpty() && !done.wait(kWaitMs))
            return {};
        return reader.snapshots();
    }

    /// prepare() then, when `execute`, execute(rom); returns after the last signal.
    bool restore(fleet::FleetRestore &restore, const QVector<fleet::FleetRestore::Job> &jobs,
                 bool execute, bool rom = false)
    {
        QSignalSpy prepared(&restore, &fleet::FleetRestore::prepared);
        restore.prepare(jobs);
        if (prepared.isEmpty() && !prepared.wait(kWaitMs))
            return false;
        if (!execute)
            return true;
        QSignalSpy finished(&restore, &fleet::FleetRestore::finished);
        restore.execute(rom);
        return !finished.isEmpty() || finished.wait(kWaitMs);
    }

    std::shared_ptr<transport::SimBusHandle> sim;
    bus::BusSession session;
};

} // namespace lk::fleettest
