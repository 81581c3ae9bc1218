#include "PollScheduler.h"

#include "BusTiming.h"

#include <motor/SeriesLimits.h>
#include <protocol/Checksum.h>

#include <algorithm>
#include <limits>

namespace lk::bus {

using protocol::Command;

bool PollScheduler::isPollable(Command command)
{
    switch (command) {
    case Command::ReadModel:
    case Command::ReadPid:
    case Command::ReadAccel:
    case Command::ReadEncoder:
    case Command::ReadMultiTurn:
    case Command::ReadSingleTurn:
    case Command::ReadState1:
    case Command::ReadState2:
    case Command::ReadState3:
        return true;
    default:
        return false;
    }
}

void PollScheduler::setPlan(const PollPlan &plan, double now)
{
    m_plan = plan;
    m_plan.ids.clear();
    m_plan.commands.clear();
    m_slots.clear();
    for (int id : plan.ids) {
        if (id >= protocol::kMinId && id <= protocol::kMaxId && !m_plan.ids.contains(id))
            m_plan.ids.append(id);
    }
    for (Command c : plan.commands) {
        if (isPollable(c) && !m_plan.commands.contains(c))
            m_plan.commands.append(c);
    }
    // ID-major order: one drive's fields arrive close together in time.
    for (int id : m_plan.ids) {
        for (Command c : m_plan.commands)
            m_slots.append(Slot{id, c, false});
    }
    m_cursor = 0;
    m_cycleStart = now;
    ++m_cycle;
}

void PollScheduler::clear()
{
    m_plan = PollPlan{};
    m_plan.commands.clear();
    m_slots.clear();
    m_cursor = 0;
}

bool PollScheduler::eligible(const Slot &slot) const
{
    return !slot.outstanding && !skipped(slot);
}

bool PollScheduler::skipped(const Slot &slot) const
{
    if (!m_series)
        return false;
    const std::optional<protocol::Series> s = m_series(slot.id);
    return s && !motor::supports(*s, slot.command);
}

std::optional<protocol::Request> PollScheduler::next(double now)
{
    if (now < nextDueTime(now))
        return std::nullopt;
    // nextDueTime() found an eligible slot at or after the cursor, or allowed a new cycle.
    for (int tried = 0; tried <= m_slots.size(); ++tried) {
        if (m_cursor >= m_slots.size()) {
            m_cursor = 0;
            m_cycleStart = now;
            ++m_cycle;
        }
        Slot &slot = m_slots[m_cursor++];
        if (!eligible(slot))
            continue;
        slot.outstanding = true;
        protocol::Request r;
        r.command = slot.command;
        r.id = static_cast<quint8>(slot.id);
        return r;
    }
    return std::nullopt;
}

double PollScheduler::nextDueTime(double now) const
{
    bool any = false;
    for (int i = 0; i < m_slots.size(); ++i) {
        if (!eligible(m_slots[i]))
            continue;
        if (i >= m_cursor)
            return now; // still in the current cycle
        any = true;
    }
    if (!any)
        return std::numeric_limits<double>::infinity(); // a completion will pump again
    return m_plan.rateHz > 0 ? std::max(now, m_cycleStart + 1.0 / m_plan.rateHz) : now;
}

void PollScheduler::completed(int id, Command command)
{
    for (Slot &s : m_slots) {
        if (s.id == id && s.command == command)
            s.outstanding = false;
    }
}

int PollScheduler::outstanding() const
{
    int n = 0;
    for (const Slot &s : m_slots)
        n += s.outstanding ? 1 : 0;
    return n;
}

double PollScheduler::busLimitPerSecond(int baud, double turnaroundS) const
{
    QVector<Command> mix;
    for (const Slot &s : m_slots) {
        if (!skipped(s))
            mix.append(s.command);
    }
    return BusTiming::transactionsPerSecond(mix, baud, turnaroundS);
}

double PollScheduler::cycleLimitHz(int baud, double turnaroundS) const
{
    double cycleS = 0;
    for (const Slot &s : m_slots) {
        if (!skipped(s))
            cycleS += BusTiming::transactionTimeS(s.command, baud, turnaroundS);
    }
    return cycleS > 0 ? 1.0 / cycleS : 0;
}

} // namespace lk::bus
