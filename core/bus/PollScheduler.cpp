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

namespace {
QVector<Command> pollableOnly(const QVector<Command> &commands)
{
    QVector<Command> out;
    for (Command c : commands) {
        if (PollScheduler::isPollable(c) && !out.contains(c))
            out.append(c);
    }
    return out;
}
} // namespace

void PollScheduler::setPlan(const PollPlan &plan, double now)
{
    m_plan = plan;
    m_plan.ids.clear();
    for (int id : plan.ids) {
        if (id >= protocol::kMinId && id <= protocol::kMaxId && !m_plan.ids.contains(id))
            m_plan.ids.append(id);
    }
    m_plan.commands = pollableOnly(plan.commands);
    const bool focus = plan.focusId >= protocol::kMinId && plan.focusId <= protocol::kMaxId;
    m_plan.focusId = focus ? plan.focusId : 0;
    m_plan.focusCommands =
        focus ? pollableOnly(plan.focusCommands.isEmpty() ? plan.commands : plan.focusCommands)
              : QVector<Command>{};
    m_plan.focusOthersEvery = std::max(0, plan.focusOthersEvery);
    m_plan.extraCommands = extrasOf(plan.extraCommands);

    m_main = Ring{};
    m_others = Ring{};
    // ID-major order: one drive's fields arrive close together in time.
    for (int id : polledIds()) {
        if (id == m_plan.focusId)
            continue;
        for (Command c : commandsOf(id))
            (focus ? m_others : m_main).entries.append(Slot{id, c, false});
    }
    for (Command c : m_plan.focusCommands)
        m_main.entries.append(Slot{m_plan.focusId, c, false});
    m_main.rateHz = focus ? 0 : m_plan.rateHz; // the focus drive goes at the bus's pace
    m_main.current = Round{++m_rounds, now};
    m_others.rateHz = m_plan.rateHz;
    // The others' first poll opens their first round, due at once.
    m_others.cursor = int(m_others.entries.size());
    m_others.current.start = -std::numeric_limits<double>::infinity();
    m_sinceOthers = 0;
    m_current = m_main.current;
}

QMap<int, QVector<Command>> PollScheduler::extrasOf(const QMap<int, QVector<Command>> &extras) const
{
    QMap<int, QVector<Command>> out;
    for (auto it = extras.begin(); it != extras.end(); ++it) {
        if (it.key() < protocol::kMinId || it.key() > protocol::kMaxId)
            continue;
        const bool inPlan = m_plan.ids.contains(it.key());
        QVector<Command> commands;
        for (Command c : pollableOnly(it.value())) {
            if (!inPlan || !m_plan.commands.contains(c)) // read once per round
                commands.append(c);
        }
        if (!commands.isEmpty())
            out.insert(it.key(), commands);
    }
    return out;
}

QVector<int> PollScheduler::polledIds() const
{
    QVector<int> ids = m_plan.ids;
    for (auto it = m_plan.extraCommands.begin(); it != m_plan.extraCommands.end(); ++it) {
        if (!ids.contains(it.key()))
            ids.append(it.key());
    }
    return ids;
}

QVector<Command> PollScheduler::commandsOf(int id) const
{
    QVector<Command> commands = m_plan.ids.contains(id) ? m_plan.commands : QVector<Command>{};
    return commands + m_plan.extraCommands.value(id);
}

void PollScheduler::setWatched(const QVector<int> &ids)
{
    Ring watch;
    for (int id : ids) {
        if (id < protocol::kMinId || id > protocol::kMaxId)
            continue;
        bool outstanding = false; // a read on the wire is not handed out twice
        for (const Slot &s : std::as_const(m_watch.entries))
            outstanding = outstanding || (s.id == id && s.outstanding);
        watch.entries.append(Slot{id, Command::ReadState2, outstanding});
    }
    watch.cursor = watch.entries.isEmpty() ? 0 : m_watch.cursor % int(watch.entries.size());
    m_watch = watch;
}

QVector<int> PollScheduler::watched() const
{
    QVector<int> ids;
    for (const Slot &s : m_watch.entries)
        ids.append(s.id);
    return ids;
}

std::optional<protocol::Request> PollScheduler::nextWatch()
{
    for (int tried = 0; tried < m_watch.entries.size(); ++tried) {
        Slot &slot = m_watch.entries[m_watch.cursor];
        m_watch.cursor = (m_watch.cursor + 1) % int(m_watch.entries.size());
        if (slot.outstanding)
            continue;
        slot.outstanding = true;
        m_lastWasWatch = true;
        protocol::Request r;
        r.command = slot.command;
        r.id = static_cast<quint8>(slot.id);
        return r;
    }
    return std::nullopt;
}

void PollScheduler::clear()
{
    m_plan = PollPlan{};
    m_plan.commands.clear();
    m_main = Ring{};
    m_others = Ring{};
    m_unanswered.clear(); // the next plan may meet other drives at those IDs
}

bool PollScheduler::isActive() const
{
    return !m_main.entries.isEmpty() || !m_others.entries.isEmpty();
}

bool PollScheduler::eligible(const Slot &slot) const
{
    return !slot.outstanding && !skipped(slot);
}

bool PollScheduler::skipped(const Slot &slot) const
{
    if (m_unanswered.isMuted(slot.id, slot.command))
        return true;
    if (!m_series)
        return false;
    const std::optional<protocol::Series> s = m_series(slot.id);
    return s && !motor::supports(*s, slot.command);
}

bool PollScheduler::pollable(const Ring &ring) const
{
    return std::any_of(ring.entries.begin(), ring.entries.end(),
                       [this](const Slot &s) { return !skipped(s); });
}

