#include "StreamEnd.h"

#include "LiveBus.h"

#include <algorithm>
#include <climits>
#include <limits>

namespace lk::lkctl {

StreamEnd::StreamEnd(LiveBus &bus, std::optional<double> durationS)
    : m_bus(bus), m_durationS(durationS)
{
    QObject::connect(&m_watcher, &system::SignalWatcher::signalled, &m_context, [this] { stop(); });
    m_duration.setSingleShot(true);
    QObject::connect(&m_duration, &QTimer::timeout, &m_context, [this] { stop(); });
    QObject::connect(&bus.session(), &bus::BusSession::connectionChanged, &m_context,
                     [this](const bus::ConnectionStatus &s) {
                         if (!s.isOpen() && !m_stop) {
                             lose();
                             m_bus.error(QStringLiteral("the bus went away: %1").arg(s.reason));
                         }
                     });
}

void StreamEnd::startClock()
{
    if (m_durationS)
        m_duration.start(int(std::min(*m_durationS * 1000, double(INT_MAX))));
}

void StreamEnd::wait()
{
    m_bus.waitUntil([this] { return m_stop; }, std::numeric_limits<int>::max());
}

} // namespace lk::lkctl
