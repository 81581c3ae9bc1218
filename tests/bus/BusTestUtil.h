#pragma once

#include "../support/ManualTimers.h"
#include "FakeTransport.h"

#include <bus/BusWorker.h>
#include <protocol/Reply.h>

#include <QtCore/QObject>
#include <QtCore/QVector>

#include <functional>
#include <memory>

namespace lk::bustest {

/// Timeouts generous enough for a loaded 2-core machine: a reply that is on its way is never
/// mistaken for silence, and a silent drive still costs only ~0.1 s.
inline bus::BusConfig relaxedConfig()
{
    bus::BusConfig c;
    c.minMarginMs = 100;
    c.initialMarginMs = 100;
    c.maxMarginMs = 400;
    return c;
}

inline protocol::Request plainRequest(protocol::Command c, int id)
{
    protocol::Request r;
    r.command = c;
    r.id = static_cast<quint8>(id);
    return r;
}

/// Where a WorkerRig's time comes from.
enum class RigTime {
    Wall,   ///< the steady clock and QTimers: the test waits (QTRY_*)
    Manual, ///< a ManualClock and ManualTimers: the test advances time (runUntil())
};

/// A BusWorker on the test thread over a FakeTransport, collecting completions.
class WorkerRig {
public:
    using Setup = std::function<void(FakeTransport &)>;

    explicit WorkerRig(Setup setup = {}, bus::BusConfig config = relaxedConfig(), int baud = 115200,
                       RigTime time = RigTime::Wall, bus::LinkMode mode = bus::LinkMode::Active)
        : m_setup(std::move(setup))
    {
        if (time == RigTime::Manual)
            timers = std::make_unique<testsupport::ManualTimers>(
                std::make_shared<testsupport::ManualClock>());
        worker = std::make_unique<bus::BusWorker>(
            [this](int b) {
                {
                    QMutexLocker lock(&log->mutex);
                    log->bauds.append(b);
                }
                auto t = std::make_unique<FakeTransport>(b, log);
                transport = t.get();
                if (timers) {
                    t->setScheduler([this](int ms, std::function<void()> f) {
                        timers->singleShot(ms, std::move(f));
                    });
                }
                if (m_setup)
                    m_setup(*t);
                return t;
            },
            baud, config, timers ? timers->timeSource() : bus::BusTimeSource{});
        QObject::connect(worker.get(), &bus::BusWorker::requestCompleted, worker.get(),
                         [this](const bus::RequestResult &r) { results.append(r); });
        worker->start(mode);
    }
    ~WorkerRig() { worker.reset(); } // its last completions still land in `results`

    /// Manual time: advance the clock timer by timer until `done()` holds, at most `limitMs`;
    /// whether it holds.
    bool runUntil(const std::function<bool()> &done, double limitMs = 60000)
    {
        return timers->advanceUntil(done, limitMs);
    }
    /// Manual time: the clock (ms since the worker was made).
    double nowMs() const { return timers->clock()->nowMs(); }

    quint64 send(const protocol::Request &r, bus::Priority p = bus::Priority::Operator,
                 int retries = -1)
    {
        bus::BusRequest b;
        b.ticket = ++m_ticket;
        b.request = r;
        b.priority = p;
        b.retries = retries;
        worker->submit(b);
        return b.ticket;
    }

    const bus::RequestResult *result(quint64 ticket) const
    {
        for (const bus::RequestResult &r : results) {
            if (r.ticket == ticket)
                return &r;
        }
        return nullptr;
    }
    int resultCount(quint64 ticket) const
    {
        int n = 0;
        for (const bus::RequestResult &r : results)
            n += r.ticket == ticket ? 1 : 0;
        return n;
    }

    /// The written frames, decoded as (command, id).
    QVector<QPair<protocol::Command, int>> writtenRequests() const
    {
        QVector<QPair<protocol::Command, int>> out;
        for (const QByteArray &b : log->writtenCopy())
            out.append({static_cast<protocol::Command>(quint8(b.at(1))), int(quint8(b.at(2)))});
        return out;
    }

    std::shared_ptr<FakeLog> log = std::make_shared<FakeLog>();
    FakeTransport *transport = nullptr;                ///< the current one (the worker owns it)
    std::unique_ptr<testsupport::ManualTimers> timers; ///< RigTime::Manual only; outlives worker
    std::unique_ptr<bus::BusWorker> worker;
    QVector<bus::RequestResult> results;

private:
    Setup m_setup;
    quint64 m_ticket = 0;
};

} // namespace lk::bustest
