#include "BusSession.h"

#include "BusLog.h"
#include "BusWorker.h"
#include "StopTargets.h"

#include <protocol/Checksum.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QMetaObject>
#include <QtCore/QThread>

namespace lk::bus {

namespace {
constexpr unsigned long kJoinTimeoutMs = 5000;
} // namespace

BusSession::BusSession(QObject *parent) : QObject(parent)
{
    registerBusMetaTypes();
}

BusSession::~BusSession()
{
    // Listeners may be half destroyed now: nothing is delivered from here on.
    ++m_generation;
    join();
}

template <typename F> void BusSession::post(F &&f)
{
    if (m_worker)
        QMetaObject::invokeMethod(m_worker, std::forward<F>(f), Qt::QueuedConnection);
}

template <typename... Args>
void BusSession::relay(void (BusWorker::*from)(Args...), void (BusSession::*to)(Args...))
{
    const quint64 gen = m_generation;
    connect(m_worker, from, this, [this, gen, to](Args... args) {
        if (gen == m_generation)
            (this->*to)(args...);
    });
}

void BusSession::connectWorker()
{
    const quint64 gen = m_generation;
    connect(m_worker, &BusWorker::connectionChanged, this, [this, gen](const ConnectionStatus &s) {
        if (gen != m_generation)
            return;
        m_connection = s;
        emit connectionChanged(s);
    });
    connect(m_worker, &BusWorker::knownMotorsChanged, this, [this, gen](const KnownMotors &m) {
        if (gen != m_generation)
            return;
        m_motors = m;
        emit knownMotorsChanged(m);
    });
    relay(&BusWorker::errorOccurred, &BusSession::errorOccurred);
    relay(&BusWorker::requestCompleted, &BusSession::finishRequest);
    relay(&BusWorker::emergencyStopFinished, &BusSession::finishStop);
    relay(&BusWorker::emergencyStopProgress, &BusSession::emergencyStopProgress);
    relay(&BusWorker::emergencyStopRefused, &BusSession::emergencyStopRefused);
    relay(&BusWorker::scanProgress, &BusSession::scanProgress);
    relay(&BusWorker::motorFound, &BusSession::motorFound);
    relay(&BusWorker::scanFinished, &BusSession::scanFinished);
    relay(&BusWorker::pollingChanged, &BusSession::pollingChanged);
    relay(&BusWorker::setpointStreamStarted, &BusSession::setpointStreamStarted);
    relay(&BusWorker::setpointStreamStopped, &BusSession::setpointStreamStopped);
    relay(&BusWorker::setpointFailed, &BusSession::setpointFailed);
    relay(&BusWorker::telemetryReceived, &BusSession::telemetryReceived);
    relay(&BusWorker::statisticsUpdated, &BusSession::statisticsUpdated);
    relay(&BusWorker::listenStatisticsUpdated, &BusSession::listenStatisticsUpdated);
    relay(&BusWorker::trafficCaptured, &BusSession::trafficCaptured);
    relay(&BusWorker::speedWatchTripped, &BusSession::speedWatchTripped);
    relay(&BusWorker::multiTorqueCompleted, &BusSession::finishMultiTorque);
}

void BusSession::finishMultiTorque(const MultiTorqueResult &result)
{
    const auto done = m_multiTorqueCallbacks.take(result.ticket);
    emit multiTorqueCompleted(result);
    if (done)
        done(result);
}

quint64 BusSession::sendMultiTorque(const MultiTorqueRequest &request, QObject *context,
                                    MultiTorqueCompletion done)
{
    const quint64 ticket = m_nextTicket++;
    m_multiTorqueCallbacks.add(ticket, context, std::move(done));
    if (!m_worker) {
        MultiTorqueResult r;
        r.ticket = ticket;
        r.status = RequestStatus::Disconnected;
        r.reason = tr("the bus is not open");
        QMetaObject::invokeMethod(
            this, [this, r] { finishMultiTorque(r); }, Qt::QueuedConnection);
        return ticket;
    }
    post([w = m_worker, ticket, request] { w->submitMultiTorque(ticket, request); });
    return ticket;
}

void BusSession::finishRequest(const RequestResult &result)
{
    const auto done = m_requestCallbacks.take(result.ticket);
    emit requestCompleted(result); // observers (CommandedMotion, ...) first: they keep state
    if (done)
        done(result); // `this` may be gone by now: a listener may have deleted the session
}

void BusSession::finishStop(quint64 ticket, const QVector<int> &acknowledged,
                            const QVector<int> &silent, const QVector<int> &unsent)
{
    const auto done = m_stopCallbacks.take(ticket);
    emit emergencyStopFinished(ticket, acknowledged, silent, unsent);
    if (done)
        done(acknowledged, silent, unsent);
}

void BusSession::open(TransportFactory factory, int baud, const BusConfig &config, LinkMode mode)
{
    close();
    m_config = config;
    m_mode = mode;
    m_thread = new QThread; // no parent: a thread that will not stop must not be deleted
    m_thread->setObjectName(QStringLiteral("lk-bus"));
    m_worker = new BusWorker(std::move(factory), baud, config);
    m_worker->moveToThread(m_thread);
    // The worker (and with it the transport) dies on its own thread once the loop has ended.
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connectWorker();
    m_thread->start();
    post([w = m_worker, mode] { w->start(mode); });
    for (auto it = m_softLimits.cbegin(); it != m_softLimits.cend(); ++it)
        post([w = m_worker, id = it.key(), limits = it.value()] { w->setSoftLimits(id, limits); });
    for (const DriveIdentity &d : std::as_const(m_identities))
        postIdentity(d);
}

void BusSession::join()
{
    if (!m_thread)
        return;
    BusWorker *w = m_worker;
    QThread *t = m_thread;
    m_worker = nullptr;
    m_thread = nullptr;
    QMetaObject::invokeMethod(
        w,
        [w] {
            w->shutdown(tr("session closed"));
            QThread::currentThread()->quit();
        },
        Qt::QueuedConnection);
    if (t->wait(kJoinTimeoutMs)) {
        delete t;
        return;
    }
    // Never terminate(): a stuck driver call must not take the process down with it.
    qCCritical(lcBus) << "bus thread did not stop within" << kJoinTimeoutMs << "ms; detached";
    connect(t, &QThread::finished, t, &QObject::deleteLater);
}

void BusSession::close()
{
    if (!m_thread)
        return;
    join();
    m_pollPlan.reset();
    m_pollExtras.clear();
    // Deliver what the worker said on its way out (Cancelled completions, Closed state) now,
    // then ignore anything else the old worker may have queued.
    QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
    ++m_generation;
    // Only a bus thread that did not stop leaves any: their ends will never be heard.
    m_requestCallbacks.clear();
    m_multiTorqueCallbacks.clear();
    m_stopCallbacks.clear();
    if (m_connection.state != transport::Transport::State::Closed) {
        m_connection.state = transport::Transport::State::Closed;
        m_connection.reason = tr("session closed");
        emit connectionChanged(m_connection);
    }
}

bool BusSession::isRunning() const
{
    return m_thread != nullptr;
}

void BusSession::takeOver()
{
    if (!m_worker || m_mode == LinkMode::Active)
        return;
    m_mode = LinkMode::Active;
    post([w = m_worker] { w->takeOver(); });
    // The worker refused every plan while it listened: the one in force now starts.
    if (effectivePollPlan())
        postPollPlan();
}

void BusSession::reconnect()
{
    post([w = m_worker] { w->reconnect(); });
}

void BusSession::setConfig(const BusConfig &config)
{
    m_config = config;
    post([w = m_worker, config] { w->setConfig(config); });
}

quint64 BusSession::send(const protocol::Request &request, Priority priority, int retries)
{
    const quint64 ticket = m_nextTicket++;
    emit requestSubmitted(ticket, request, priority);
    if (!m_worker) {
        RequestResult r;
        r.ticket = ticket;
        r.request = request;
        r.priority = priority;
        r.status = RequestStatus::Disconnected;
        r.reason = tr("the bus is not open");
        // Queued, so that the caller holds the ticket before the result arrives.
        QMetaObject::invokeMethod(
            this, [this, r] { finishRequest(r); }, Qt::QueuedConnection);
        return ticket;
    }
    BusRequest b;
    b.ticket = ticket;
    b.request = request;
    b.priority = priority;
    b.retries = retries;
    b.origin = RequestOrigin::User;
    post([w = m_worker, b] { w->submit(b); });
    return ticket;
}

quint64 BusSession::send(const protocol::Request &request, QObject *context, Completion done,
                         Priority priority, int retries)
{
    const quint64 ticket = send(request, priority, retries);
    // Its end comes back through the event loop at the earliest: the callback is in time.
    m_requestCallbacks.add(ticket, context, std::move(done));
    return ticket;
}

quint64 BusSession::emergencyStop(const QVector<int> &ids, protocol::Command halt)
{
    const quint64 ticket = m_nextTicket++;
    if (!m_worker) {
        // Nothing can be sent: every ID the stop would have reached stays unacknowledged.
        const QVector<int> silent = StopTargets::of(ids, m_motors.keys()).all();
        QMetaObject::invokeMethod(
            this, [this, ticket, silent] { finishStop(ticket, {}, silent, silent); },
            Qt::QueuedConnection);
        return ticket;
    }
    post([w = m_worker, ticket, ids, halt] { w->emergencyStop(ticket, ids, halt); });
    return ticket;
}

quint64 BusSession::emergencyStop(const QVector<int> &ids, protocol::Command halt, QObject *context,
                                  StopCompletion done)
{
    const quint64 ticket = emergencyStop(ids, halt);
    m_stopCallbacks.add(ticket, context, std::move(done));
    return ticket;
}

void BusSession::scan(const ScanOptions &options)
{
    if (!m_worker) {
        ScanSummary s;
        s.error = tr("the bus is not open");
        QMetaObject::invokeMethod(
            this, [this, s] { emit scanFinished(s); }, Qt::QueuedConnection);
        return;
    }
    post([w = m_worker, options] { w->scan(options); });
}

void BusSession::cancelScan()
{
    post([w = m_worker] { w->cancelScan(); });
}

void BusSession::startPolling(const PollPlan &plan)
{
    m_pollPlan = plan;
    postPollPlan();
}

void BusSession::stopPolling()
{
    m_pollPlan.reset();
    postPollPlan();
}

quint64 BusSession::addPollExtras(int id, const QVector<protocol::Command> &commands)
{
    const quint64 handle = m_nextExtrasHandle++;
    m_pollExtras.insert(handle, PollExtras{id, commands});
    postPollPlan();
    return handle;
}

void BusSession::removePollExtras(quint64 handle)
{
    if (m_pollExtras.remove(handle))
        postPollPlan();
}

std::optional<PollPlan> BusSession::effectivePollPlan() const
{
    if (m_pollExtras.isEmpty())
        return m_pollPlan;
    PollPlan plan = m_pollPlan.value_or(PollPlan{});
    if (!m_pollPlan)
        plan.commands.clear(); // no plan: the extras alone
    for (const PollExtras &e : m_pollExtras) {
        QVector<protocol::Command> &commands = plan.extraCommands[e.id];
        for (protocol::Command c : e.commands) {
            if (!commands.contains(c))
                commands.append(c);
        }
    }
    return plan;
}

void BusSession::postPollPlan()
{
    if (const std::optional<PollPlan> plan = effectivePollPlan())
        post([w = m_worker, p = *plan] { w->startPolling(p); });
    else
        post([w = m_worker] { w->stopPolling(); });
}

quint64 BusSession::startSetpointStream(SetpointStreamPlan plan)
{
    plan.stream = m_nextStream++;
    if (!m_worker) {
        SetpointStop s;
        s.stream = plan.stream;
        s.reason = SetpointStopReason::Closed;
        QMetaObject::invokeMethod(
            this, [this, s] { emit setpointStreamStopped(s); }, Qt::QueuedConnection);
        return plan.stream;
    }
    post([w = m_worker, plan] { w->startSetpointStream(plan); });
    return plan.stream;
}

void BusSession::stopSetpointStream()
{
    post([w = m_worker] { w->stopSetpointStream(); });
}

void BusSession::setSoftLimits(int id, const safety::SoftLimits &limits)
{
    m_softLimits.insert(id, limits);
    post([w = m_worker, id, limits] { w->setSoftLimits(id, limits); });
}

void BusSession::setSeries(int id, protocol::Series series)
{
    // Update the local copy at once so that series() answers before the worker echoes it.
    KnownMotor &m = m_motors[id];
    m.id = id;
    m.series = series;
    post([w = m_worker, id, series] { w->setSeries(id, series); });
}

void BusSession::setDriveIdentity(const DriveIdentity &identity)
{
    if (identity.id < protocol::kMinId || identity.id > protocol::kMaxId)
        return;
    m_identities.insert(identity.id, identity);
    KnownMotor &m = m_motors[identity.id];
    m.id = identity.id;
    m.series = identity.series;
    m.generation = identity.generation;
    m.gearRatio = identity.gearRatio;
    m.identityChosen = true;
    postIdentity(identity);
}

void BusSession::postIdentity(const DriveIdentity &d)
{
    post([w = m_worker, d] { w->setDriveIdentity(d.id, d.series, d.generation, d.gearRatio); });
}

std::optional<DriveIdentity> BusSession::driveIdentity(int id) const
{
    const auto it = m_identities.constFind(id);
    return it == m_identities.cend() ? std::nullopt : std::optional<DriveIdentity>(*it);
}

void BusSession::forgetMotors()
{
    m_motors.clear();
    post([w = m_worker] { w->forgetMotors(); });
}

std::optional<protocol::Series> BusSession::series(int id) const
{
    const auto it = m_motors.constFind(id);
    return it == m_motors.cend() ? std::nullopt : it->series;
}

void BusSession::setTrafficCapture(bool enabled)
{
    post([w = m_worker, enabled] { w->setTrafficCapture(enabled); });
}

void BusSession::resetStatistics()
{
    post([w = m_worker] { w->resetStatistics(); });
}

} // namespace lk::bus