bool PollScheduler::othersTurn() const
{
    if (m_others.entries.isEmpty())
        return false;
    // A focus the drive cannot answer (every command skipped) leaves the bus to the others.
    if (!pollable(m_main))
        return true;
    return m_plan.focusOthersEvery > 0 && m_sinceOthers >= m_plan.focusOthersEvery;
}

std::optional<protocol::Request> PollScheduler::take(Ring &ring, double now)
{
    if (now < dueTime(ring, now))
        return std::nullopt;
    // dueTime() found an eligible slot at or after the cursor, or allowed a new round.
    for (int tried = 0; tried <= ring.entries.size(); ++tried) {
        if (ring.cursor >= ring.entries.size()) {
            ring.cursor = 0;
            ring.current = Round{++m_rounds, now};
        }
        Slot &slot = ring.entries[ring.cursor++];
        if (!eligible(slot))
            continue;
        slot.outstanding = true;
        m_current = ring.current;
        protocol::Request r;
        r.command = slot.command;
        r.id = static_cast<quint8>(slot.id);
        return r;
    }
    return std::nullopt;
}

std::optional<protocol::Request> PollScheduler::next(double now)
{
    // A watched drive's speed is read every other poll at least: the watch's reaction time
    // does not depend on the plan's size or rate.
    if (!m_lastWasWatch) {
        if (std::optional<protocol::Request> r = nextWatch())
            return r;
    }
    if (std::optional<protocol::Request> r = nextOfPlan(now)) {
        m_lastWasWatch = false;
        return r;
    }
    return nextWatch();
}

std::optional<protocol::Request> PollScheduler::nextOfPlan(double now)
{
    if (othersTurn()) {
        if (std::optional<protocol::Request> r = take(m_others, now)) {
            m_sinceOthers = 0;
            return r;
        }
    }
    std::optional<protocol::Request> r = take(m_main, now);
    if (r && m_plan.hasFocus())
        ++m_sinceOthers;
    return r;
}

double PollScheduler::dueTime(const Ring &ring, double now) const
{
    bool any = false;
    for (int i = 0; i < ring.entries.size(); ++i) {
        if (!eligible(ring.entries[i]))
            continue;
        if (i >= ring.cursor)
            return now; // still in the current round
        any = true;
    }
    if (!any)
        return std::numeric_limits<double>::infinity(); // a completion will pump again
    return ring.rateHz > 0 ? std::max(now, ring.current.start + 1.0 / ring.rateHz) : now;
}

double PollScheduler::nextDueTime(double now) const
{
    for (const Slot &s : m_watch.entries) {
        if (!s.outstanding)
            return now;
    }
    const double main = dueTime(m_main, now);
    return othersTurn() ? std::min(main, dueTime(m_others, now)) : main;
}

void PollScheduler::completed(int id, Command command)
{
    for (Ring *ring : {&m_main, &m_others, &m_watch}) {
        for (Slot &s : ring->entries) {
            if (s.id == id && s.command == command)
                s.outstanding = false;
        }
    }
}

bool PollScheduler::noteAnswer(int id, Command command, bool answered)
{
    // A drive of known series is asked only what its series answers: a timeout there is a
    // fault to show, never a series to learn.
    if (m_series && m_series(id))
        return false;
    return m_unanswered.noteResult(id, command, answered);
}

int PollScheduler::outstanding() const
{
    int n = 0;
    for (const Ring *ring : {&m_main, &m_others, &m_watch}) {
        for (const Slot &s : ring->entries)
            n += s.outstanding ? 1 : 0;
    }
    return n;
}

QVector<Command> PollScheduler::pollMix(int *rounds) const
{
    const auto unskipped = [this](const Ring &ring) {
        QVector<Command> mix;
        for (const Slot &s : ring.entries) {
            if (!skipped(s))
                mix.append(s.command);
        }
        return mix;
    };
    QVector<Command> mix = unskipped(m_main);
    const QVector<Command> others = unskipped(m_others);
    *rounds = 1;
    if (others.isEmpty() || m_plan.focusOthersEvery == 0)
        return mix.isEmpty() ? others : mix;
    if (mix.isEmpty())
        return others;
    // focusOthersEvery focus polls, then one of the others, as next() hands them out: over
    // focusOthersEvery focus rounds, one per focus command of the others' polls.
    const int focusPolls = int(mix.size());
    QVector<Command> stretch;
    for (int k = 0; k < focusPolls * m_plan.focusOthersEvery; ++k)
        stretch.append(mix.at(k % focusPolls));
    for (int k = 0; k < focusPolls; ++k)
        stretch.append(others.at(k % others.size()));
    *rounds = m_plan.focusOthersEvery;
    return stretch;
}

double PollScheduler::busLimitPerSecond(int baud, double turnaroundS) const
{
    return busLimitPerSecond(LinkTiming::rs485(baud), turnaroundS);
}

double PollScheduler::cycleLimitHz(int baud, double turnaroundS) const
{
    return cycleLimitHz(LinkTiming::rs485(baud), turnaroundS);
}

double PollScheduler::busLimitPerSecond(const LinkTiming &timing, double turnaroundS) const
{
    int rounds = 0;
    return timing.transactionsPerSecond(pollMix(&rounds), turnaroundS);
}

double PollScheduler::cycleLimitHz(const LinkTiming &timing, double turnaroundS) const
{
    int rounds = 0;
    double stretchS = 0;
    for (Command c : pollMix(&rounds))
        stretchS += timing.transactionTimeS(c, turnaroundS);
    return stretchS > 0 ? rounds / stretchS : 0;
}

} // namespace lk::bus
