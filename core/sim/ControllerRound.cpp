#include "ControllerRound.h"

#include "protocol/RequestBuilder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lk::sim {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
} // namespace

ControllerRound::ControllerRound(const ControllerSpec &spec, QList<int> ids, double startS)
    : m_spec(spec), m_ids(std::move(ids)), m_startS(startS)
{
}

std::optional<protocol::Request> ControllerRound::next(double atS)
{
    if (m_ids.isEmpty())
        return std::nullopt;
    const int items = 1 + static_cast<int>(m_spec.poll.size());
    const int slotCount = static_cast<int>(m_ids.size()) * items;
    for (int step = 0; step < slotCount; ++step) {
        const int id = m_ids[m_idIndex];
        const int item = m_itemIndex;
        if (++m_itemIndex >= items) {
            m_itemIndex = 0;
            m_idIndex = (m_idIndex + 1) % static_cast<int>(m_ids.size());
        }
        if (item == 0) {
            if (std::optional<protocol::Request> r = setpoint(id, atS))
                return r;
            continue;
        }
        return protocol::build::plain(m_spec.poll[item - 1], id).request;
    }
    return std::nullopt; // only setpoints, and none is due: wait for one
}

std::optional<protocol::Request> ControllerRound::setpoint(int id, double atS)
{
    const double elapsed = atS - m_startS;
    if (m_spec.move) {
        const ControllerSpec::Move &m = *m_spec.move;
        // Moves due so far; a master that fell behind sends the latest one, not a burst.
        const int due = static_cast<int>(std::floor(elapsed / m.periodS));
        if (due > m_movesSent.value(id)) {
            m_movesSent[id] = due;
            m_holdUntilS[id] = atS + m.stepDeg / m.maxSpeedDps + kMoveSettleS;
            const double step = due % 2 ? m.stepDeg : -m.stepDeg;
            return protocol::build::incrementPosition(id, step, m.maxSpeedDps).request;
        }
    }
    if (m_spec.speed && atS >= m_holdUntilS.value(id, -kNever)) {
        const double v =
            m_spec.speed->amplitudeDps * std::sin(2 * M_PI * m_spec.speed->frequencyHz * elapsed);
        return protocol::build::speed(id, v).request;
    }
    return std::nullopt;
}

double ControllerRound::idleUntilS(double atS) const
{
    double wake = kNever;
    for (int id : m_ids) {
        if (m_spec.move)
            wake = std::min(wake, m_startS + (m_movesSent.value(id) + 1) * m_spec.move->periodS);
        const double hold = m_holdUntilS.value(id, -kNever);
        if (m_spec.speed && hold > atS)
            wake = std::min(wake, hold);
    }
    return wake;
}

} // namespace lk::sim
