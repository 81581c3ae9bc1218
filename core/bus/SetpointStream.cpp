#include "SetpointStream.h"

#include "BusLog.h"
#include "BusRequest.h"
#include "BusWorker.h"

#include <protocol/RequestBuilder.h>

#include <algorithm>
#include <cmath>

namespace lk::bus {

namespace {
/// Setpoint tickets have the top bit set: BusSession counts its own from 1 and never gets
/// there, so a setpoint's end never takes the callback of a request the session sent.
constexpr quint64 kTicketBit = quint64(1) << 63;
using Target = SetpointWaveform::Target;
} // namespace

SetpointStream::SetpointStream(BusWorker &worker, const SingleShotTimerFactory &timers)
    : QObject(&worker), m_worker(worker), m_clock([&worker] { return worker.now(); })
{
    // Precise: a coarse timer may fire 5 % late, which a 50 Hz waveform would show.
    m_timer = timers(
        this, [this] { tick(); }, Qt::PreciseTimer);
}

SetpointStream::~SetpointStream() = default;

void SetpointStream::setTiming(const SingleShotTimerFactory &timers, std::function<double()> clock)
{
    m_timer = timers(
        this, [this] { tick(); }, Qt::PreciseTimer);
    m_clock = std::move(clock);
}

bool SetpointStream::isSetpointTicket(quint64 ticket)
{
    return (ticket & kTicketBit) != 0;
}

protocol::BuildResult SetpointStream::build(const SetpointStreamPlan &plan, double value,
                                            protocol::Generation generation)
{
    namespace build = protocol::build;
    switch (plan.settings.target) {
    case Target::Speed:
        return build::speed(plan.id, value);
    case Target::Position:
        return build::multiPosition(plan.id, value);
    case Target::Torque:
        return build::torque(plan.id, value,
                             {plan.series.value_or(protocol::Series::MF), generation});
    }
    return build::speed(plan.id, value);
}

void SetpointStream::start(const SetpointStreamPlan &plan)
{
    stop(SetpointStopReason::Replaced);
    m_plan = plan;
    m_plan.settings = SetpointWaveform::bounded(plan.settings);
    // The bus knows the drive's generation (its model reply): torques go out at its scale.
    m_generation = m_worker.knownMotors().value(plan.id).generation;
    m_emitted = 0;
    m_skipped = 0;
    // m_ticket stays: a setpoint of the previous stream still on its way is waited for.
    m_running = true;
    m_startS = m_clock();
    m_nextS = 0;
    emit started(m_plan.stream);
    if (!m_worker.isOpen()) {
        stop(SetpointStopReason::Disconnected);
        return;
    }
    tick();
}

void SetpointStream::stop(SetpointStopReason reason)
{
    if (!m_running)
        return;
    SetpointStop s;
    s.reason = reason;
    finish(s);
}

void SetpointStream::stopRefused(const safety::Verdict &verdict,
                                 const std::optional<protocol::FieldError> &fieldError)
{
    SetpointStop s;
    s.reason = SetpointStopReason::Refused;
    s.verdict = verdict;
    s.fieldError = fieldError;
    finish(s);
}

void SetpointStream::finish(SetpointStop stop)
{
    m_running = false;
    m_timer->stop();
    stop.stream = m_plan.stream;
    stop.emitted = m_emitted;
    stop.skipped = m_skipped;
    qCInfo(lcBus) << "setpoint stream" << stop.stream << "stopped, reason" << int(stop.reason)
                  << "sent" << stop.emitted << "skipped" << stop.skipped;
    emit stopped(stop);
}

void SetpointStream::scheduleNext(double t)
{
    // Due times are counted from the start, so that a late tick does not shift the rest; a
    // tick later than a whole interval is not caught up with a burst.
    const double interval = 1.0 / m_plan.settings.rateHz;
    m_nextS += interval;
    if (m_nextS <= t)
        m_nextS = t + interval;
    m_timer->start(std::max(0, static_cast<int>(std::ceil((m_nextS - t) * 1e3 - 1e-6))));
}

void SetpointStream::tick()
{
    if (!m_running)
        return;
    const double t = std::max(0.0, m_clock() - m_startS);
    scheduleNext(t);
    // One setpoint queued or on the wire at most: a slow bus gets fewer, never a backlog.
    if (m_ticket) {
        ++m_skipped;
        return;
    }
    const protocol::BuildResult built =
        build(m_plan, SetpointWaveform::valueAt(m_plan.settings, t), m_generation);
    if (!built.ok()) {
        stopRefused({}, built.error);
        return;
    }
    // The GUI's motion gate, per setpoint: position targets are checked from the start angle
    // and get their speed cap (limited form), speeds and torques the series and soft limits.
    const safety::MotionPlan planned =
        safety::MotionPlanner::plan(*built.request, m_plan.series, m_plan.limits, m_plan.position);
    if (!planned.allowed()) {
        stopRefused(planned.verdict, std::nullopt);
        return;
    }
    BusRequest b;
    b.ticket = kTicketBit | ++m_lastTicket;
    b.request = *planned.request;
    b.priority = Priority::Operator;
    // A position setpoint is one point of a path: repeated after a lost reply it would go out
    // when the next target is already due, and pull the drive back. The next tick sends a
    // fresh one. Speed and torque keep the gate's retries.
    b.retries = m_plan.settings.target == Target::Position ? 0 : -1;
    b.origin = RequestOrigin::Setpoint;
    m_ticket = b.ticket;
    ++m_emitted;
    m_worker.submit(
        b, [this, stream = m_plan.stream](const RequestResult &r) { onCompleted(stream, r); });
}

void SetpointStream::onCompleted(quint64 stream, const RequestResult &result)
{
    if (result.ticket == m_ticket)
        m_ticket = 0;
    emit setpointCompleted(result);
    if (!result.ok())
        emit setpointFailed(stream, result);
    // A setpoint of a stream stopped or replaced since says nothing about the running one.
    if (!m_running || stream != m_plan.stream)
        return;
    // The bus dropped it (an emergency stop cancels motion; a lost link): never send more.
    if (result.status == RequestStatus::Cancelled)
        stop(SetpointStopReason::Cancelled);
    else if (result.status == RequestStatus::Disconnected)
        stop(SetpointStopReason::Disconnected);
}

} // namespace lk::bus
