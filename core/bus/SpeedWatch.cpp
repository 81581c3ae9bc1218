#include "SpeedWatch.h"

#include "BusLog.h"

#include <protocol/Command.h>

#include <algorithm>
#include <cmath>
#include <variant>

namespace lk::bus {

using protocol::Command;

double SpeedWatch::thresholdDps(double limitDps)
{
    return limitDps + std::max(limitDps * kMarginFraction, kMarginMinDps);
}

bool SpeedWatch::isWatchedMode(Command command)
{
    return command == Command::Torque || command == Command::OpenLoop;
}

bool SpeedWatch::drives(const protocol::Request &r)
{
    if (const auto *t = std::get_if<protocol::TorqueCommand>(&r.payload))
        return t->iqRaw != 0;
    if (const auto *p = std::get_if<protocol::OpenLoopCommand>(&r.payload))
        return p->power != 0;
    return false;
}

SpeedWatch::SpeedWatch(StopSender stop, SeriesLookup series, std::function<double()> now,
                       QObject *parent)
    : QObject(parent), m_stop(std::move(stop)), m_series(std::move(series)), m_now(std::move(now))
{
}

void SpeedWatch::setSoftLimits(int id, const safety::SoftLimits &limits)
{
    m_limits.insert(id, limits.maxSpeedDps);
}

double SpeedWatch::limitDps(int id, SpeedWatchSource *source) const
{
    const auto it = m_limits.constFind(id);
    if (source)
        *source =
            it != m_limits.cend() ? SpeedWatchSource::SoftLimit : SpeedWatchSource::SeriesDefault;
    if (it != m_limits.cend())
        return *it;
    return safety::SoftLimits::defaults(m_series ? m_series(id) : std::nullopt).maxSpeedDps;
}

QVector<int> SpeedWatch::watchedIds() const
{
    QVector<int> ids;
    for (auto it = m_drives.cbegin(); it != m_drives.cend(); ++it) {
        if (it->state != State::Held)
            ids.append(it.key()); // QMap: ascending
    }
    return ids;
}

std::optional<Command> SpeedWatch::modeOf(int id) const
{
    const auto it = m_drives.constFind(id);
    if (it == m_drives.cend() || it->state == State::Held)
        return std::nullopt;
    return it->mode;
}

void SpeedWatch::clear()
{
    const bool had = !watchedIds().isEmpty();
    m_drives.clear();
    if (had)
        emit watchedChanged({});
}

void SpeedWatch::setState(int id, std::optional<State> state)
{
    const QVector<int> before = watchedIds();
    if (state)
        m_drives[id].state = *state;
    else
        m_drives.remove(id);
    const QVector<int> after = watchedIds();
    if (after != before)
        emit watchedChanged(after);
}

void SpeedWatch::arm(int id, Command mode)
{
    const QVector<int> before = watchedIds();
    const bool stopping = m_drives.value(id).state == State::Stopping && m_drives.contains(id);
    m_drives[id] = Drive{stopping ? State::Stopping : State::Watching, mode};
    const QVector<int> after = watchedIds();
    if (after != before) {
        SpeedWatchSource source;
        const double limit = limitDps(id, &source);
        qCInfo(lcBus).noquote() << "speed watch: drive" << id << "under"
                                << protocol::CommandTable::name(mode) << "is stopped above"
                                << thresholdDps(limit) << "dps (limit" << limit
                                << (source == SpeedWatchSource::SoftLimit ? "dps, soft limit)"
                                                                          : "dps, series default)");
        emit watchedChanged(after);
    }
}

void SpeedWatch::noteRequestEnded(const protocol::Request &request, RequestStatus status,
                                  int attempts)
{
    if (attempts == 0)
        return; // never on the wire: it changed nothing
    const int id = request.id;
    const Command c = request.command;
    const bool ok = status == RequestStatus::Ok;
    if (isWatchedMode(c)) {
        if (drives(request))
            arm(id, c); // even unanswered: the drive may have acted on it
        else if (ok)
            setState(id, std::nullopt);
        return;
    }
    if (!ok || !m_drives.contains(id))
        return; // a drive that may not have heard it keeps what it was doing
    const State state = m_drives.value(id).state;
    if (c == Command::MotorRun) {
        if (state == State::Held)
            setState(id, State::Watching); // V2.3 resumes the command the stop kept
    } else if (c == Command::MotorStop) {
        if (state == State::Watching)
            setState(id, State::Held);
    } else if (c == Command::MotorOff || protocol::CommandTable::info(c).movesMotor) {
        setState(id, std::nullopt); // off, or a closed loop the drive bounds itself
    }
}

void SpeedWatch::noteSample(const TelemetrySample &sample)
{
    if (!sample.has(TelemetryField::Speed))
        return;
    const auto it = m_drives.constFind(sample.id);
    if (it == m_drives.cend() || it->state != State::Watching)
        return;
    if (std::abs(sample.speedDps) > thresholdDps(limitDps(sample.id)))
        trip(sample.id, sample);
}

void SpeedWatch::trip(int id, const TelemetrySample &sample)
{
    SpeedWatchTrip t;
    t.id = id;
    t.mode = m_drives.value(id).mode;
    t.limitDps = limitDps(id, &t.source);
    t.thresholdDps = thresholdDps(t.limitDps);
    t.speedDps = sample.speedDps;
    t.seenS = sample.time;
    qCWarning(lcBus).noquote() << "speed watch: drive" << id << "at" << t.speedDps << "dps under"
                               << protocol::CommandTable::name(t.mode) << "is over"
                               << t.thresholdDps << "dps: Motor Stop";
    m_drives[id].state = State::Stopping; // still polled until the stop has ended
    m_stop(id, [this, t](const RequestResult &r) { onStopEnded(t, r); });
}

void SpeedWatch::onStopEnded(SpeedWatchTrip trip, const RequestResult &result)
{
    trip.stopEndedS = m_now ? m_now() : 0;
    trip.stopStatus = result.status;
    trip.stopReason = result.reason;
    const auto it = m_drives.find(trip.id);
    // An acknowledged stop held the drive already (noteRequestEnded ran first); a failed one
    // leaves it watched: the next fast reply stops it again. A later command may have
    // replaced the watch meanwhile: then that one stands.
    if (it != m_drives.end() && it->state == State::Stopping)
        setState(trip.id, result.ok() ? State::Held : State::Watching);
    emit tripped(trip);
}

} // namespace lk::bus
