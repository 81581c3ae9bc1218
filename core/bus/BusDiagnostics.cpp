#include "BusDiagnostics.h"

#include "MotorRegistry.h"

#include <algorithm>

namespace lk::bus {

namespace {
constexpr int kTrafficIntervalMs = 50;

int intervalMs(double hz)
{
    return static_cast<int>(1000.0 / std::max(0.1, hz));
}
} // namespace

BusDiagnostics::BusDiagnostics(const MotorRegistry &motors, std::shared_ptr<BusClock> clock,
                               const SingleShotTimerFactory &timers, QObject *parent)
    : QObject(parent), m_motors(motors), m_clock(std::move(clock))
{
    // Both only feed the screen: coarse, each restarted on its timeout (a periodic timer).
    m_statsTimer = timers(
        this,
        [this] {
            m_statsTimer->start(m_statsIntervalMs);
            emit statisticsDue();
        },
        Qt::CoarseTimer);
    m_trafficTimer = timers(
        this,
        [this] {
            m_trafficTimer->start(kTrafficIntervalMs);
            flushTraffic();
        },
        Qt::CoarseTimer);
}

BusDiagnostics::~BusDiagnostics() = default;

void BusDiagnostics::startStatistics(double statisticsHz)
{
    m_statsIntervalMs = intervalMs(statisticsHz);
    m_statsTimer->start(m_statsIntervalMs);
}

void BusDiagnostics::setStatisticsHz(double statisticsHz)
{
    m_statsIntervalMs = intervalMs(statisticsHz);
    if (m_statsTimer->isActive())
        m_statsTimer->start(m_statsIntervalMs);
}

void BusDiagnostics::setTrafficCapture(bool enabled)
{
    m_traffic.setEnabled(enabled);
    if (enabled)
        m_trafficTimer->start(kTrafficIntervalMs);
    else
        m_trafficTimer->stop();
}

void BusDiagnostics::stop()
{
    m_statsTimer->stop();
    m_trafficTimer->stop();
}

void BusDiagnostics::flushTraffic()
{
    if (m_traffic.hasPending())
        emit trafficCaptured(m_traffic.take(now()));
}

void BusDiagnostics::recordSent(const QByteArray &bytes, int id)
{
    if (m_traffic.isEnabled())
        m_traffic.recordSent(now(), bytes, m_motors.decodeContext(id));
}

void BusDiagnostics::recordTimeout(int id, quint8 command)
{
    if (m_traffic.isEnabled())
        m_traffic.record(TrafficEvent::Kind::Timeout, now(), {}, id, command);
}

void BusDiagnostics::recordNote(const QString &text)
{
    if (m_traffic.isEnabled())
        m_traffic.record(TrafficEvent::Kind::Note, now(), {}, 0, 0, text);
}

void BusDiagnostics::recordParseEvent(const protocol::ParseEvent &event)
{
    if (!m_traffic.isEnabled())
        return;
    m_traffic.recordParseEvent(event, now(),
                               event.isFrame ? m_motors.decodeContext(event.frame.id)
                                             : protocol::DecodeContext{});
}

} // namespace lk::bus
