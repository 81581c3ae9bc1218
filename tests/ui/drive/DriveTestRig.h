#pragma once

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>
#include <sim/SimBus.h>
#include <sim/SimBusSpec.h>
#include <transport/SimBusHandle.h>

#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QPushButton>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

namespace lk::drivetest {

/// Waits on a loaded 2-core machine: generous, never a timing assertion.
constexpr int kWaitMs = 20000;

/// A BusSession on lkstudio's built-in simulated bus, scanned, with access to the simulated
/// drives on the bus thread (SimBusHandle::withBus) for checks on the simulator's side.
class SimRig {
public:
    explicit SimRig(const QString &spec = QStringLiteral("1:MF,2:MG,3:MS,4:MH"))
        : sim(std::make_shared<transport::SimBusHandle>(*sim::SimBusSpec::parse(spec)))
    {
    }
    ~SimRig() { session.close(); }

    /// The reply margins the session opens with: a loaded machine must never turn a late
    /// reply into silence. A test whose every write must be answered (a ROM write is never
    /// retried) may widen them before open().
    int minMarginMs = 100;
    int maxMarginMs = 400;

    /// Opens, waits for the link and scans the IDs of the spec. False on failure.
    bool open()
    {
        bus::BusConfig config;
        config.minMarginMs = minMarginMs;
        config.initialMarginMs = minMarginMs;
        config.maxMarginMs = std::max(maxMarginMs, minMarginMs);
        session.open(transport::SimBusHandle::factory(sim), 115200, config);
        if (!QTest::qWaitFor([this] { return session.connection().isOpen(); }, kWaitMs))
            return false;
        QSignalSpy finished(&session, &bus::BusSession::scanFinished);
        bus::ScanOptions options;
        options.firstId = 1;
        options.lastId = 8;
        session.scan(options);
        return finished.count() > 0 || finished.wait(kWaitMs);
    }

    bus::KnownMotor motor(int id) const { return session.knownMotors().value(id); }

    /// Runs `f` with the simulated drive on the bus thread.
    void withDrive(int id, const std::function<void(sim::SimDrive &)> &f)
    {
        sim->withBus([&](sim::SimBus &bus) {
            if (sim::SimDrive *d = bus.drive(id))
                f(*d);
        });
    }
    template <typename T> T read(int id, const std::function<T(const sim::SimDrive &)> &f)
    {
        T value{};
        withDrive(id, [&](sim::SimDrive &d) { value = f(d); });
        return value;
    }
    protocol::PidGains ramPid(int id)
    {
        return read<protocol::PidGains>(id, [](const sim::SimDrive &d) { return d.ramPid(); });
    }
    protocol::PidGains romPid(int id)
    {
        return read<protocol::PidGains>(id, [](const sim::SimDrive &d) { return d.rom().pid; });
    }
    double speedDps(int id)
    {
        return read<double>(id, [](const sim::SimDrive &d) { return d.speedDps(); });
    }
    double multiTurnDeg(int id)
    {
        return read<double>(id, [](const sim::SimDrive &d) { return d.multiTurnRaw() * 0.01; });
    }
    double singleTurnDeg(int id)
    {
        return read<double>(id, [](const sim::SimDrive &d) { return d.singleTurnRaw() * 0.01; });
    }
    void restartDrive(int id)
    {
        withDrive(id, [](sim::SimDrive &d) { d.restart(); });
    }
    int count(int id, protocol::Command command) { return sim->requestCount(id, command); }

    /// Sends a read and waits for its completion: every request queued before it has been
    /// through the bus by then (one queue, in order), so counters can be checked.
    bool barrier(int id = 1)
    {
        QSignalSpy done(&session, &bus::BusSession::requestCompleted);
        const quint64 ticket =
            session.send(*protocol::build::plain(protocol::Command::ReadState1, id).request,
                         bus::Priority::Background);
        return QTest::qWaitFor(
            [&] {
                for (const QList<QVariant> &args : std::as_const(done)) {
                    if (args.at(0).value<bus::RequestResult>().ticket == ticket)
                        return true;
                }
                return false;
            },
            kWaitMs);
    }

    /// Winds drive `id` more than 2000 deg from 0 and leaves it still with its motor off: for
    /// tests of targets that must start where the drive is, never at 0 absolute.
    bool windAway(int id)
    {
        using protocol::build::speed;
        if (session.send(*speed(id, 5000).request) == 0 ||
            !QTest::qWaitFor([&] { return multiTurnDeg(id) > 2000; }, kWaitMs))
            return false;
        session.send(*speed(id, 0).request);
        if (!QTest::qWaitFor([&] { return std::fabs(speedDps(id)) < 1; }, kWaitMs))
            return false;
        session.send(*protocol::build::plain(protocol::Command::MotorOff, id).request,
                     bus::Priority::Emergency);
        return barrier(id);
    }

    std::shared_ptr<transport::SimBusHandle> sim;
    bus::BusSession session;
};

/// A drive view of type View on drive `id` of the rig: sized, connected and shown.
template <typename View> std::unique_ptr<View> showView(SimRig &rig, int id, QSize size)
{
    auto view = std::make_unique<View>();
    view->resize(size);
    view->setSession(&rig.session);
    view->setConnected(true);
    view->setDrive(id, rig.motor(id));
    view->show();
    return view;
}

/// The push button named `name` inside `view` (nullptr when there is none).
inline QPushButton *button(QWidget &view, const char *name)
{
    return view.findChild<QPushButton *>(QLatin1String(name));
}

} // namespace lk::drivetest
