#pragma once

#include "BusTiming.h"

#include "PollPlan.h"

#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QVector>

#include <functional>
#include <optional>

namespace lk::bus {

/// Round robin over (ID, command) slots of a PollPlan. Pulled by the BusWorker whenever the
/// bus is idle, so polls fill the gaps between operator requests. A slot is never handed out
/// while its previous poll is outstanding; a cycle starts at most every 1/rateHz seconds.
class PollScheduler {
public:
    /// Series of an ID, to skip commands the series does not answer (0x9D on MS).
    using SeriesLookup = std::function<std::optional<protocol::Series>(int id)>;

    void setSeriesLookup(SeriesLookup lookup) { m_series = std::move(lookup); }
    /// Replace the plan; non-read commands and IDs outside 1..32 are dropped.
    void setPlan(const PollPlan &plan, double now);
    void clear();
    bool isActive() const { return !m_slots.isEmpty(); }
    const PollPlan &plan() const { return m_plan; }

    /// The poll to send now, or nullopt (nothing due, or everything outstanding).
    std::optional<protocol::Request> next(double now);
    /// When next() may return a poll again (now when one is due; +inf when none will be).
    double nextDueTime(double now) const;
    /// The poll for (id, command) ended (any status); its slot may be handed out again.
    void completed(int id, protocol::Command command);
    int outstanding() const;
    /// The round the polls handed out by next() belong to: 1 for the first round of the
    /// first plan, +1 for every new round and every new plan (never reused, never 0).
    quint64 cycle() const { return m_cycle; }
    /// When that round began (the clock next() and setPlan() are given).
    double cycleStart() const { return m_cycleStart; }
    /// The bus limit, in transactions/s, for the plan's command mix at `baud` with the
    /// drives' turnaround `turnaroundS` (the formula's 0.5 ms until one was measured).
    double busLimitPerSecond(int baud, double turnaroundS = BusTiming::kTurnaroundS) const;
    /// Full rounds per second at that limit (every polled command of every ID once).
    double cycleLimitHz(int baud, double turnaroundS = BusTiming::kTurnaroundS) const;

    static bool isPollable(protocol::Command command);

private:
    struct Slot {
        int id = 0;
        protocol::Command command = protocol::Command::ReadState2;
        bool outstanding = false;
    };
    bool skipped(const Slot &slot) const;
    bool eligible(const Slot &slot) const;

    PollPlan m_plan;
    QVector<Slot> m_slots;
    SeriesLookup m_series;
    int m_cursor = 0;
    double m_cycleStart = 0;
    quint64 m_cycle = 0;
};

} // namespace lk::bus
